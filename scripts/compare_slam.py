#!/usr/bin/env python3
"""compare_slam.py: our pose estimators against MRPT's icp-slam and rbpf-slam.

Writes the three tables of docs/pose-estimation.md (standard library only):

  1. ATE RMSE per data set and method (the CARMEN logs and the simulated
     samples of rawlog_samples/);
  2. the comparison on the CARMEN logs with MRPT's own SLAM apps (ATE, RPE,
     time per scan);
  3. the time per scan of the pose-estimation stages on intel (timing.csv).

Per CARMEN log: hslam-carmen2rawlog writes the observations-only rawlog and
(--format frames) the actions + sensory-frames rawlog with MRPT's own classes,
with the same odometry-gap semantics (no odometry, never differenced across);
hslam-process runs each pose-estimation method; MRPT's icp-slam runs on the
observations-only rawlog and rbpf-slam on the frames rawlog (it needs actions),
both with the STOCK configs of /usr/share/mrpt/config_files/ where only I/O keys
change (windows and 3D/image dumps off, rbpf-slam's RANDOM_SEED fixed); every
trajectory is scored by hslam-evaluate against the reference.

Usage: scripts/compare_slam.py [--datasets DIR] [--out DIR] [--bin DIR]
                               [--logs intel,aces,csail] [--samples corridor,...]
Outputs in OUT: tables.md (the three tables), comparison.csv, and one folder
per data set with every run's files and log.
"""
import argparse
import csv
import json
import math
import os
import re
import resource
import shutil
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
HSLAM_METHODS = ["odometry", "lines", "icp", "lines+icp", "default"]
DEFAULT_METHOD = "default"  # the INI as shipped: lines+icp with the loop-closure back-end
MRPT_CONFIGS = "/usr/share/mrpt/config_files"
ICP_INI = MRPT_CONFIGS + "/icp-slam/icp-slam_demo_classic.ini"
RBPF_INI = MRPT_CONFIGS + "/rbpf-slam/gridmapping_RBPF_ICPbased_intel.ini"
TIMING_STAGES = ["line_extraction", "line_matching", "icp", "ukf", "pose_estimation", "loop_closure"]
METRICS = [("ate_rmse_m", "ATE RMSE (m)", "%.3f"),
           ("rpe_consecutive_trans_rmse_m", "RPE cons. trans RMSE (m)", "%.4f"),
           ("rpe_consecutive_rot_rmse_deg", "RPE cons. rot RMSE (deg)", "%.3f"),
           ("rpe_1m_trans_rmse_m", "RPE 1m trans RMSE (m)", "%.4f")]


class CompareError(Exception):
    """A fault in the inputs or in a run that makes the whole comparison meaningless."""


# ------------------------------------------------------------ poses and text files
def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def compose(p, d):
    """p (+) d for 2-D poses (x, y, yaw)."""
    c, s = math.cos(p[2]), math.sin(p[2])
    return (p[0] + c * d[0] - s * d[1], p[1] + s * d[0] + c * d[1], wrap(p[2] + d[2]))


def relative(a, b):
    """a^-1 (+) b: pose b in the frame of pose a."""
    c, s = math.cos(a[2]), math.sin(a[2])
    ex, ey = b[0] - a[0], b[1] - a[1]
    return (c * ex + s * ey, -s * ex + c * ey, wrap(b[2] - a[2]))


def numeric_rows(lines):
    """Rows of numbers of a text table; '#' and '%' lines are comments."""
    rows = []
    for line in lines:
        s = line.strip()
        if s and s[0] not in "#%":
            rows.append([float(v) for v in s.split()])
    return rows


def tum_rows(lines):
    """TUM 't x y z qx qy qz qw' -> (t, x, y, yaw)."""
    return [(r[0], r[1], r[2], 2 * math.atan2(r[6], r[7])) for r in numeric_rows(lines)]


