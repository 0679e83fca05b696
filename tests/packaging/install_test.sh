#!/usr/bin/env bash
# cmake --install into a scratch prefix, then checks the layout of
# docs/install.md and that installed binaries find their libraries through
# $ORIGIN (relocatable prefix). Usage: install_test.sh BUILD_DIR PREFIX
set -euo pipefail
build=$1 prefix=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$prefix" && mkdir -p "$(dirname "$prefix")"
cmake --install "$build" --prefix "$prefix" > "$prefix.install.log" 2>&1 || { cat "$prefix.install.log"; fail "cmake --install"; }
for f in bin/hslam-process bin/hslam-carmen2rawlog bin/hslam-evaluate \
         lib/libhslam-maps.so lib/libhslam-slam.so lib/libhslam-common.so \
         lib/libhslam-hwdrivers-plugin.so lib/libhslam-maps-plugin.so \
         include/hslam/maps/CTiledOccupancyGridMap2D.h include/hslam/batch/CBatchProcessor.h \
         share/hslam/config_ini/hslam-default.ini share/hslam/config_ini/models/legs-hokuyo-forest.yml.gz \
         share/hslam/rawlog_samples/lab/sim.rawlog share/doc/hslam/README.md share/doc/hslam/install.md \
         lib/cmake/hslam/hslamConfig.cmake lib/cmake/hslam/hslamTargets.cmake; do
  [ -e "$prefix/$f" ] || fail "not installed: $prefix/$f"
done
if command -v help2man > /dev/null; then [ -s "$prefix/share/man/man1/hslam-process.1" ] || fail "no man page"; fi
grep -q 'R.*PATH.*\$ORIGIN/../lib' <<<"$(readelf -d "$prefix/bin/hslam-process")" || fail "hslam-process RUNPATH"
grep -q 'R.*PATH.*\$ORIGIN' <<<"$(readelf -d "$prefix/lib/libhslam-hwdrivers-plugin.so")" || fail "plug-in RUNPATH"
ldd "$prefix/bin/hslam-process" | grep 'libhslam-' | grep -v "$prefix/bin/../lib" && fail "libraries outside the prefix"
echo "installed $(find "$prefix" -type f | wc -l) files into $prefix"
echo "PASS"
