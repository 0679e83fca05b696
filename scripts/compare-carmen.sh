#!/usr/bin/env bash
# compare-carmen.sh — the pose-estimation comparison table of issue 3.
#
# For each CARMEN log (intel, aces, csail by default) this script:
#   1. converts the log with hslam-carmen2rawlog into an observations-only
#      MRPT rawlog plus the reference trajectory (TUM, one pose per scan);
#   2. runs hslam-process with pose_estimation.method = odometry, lines, icp,
#      lines+icp (config_ini/hslam-default.ini otherwise);
#   3. runs MRPT's own icp-slam and rbpf-slam with their STOCK configs
#      (/usr/share/mrpt/config_files/...), windows and 3D-scene dumps off, on
#      the same data, and converts the paths they write to TUM;
#   4. evaluates every trajectory with hslam-evaluate against the reference and
#      prints ONE table (also written as OUT/table.md and OUT/table.csv).
#
# Usage:  scripts/compare-carmen.sh [DATASETS_DIR] [OUT_DIR]
#   DATASETS_DIR  folder with <log>-corrected.log.gz   (default: ../shared/datasets/carmen,
#                 relative to the repository)
#   OUT_DIR       results folder (default: results/compare in the repository)
# Environment knobs (all optional):
#   HSLAM_BIN_DIR     where the hslam apps are        (default: <repo>/build/bin)
#   COMPARE_LOGS      logs to run                     (default: "intel aces csail")
#   COMPARE_TIMEOUT_S time limit per run, seconds     (default: 3600)
#   RBPF_SEED         rbpf-slam RANDOM_SEED; "random" keeps MRPT's stock
#                     time-based seed (default: 1, so the table is reproducible)
#
# Notes on the MRPT apps (MRPT 2.5.8):
# - icp-slam reads the observations-only rawlog directly and writes
#   log_estimated_path.txt: "step x y yaw" after every rawlog entry. Entry k of
#   the rawlog is found with `rawlog-edit --list-timestamps`; the pose after
#   each laser scan entry gets that scan's timestamp.
# - rbpf-slam only accepts the actions/sensory-frames rawlog format (on an
#   observations-only rawlog it dereferences a null action and segfaults), and
#   no MRPT 2.5.8 command-line tool converts between the formats (MRPT's own
#   carmen2rawlog also writes observations only, and would take the odometry
#   from the FLASER fields, which hold the corrected reference pose in these
#   logs). So this script rewrites OUR rawlog in that format: one
#   CActionRobotMovement2D (odometry increment between consecutive scans, MRPT's
#   default Gaussian motion model) + one CSensoryFrame holding the scan,
#   byte-for-byte as MRPT serialises them (checked: `rawlog-edit --info` and
#   `--describe` parse it and show the increments). rbpf-slam writes the path
#   of the most likely particle (most_likely_path.txt) at the end: the initial
#   pose, then one pose per particle-filter update; steps below the stock
#   localizeLinDistance/localizeAngDistance thresholds do no update, so the rows
#   are mapped to scans through the app's console log (see cmd_rbpf2tum).
# - Config copies (OUT/<log>/mrpt-*/<app>.ini) differ from the stock files only
#   in [MappingApplication] I/O keys, each marked with a comment: rawlog_file,
#   logOutput_dir, windows off, SAVE_3D_SCENE/SAVE_MAP_IMAGES/SAVE_POSE_LOG off,
#   and rbpf-slam's RANDOM_SEED. Every algorithm parameter stays stock.
# - Time per scan is the wall time of the whole command divided by the number
#   of scans, for every method alike (it includes reading the rawlog and
#   writing outputs); the CPU column (user + system time) is the same figure
#   less disturbed by other jobs on the machine.
# - The hslam apps are copied into OUT/bin first (a rebuild during the run
#   cannot mix versions); OUT/version.txt records what was measured.
#
# Requires: the built hslam apps, mrpt-apps (icp-slam, rbpf-slam, rawlog-edit),
# python3 (standard library only), coreutils `timeout`.
set -euo pipefail

