#!/usr/bin/env bash
# The test suite from a fresh clone: installs dependencies, builds, and runs
# every unit and integration test with CTest; then (scripts/sanitize-and-fuzz.sh)
# the input-facing unit tests under ASan + UBSan and every fuzz target for a
# bounded time. Developers may skip that second part with HSLAM_SKIP_SANITIZE=1
# (ignored when CI=true: CI always runs it).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)")
if [ "${CI:-}" = "true" ] || [ "${HSLAM_SKIP_SANITIZE:-0}" != "1" ]; then
  bash scripts/sanitize-and-fuzz.sh
fi
