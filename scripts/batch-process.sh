#!/usr/bin/env bash
# Runs hslam-process over a manifest of rawlogs with a bounded number of
# parallel jobs (GNU parallel if installed, else xargs -P; both Debian), one
# output folder per log, then collects every run's summary.json into a table
# (summary.csv + summary.md, linking each report.html). See docs/install.md
# ("Many logs") for the manifest format and the same manifest as a Slurm job
# array.
#
#   scripts/batch-process.sh MANIFEST OUT_ROOT [-j JOBS] [-c INI] [--resolve-only] [-- HSLAM_PROCESS_ARGS...]
#   scripts/batch-process.sh --run-one OUT_ROOT LINE      # one manifest line (used by the tools, Slurm)
#   scripts/batch-process.sh --summarize OUT_ROOT         # only rebuild the table
#
# MANIFEST: one run per line, "NAME RAWLOG [REFERENCE.tum]", blanks between
# fields, no blanks inside them, '#' starts a comment; relative paths are
# relative to the manifest's folder. Outputs: OUT_ROOT/NAME/ (hslam-process
# files + log.txt + exit_code), OUT_ROOT/summary.{csv,md}, OUT_ROOT/joblog.tsv
# (GNU parallel). Exit code: 0 if every run exited 0, else 1.
# hslam-process: $HSLAM_PROCESS, else the one on PATH, else build/bin/.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)

die() { echo "batch-process: $*" >&2; exit 1; }

find_hslam_process() {
  if [ -n "${HSLAM_PROCESS:-}" ]; then echo "$HSLAM_PROCESS"
  elif command -v hslam-process > /dev/null; then command -v hslam-process
  elif [ -x "$here/../build/bin/hslam-process" ]; then echo "$here/../build/bin/hslam-process"
  else die "hslam-process not found (set HSLAM_PROCESS, or install it, or build it)"; fi
}

# Writes OUT_ROOT/manifest.tsv: NAME<TAB>ABS_RAWLOG<TAB>ABS_REF, checked.
resolve_manifest() {
  local manifest=$1 out=$2 dir line_no=0 name rawlog ref extra
  dir=$(cd "$(dirname "$manifest")" && pwd)
  : > "$out/manifest.tsv"
  while IFS= read -r line || [ -n "$line" ]; do
    line_no=$((line_no + 1))
    line=${line%%#*}
    read -r name rawlog ref extra <<< "$line" || true
    [ -z "${name:-}" ] && continue
    [ -n "${rawlog:-}" ] && [ -z "${extra:-}" ] || die "$manifest:$line_no: expected 'NAME RAWLOG [REFERENCE.tum]'"
    [[ "$name" =~ ^[A-Za-z0-9._-]+$ ]] || die "$manifest:$line_no: NAME '$name' must be [A-Za-z0-9._-]"
    [[ "$rawlog" = /* ]] || rawlog="$dir/$rawlog"
    [ -f "$rawlog" ] || die "$manifest:$line_no: no such rawlog: $rawlog"
    if [ -n "${ref:-}" ]; then
      [[ "$ref" = /* ]] || ref="$dir/$ref"
      [ -f "$ref" ] || die "$manifest:$line_no: no such reference: $ref"
    fi
    grep -q "^$name	" "$out/manifest.tsv" && die "$manifest:$line_no: NAME '$name' used twice"
    printf '%s\t%s\t%s\n' "$name" "$rawlog" "${ref:-}" >> "$out/manifest.tsv"
  done < "$manifest"
  [ -s "$out/manifest.tsv" ] || die "$manifest: no runs"
}

# One run: LINE = "NAME<TAB>RAWLOG<TAB>REF" of manifest.tsv; the hslam-process
# arguments are in OUT_ROOT/process_args (one per line).
run_one() {
  local out=$1 line=$2 name rawlog ref args=()
  IFS=$'\t' read -r name rawlog ref <<< "$line"
  mapfile -t args < "$out/process_args"
  [ -n "$ref" ] && args+=(--ground-truth "$ref")
  # The log goes beside the run's folder until the run ends: a log.txt in it
  # beforehand would make hslam-process refuse a folder it did not write.
  local rc=0 log="$out/.$name.log"
  "$(find_hslam_process)" -q -i "$rawlog" -o "$out/$name" "${args[@]}" > "$log" 2>&1 || rc=$?
  mkdir -p "$out/$name"
  mv -f "$log" "$out/$name/log.txt"
  echo "$rc" > "$out/$name/exit_code"
  echo "batch-process: $name done (exit $rc)"
}

summarize() {
  python3 "$here/batch_summary.py" "$1"
}

case "${1:-}" in
  --run-one) run_one "$2" "$3"; exit 0 ;;
  --summarize) summarize "$2"; exit 0 ;;
  ""|-h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
esac

[ $# -ge 2 ] || die "usage: $0 MANIFEST OUT_ROOT [-j JOBS] [-c INI] [-- ARGS]"
manifest=$1 out=$2; shift 2
jobs=2 config="" resolve_only=0
while [ $# -gt 0 ]; do
  case "$1" in
    -j) jobs=$2; shift 2 ;;
    --resolve-only) resolve_only=1; shift ;;
    -c) config=$2; shift 2 ;;
    --) shift; break ;;
    *) die "unknown option $1" ;;
  esac
done
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || die "-j: expected a positive number of jobs, got '$jobs'"
mkdir -p "$out" && out=$(cd "$out" && pwd)
resolve_manifest "$manifest" "$out"
# With more than one run at a time each hslam-process runs on one thread: its
# back-end and ICP-restart threads only save time when a core is free, and
# with the cores shared between runs they cost CPU (twenty-start ensembles, 2
# runs on 2 cores: 13-20 % more CPU). Arguments after -- can set them back.
one_thread=()
[ "$jobs" -gt 1 ] && one_thread=(--set loop_closure.background_thread=false --set loop_closure.search_threads=1
  --set pose_estimation.parallel_restarts=false)
{ [ -n "$config" ] && printf '%s\n' -c "$(cd "$(dirname "$config")" && pwd)/$(basename "$config")"
  for a in "${one_thread[@]}" "$@"; do printf '%s\n' "$a"; done; } > "$out/process_args" || true
find_hslam_process > /dev/null
if [ "$resolve_only" = 1 ]; then echo "batch-process: $out/manifest.tsv ready"; exit 0; fi

runs=$(wc -l < "$out/manifest.tsv")
start=$(date +%s.%N)
if command -v parallel > /dev/null && [ "${BATCH_TOOL:-parallel}" = parallel ]; then
  echo "batch-process: $runs runs, $jobs parallel jobs (GNU parallel)"
  parallel --will-cite --jobs "$jobs" --joblog "$out/joblog.tsv" bash "$0" --run-one "$out" {} < "$out/manifest.tsv" || true
else
  echo "batch-process: $runs runs, $jobs parallel jobs (xargs -P)"
  tr '\n' '\0' < "$out/manifest.tsv" | xargs -0 -P "$jobs" -I{} bash "$0" --run-one "$out" {} || true
fi
end=$(date +%s.%N)
wall=$(python3 -c "print(f'{$end - $start:.1f}')")
echo "$wall" > "$out/batch_wall_s"
echo "batch-process: wall time ${wall} s for $runs runs with $jobs jobs"
summarize "$out"