def tum_text(rows):
    out = ["# timestamp tx ty tz qx qy qz qw"]
    for t, x, y, yaw in rows:
        out.append("%.6f %.6f %.6f 0 0 0 %.9f %.9f" % (t, x, y, math.sin(yaw / 2), math.cos(yaw / 2)))
    return "\n".join(out) + "\n"


# ------------------------------------------------------------ MRPT outputs -> TUM
def read_listing(lines):
    """rawlog-edit --list-timestamps: 'time label class' per rawlog entry (label may be empty)."""
    rows = []
    for line in lines:
        parts = line.split()
        if len(parts) == 2:
            parts = [parts[0], "", parts[1]]
        if parts:
            rows.append((float(parts[0]), parts[1], parts[2]))
    return rows


def scan_entries(listing, label):
    """(entry index, time) of the laser scans labelled `label`."""
    return [(i, t) for i, (t, lab, cls) in enumerate(listing)
            if cls == "mrpt::obs::CObservation2DRangeScan" and lab == label]


def icp_scan_poses(path_rows, listing, label):
    """icp-slam log_estimated_path.txt rows ('entry x y yaw') -> (t, x, y, yaw)
    after each scan entry that has a pose."""
    poses = {int(r[0]): r[1:4] for r in path_rows}
    return [(t, *poses[i]) for i, t in scan_entries(listing, label) if i in poses]


def rbpf_updated_steps(log_lines, steps):
    """Which rbpf-slam steps updated the filter: the app prints 'STEP k' before
    step k and 'New pose=' on each update."""
    updated, step = [False] * steps, 0
    for line in log_lines:
        m = re.search(r"-+ STEP (\d+) -+", line)
        if m:
            step = int(m.group(1))
        elif "New pose=" in line and step < steps:
            updated[step] = True
    return updated


def odometry_per_scan(odometry_rows, scan_times):
    """(t, x, y, yaw) per scan from rawlog-edit --export-odometry-txt rows
    (t, x, y, phi, ...): our importer gives each ODOMETRY the time of its scan;
    a scan without one (an ODOMETRY_GAP) keeps the previous pose, i.e. zero
    motion, which is what rbpf-slam does with the empty action of that step."""
    by_time = {round(r[0], 4): tuple(r[1:4]) for r in odometry_rows}
    rows, pose = [], (0.0, 0.0, 0.0)
    for t in scan_times:
        pose = by_time.get(round(t, 4), pose)
        rows.append((t, *pose))
    return rows


def rbpf_scan_poses(path_rows, updated, odometry):
    """rbpf-slam most_likely_path.txt (initial pose, then one row per filter
    update) -> one pose per scan. A step below localizeLinDistance /
    localizeAngDistance does no update: it gets the previous pose composed with
    the odometry increment, as CMetricMapBuilderRBPF::getCurrentPoseEstimation()
    does. `odometry`: (t, x, y, yaw) odometry per scan (odometry_per_scan)."""
    if len(path_rows) != 1 + sum(updated):
        raise CompareError("most_likely_path.txt has %d rows but the log shows %d filter updates (+1 initial pose)"
                           % (len(path_rows), sum(updated)))
    if len(odometry) != len(updated):
        raise CompareError("%d odometry poses for %d rbpf-slam steps" % (len(odometry), len(updated)))
    rows, pose, k = [], tuple(path_rows[0][:3]), 1
    for i, upd in enumerate(updated):
        if upd:
            pose, k = tuple(path_rows[k][:3]), k + 1
        elif i > 0:
            pose = compose(pose, relative(odometry[i - 1][1:4], odometry[i][1:4]))
        rows.append((odometry[i][0], *pose))
    return rows


