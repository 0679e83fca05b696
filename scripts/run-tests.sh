#!/usr/bin/env bash
# The test suite from a fresh clone: installs dependencies, builds, and runs
# every unit and integration test with CTest; then (scripts/sanitize-and-fuzz.sh)
# the input-facing unit tests under ASan + UBSan and every fuzz target for a
# bounded time, when HSLAM_SANITIZE=1. It is opt-in until it has been run to
# completion on a CI-sized machine (see docs/reliability.md).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)")
if [ "${HSLAM_SANITIZE:-0}" = "1" ]; then
  bash scripts/sanitize-and-fuzz.sh
fi