# ---------------------------------------------------------------- arguments
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
datasets="${1:-$repo/../shared/datasets/carmen}"
out="${2:-$repo/results/compare}"
bin="${HSLAM_BIN_DIR:-$repo/build/bin}"
logs="${COMPARE_LOGS:-intel aces csail}"
timeout_s="${COMPARE_TIMEOUT_S:-3600}"
rbpf_seed="${RBPF_SEED:-1}"
config="$repo/config_ini/hslam-default.ini"
icp_ini_stock=/usr/share/mrpt/config_files/icp-slam/icp-slam_demo_classic.ini
rbpf_ini_stock=/usr/share/mrpt/config_files/rbpf-slam/gridmapping_RBPF_ICPbased_intel.ini
hslam_methods=(odometry lines icp lines+icp)

die() { echo "compare-carmen: error: $*" >&2; exit 1; }
say() { echo "[compare $(date +%H:%M:%S)] $*"; }

# ---------------------------------------------------------------- checks
for b in hslam-carmen2rawlog hslam-process hslam-evaluate; do
	[ -x "$bin/$b" ] || die "$bin/$b not found or not executable (build first: scripts/build.sh, or set HSLAM_BIN_DIR)"
done
for b in icp-slam rbpf-slam rawlog-edit python3 timeout; do
	command -v "$b" >/dev/null || die "'$b' not found in PATH (scripts/install-deps.sh installs mrpt-apps; python3 and coreutils are Debian packages)"
done
for f in "$config" "$icp_ini_stock" "$rbpf_ini_stock"; do
	[ -f "$f" ] || die "missing file $f"
done
[ -d "$datasets" ] || die "datasets folder '$datasets' not found (first argument)"
for log in $logs; do
	[ -f "$datasets/$log-corrected.log.gz" ] || die "missing $datasets/$log-corrected.log.gz"
done
datasets="$(cd "$datasets" && pwd)"
mkdir -p "$out"
out="$(cd "$out" && pwd)"  # MRPT configs need absolute paths

# Run copies of the hslam apps and of the INI, so that a rebuild or an edit
# during the run (it takes minutes) cannot mix two versions in one table; note
# what was measured.
mkdir -p "$out/bin"
for b in hslam-carmen2rawlog hslam-process hslam-evaluate; do
	cp "$bin/$b" "$out/bin/$b"
done
cp "$config" "$out/hslam-config.ini"
config="$out/hslam-config.ini"
{
	echo "date: $(date -u +%Y-%m-%dT%H:%M:%SZ)"
	echo "hslam: $(git -C "$repo" describe --always --dirty 2>/dev/null || echo unknown) (binaries copied from $bin)"
	echo "mrpt-apps: $(dpkg-query -W -f='${Version}' mrpt-apps 2>/dev/null || echo unknown)"
	echo "host: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg) at start"
} >"$out/version.txt"
bin="$out/bin"

# Preflight: hslam-process checks the INI (and --set) before opening its input,
# so a missing input tells whether the apps and the INI agree; on disagreement
# the runs below fail and are recorded as such in the table.
for m in "${hslam_methods[@]}"; do
	msg=$("$bin/hslam-process" -c "$config" --set "pose_estimation.method=$m" -q \
		-i "$out/.preflight-missing.rawlog" -o "$out/.preflight" 2>&1 || true)
	case "$msg" in
	*"rawlog file not found"*) ;;
	*) echo "compare-carmen: warning: hslam-process (method=$m) rejects $config: $msg" >&2 ;;
	esac
done
rm -rf "$out/.preflight"

# ---------------------------------------------------------------- python helpers
# Small stdlib-only tools: rawlog format conversion, path -> TUM, the table.
# Invoked as: python3 -c "$PYTOOL" <command> args...
read -r -d '' PYTOOL <<'PY' || true
import csv, gzip, json, math, re, struct, sys

