#!/usr/bin/env bash
# real-log-matrix.sh OUT [hslam-process options...]
#
# The stress matrix on real data: each CARMEN reference log (aces, csail,
# intel) is rewritten as another robot or sensor would have recorded it
# (scripts/perturb_carmen_log.py: laser only, odometry frozen or lost for ten
# scans, biased or noisy odometry, a 5.6 m scanner, every second scan),
# converted with hslam-carmen2rawlog, processed with the default pipeline and
# scored against the corrected poses and against its own odometry. Prints one
# line per run, writes OUT/matrix.csv, and flags a run worse than its
# odometry WORSE (issue 12: the estimate is never worse than raw odometry).
# The simulated stress matrix (scripts/stress-matrix.sh) drives at 5 Hz; these
# logs keep a scan per 1-3 s and turn up to 80 deg between scans.
#
#   scripts/real-log-matrix.sh out/real
#   LOGS="aces" VARIANTS="freeze@0.2 freeze@0.8" scripts/real-log-matrix.sh out/aces-freeze
#   scripts/real-log-matrix.sh out/real-off --set pose_estimation.standstill_seed_after_gap=false
#
# VARIANTS: see scripts/perturb_carmen_log.py ("@F": the fault starts at
# fraction F of the scans). DATASETS: the folder of the *-corrected.log.gz
# files (default ../shared/datasets/carmen).
set -euo pipefail
[ $# -ge 1 ] || { sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 2; }
out=$1; shift
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${HSLAM_BIN:-$here/build/bin}
datasets=${DATASETS:-$here/../shared/datasets/carmen}
logs=${LOGS:-aces csail intel}
# shellcheck source=scripts/matrix-run.sh
source "$here/scripts/matrix-run.sh"
variants=${VARIANTS:-base urg laseronly freeze gap wbias curve noisy thin}

mkdir -p "$out"
echo "log,variant,ate_m,odometry_ate_m,rpe5_m,odometry_rpe5_m,scans" > "$out/matrix.csv"
for log in $logs; do
	input_log=$datasets/$log-corrected.log.gz
	[ -f "$input_log" ] || { echo "real-log-matrix: $input_log: no such log (DATASETS=$datasets)" >&2; exit 2; }
	for variant in $variants; do
		run=$out/$log-$variant
		rm -rf "$run" && mkdir -p "$run"
		python3 "$here/scripts/perturb_carmen_log.py" "$input_log" "$run/in.log" "$variant" ||
			{ echo "real-log-matrix: perturbing $log/$variant failed" >&2; exit 1; }
		"$bin/hslam-carmen2rawlog" --reference "$run/reference.tum" "$run/in.log" "$run/in.rawlog" > "$run/convert.log" 2>&1 ||
			{ echo "real-log-matrix: converting $log/$variant failed, see $run/convert.log" >&2; exit 1; }
		matrixRun real-log-matrix "$run" "$run/in.rawlog" "$run/reference.tum" "$run/run/odometry.tum" \
			"$log" "$variant" "$out/matrix.csv" "$@"
	done
done
