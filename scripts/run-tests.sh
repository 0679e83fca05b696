#!/usr/bin/env bash
# The test suite from a fresh clone: installs dependencies, builds, and runs
# every unit and integration test with CTest; then (scripts/sanitize-and-fuzz.sh)
# the input-facing unit tests under ASan + UBSan and every fuzz target for a
# bounded time (HSLAM_FUZZ_SECONDS, default 15 s each). HSLAM_SANITIZE=0 skips
# that second part. Each phase prints its duration (CI must stay under 30 min
# on 2 cores; see docs/reliability.md).
set -euo pipefail
cd "$(dirname "$0")/.."
phase() { echo "run-tests: $1 took $(( $(date +%s) - $2 )) s"; }
t=$(date +%s); bash scripts/install-deps.sh; phase "install-deps" "$t"
t=$(date +%s); bash scripts/build.sh; phase "build" "$t"
t=$(date +%s); (cd build && ctest --output-on-failure -j"$(nproc)"); phase "ctest" "$t"
# HSLAM_FUZZ_TARGETS (space-separated) limits the timed fuzzing to some targets.
if [ "${HSLAM_SANITIZE:-1}" = "1" ]; then
  t=$(date +%s)
  HSLAM_FUZZ_SECONDS=${HSLAM_FUZZ_SECONDS:-15} bash scripts/sanitize-and-fuzz.sh
  phase "sanitize-and-fuzz" "$t"
fi
