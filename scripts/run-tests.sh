#!/usr/bin/env bash
# The test suite from a fresh clone: installs dependencies, builds, and runs
# every unit and integration test with CTest.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j"$(nproc)"