END = b"\x88"                       # MRPT CArchive end-of-object flag
UNIX_EPOCH_TICKS = 116444736000000000  # mrpt TTimeStamp (100 ns since 1601) of 1970-01-01

def fail(msg):
    sys.exit("compare-carmen (python): " + msg)

def header(name, version):
    """MRPT CArchive object header: 0x80 | len(name), class name, version byte."""
    n = name.encode()
    return bytes([0x80 | len(n)]) + n + bytes([version])

def read_listing(path):
    """rawlog-edit --list-timestamps output: 'time label class' per rawlog entry
    (label may be empty)."""
    rows = []
    with open(path) as f:
        for line in f:
            parts = line.split()
            if not parts:
                continue
            if len(parts) == 2:
                parts = [parts[0], "", parts[1]]
            rows.append((float(parts[0]), parts[1], parts[2]))
    return rows

def scan_entries(listing, label):
    """Indices and timestamps of the laser scans labelled `label`."""
    return [(i, t) for i, (t, lab, cls) in enumerate(listing)
            if cls == "mrpt::obs::CObservation2DRangeScan" and lab == label]

def split_objects(data):
    """Top-level objects of an observations-only rawlog. Each observation is a
    serialized object 'header ... 0x88'; a new one starts where 0x88 is followed
    by the header of an mrpt::obs::CObservation* class."""
    cuts = [0] + [m.start() + 1 for m in re.finditer(rb"\x88(?=[\x80-\xff]mrpt::obs::CObservation)", data)]
    cuts.append(len(data))
    objs = []
    for a, b in zip(cuts, cuts[1:]):
        o = data[a:b]
        n = o[0] & 0x7F
        name = o[1:1 + n].decode("ascii", "replace")
        if not (o[0] & 0x80) or not name.startswith("mrpt::obs::") or o[-1:] != END:
            fail("unexpected object layout at byte %d (%r)" % (a, name))
        objs.append((name, o))
    return objs

def odometry_pose(obj):
    """(x, y, phi, ticks) of a serialized CObservationOdometry (version 2:
    CPose2D object, sensorLabel, timestamp, ...)."""
    h = header("mrpt::obs::CObservationOdometry", 2)
    p = header("mrpt::poses::CPose2D", 1)
    if not obj.startswith(h + p):
        fail("CObservationOdometry with an unknown serialization layout/version")
    off = len(h) + len(p)
    x, y, phi = struct.unpack_from("<3d", obj, off)
    off += 24
    if obj[off:off + 1] != END:
        fail("CObservationOdometry: CPose2D not terminated")
    off += 1
    (n,) = struct.unpack_from("<I", obj, off)
    off += 4 + n
    (ticks,) = struct.unpack_from("<Q", obj, off)
    return x, y, phi, ticks

def action_collection(dx, dy, dphi, ticks):
    """CActionCollection with one CActionRobotMovement2D (serialization version 7,
    emOdometry): raw increment + MRPT's default motion model options (Gaussian
    model a1..a4, minStdXY, minStdPHI; Thrun model defaults), exactly as
    CActionRobotMovement2D::TMotionModelOptions() initialises them. MRPT rebuilds
    the pose PDF from these when it reads the object."""
    gm = (0.01, math.degrees(0.001), math.radians(1.0), 0.05, 0.01, math.radians(0.2))
    tm = (0.05, math.radians(4.0), 0.01, math.degrees(0.0001), 0.001, math.radians(0.05))
    pose = header("mrpt::poses::CPose2D", 1) + struct.pack("<3d", dx, dy, dphi) + END
    act = (header("mrpt::obs::CActionRobotMovement2D", 7) + struct.pack("<I", 0) + pose
           + struct.pack("<I", 0) + struct.pack("<6f", *gm)
           + struct.pack("<I", 300) + struct.pack("<6f", *tm)
           + b"\x00"                      # hasVelocities = false
           + b"\x00"                      # hasEncodersInfo = false
           + struct.pack("<Q", ticks) + END)
    return header("mrpt::obs::CActionCollection", 0) + struct.pack("<I", 1) + act + END

