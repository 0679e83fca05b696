#!/usr/bin/env bash
# stress-matrix.sh OUT [hslam-process options...]
#
# The front-end on buildings nobody tuned it on, reproduced in simulation:
# every world of WORLDS (config_ini/sim-<world>.ini) is simulated once per
# variant of VARIANTS (a sensor, a robot or a driving style unlike the
# samples'), processed with the default pipeline and scored against its
# ground truth and against its own dead reckoning. Prints one line per run
# and writes OUT/matrix.csv; a run worse than odometry is flagged WORSE
# (issue 12: the estimate is never worse than raw odometry).
#
# Variants:
#   base      the world's INI as it is
#   urg       Hokuyo URG-04LX: 240 deg, 0.36 deg, 5.6 m, 10 Hz
#   lms100    SICK LMS100: 270 deg, 0.5 deg, 20 m
#   far       the LMS200 with a 30 m range (the samples' 8 m)
#   slowscan  1 scan per second (csail's spacing); fastscan: 20 per second
#   wbias     wheelbase 4 % off (UMBmark Eb = 1.04: turns over-reported)
#   dbias     one wheel 2 % larger (Ed = 1.02: 3.4 deg per metre of curve)
#   noisy     odometry noise ten times the samples'
#   fast      1.2 m/s and 100 deg/s
#   freeze    odometry readings frozen for 10 s from t = 30 s; drop: missing
#   lag       every odometry reading 0.3 s old
#   creep     odometry reports 1 % of the wheel motion all run (laser only)
#   mount     the laser 0.25 m ahead, 0.05 m left, turned 3 deg (not in VARIANTS
#             by default: the rawlog's sensor pose says so, as a grabber's would)
#   upsidedown  the laser mounted upside down (sensorPose roll 180 deg)
#   artefacts  a real scanner's faults: 5 % of returns lost, 1 % spurious short
#             ones, mixed pixels at every other range edge (not in VARIANTS by
#             default)
#   narrow    a depth camera's fake scan: 60 deg, 0.1 deg, 4.5 m, 10 Hz (not in
#             VARIANTS by default: the product's scanners cover 180 deg or more;
#             floor and long corridor are slightly worse than odometry, see
#             docs/pose-estimation.md)
#
# A variant may combine others with "+": slowscan+fast is csail's spacing with
# fast turns (up to 100 deg between scans).
#
# SEED=N simulates every run with [simulation] seed = N instead of the
# world's own: one draw of noise, faults and people is one sample, so a
# default change is checked over a few seeds (SEED=1 ... SEED=4).
#
#   scripts/stress-matrix.sh out/stress
#   WORLDS="open-hall" VARIANTS="urg" scripts/stress-matrix.sh out/hall --set icp.min_good_points=0
#   SEED=2 scripts/stress-matrix.sh out/stress-seed2
set -euo pipefail
[ $# -ge 1 ] || { sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 2; }
[[ -z ${SEED:-} || $SEED =~ ^[0-9]+$ ]] || { echo "stress-matrix: SEED must be a non-negative integer, not '$SEED'" >&2; exit 2; }
out=$1; shift
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${HSLAM_BIN:-$here/build/bin}
worlds=${WORLDS:-floor corridor long-corridor open-hall lab floor-laps}
# shellcheck source=scripts/matrix-run.sh
source "$here/scripts/matrix-run.sh"
variants=${VARIANTS:-base urg lms100 far slowscan fastscan wbias dbias noisy fast freeze drop lag creep upsidedown}

variantSettings() {
	case $1 in
		base) ;;
		urg) echo "--set laser.preset=custom --set laser.fov_deg=240 --set laser.resolution_deg=0.36 --set laser.max_range_m=5.6 --set laser.rate_hz=10" ;;
		lms100) echo "--set laser.preset=lms100" ;;
		far) echo "--set laser.max_range_m=30" ;;
		slowscan) echo "--set laser.rate_hz=1" ;;
		fastscan) echo "--set laser.rate_hz=20" ;;
		wbias) echo "--set robot.eb_wheelbase_ratio=1.04" ;;
		dbias) echo "--set robot.ed_wheel_diameter_ratio=1.02" ;;
		noisy) echo "--set robot.wheel_noise_m_per_sqrt_m=0.01 --set robot.rotation_noise_rad_per_sqrt_rad=0.03" ;;
		fast) echo "--set path.cruise_speed_mps=1.2 --set path.turn_rate_deg_s=100" ;;
		freeze) echo "--set odometry.fault=freeze --set odometry.fault_start_s=30 --set odometry.fault_duration_s=10" ;;
		drop) echo "--set odometry.fault=drop --set odometry.fault_start_s=30 --set odometry.fault_duration_s=10" ;;
		lag) echo "--set odometry.fault=lag --set odometry.fault_lag_s=0.3" ;;
		creep) echo "--set odometry.fault=freeze --set odometry.fault_motion_scale=0.01" ;;
		mount) echo "--set laser.x_m=0.25 --set laser.y_m=0.05 --set laser.yaw_deg=3" ;;
		upsidedown) echo "--set laser.upside_down=true" ;;
		artefacts) echo "--set laser.dropout_probability=0.05 --set laser.spurious_probability=0.01 --set laser.mixed_pixel_probability=0.5" ;;
		narrow) echo "--set laser.preset=custom --set laser.fov_deg=60 --set laser.resolution_deg=0.1 --set laser.max_range_m=4.5 --set laser.rate_hz=10" ;;
		*) echo "stress-matrix: unknown variant '$1'" >&2; return 2 ;;
	esac
}

mkdir -p "$out"
echo "world,variant,ate_m,odometry_ate_m,rpe5_m,odometry_rpe5_m,scans" > "$out/matrix.csv"
for world in $worlds; do
	[ -f "$here/config_ini/sim-$world.ini" ] || { echo "stress-matrix: no config_ini/sim-$world.ini" >&2; exit 2; }
	for variant in $variants; do
		settings=${SEED:+--set simulation.seed=$SEED}
		for part in ${variant//+/ }; do settings="$settings $(variantSettings "$part")"; done
		run=$out/$world-$variant
		rm -rf "$run" && mkdir -p "$run"
		# shellcheck disable=SC2086  # the settings are words
		"$bin/hslam-simulate" -q -c "$here/config_ini/sim-$world.ini" -o "$run/sim" $settings > "$run/simulate.log" 2>&1 ||
			{ echo "stress-matrix: simulating $world/$variant failed, see $run/simulate.log" >&2; exit 1; }
		matrixRun stress-matrix "$run" "$run/sim/sim.rawlog" "$run/sim/ground_truth.tum" "$run/sim/odometry.tum" \
			"$world" "$variant" "$out/matrix.csv" "$@"
	done
done
