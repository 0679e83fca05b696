# matrix-run.sh: sourced by scripts/stress-matrix.sh and scripts/real-log-matrix.sh.
#
# matrixRun TOOL RUN RAWLOG REFERENCE.tum ODOMETRY.tum NAME VARIANT CSV [hslam-process options...]
#   runs the default pipeline on RAWLOG into RUN/run, scores it and the
#   odometry ODOMETRY.tum against REFERENCE.tum, prints one line (WORSE when
#   the estimate is no better than odometry, issue 12) and appends a row to
#   CSV. Needs $bin (the apps) and $here (the repository) set by the caller.
matrixRun() {
	local tool=$1 run=$2 rawlog=$3 reference=$4 odometry=$5 name=$6 variant=$7 csv=$8
	shift 8
	"$bin/hslam-process" -c "$here/config_ini/hslam-default.ini" -i "$rawlog" -o "$run/run" \
		--ground-truth "$reference" -q --overwrite --set output.write_tiles=false "$@" > "$run/process.log" 2>&1 ||
		{ echo "$tool: processing $name/$variant failed, see $run/process.log" >&2; exit 1; }
	"$bin/hslam-evaluate" "$reference" "$odometry" --json "$run/odometry.json" > /dev/null
	python3 - "$run" "$name" "$variant" "$csv" <<'PY'
import json, sys
run, name, variant, csv = sys.argv[1:5]
est = json.load(open(run + '/run/evaluation.json'))
odo = json.load(open(run + '/odometry.json'))
row = (est['ate_rmse_m'], odo['ate_rmse_m'], est['rpe_5m_trans_rmse_m'], odo['rpe_5m_trans_rmse_m'])
flag = '  WORSE than odometry' if row[0] >= row[1] else ''
print('%-14s %-12s ate_m=%.3f odometry_ate_m=%.3f rpe5_m=%.3f odometry_rpe5_m=%.3f%s' % ((name, variant) + row + (flag,)))
open(csv, 'a').write('%s,%s,%.4f,%.4f,%.4f,%.4f,%d\n' % ((name, variant) + row + (est['matched'],)))
PY
}