def sensory_frame(obs):
    return header("mrpt::obs::CSensoryFrame", 2) + struct.pack("<I", 1) + obs + END

def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))

def cmd_obs2sf(src, listing_path, label, dst, increments_path):
    """Observations-only rawlog -> actions/sensory-frames rawlog (one pair per
    scan labelled `label`; the action is the odometry increment since the
    previous such scan, zero before the first odometry). The increments are
    also written to `increments_path` ('t dx dy dphi' per scan)."""
    with open(src, "rb") as f:
        data = f.read()
    if data[:2] == b"\x1f\x8b":
        data = gzip.decompress(data)
    objs = split_objects(data)
    listing = read_listing(listing_path)
    if len(objs) != len(listing):
        fail("%s: %d objects parsed but rawlog-edit lists %d" % (src, len(objs), len(listing)))
    for (name, _), (_, _, cls) in zip(objs, listing):
        if name != cls:
            fail("%s: object class %s != listed %s" % (src, name, cls))
    odo, prev, pairs = None, None, 0
    with open(dst, "wb") as fraw, gzip.GzipFile(fileobj=fraw, mode="wb", compresslevel=1, mtime=0) as f, \
            open(increments_path, "w") as finc:
        for (name, o), (t, lab, cls) in zip(objs, listing):
            if name == "mrpt::obs::CObservationOdometry":
                odo = odometry_pose(o)
            elif name == "mrpt::obs::CObservation2DRangeScan" and lab == label:
                d = (0.0, 0.0, 0.0)
                if odo is not None and prev is not None:
                    c, s = math.cos(prev[2]), math.sin(prev[2])
                    ex, ey = odo[0] - prev[0], odo[1] - prev[1]
                    d = (c * ex + s * ey, -s * ex + c * ey, wrap(odo[2] - prev[2]))
                ticks = int(round(t * 1e7)) + UNIX_EPOCH_TICKS
                f.write(action_collection(*d, ticks))
                f.write(sensory_frame(o))
                finc.write("%.6f %.9f %.9f %.9f\n" % (t, *d))
                prev, pairs = odo, pairs + 1
    print("%d action/sensory-frame pairs written to %s" % (pairs, dst))

def write_tum(path, rows):
    with open(path, "w") as f:
        f.write("# timestamp tx ty tz qx qy qz qw\n")
        for t, x, y, yaw in rows:
            f.write("%.6f %.6f %.6f 0 0 0 %.9f %.9f\n" % (t, x, y, math.sin(yaw / 2), math.cos(yaw / 2)))

def read_numeric_rows(path):
    rows = []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if s and not s.startswith("%") and not s.startswith("#"):
                rows.append([float(v) for v in s.split()])
    return rows

def cmd_icp2tum(path_txt, listing_path, label, dst):
    """icp-slam log_estimated_path.txt ('step x y yaw', step = rawlog entry) ->
    TUM with the pose after each scan entry."""
    listing = read_listing(listing_path)
    poses = {int(r[0]): r[1:4] for r in read_numeric_rows(path_txt)}
    scans = scan_entries(listing, label)
    rows = [(t, *poses[i]) for i, t in scans if i in poses]
    write_tum(dst, rows)
    print("%d of %d scan poses" % (len(rows), len(scans)))

def compose(p, d):
    c, s = math.cos(p[2]), math.sin(p[2])
    return (p[0] + c * d[0] - s * d[1], p[1] + s * d[0] + c * d[1], wrap(p[2] + d[2]))

