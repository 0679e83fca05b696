#!/usr/bin/env bash
# offset-ensemble.sh OUT RAWLOG TUM [hslam-process options...]
#
# Runs hslam-process on RAWLOG started at entries 0, 6, 14, 24 and 36 (cut
# with MRPT's rawlog-edit) and prints the ATE of each start and their median.
# On a real log a single run's ATE is decided by a few slips and moves 2-10x
# under changes that should be harmless (docs/pose-estimation.md, "Reading
# real-log figures"); the spread over start offsets shows how much of a
# difference between two settings is noise.
#
#   scripts/offset-ensemble.sh out/ens-aces aces.rawlog aces.tum --set icp.engine=cached
set -euo pipefail
[ $# -ge 3 ] || { sed -n 2,12p "$0"; exit 2; }
out=$1; rawlog=$2; tum=$3; shift 3
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${HSLAM_BIN:-$here/build/bin}
[ -f "$rawlog" ] || { echo "offset-ensemble: $rawlog: no such rawlog" >&2; exit 2; }
[ -f "$tum" ] || { echo "offset-ensemble: $tum: no such TUM file" >&2; exit 2; }
mkdir -p "$out"
ates=()
for offset in 0 6 14 24 36; do
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
printf '%s\n' "${ates[@]}" | sort -n | sed -n 3p | sed 's/^/ate_median_m=/'
