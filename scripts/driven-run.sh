#!/usr/bin/env bash
# The driven run of thesis 4.9 in one command, without hardware: our
# subsumption controller (hslam-navigate, thesis 4.2) drives the P3-DX through
# our Pioneer driver (CPioneerSensor, ARCOS over a pseudo-terminal) and reads
# the SICK LMS200 through MRPT's CSickLaserSerial (LMS200 telegrams over a
# second pseudo-terminal); both devices are hslam-device-emulator, which moves
# the robot in the lab world (config_ini/sim-worlds/nav-lab.scene) with the
# simulator's kinematics (UMBmark errors, thesis 4.1), sonar and laser models.
# hslam-navigate records the rawlog and builds the live map; hslam-process
# (the batch job) then maps the recording again.
#
#   scripts/driven-run.sh OUT [--short] [--targets "x y; x y"] [--timeout-s S]
#
# OUT (created, must not exist): emulator.log, truth.tum (true pose, 20 Hz),
# grabber.ini, nav/ (navigation.rawlog, path.csv, path.png, live_map.png,
# live_map.gridmap.gz), map/ (hslam-process: map.png, map.gridmap.gz,
# trajectory.tum, ...), targets.txt (world frame), summary.txt.
# --short: 2 targets (the CI test, tests/hwdrivers/driven_run_unittest.cpp).
# Binaries: $HSLAM_BIN, else build/bin beside this script.
# Exit: 0 every target reached and the map built, 3 a target missed, 1 error.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "$here/.." && pwd)
bin=${HSLAM_BIN:-$src/build/bin}

die() { echo "driven-run: $*" >&2; exit 1; }

out=""
short=0
# Lab tour from the start (2.0, 2.2, heading 0), in the world frame (m).
targets="1.5 5.2; 4.0 4.6; 7.5 5.0; 8.0 2.0; 4.5 1.5"
timeout_s=240
while [ $# -gt 0 ]; do
  case "$1" in
    --short) short=1; shift ;;
    --targets) [ $# -ge 2 ] || die "--targets needs a value"; targets=$2; shift 2 ;;
    --timeout-s) [ $# -ge 2 ] || die "--timeout-s needs a value"; timeout_s=$2; shift 2 ;;
    -h|--help) sed -n '2,20p' "$0"; exit 0 ;;
    -*) die "unknown option $1" ;;
    *) [ -z "$out" ] || die "one OUT folder only"; out=$1; shift ;;
  esac
done
[ -n "$out" ] || die "usage: driven-run.sh OUT [--short] [--targets LIST] [--timeout-s S]"
[ ! -e "$out" ] || die "$out exists; choose a new folder"
if [ "$short" = 1 ]; then targets="1.5 2.7; 1.5 5.2"; timeout_s=90; fi
for b in hslam-device-emulator hslam-navigate hslam-process; do
  [ -x "$bin/$b" ] || die "$bin/$b not found (build it, or set HSLAM_BIN)"
done
mkdir -p "$out"
out=$(cd "$out" && pwd)
echo "$targets" | tr ';' '\n' | sed 's/^ *//' > "$out/targets.txt"

start="2.0 2.2 0"   # sim-nav-lab.ini [robot] start_*
"$bin/hslam-device-emulator" --scene "$src/config_ini/sim-worlds/nav-lab.scene" \
  --sim-ini "$src/config_ini/sim-nav-lab.ini" --start "$start" \
  --pioneer-pty "$out/pioneer" --lms200-pty "$out/lms200" --truth "$out/truth.tum" \
  > "$out/emulator.log" 2>&1 &
emu=$!
stop_emulator() { kill -TERM "$emu" 2>/dev/null || true; wait "$emu" 2>/dev/null || true; }
trap stop_emulator EXIT

# Wait for the emulator's "ready" line (its ptys exist then); hang guard 30 s.
for _ in $(seq 300); do
  grep -q '^ready' "$out/emulator.log" && break
  kill -0 "$emu" 2>/dev/null || die "emulator exited: $(cat "$out/emulator.log")"
  sleep 0.1
done
grep -q '^ready' "$out/emulator.log" || die "emulator not ready after 30 s: $(cat "$out/emulator.log")"

# The shipped grabber INI with the emulator's pseudo-terminals.
sed -e "/^\[PIONEER\]/,/^\[/ s|^COM_port_LIN *=.*|COM_port_LIN = $out/pioneer|" \
    -e "/^\[LASER\]/,/^\[/ s|^COM_port_LIN *=.*|COM_port_LIN = $out/lms200|" \
    "$src/config_ini/grabber-pioneer-lms200.ini" > "$out/grabber.ini"

set +e
"$bin/hslam-navigate" --pioneer "$out/grabber.ini" --laser-section LASER --start-pose "$start" \
  --targets "$targets" --timeout-s "$timeout_s" -o "$out/nav" 2>&1 | tee "$out/navigate.log"
nav_rc=${PIPESTATUS[0]}
set -e
stop_emulator
trap - EXIT
[ "$nav_rc" = 0 ] || [ "$nav_rc" = 3 ] || die "hslam-navigate failed ($nav_rc), see $out/navigate.log"

"$bin/hslam-process" -q -i "$out/nav/navigation.rawlog" -o "$out/map" > "$out/process.log" 2>&1 \
  || die "hslam-process failed, see $out/process.log"
{
  echo "targets_world=$targets"
  echo "navigate_exit=$nav_rc"
  grep -E '^(robot run|targets reached)' "$out/navigate.log" || true
  echo "rawlog=$out/nav/navigation.rawlog"
  echo "map=$out/map/map.gridmap.gz"
} | tee "$out/summary.txt"
exit "$nav_rc"
