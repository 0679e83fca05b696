#!/usr/bin/env bash
# Regenerates rawlog_samples/<name>/ bit for bit from config_ini/sim-<name>.ini
# (each INI holds its seed) with hslam-simulate, then runs hslam-process and
# hslam-evaluate on each sample (odometry-only ATE) into results/samples/.
#
#   bash scripts/make-samples.sh [build-dir]      (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
cmake --build "$BUILD" -j2 --target hslam-simulate hslam-process hslam-evaluate >/dev/null
SIM="$BUILD/bin/hslam-simulate"

# The floor sample's walls are an occupancy image rasterised from a scene.
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$SIM" -q -c config_ini/sim-floor.ini -o "$tmp/floor" --set world.scene_file=sim-worlds/floor.scene \
	--set world.map_image= --set simulation.duration_s=0.01
cp "$tmp/floor/gt_map.png" config_ini/sim-worlds/floor.png

for name in lab corridor umbmark floor laser-only odometry-gap people-crossing camera; do
	out=rawlog_samples/$name
	rm -rf "$out"
	"$SIM" -q -c "config_ini/sim-$name.ini" -o "$out"
	# Large per-scan CSVs are stored gzip-compressed (-n: no name/time stamp,
	# so the bytes are reproducible); hslam::io::CGzLineReader and zcat read them.
	for f in people beam_labels sonar_truth; do gzip -n -9 -f "$out/$f.csv"; done
	rm -f "$out/odometry.tum"  # dead reckoning is in the rawlog itself
	rawlog-edit --info -i "$out/sim.rawlog" 2>/dev/null | grep -q "Observations format               : Yes" ||
		{ echo "$name: rawlog-edit --info cannot read $out/sim.rawlog" >&2; exit 1; }
	mkdir -p "results/samples/$name"
	"$BUILD/bin/hslam-process" -q -c config_ini/hslam-default.ini -i "$out/sim.rawlog" \
		-o "results/samples/$name" --overwrite --ground-truth "$out/ground_truth.tum" >"results/samples/$name/process.log"
	ate=$(grep -o '"ate_rmse_m": [0-9.]*' "results/samples/$name/evaluation.json" | awk '{print $2}')
	echo "$name: $(du -sh "$out" | cut -f1), $(grep '^laser_scans=' "$out/summary.txt"), odometry-only ATE rmse = $ate m"
done
