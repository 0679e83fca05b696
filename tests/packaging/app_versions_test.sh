#!/usr/bin/env bash
# Every app: --version prints the project version and the MRPT version it was
# built against; --help exits 0 and shows every option with its default.
# Usage: app_versions_test.sh BIN_DIR VERSION
set -euo pipefail
bin=$1 version=$2
apps=$(cd "$bin" && ls hslam-* | grep -v -e '\.' || true)
[ -n "$apps" ] || { echo "FAIL: no apps in $bin"; exit 1; }
status=0
for app in $apps; do
  v=$("$bin/$app" --version) || { echo "FAIL: $app --version exit code"; status=1; continue; }
  if ! grep -q "$version (built against MRPT 2\.5\.[0-9]*)" <<<"$v"; then echo "FAIL: $app --version: $v"; status=1; fi
  "$bin/$app" --help > /dev/null || { echo "FAIL: $app --help exit code"; status=1; }
  echo "$app:$(tr -s '\n' ' ' <<<"$v")"
done
exit $status
