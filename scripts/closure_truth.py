#!/usr/bin/env python3
"""closure_truth.py: loop closures of a run judged against ground truth.

For an hslam-process output folder run with the loop-closure back-end, and
the ground truth (or a reference trajectory) in TUM format, prints:

  * every accepted closure's error: the measured pose of the query keyframe
    in the anchor's frame (loop_closures.csv rel_x_m, rel_y_m, rel_yaw_deg)
    against the same relative pose from the truth; a closure beyond
    --bad-xy-m or --bad-yaw-deg is "bad" (issue 13: 0.2 m, 2 deg);
  * the recall of true revisits: a scan revisits when the truth was within
    --revisit-radius-m of it earlier, at least --revisit-min-path-m of travel
    before; consecutive revisiting scans form a revisit pass; a pass is
    closed when an accepted closure's query keyframe lies in it. A pass is
    cut into pieces of --revisit-segment-m of travel (a ring driven three
    times is one long pass: each 10 m of it should see a closure).

Keyframe ids are scan indices (rows of pose_estimates.csv, whose t_s gives
each scan's time); truth poses are taken at the nearest truth stamp within
--max-dt-s. Standard library only.

Usage: scripts/closure_truth.py RUN_DIR TRUTH.tum [--list-bad] [options]
Prints key=value lines (closures_accepted=, closures_without_truth=,
closures_bad=, worst_xy_m=,
worst_yaw_deg=, revisit_passes=, revisit_passes_closed=, revisit_recall=).
Exit status 2 with a message naming the file on unreadable input.
"""
import argparse
import bisect
import csv
import math
import sys


class InputError(Exception):
    pass


def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def read_tum(path):
    """[(t, x, y, yaw)] sorted by t."""
    poses = []
    try:
        with open(path) as f:
            for number, line in enumerate(f, 1):
                if not line.strip() or line.lstrip().startswith('#'):
                    continue
                v = line.split()
                if len(v) != 8:
                    raise InputError(f"{path}:{number}: expected 8 fields (t x y z qx qy qz qw), got {len(v)}")
                t, x, y, _, qx, qy, qz, qw = map(float, v)
                yaw = math.atan2(2 * (qw * qz + qx * qy), 1 - 2 * (qy * qy + qz * qz))
                poses.append((t, x, y, yaw))
    except (OSError, ValueError) as e:
        raise InputError(f"{path}: {e}")
    if not poses:
        raise InputError(f"{path}: no poses")
    return sorted(poses)


def read_csv(path, columns):
    try:
        with open(path, newline='') as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        raise InputError(f"{path}: {e}")
    if rows and any(c not in rows[0] for c in columns):
        missing = [c for c in columns if c not in rows[0]]
        raise InputError(f"{path}: missing column(s) {', '.join(missing)}")
    return rows


class Truth:
    def __init__(self, poses, max_dt_s):
        self.poses, self.stamps, self.max_dt_s = poses, [p[0] for p in poses], max_dt_s

    def at(self, t):
        i = bisect.bisect_left(self.stamps, t)
        near = [k for k in (i - 1, i) if 0 <= k < len(self.stamps)]
        k = min(near, key=lambda k: abs(self.stamps[k] - t))
        return self.poses[k][1:] if abs(self.stamps[k] - t) <= self.max_dt_s else None