def mrpt_ini_with(text, keys, tool="compare_slam.py"):
    """A stock MRPT config with keys of [MappingApplication] replaced (or added
    right below its header), each change marked by a comment."""
    eol = "\r\n" if "\r\n" in text else "\n"
    out, seen, header_at, section = [], set(), None, None
    for line in text.splitlines():
        m = re.match(r"\s*\[(.+)\]", line)
        if m:
            section = m.group(1).strip()
            header_at = len(out) if section == "MappingApplication" else header_at
        elif section == "MappingApplication":
            m = re.match(r"\s*([A-Za-z_0-9]+)\s*=", line)
            if m and m.group(1) in keys:
                stock = line.split("=", 1)[1].strip()
                line = "%s=%s   // changed by %s (stock: %s)" % (m.group(1), keys[m.group(1)], tool, stock)
                seen.add(m.group(1))
        out.append(line)
    if header_at is None:
        raise CompareError("no [MappingApplication] section in the MRPT config")
    added = ["%s=%s   // added by %s" % (k, v, tool) for k, v in keys.items() if k not in seen]
    out[header_at + 1:header_at + 1] = added
    return eol.join(out) + eol


# ------------------------------------------------------------ tables
def ms_per_scan(seconds, scans):
    return "%.2f" % (1000.0 * seconds / scans) if seconds is not None and scans > 0 else "-"


def comparison_row(run, odometry_ate):
    """One row of table 2 from a run record (dict: log, method, eval, wall_s, cpu_s, scans, note)."""
    ev, notes = run.get("eval"), [run["note"]] if run.get("note") else []
    row = [run["log"], run["method"]] + [fmt % ev[k] if ev else "-" for k, _, fmt in METRICS]
    row += [ms_per_scan(run.get("wall_s") if ev else None, run["scans"]),
            ms_per_scan(run.get("cpu_s") if ev else None, run["scans"])]
    if ev and ev.get("matched", 0) < ev.get("reference_poses", 0):
        notes.append("%d/%d poses matched" % (ev["matched"], ev["reference_poses"]))
    if ev and run["method"] != "odometry" and odometry_ate is not None and ev["ate_rmse_m"] > odometry_ate:
        notes.append("ATE worse than odometry")
    return row + ["; ".join(notes)]


def comparison_table(runs):
    """Table 2 as rows (header first)."""
    header = ["log", "method"] + [title for _, title, _ in METRICS] + ["ms/scan (wall)", "ms/scan (CPU)", "notes"]
    odometry_ate = {r["log"]: r["eval"]["ate_rmse_m"] for r in runs if r["method"] == "odometry" and r.get("eval")}
    return [header] + [comparison_row(r, odometry_ate.get(r["log"])) for r in runs]


def significant(value, digits=3):
    """ATE in the style of table 1: 3 significant digits, at least 2 decimals."""
    if value == 0:
        return "0"
    decimals = max(2, digits - 1 - int(math.floor(math.log10(abs(value)))))
    return "%.*f" % (decimals, value)


def hslam_overrides(method):
    """hslam-process --set options of a method: a pose-estimation method with
    the loop-closure back-end off (the front-end alone), or none for the
    default (the INI as shipped)."""
    if method == DEFAULT_METHOD:
        return []
    return ["--set", "pose_estimation.method=" + method, "--set", "loop_closure.enabled=false"]


def ate_table(runs, datasets):
    """Table 1: one row per data set, one column per hslam method."""
    ate = {(r["log"], r["method"]): r["eval"]["ate_rmse_m"] for r in runs if r.get("eval")}
    rows = [["data"] + HSLAM_METHODS]
    for name in datasets:
        rows.append([name] + [significant(ate[(name, m)]) if (name, m) in ate else "-" for m in HSLAM_METHODS])
    return rows


def read_timing_csv(lines):
    """timing.csv (stage,count,mean_ms,p95_ms,max_ms,total_ms) -> {stage: total_ms}."""
    return {r["stage"]: float(r["total_ms"]) for r in csv.DictReader(lines)}


