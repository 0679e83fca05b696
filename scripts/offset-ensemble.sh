#!/usr/bin/env bash
# offset-ensemble.sh OUT RAWLOG TUM [hslam-process options...]
#
# Runs hslam-process on RAWLOG started at entries 0, 6, 14, 24 and 36 (cut
# with MRPT's rawlog-edit; other entries with START_ENTRIES="0 6 ... 130")
# and prints the ATE of each start, their median, mean and worst.
# On a real log a single run's ATE is decided by a few slips and moves 2-10x
# under changes that should be harmless (docs/pose-estimation.md, "Reading
# real-log figures"); the spread over start offsets shows how much of a
# difference between two settings is noise.
#
#   scripts/offset-ensemble.sh out/ens-aces aces.rawlog aces.tum --set icp.engine=mrpt
#   START_ENTRIES="0 6 14 24 36 50 70 90 110 130" scripts/offset-ensemble.sh out/ens-csail csail.rawlog csail.tum
set -euo pipefail
[ $# -ge 3 ] || { sed -n 2,12p "$0"; exit 2; }
out=$1; rawlog=$2; tum=$3; shift 3
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${HSLAM_BIN:-$here/build/bin}
[ -f "$rawlog" ] || { echo "offset-ensemble: $rawlog: no such rawlog" >&2; exit 2; }
[ -f "$tum" ] || { echo "offset-ensemble: $tum: no such TUM file" >&2; exit 2; }
mkdir -p "$out"
ates=()
for offset in ${START_ENTRIES:-0 6 14 24 36}; do
	input=$rawlog
	if [ "$offset" != 0 ]; then
		input=$out/start-$offset.rawlog
		[ -f "$input" ] || rawlog-edit --cut --from-index "$offset" -i "$rawlog" -o "$input" -q > /dev/null
	fi
	"$bin/hslam-process" -c "$here/config_ini/hslam-default.ini" -i "$input" -o "$out/run-$offset" \
		--ground-truth "$tum" -q --overwrite --set output.write_tiles=false "$@" > "$out/run-$offset.log" 2>&1 ||
		{ echo "offset-ensemble: start $offset failed, see $out/run-$offset.log" >&2; exit 1; }
	ate=$(python3 -c "import json,sys; print('%.3f' % json.load(open(sys.argv[1]))['ate_rmse_m'])" "$out/run-$offset/evaluation.json")
	ates+=("$ate")
	echo "start_entry=$offset ate_m=$ate"
done
python3 -c "import statistics as s, sys; v = [float(a) for a in sys.argv[1:]]; print('ate_median_m=%.3f\nate_mean_m=%.3f\nate_worst_m=%.3f' % (s.median(v), s.mean(v), max(v)))" "${ates[@]}"
