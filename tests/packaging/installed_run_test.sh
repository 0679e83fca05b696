#!/usr/bin/env bash
# Runs the installed hslam-process from a scratch prefix, from a working
# directory outside the source and build trees, without -c: it must find its
# default INI (and the leg model) in <prefix>/share/hslam from its own
# location. Input: the lab sample installed with it, with its ground truth.
# Usage: installed_run_test.sh PREFIX OUT_DIR VERSION
set -euo pipefail
prefix=$1 out=$2 version=$3
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$out"
scratch=$(mktemp -d) && trap 'rm -rf "$scratch"' EXIT
cd "$scratch"
"$prefix/bin/hslam-process" --version | tee version.txt
grep -q "$version (built against MRPT 2\.5\.[0-9]*)" version.txt || fail "--version"
sample="$prefix/share/hslam/rawlog_samples/lab"
"$prefix/bin/hslam-process" -q -i "$sample/sim.rawlog" -o "$out" --ground-truth "$sample/ground_truth.tum" > run.log 2>&1 ||
  { cat run.log; fail "installed hslam-process"; }
tail -n 4 run.log
for f in map.png pose_plot.png trajectory.tum config_used.ini summary.json report.html tracks.csv sonar_corners.csv; do
  [ -s "$out/$f" ] || fail "missing $out/$f"
done
# The default INI was the installed one: config_used.ini is the default
# configuration (the lab sample's 1336 scans are all used) ...
python3 - "$out/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print({k: s[k] for k in ("scans", "ms_per_scan", "ate_rmse_m", "leg_tracks", "sonar_corners", "warnings")})
assert s["scans"] == 1336, s["scans"]
assert s["evaluated"] and 0 < s["ate_rmse_m"] < 0.5, s["ate_rmse_m"]
assert s["matched_poses"] == 1336, s["matched_poses"]
assert s["ms_per_scan"] > 0 and s["input_error"] is None
PY
# ... and nothing was read from or written to the working directory.
[ -z "$(ls -A "$scratch" | grep -v -e version.txt -e run.log)" ] || fail "files appeared in the working directory"
echo "PASS"