def timing_table(totals, scans):
    """Table 3: ms per scan of each pose-estimation stage, per method ({method: {stage: total_ms}})."""
    methods = [m for m in HSLAM_METHODS if m != "odometry"]
    rows = [["stage"] + methods]
    for stage in TIMING_STAGES:
        name = "whole pose_estimation" if stage == "pose_estimation" else stage
        cells = ["%.2f ms" % (totals[m][stage] / scans) if stage in totals.get(m, {}) else "-" for m in methods]
        rows.append([name] + cells)
    return rows


def markdown(rows, right_from=1):
    """A markdown table; columns from `right_from` on are right-aligned numbers."""
    align = ["---" if i < right_from or i == len(rows[0]) - 1 and rows[0][i] == "notes" else "---:"
             for i in range(len(rows[0]))]
    lines = ["| " + " | ".join(rows[0]) + " |", "|" + "|".join(align) + "|"]
    lines += ["| " + " | ".join(r) + " |" for r in rows[1:]]
    return "\n".join(lines) + "\n"


# ------------------------------------------------------------ running programs
class Runner:
    """Runs commands with a time limit; measures wall and CPU (user + system) time."""

    def __init__(self, timeout_s):
        self.timeout_s = timeout_s

    def run(self, name, argv, log_path, progress=None):
        """Returns (exit code, wall s, cpu s); prints progress every 20 s
        (`progress`: a callable giving a short status)."""
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        start = time.monotonic()
        with open(log_path, "w") as log:
            proc = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT)
            code = self._wait(name, proc, start, progress)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        return code, time.monotonic() - start, cpu

    def _wait(self, name, proc, start, progress):
        while True:
            try:
                return proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                waited = time.monotonic() - start
                if waited > self.timeout_s:
                    proc.kill()
                    proc.wait()
                    return 124
                say("  %s: %d s%s" % (name, waited, ", " + progress() if progress else ""))


def say(text):
    print("[compare %s] %s" % (time.strftime("%H:%M:%S"), text), flush=True)


def describe_exit(code, timeout_s):
    return {124: "timed out after %d s" % timeout_s, -11: "crashed (segmentation fault)",
            -6: "crashed (abort)"}.get(code, "failed (exit code %d)" % code)


def lines_of(path):
    with open(path, errors="replace") as f:
        return f.read().splitlines()


def write_text(path, text):
    with open(path, "w") as f:
        f.write(text)


def count_lines(path):
    return len(lines_of(path)) if os.path.exists(path) else 0