def cmd_rbpf2tum(path_txt, app_log, increments_path, dst):
    """rbpf-slam most_likely_path.txt -> TUM, one pose per scan.
    The path holds the initial pose and then one pose per particle-filter
    update, and CMetricMapBuilderRBPF skips the update on steps whose
    accumulated odometry is below localizeLinDistance/localizeAngDistance. The
    app prints "New pose=" (INFO level) on each update and "STEP k" after step
    k-1, so its console log tells which steps the path rows belong to. A skipped
    step gets the previous pose composed with the odometry increment, as
    CMetricMapBuilderRBPF::getCurrentPoseEstimation() does."""
    incs = read_numeric_rows(increments_path)
    updated = [False] * len(incs)
    step = 0
    with open(app_log, errors="replace") as f:
        for line in f:
            m = re.search(r"-+ STEP (\d+) -+", line)
            if m:
                step = int(m.group(1))
            elif "New pose=" in line and step < len(updated):
                updated[step] = True
    path = read_numeric_rows(path_txt)
    if len(path) != 1 + sum(updated):
        fail("most_likely_path.txt has %d rows but the log shows %d filter updates (+1 initial pose)"
             % (len(path), sum(updated)))
    rows, pose, k = [], tuple(path[0][:3]), 1
    for inc, upd in zip(incs, updated):
        if upd:
            pose, k = tuple(path[k][:3]), k + 1
        else:
            pose = compose(pose, inc[1:4])
        rows.append((inc[0], *pose))
    write_tum(dst, rows)
    print("%d scan poses: %d filter updates, %d skipped steps filled with odometry"
          % (len(rows), sum(updated), len(rows) - sum(updated)))

def cmd_table(results_tsv, md_path, csv_path):
    """results.tsv (log, method, status, note, eval.json, wall_s, cpu_s, scans) -> table."""
    cols = ["log", "method", "ATE RMSE (m)", "RPE cons. trans RMSE (m)",
            "RPE cons. rot RMSE (deg)", "RPE 1m trans RMSE (m)", "ms/scan (wall)", "ms/scan (CPU)", "notes"]
    keys = ["ate_rmse_m", "rpe_consecutive_trans_rmse_m", "rpe_consecutive_rot_rmse_deg", "rpe_1m_trans_rmse_m"]
    fmts = ["%.3f", "%.4f", "%.3f", "%.4f"]
    table, odo_ate = [], {}
    with open(results_tsv) as f:
        for r in csv.reader(f, delimiter="\t"):
            log, method, status, note, ev, wall_s, cpu_s, scans = r
            row = [log, method]
            ej = None
            if status == "ok":
                try:
                    with open(ev) as fe:
                        ej = json.load(fe)
                except (OSError, ValueError) as e:
                    note = (note + "; " if note else "") + "no evaluation (%s)" % e
            row += [fm % ej[k] if ej else "-" for k, fm in zip(keys, fmts)]
            for secs in (wall_s, cpu_s):  # a failed run's time per scan means nothing
                ok = status == "ok" and secs and int(scans) > 0
                row.append("%.2f" % (1000.0 * float(secs) / int(scans)) if ok else "-")
            if ej and ej.get("matched", 0) < ej.get("reference_poses", 0):
                note = (note + "; " if note else "") + "%d/%d poses matched" % (ej["matched"], ej["reference_poses"])
            if ej and method == "odometry":
                odo_ate[log] = ej["ate_rmse_m"]
            elif ej and log in odo_ate and ej["ate_rmse_m"] > odo_ate[log]:
                note = (note + "; " if note else "") + "ATE worse than odometry"
            row.append(note)
            table.append(row)
    with open(csv_path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols)
        w.writerows(table)
    with open(md_path, "w") as f:
        f.write("| " + " | ".join(cols) + " |\n")
        f.write("|" + "|".join(["---", "---"] + ["---:"] * 6 + ["---"]) + "|\n")
        for row in table:
            f.write("| " + " | ".join(row) + " |\n")
    widths = [max(len(c), *(len(r[i]) for r in table)) for i, c in enumerate(cols)]
    def line(cells):
        return "  ".join(c.ljust(w) if i < 2 or i == len(cols) - 1 else c.rjust(w)
                         for i, (c, w) in enumerate(zip(cells, widths))).rstrip()
    print(line(cols))
    print(line(["-" * w for w in widths]))
    prev = None
    for row in table:
        if prev is not None and row[0] != prev:
            print()
        print(line(row))
        prev = row[0]

