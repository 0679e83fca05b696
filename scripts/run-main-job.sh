#!/usr/bin/env bash
# The main job from a fresh clone: installs dependencies, builds, and runs the
# batch mapping (UKF pose estimation with line features + ICP, tiled grid,
# people excluded) on MRPT's real sample rawlog (laser + odometry) with the
# default configuration. Results go to results/default/ (or the folder given
# as the first argument).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
out="${1:-results/default}"
input="/usr/share/mrpt/datasets/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog"
./build/bin/hslam-process -c config_ini/hslam-default.ini -i "$input" -o "$out"
echo
echo "Done. Open $out/report.html (figures, maps, timing, warnings), $out/map.png (merged map, estimated path red, odometry orange) and $out/pose_plot.png;"
echo "see $out/ for tiles/, map.gridmap.gz (MRPT), trajectory.tum, pose_estimates.csv, tracks.csv and timing.txt."
