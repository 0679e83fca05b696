#!/usr/bin/env bash
# laser-only-ensemble.sh OUT [hslam-process options...]
#
# Issue 12's laser-only class on the real logs: each CARMEN reference log of
# LOGS (default "aces csail intel") is rewritten with every odometry reading
# zero (scripts/real-log-matrix.sh, variant laseronly), then processed from
# each entry of START_ENTRIES (default "0 50 100 150 200 250 300 350") with
# scripts/offset-ensemble.sh. Prints each log's ATE per start, its median /
# mean / worst, and the ATE of no motion at all (the zero odometry's), and
# flags a start worse than no motion. A single laser-only run moves by
# metres under harmless changes (one wrong step of 30 deg decides the rest):
# compare settings by the ensemble (docs/pose-estimation.md, "A heading the
# prior no longer holds").
#
#   scripts/laser-only-ensemble.sh out/laser-only
#   LOGS=intel scripts/laser-only-ensemble.sh out/lo-intel --set gap_search.whole_circle_if_heading_unknown=false
set -euo pipefail
[ $# -ge 1 ] || { sed -n '2,/^set -euo/p' "$0" | sed '$d'; exit 2; }
out=$1; shift
here=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
for log in ${LOGS:-aces csail intel}; do
	LOGS=$log VARIANTS=laseronly "$here/scripts/real-log-matrix.sh" "$out/rewritten-$log" "$@" > "$out/$log-rewrite.txt" 2>&1 ||
		{ echo "laser-only-ensemble: rewriting $log failed, see $out/$log-rewrite.txt" >&2; exit 1; }
	rewritten=$out/rewritten-$log/$log-laseronly
	no_motion=$(python3 -c "import csv,sys; print([r for r in csv.DictReader(open(sys.argv[1]))][0]['odometry_ate_m'])" \
		"$out/rewritten-$log/matrix.csv")
	START_ENTRIES=${START_ENTRIES:-0 50 100 150 200 250 300 350} "$here/scripts/offset-ensemble.sh" "$out/$log" \
		"$rewritten/in.rawlog" "$rewritten/reference.tum" "$@" > "$out/$log.txt"
	echo "== $log (no motion at all: ATE $no_motion m)"
	awk -v z="$no_motion" -F'ate_m=' '/^start_entry=/ { printf "%s%s\n", $0, ($2 + 0 > z + 0 ? "  WORSE than no motion" : "") } !/^start_entry=/' "$out/$log.txt"
done