def relative(a, b):
    """b in the frame of a, both (x, y, yaw)."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return c * dx + s * dy, -s * dx + c * dy, wrap(b[2] - a[2])


def closure_errors(closures, scan_truth):
    """[(query, anchor, xy_m, yaw_deg)] of the accepted closures with truth at
    both ends, and how many accepted closures had none."""
    out, without_truth = [], 0
    for line, c in enumerate(closures, 2):
        if c['accepted'] != '1':
            continue
        try:
            q, a = int(c['query_keyframe']), int(c['anchor_keyframe'])
            measured = (float(c['rel_x_m']), float(c['rel_y_m']), math.radians(float(c['rel_yaw_deg'])))
        except (TypeError, ValueError) as e:
            raise InputError(f"loop_closures.csv:{line}: {e}")
        if not (0 <= q < len(scan_truth) and 0 <= a < len(scan_truth)):
            raise InputError(f"loop_closures.csv:{line}: keyframe {q} or {a} is not a scan of pose_estimates.csv")
        tq, ta = scan_truth[q], scan_truth[a]
        if tq is None or ta is None:
            without_truth += 1
            continue
        true_rel = relative(ta, tq)
        xy = math.hypot(true_rel[0] - measured[0], true_rel[1] - measured[1])
        out.append((q, a, xy, abs(math.degrees(wrap(true_rel[2] - measured[2])))))
    return out, without_truth


def revisit_passes(scan_truth, radius_m, min_path_m, segment_m):
    """[[scan indices]] of the runs of revisiting scans, each at most segment_m of travel."""
    travelled, cells, passes = 0.0, {}, []
    previous, run = None, []
    cumulative = []
    for i, p in enumerate(scan_truth):
        if p is not None and previous is not None:
            travelled += math.hypot(p[0] - previous[0], p[1] - previous[1])
        cumulative.append(travelled)
        revisits = False
        if p is not None:
            cx, cy = math.floor(p[0] / radius_m), math.floor(p[1] / radius_m)
            for nx in (cx - 1, cx, cx + 1):
                for ny in (cy - 1, cy, cy + 1):
                    for j in cells.get((nx, ny), ()):
                        q = scan_truth[j]
                        if travelled - cumulative[j] >= min_path_m and math.hypot(p[0] - q[0], p[1] - q[1]) <= radius_m:
                            revisits = True
                            break
            cells.setdefault((cx, cy), []).append(i)
            previous = p
        if revisits and run and travelled - cumulative[run[0]] >= segment_m:
            passes.append(run)
            run = []
        if revisits:
            run.append(i)
        elif run:
            passes.append(run)
            run = []
    if run:
        passes.append(run)
    return passes


def evaluate(run_dir, truth_path, args):
    truth = Truth(read_tum(truth_path), args.max_dt_s)
    scans = read_csv(f"{run_dir}/pose_estimates.csv", ['t_s'])
    closures = read_csv(f"{run_dir}/loop_closures.csv",
                        ['query_keyframe', 'anchor_keyframe', 'accepted', 'rel_x_m', 'rel_y_m', 'rel_yaw_deg'])
    try:
        scan_truth = [truth.at(float(r['t_s'])) for r in scans]
    except ValueError as e:
        raise InputError(f"{run_dir}/pose_estimates.csv: {e}")
    errors, without_truth = closure_errors(closures, scan_truth)
    if without_truth and not errors:
        raise InputError(f"{truth_path}: no truth pose within {args.max_dt_s} s of any accepted closure's keyframes "
                         "(another run's truth?)")
    bad = [e for e in errors if e[2] > args.bad_xy_m or e[3] > args.bad_yaw_deg]
    passes = revisit_passes(scan_truth, args.revisit_radius_m, args.revisit_min_path_m, args.revisit_segment_m)
    accepted_queries = {int(c['query_keyframe']) for c in closures if c['accepted'] == '1'}
    closed = sum(1 for run in passes if accepted_queries.intersection(run))
    return errors, without_truth, bad, passes, closed


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split('\n\n')[0])
    ap.add_argument('run_dir')
    ap.add_argument('truth')
    ap.add_argument('--bad-xy-m', type=float, default=0.2)
    ap.add_argument('--bad-yaw-deg', type=float, default=2.0)
    ap.add_argument('--revisit-radius-m', type=float, default=2.0)
    ap.add_argument('--revisit-min-path-m', type=float, default=20.0)
    ap.add_argument('--revisit-segment-m', type=float, default=10.0)
    ap.add_argument('--max-dt-s', type=float, default=0.1)
    ap.add_argument('--list-bad', action='store_true', help='print each bad closure')
    args = ap.parse_args(argv)
    try:
        errors, without_truth, bad, passes, closed = evaluate(args.run_dir, args.truth, args)
    except InputError as e:
        print(f"closure_truth.py: error: {e}", file=sys.stderr)
        return 2
    if args.list_bad:
        for q, a, xy, yaw in bad:
            print(f"bad closure query={q} anchor={a} error_xy_m={xy:.3f} error_yaw_deg={yaw:.2f}")
    print(f"closures_accepted={len(errors)}")
    print(f"closures_without_truth={without_truth}")
    print(f"closures_bad={len(bad)}")
    print(f"worst_xy_m={max((e[2] for e in errors), default=0):.3f}")
    print(f"worst_yaw_deg={max((e[3] for e in errors), default=0):.2f}")
    print(f"revisit_passes={len(passes)}")
    print(f"revisit_passes_closed={closed}")
    print(f"revisit_recall={closed / len(passes) if passes else float('nan'):.3f}")
    return 0


if __name__ == '__main__':
    sys.exit(main())