commands = {"obs2sf": cmd_obs2sf, "icp2tum": cmd_icp2tum, "rbpf2tum": cmd_rbpf2tum, "table": cmd_table}
if len(sys.argv) < 2 or sys.argv[1] not in commands:
    fail("usage: obs2sf|icp2tum|rbpf2tum|table args...")
commands[sys.argv[1]](*sys.argv[2:])
PY
pytool() { python3 -c "$PYTOOL" "$@"; }

# ---------------------------------------------------------------- helpers
# run_timed NAME LOGFILE PROGRESS_FILE TOTAL_STEPS -- CMD...
# Runs CMD (stdout+stderr to LOGFILE, stdin closed) under `timeout`, prints a
# progress line every 20 s from the line count of PROGRESS_FILE (an MRPT app's
# per-step log; "" for none) and sets RUN_RC, RUN_WALL_S and RUN_CPU_S (user +
# system time of the command and its children: less sensitive than the wall
# time to other jobs sharing the machine).
run_timed() {
	local name="$1" logfile="$2" progress="$3" total="$4"
	shift 5
	local tfile
	tfile="$(mktemp)"
	(
		TIMEFORMAT='%R %U %S'
		rc=0
		{ time timeout "$timeout_s" "$@" </dev/null >"$logfile" 2>&1 || rc=$?; } 2>"$tfile"
		echo "$rc" >>"$tfile"
	) &
	local pid=$! waited=0
	while kill -0 "$pid" 2>/dev/null; do
		sleep 1
		waited=$((waited + 1))
		if [ $((waited % 20)) -eq 0 ]; then
			local done_steps="?"
			[ -n "$progress" ] && [ -f "$progress" ] && done_steps=$(wc -l <"$progress")
			say "  $name: ${waited} s, step $done_steps/$total"
		fi
	done
	wait "$pid" || true
	local real user sys
	{ read -r real user sys; read -r RUN_RC; } <"$tfile"
	rm -f "$tfile"
	RUN_WALL_S=$real
	RUN_CPU_S=$(python3 -c "print('%.3f' % ($user + $sys))")
}

# describe_rc RC -> human-readable failure
describe_rc() {
	case "$1" in
	124) echo "timed out after ${timeout_s} s" ;;
	139) echo "crashed (segmentation fault)" ;;
	134) echo "crashed (abort)" ;;
	*) echo "failed (exit code $1)" ;;
	esac
}

# steps_done LOGDIR -> number of steps an MRPT app finished (it appends one
# line per step to log_MemoryUsage.txt, opening and closing the file each time)
steps_done() {
	if [ -f "$1/log_MemoryUsage.txt" ]; then wc -l <"$1/log_MemoryUsage.txt"; else echo 0; fi
}

# evaluate REF EST JSON -> 0 if the evaluation was written
evaluate() {
	"$bin/hslam-evaluate" "$1" "$2" --json "$3" >"${3%.json}.txt" 2>&1
}

# record LOG METHOD STATUS NOTE EVAL_JSON WALL_S CPU_S SCANS
record() {
	printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$@" >>"$results"
}

# mrpt_ini STOCK OUT KEY=VALUE... : copy of a stock MRPT config with keys of
# [MappingApplication] replaced (or appended there if absent); everything else
# is untouched.
mrpt_ini() {
	local stock="$1" dst="$2"
	shift 2
	python3 - "$stock" "$dst" "$@" <<'PY'
import re, sys
stock, dst, kvs = sys.argv[1], sys.argv[2], dict(a.split("=", 1) for a in sys.argv[3:])
text = open(stock, newline="").read()
eol = "\r\n" if "\r\n" in text else "\n"   # keep the stock file's line endings
section, out, seen, header_at = None, [], set(), None
for line in text.splitlines():
    m = re.match(r"\s*\[(.+)\]", line)
    if m:
        section = m.group(1).strip()
        if section == "MappingApplication":
            header_at = len(out)
    elif section == "MappingApplication":
        m = re.match(r"\s*([A-Za-z_0-9]+)\s*=", line)
        if m and m.group(1) in kvs:
            stock_value = line.split("=", 1)[1].strip()
            line = "%s=%s   // changed by compare-carmen.sh (stock: %s)" % (m.group(1), kvs[m.group(1)], stock_value)
            seen.add(m.group(1))
    out.append(line)
if header_at is None:
    sys.exit("mrpt_ini: no [MappingApplication] section in " + stock)
missing = ["%s=%s   // added by compare-carmen.sh" % (k, v) for k, v in kvs.items() if k not in seen]
out[header_at + 1:header_at + 1] = missing   # right below the section header
with open(dst, "w", newline="") as f:
    f.write(eol.join(out) + eol)
PY
}

