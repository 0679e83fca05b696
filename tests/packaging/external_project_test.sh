#!/usr/bin/env bash
# Configures, builds and runs tests/packaging/external (a user's project:
# find_package(hslam CONFIG REQUIRED), MRPT's map factory creates our tiled map
# by its INI name, a scan is inserted and checked) against an installed prefix.
# Usage: external_project_test.sh PREFIX SOURCE_DIR WORK_DIR
set -euo pipefail
prefix=$1 src=$2 work=$3
rm -rf "$work"
cmake -S "$src" -B "$work" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release > "$work.configure.log" 2>&1 ||
  { cat "$work.configure.log"; echo "FAIL: configure"; exit 1; }
grep -i "hslam" "$work/CMakeCache.txt" | grep -i "hslam_DIR" || true
cmake --build "$work" > "$work.build.log" 2>&1 || { cat "$work.build.log"; echo "FAIL: build"; exit 1; }
"$work/tiled_map_user"
