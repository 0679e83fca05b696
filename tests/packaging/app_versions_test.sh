#!/usr/bin/env bash
# Every app: --version prints the project version and the MRPT version it was
# built against; --help exits 0 and shows every option with its default; an
# unknown option exits non-zero with a parse error on stderr (a misspelt flag in a
# batch script must not pass as a run).
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
  if err=$("$bin/$app" --no-such-option 2>&1 >/dev/null); then echo "FAIL: $app --no-such-option exit code 0"; status=1
  elif ! grep -q -e "--no-such-option" -e "PARSE ERROR" <<<"$err"; then echo "FAIL: $app --no-such-option: no parse error: $err"; status=1; fi
  echo "$app:$(tr -s '\n' ' ' <<<"$v")"
done
for suite in pipeline graph nav; do  # hslam-bench's suites parse their own options
  if "$bin/hslam-bench" $suite --no-such-option > /dev/null 2>&1; then
    echo "FAIL: hslam-bench $suite --no-such-option exit code 0"; status=1
  fi
done
exit $status