# ---------------------------------------------------------------- main
results="$out/results.tsv"
: >"$results"
t_start=$(date +%s)
say "datasets: $datasets"
say "output:   $out"
say "logs:     $logs   (time limit per run ${timeout_s} s)"

for log in $logs; do
	dir="$out/$log"
	rm -rf "$dir"
	mkdir -p "$dir"
	rawlog="$dir/$log.rawlog"
	ref="$dir/$log.tum"
	listing="$dir/$log.entries.txt"

	# 1. CARMEN -> rawlog + reference ----------------------------------------
	say "$log: converting $datasets/$log-corrected.log.gz"
	"$bin/hslam-carmen2rawlog" "$datasets/$log-corrected.log.gz" "$rawlog" --reference "$ref" >"$dir/convert.txt" 2>&1 ||
		die "hslam-carmen2rawlog failed on $log (see $dir/convert.txt)"
	rawlog-edit --list-timestamps -i "$rawlog" --text-file-output "$listing" >"$dir/list-timestamps.txt" 2>&1 ||
		die "rawlog-edit --list-timestamps failed on $rawlog"
	scans=$(grep -c " LASER mrpt::obs::CObservation2DRangeScan" "$listing" || true)
	refposes=$(grep -vc '^#' "$ref" || true)
	[ "$scans" -gt 0 ] || die "$log: no LASER scans in $rawlog"
	[ "$scans" -eq "$refposes" ] || die "$log: $scans scans but $refposes reference poses"
	say "$log: $scans scans"

	# 2. hslam-process, one run per pose estimation method -------------------
	for m in "${hslam_methods[@]}"; do
		mdir="$dir/hslam-$m"
		say "$log: hslam-process method=$m"
		run_timed "hslam $m" "$dir/hslam-$m.log" "" "$scans" -- \
			"$bin/hslam-process" -c "$config" -i "$rawlog" -o "$mdir" \
			--set "pose_estimation.method=$m" -q --ground-truth "$ref"
		if [ "$RUN_RC" -ne 0 ]; then
			record "$log" "$m" fail "$(describe_rc "$RUN_RC") (see hslam-$m.log)" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
		elif evaluate "$ref" "$mdir/trajectory.tum" "$mdir/eval.json"; then
			record "$log" "$m" ok "" "$mdir/eval.json" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
		else
			record "$log" "$m" fail "evaluation failed (see hslam-$m/eval.txt)" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
		fi
	done

	# 3a. MRPT icp-slam on the same rawlog -----------------------------------
	idir="$dir/mrpt-icp-slam"
	mkdir -p "$idir"
	mrpt_ini "$icp_ini_stock" "$idir/icp-slam.ini" \
		"rawlog_file=$rawlog" "logOutput_dir=$idir/log" \
		SHOW_PROGRESS_3D_REAL_TIME=0 SAVE_3D_SCENE=0 SAVE_POSE_LOG=0
	entries=$(wc -l <"$listing")
	say "$log: MRPT icp-slam"
	run_timed "icp-slam $log" "$idir/icp-slam.log" "$idir/log/log_MemoryUsage.txt" "$entries" -- \
		icp-slam "$idir/icp-slam.ini"
	if [ "$RUN_RC" -ne 0 ]; then
		record "$log" "mrpt icp-slam" fail "$(describe_rc "$RUN_RC") after $(steps_done "$idir/log") of $entries rawlog entries" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
	elif [ ! -s "$idir/log/log_estimated_path.txt" ]; then
		record "$log" "mrpt icp-slam" fail "no log_estimated_path.txt" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
	else
		if ! pytool icp2tum "$idir/log/log_estimated_path.txt" "$listing" LASER "$idir/trajectory.tum" >"$idir/totum.txt" 2>&1; then
			record "$log" "mrpt icp-slam" fail "path conversion failed (see mrpt-icp-slam/totum.txt)" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
		elif evaluate "$ref" "$idir/trajectory.tum" "$idir/eval.json"; then
			record "$log" "mrpt icp-slam" ok "" "$idir/eval.json" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
		else
			record "$log" "mrpt icp-slam" fail "evaluation failed (see mrpt-icp-slam/eval.txt)" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
		fi
	fi

	# 3b. MRPT rbpf-slam on the same data in actions/sensory-frames format ---
	rdir="$dir/mrpt-rbpf-slam"
	mkdir -p "$rdir"
	sf_rawlog="$dir/$log.sf.rawlog"
	if ! pytool obs2sf "$rawlog" "$listing" LASER "$sf_rawlog" "$rdir/odometry_increments.txt" >"$rdir/obs2sf.txt" 2>&1; then
		record "$log" "mrpt rbpf-slam" fail "rawlog format conversion failed (see mrpt-rbpf-slam/obs2sf.txt)" "" "" "" "$scans"
		continue
	fi
	rbpf_keys=("rawlog_file=$sf_rawlog" "logOutput_dir=$rdir/log"
		SHOW_PROGRESS_IN_WINDOW=0 SAVE_3D_SCENE=0 SAVE_MAP_IMAGES=0 SAVE_POSE_LOG=0)
	[ "$rbpf_seed" = random ] || rbpf_keys+=("RANDOM_SEED=$rbpf_seed")
	mrpt_ini "$rbpf_ini_stock" "$rdir/rbpf-slam.ini" "${rbpf_keys[@]}"
	say "$log: MRPT rbpf-slam (slow: ~0.1 s per scan; progress every 20 s)"
	run_timed "rbpf-slam $log" "$rdir/rbpf-slam.log" "$rdir/log/log_MemoryUsage.txt" "$scans" -- \
		rbpf-slam "$rdir/rbpf-slam.ini"
	if [ "$RUN_RC" -ne 0 ]; then
		record "$log" "mrpt rbpf-slam" fail "$(describe_rc "$RUN_RC") after $(steps_done "$rdir/log") of $scans steps" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
	elif [ ! -s "$rdir/log/most_likely_path.txt" ]; then
		record "$log" "mrpt rbpf-slam" fail "no most_likely_path.txt" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
	else
		if ! pytool rbpf2tum "$rdir/log/most_likely_path.txt" "$rdir/rbpf-slam.log" \
			"$rdir/odometry_increments.txt" "$rdir/trajectory.tum" >"$rdir/totum.txt" 2>&1; then
			record "$log" "mrpt rbpf-slam" fail "path conversion failed (see mrpt-rbpf-slam/totum.txt)" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
		elif evaluate "$ref" "$rdir/trajectory.tum" "$rdir/eval.json"; then
			record "$log" "mrpt rbpf-slam" ok "" "$rdir/eval.json" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
		else
			record "$log" "mrpt rbpf-slam" fail "evaluation failed (see mrpt-rbpf-slam/eval.txt)" "" "$RUN_WALL_S" "$RUN_CPU_S" "$scans"
		fi
	fi
done

# 4. the table ---------------------------------------------------------------
echo
pytool table "$results" "$out/table.md" "$out/table.csv"
echo
say "total run time: $(($(date +%s) - t_start)) s; table in $out/table.md and $out/table.csv"
