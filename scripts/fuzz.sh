#!/usr/bin/env bash
# Runs every libFuzzer target of tests/fuzz for a bounded time each and fails
# on any crash, leak, timeout or out-of-memory (libFuzzer's own exit codes).
#   scripts/fuzz.sh BUILD_DIR [SECONDS_PER_TARGET]   (default 25 s)
# BUILD_DIR must be configured with -DHSLAM_FUZZ=ON (clang); see
# scripts/sanitize-and-fuzz.sh. The corpus starts from tests/fuzz/corpus/<t>
# plus the repository's own samples (INI files, rawlog and TUM samples);
# crashers are written to BUILD_DIR/fuzz-artifacts/<t>/: keep them as
# regression inputs in tests/fuzz/regressions/<t>/ once fixed.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:?usage: scripts/fuzz.sh BUILD_DIR [SECONDS]}
seconds=${2:-25}
work="$build/fuzz-work"
rm -rf "$work"
mkdir -p "$work"

seed() {  # seed TARGET FILE...: copies small inputs into the target's corpus
  local t=$1; shift
  mkdir -p "$work/corpus/$t"
  for f in "$@"; do [ -f "$f" ] && head -c 65536 "$f" > "$work/corpus/$t/$(echo "$f" | tr '/' '_')"; done
  return 0
}
for t in carmen_line ini_options arcos_packets rawlog_reader tiled_map tum_reader; do
  mkdir -p "$work/corpus/$t" "$build/fuzz-artifacts/$t"
  cp tests/fuzz/corpus/$t/* "$work/corpus/$t/" 2>/dev/null || true
  cp tests/fuzz/regressions/$t/* "$work/corpus/$t/" 2>/dev/null || true
done
seed ini_options config_ini/*.ini
seed tum_reader rawlog_samples/*/ground_truth.tum

# HSLAM_FUZZ_TARGETS (space-separated) limits the timed runs to some targets.
targets=${HSLAM_FUZZ_TARGETS:-carmen_line ini_options arcos_packets rawlog_reader tiled_map tum_reader}
status=0
for t in $targets; do
  bin="$build/bin/fuzz_$t"
  log="$work/$t.log"
  set +e
  # -rss_limit_mb / -malloc_limit_mb: an allocation of > 1 GB is a finding
  # (issue 15: crafted sizes must be refused before allocating).
  "$bin" "$work/corpus/$t" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
    -max_len=65536 -print_final_stats=1 -artifact_prefix="$build/fuzz-artifacts/$t/" > "$log" 2>&1
  rc=$?
  set -e
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo 0)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | grep -o '[0-9]*' || echo 0)
  echo "fuzz: $t: exit=$rc execs=$execs coverage_edges=$cov features=$ft seconds=$seconds"
  if [ $rc -ne 0 ]; then
    echo "fuzz: $t FAILED; last lines of $log:"
    tail -40 "$log"
    status=1
  fi
done
exit $status
