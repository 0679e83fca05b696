#!/usr/bin/env bash
# Builds the Debian package of a finished build tree (cpack -G DEB), checks its
# name and shlibdeps Depends:, unpacks it into a scratch root (dpkg -x) and runs
# the unpacked files: hslam-process --help / --version, and MRPT's own
# rawlog-grabber loading the unpacked plug-in to record the unpacked Pioneer
# emulator. Usage: deb_package_test.sh BUILD_DIR WORK_DIR VERSION
set -euo pipefail
build=$1 work=$2 version=$3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*" >&2; exit 1; }

(cd "$build" && cpack -G DEB -B "$work/pkg" > "$work/cpack.log" 2>&1) || { cat "$work/cpack.log"; fail "cpack -G DEB"; }
deb="$work/pkg/hslam_${version}_amd64.deb"
[ -f "$deb" ] || fail "no $deb (got: $(ls "$work/pkg"))"
depends=$(dpkg-deb -f "$deb" Depends)
echo "Package: $(basename "$deb") ($(du -k "$deb" | cut -f1) KiB)"
echo "Depends: $depends"
for lib in libmrpt-maps2.5 libmrpt-hwdrivers2.5 libopencv-ml406 libc6; do
  grep -q "$lib" <<<"$depends" || fail "Depends: lacks $lib"
done

root="$work/root"
dpkg -x "$deb" "$root"
bin="$root/usr/bin" lib="$root/usr/lib"
[ -f "$lib/libhslam-hwdrivers-plugin.so" ] || fail "plug-in not in $lib"
[ -f "$root/usr/share/hslam/config_ini/hslam-default.ini" ] || fail "default INI not installed"
[ -f "$root/usr/share/man/man1/hslam-process.1.gz" ] || [ -f "$root/usr/share/man/man1/hslam-process.1" ] ||
  fail "no man page for hslam-process"
# (captured first: grep -q closing the pipe early would fail the pipeline under pipefail)
help=$("$bin/hslam-process" --help) || fail "hslam-process --help exited non-zero"
grep -q -- "--ground-truth" <<<"$help" || fail "hslam-process --help lacks --ground-truth"
ver=$("$bin/hslam-process" --version) || fail "hslam-process --version exited non-zero"
grep -q "$version (built against MRPT 2\.5" <<<"$ver" || fail "hslam-process --version: $ver"
# The unpacked app must not use the build tree: its libraries come from the root.
outside=$(ldd "$bin/hslam-process" | grep libhslam- | grep -v "$root" || true)
[ -z "$outside" ] || fail "hslam-process uses libraries outside $root: $outside"

# MRPT's rawlog-grabber without the plug-in does not know our sensor ...
ini="$work/grab.ini"
awk '/^\[LASER\]/{skip=1} /^\[/{if ($0 != "[LASER]") skip=0} !skip' \
  "$root/usr/share/hslam/config_ini/grabber-pioneer-lms200.ini" |
  sed -e "s|^rawlog_prefix = .*|rawlog_prefix = $work/rec|" -e "s|^COM_port_LIN = .*|COM_port_LIN = $work/pioneer|" \
      -e "s|^GRABBER_PERIOD_MS = .*|GRABBER_PERIOD_MS = 200|" > "$ini"
(echo q | timeout 60 rawlog-grabber "$ini" > "$work/noplugin.log" 2>&1) || true
grep -qiE "not recognized|unknown" "$work/noplugin.log" || { cat "$work/noplugin.log"; fail "no unknown-class error without the plug-in"; }
# That run left an empty rec_<time>.rawlog; the recording checked below is the next one.
rm -f "$work"/rec_*.rawlog
# ... and records our unpacked emulator with it.
"$bin/hslam-device-emulator" --pioneer-pty "$work/pioneer" --duration 15 > "$work/emulator.log" 2>&1 &
emulator=$!
trap 'kill $emulator 2>/dev/null || true' EXIT
for _ in $(seq 50); do [ -e "$work/pioneer" ] && break; sleep 0.1; done
# Stop it (a key on its stdin) once it has written 15 periods, not after a
# fixed time: on a loaded machine the link can take seconds to come up.
mkfifo "$work/grabber-stdin"
timeout 90 rawlog-grabber -p "$lib/libhslam-hwdrivers-plugin.so" "$ini" < "$work/grabber-stdin" > "$work/grabber.log" 2>&1 &
grabber=$!
exec 3> "$work/grabber-stdin"
for _ in $(seq 600); do
  [ "$(grep -c 'Saved' "$work/grabber.log" || true)" -ge 15 ] && break
  kill -0 $grabber 2>/dev/null || break
  sleep 0.1
done
echo q >&3
exec 3>&-
wait $grabber || { cat "$work/grabber.log"; fail "rawlog-grabber -p"; }
rawlog=$(ls "$work"/rec_*.rawlog | head -1)
rawlog-edit --info -i "$rawlog" > "$work/info.txt" 2>&1 || { cat "$work/info.txt"; fail "rawlog-edit --info"; }
odometry=$(grep -oP 'ODOMETRY /\s*\K[0-9]+' "$work/info.txt" || true)
echo "rawlog-grabber -p $lib/libhslam-hwdrivers-plugin.so recorded $(basename "$rawlog"): ODOMETRY x ${odometry:-0}"
[ "${odometry:-0}" -ge 10 ] || { cat "$work/info.txt" "$work/grabber.log"; fail "fewer than 10 odometry observations"; }
echo "PASS"