# ------------------------------------------------------------ one data set
class Comparison:
    def __init__(self, args):
        self.args = args
        self.bin = os.path.join(args.out, "bin")
        self.runner = Runner(args.timeout)
        self.runs = []
        self.timing = {}  # method -> {stage: total_ms} on the timing log

    def tool(self, name):
        return os.path.join(self.bin, name)

    def record(self, log, method, scans, timing=(None, None), evaluation=None, note=""):
        self.runs.append({"log": log, "method": method, "scans": scans, "wall_s": timing[0],
                          "cpu_s": timing[1], "eval": evaluation, "note": note})

    def evaluate(self, reference, estimate, json_path):
        """hslam-evaluate; returns its JSON (dict) or raises CompareError."""
        code = subprocess.run([self.tool("hslam-evaluate"), reference, estimate, "--json", json_path],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        if code.returncode != 0:
            raise CompareError("evaluation of %s failed: %s" % (estimate, code.stderr.strip()))
        with open(json_path) as f:
            return json.load(f)

    def scored(self, log, method, scans, timing, reference, estimate, folder):
        try:
            self.record(log, method, scans, timing, self.evaluate(reference, estimate, folder + "/eval.json"))
        except CompareError as e:
            self.record(log, method, scans, note=str(e))

    def run_hslam(self, log, rawlog, reference, folder, scans):
        """Each method: a front-end alone (back-end off) or the shipped default."""
        for method in self.args.methods:
            out = os.path.join(folder, "hslam-" + method)
            say("%s: hslam-process method=%s" % (log, method))
            code, wall, cpu = self.runner.run(
                "hslam " + method,
                [self.tool("hslam-process"), "-c", self.args.config, "-i", rawlog, "-o", out, "-q",
                 "--ground-truth", reference] + hslam_overrides(method),
                out + ".log")
            if code != 0:
                self.record(log, method, scans, note="%s (see %s.log)" % (describe_exit(code, self.args.timeout), out))
                continue
            self.scored(log, method, scans, (wall, cpu), reference, out + "/trajectory.tum", out)
            if log == self.args.timing_log and os.path.exists(out + "/timing.csv"):
                self.timing[method] = read_timing_csv(lines_of(out + "/timing.csv"))

    def convert(self, log, folder):
        """CARMEN log -> observations-only and frames rawlogs + reference TUM."""
        source = os.path.join(self.args.datasets, log + "-corrected.log.gz")
        rawlogs = {}
        for fmt in ("observations", "frames"):
            rawlogs[fmt] = os.path.join(folder, "%s.%s.rawlog" % (log, fmt))
            code, _, _ = self.runner.run(
                "convert", [self.tool("hslam-carmen2rawlog"), source, rawlogs[fmt], "--format", fmt,
                            "--reference", os.path.join(folder, log + ".tum")],
                os.path.join(folder, "convert-%s.txt" % fmt))
            if code != 0:
                raise CompareError("hslam-carmen2rawlog failed on %s (see %s/convert-%s.txt)" % (source, folder, fmt))
        return rawlogs

    def run_carmen_log(self, log):
        folder = os.path.join(self.args.out, log)
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        say("%s: converting" % log)
        rawlogs = self.convert(log, folder)
        reference = os.path.join(folder, log + ".tum")
        scans = len(numeric_rows(lines_of(reference)))
        say("%s: %d scans" % (log, scans))
        self.run_hslam(log, rawlogs["observations"], reference, folder, scans)
        self.run_icp_slam(log, rawlogs["observations"], reference, folder, scans)
        odometry = self.odometry(rawlogs["observations"], reference)
        self.run_rbpf_slam(log, rawlogs["frames"], reference, odometry, folder, scans)

    def odometry(self, rawlog, reference):
        """Odometry per scan as MRPT reads it from the observations-only rawlog."""
        subprocess.run(["rawlog-edit", "--export-odometry-txt", "-i", rawlog], stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=True)
        # MRPT 2.5 joins the folder and the file name without a separator.
        stem = os.path.dirname(rawlog) + os.path.splitext(os.path.basename(rawlog))[0]
        exported = os.path.splitext(rawlog)[0] + "_ODOMETRY.txt"
        for label in ("ODOMETRY", "LASER"):
            if os.path.exists("%s_%s.txt" % (stem, label)):
                os.replace("%s_%s.txt" % (stem, label), os.path.splitext(rawlog)[0] + "_%s.txt" % label)
        scan_times = [r[0] for r in numeric_rows(lines_of(reference))]
        return odometry_per_scan(numeric_rows(lines_of(exported)), scan_times)

    def mrpt_app(self, app, stock, keys, folder, steps):
        """Runs an MRPT app on a stock config with `keys` changed; returns (code, wall, cpu)."""
        os.makedirs(folder, exist_ok=True)
        ini = os.path.join(folder, app + ".ini")
        write_text(ini, mrpt_ini_with(open(stock, newline="").read(), keys))
        memory_log = os.path.join(folder, "log", "log_MemoryUsage.txt")
        return self.runner.run(app, [app, ini], os.path.join(folder, app + ".log"),
                               lambda: "step %d/%d" % (count_lines(memory_log), steps))

    def run_icp_slam(self, log, rawlog, reference, folder, scans):
        out = os.path.join(folder, "mrpt-icp-slam")
        listing_path = os.path.join(folder, log + ".entries.txt")
        subprocess.run(["rawlog-edit", "--list-timestamps", "-i", rawlog, "--text-file-output", listing_path],
                       stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
        listing = read_listing(lines_of(listing_path))
        say("%s: MRPT icp-slam" % log)
        code, wall, cpu = self.mrpt_app("icp-slam", ICP_INI, {
            "rawlog_file": rawlog, "logOutput_dir": out + "/log", "SHOW_PROGRESS_3D_REAL_TIME": "0",
            "SAVE_3D_SCENE": "0", "SAVE_POSE_LOG": "0"}, out, len(listing))
        path = out + "/log/log_estimated_path.txt"
        if code != 0 or not os.path.exists(path):
            self.record(log, "mrpt icp-slam", scans, note=describe_exit(code, self.args.timeout) if code else
                        "no log_estimated_path.txt")
            return
        write_text(out + "/trajectory.tum", tum_text(icp_scan_poses(numeric_rows(lines_of(path)), listing, "LASER")))
        self.scored(log, "mrpt icp-slam", scans, (wall, cpu), reference, out + "/trajectory.tum", out)

    def run_rbpf_slam(self, log, rawlog, reference, odometry, folder, scans):
        out = os.path.join(folder, "mrpt-rbpf-slam")
        keys = {"rawlog_file": rawlog, "logOutput_dir": out + "/log", "SHOW_PROGRESS_IN_WINDOW": "0",
                "SAVE_3D_SCENE": "0", "SAVE_MAP_IMAGES": "0", "SAVE_POSE_LOG": "0"}
        if self.args.rbpf_seed != "random":
            keys["RANDOM_SEED"] = self.args.rbpf_seed
        say("%s: MRPT rbpf-slam (slow; progress every 20 s)" % log)
        code, wall, cpu = self.mrpt_app("rbpf-slam", RBPF_INI, keys, out, scans)
        path = out + "/log/most_likely_path.txt"
        if code != 0 or not os.path.exists(path):
            self.record(log, "mrpt rbpf-slam", scans, note=describe_exit(code, self.args.timeout) if code else
                        "no most_likely_path.txt")
            return
        try:
            odo = odometry
            updated = rbpf_updated_steps(lines_of(out + "/rbpf-slam.log"), len(odo))
            write_text(out + "/trajectory.tum", tum_text(rbpf_scan_poses(numeric_rows(lines_of(path)), updated, odo)))
        except (CompareError, OSError) as e:
            self.record(log, "mrpt rbpf-slam", scans, note="path conversion failed: %s" % e)
            return
        self.scored(log, "mrpt rbpf-slam", scans, (wall, cpu), reference, out + "/trajectory.tum", out)

    def run_sample(self, name):
        folder = os.path.join(self.args.out, "sim-" + name)
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        sample = os.path.join(self.args.samples_dir, name)
        reference = os.path.join(sample, "ground_truth.tum")
        scans = len(numeric_rows(lines_of(reference)))
        self.run_hslam("sim " + name, os.path.join(sample, "sim.rawlog"), reference, folder, scans)


# ------------------------------------------------------------ main
def hslam_tools(args):
    return ["hslam-carmen2rawlog", "hslam-evaluate"] + (["hslam-process"] if args.methods else [])


def check_inputs(args):
    for name in hslam_tools(args):
        if not os.access(os.path.join(args.bin, name), os.X_OK):
            raise CompareError("%s/%s not found (build first, or give --bin)" % (args.bin, name))
    for app in ("icp-slam", "rbpf-slam", "rawlog-edit"):
        if not shutil.which(app):
            raise CompareError("'%s' not in PATH (scripts/install-deps.sh installs mrpt-apps)" % app)
    for path in [args.config, ICP_INI, RBPF_INI] + [os.path.join(args.datasets, l + "-corrected.log.gz")
                                                    for l in args.logs]:
        if not os.path.isfile(path):
            raise CompareError("missing file " + path)
    for name in args.samples:
        if not os.path.isfile(os.path.join(args.samples_dir, name, "sim.rawlog")):
            raise CompareError("missing sample %s/%s/sim.rawlog" % (args.samples_dir, name))


def freeze_inputs(args):
    """Copies the apps and the INI into OUT so a rebuild during the run cannot mix versions."""
    os.makedirs(os.path.join(args.out, "bin"), exist_ok=True)
    for name in hslam_tools(args):
        shutil.copy2(os.path.join(args.bin, name), os.path.join(args.out, "bin", name))
    config = os.path.join(args.out, "hslam-config.ini")
    shutil.copy2(args.config, config)
    args.config = config
    git = subprocess.run(["git", "-C", REPO, "describe", "--always", "--dirty"], capture_output=True, text=True)
    write_text(os.path.join(args.out, "version.txt"),
               "date: %s\nhslam: %s\nhost: %d cores, load %s\n" % (
                   time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), git.stdout.strip() or "unknown",
                   os.cpu_count(), " ".join("%.2f" % v for v in os.getloadavg())))


def write_tables(comparison, args):
    carmen = [r for r in comparison.runs if not r["log"].startswith("sim ")]
    table1 = ate_table(comparison.runs, args.logs + ["sim " + s for s in args.samples])
    table2 = comparison_table(carmen)
    with open(os.path.join(args.out, "comparison.csv"), "w", newline="") as f:
        csv.writer(f).writerows(table2)
    text = "## ATE RMSE (m)\n\n" + markdown(table1) + "\n## Against MRPT's SLAM apps\n\n" + markdown(table2, 2)
    timing_scans = next((r["scans"] for r in carmen if r["log"] == args.timing_log), 0)
    if comparison.timing and timing_scans:
        text += "\n## Pose-estimation stages on %s (%d scans)\n\n" % (args.timing_log, timing_scans)
        text += markdown(timing_table(comparison.timing, timing_scans))
    write_text(os.path.join(args.out, "tables.md"), text)
    print(text)


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--datasets", default=os.path.join(REPO, "..", "shared", "datasets", "carmen"),
                   help="folder with <log>-corrected.log.gz")
    p.add_argument("--samples-dir", default=os.path.join(REPO, "rawlog_samples"))
    p.add_argument("--out", default=os.path.join(REPO, "results", "compare"))
    p.add_argument("--bin", default=os.path.join(REPO, "build", "bin"))
    p.add_argument("--config", default=os.path.join(REPO, "config_ini", "hslam-default.ini"))
    p.add_argument("--logs", default="intel,aces,csail")
    p.add_argument("--samples", default="corridor,floor,lab,umbmark")
    p.add_argument("--methods", default=",".join(HSLAM_METHODS), help="our pose-estimation methods to run")
    p.add_argument("--timing-log", default="intel", help="log whose stage timing makes table 3")
    p.add_argument("--timeout", type=int, default=3600, help="time limit per run, s")
    p.add_argument("--rbpf-seed", default="1", help='rbpf-slam RANDOM_SEED ("random": MRPT\'s time-based seed)')
    args = p.parse_args(argv)
    args.logs = [s for s in args.logs.split(",") if s]
    args.samples = [s for s in args.samples.split(",") if s]
    args.methods = [s for s in args.methods.split(",") if s]
    for key in ("datasets", "samples_dir", "out", "bin", "config"):
        setattr(args, key, os.path.abspath(getattr(args, key)))  # MRPT configs need absolute paths
    return args


def main(argv):
    args = parse_args(argv)
    try:
        check_inputs(args)
        os.makedirs(args.out, exist_ok=True)
        freeze_inputs(args)
        comparison = Comparison(args)
        comparison.bin = os.path.join(args.out, "bin")
        start = time.monotonic()
        for log in args.logs:
            comparison.run_carmen_log(log)
        for name in args.samples:
            comparison.run_sample(name)
        write_tables(comparison, args)
        say("total %d s; tables in %s/tables.md" % (time.monotonic() - start, args.out))
        return 0
    except (CompareError, subprocess.CalledProcessError, OSError) as e:
        print("compare_slam: error: %s" % e, file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
