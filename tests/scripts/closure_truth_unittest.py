#!/usr/bin/env python3
"""Tests of scripts/closure_truth.py on a hand-made run: a 10 x 10 m square
driven twice, a scan every metre, with closures whose errors are known."""
import contextlib
import io
import math
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import closure_truth as ct  # noqa: E402

HEADER = "query_keyframe,anchor_keyframe,accepted,reason,rel_x_m,rel_y_m,rel_yaw_deg\n"


def square_pose(i):
    """Scan i at i metres along the square's perimeter (40 m), heading along it."""
    s = i % 40
    side, along = divmod(s, 10)
    corners = [(0, 0), (10, 0), (10, 10), (0, 10)]
    directions = [(1, 0), (0, 1), (-1, 0), (0, -1)]
    (x0, y0), (dx, dy) = corners[side], directions[side]
    return x0 + along * dx, y0 + along * dy, math.atan2(dy, dx)


def write_run(folder, closure_rows, header=HEADER):
    with open(os.path.join(folder, "truth.tum"), "w") as f:
        f.write("# timestamp tx ty tz qx qy qz qw\n")
        for i in range(80):
            x, y, yaw = square_pose(i)
            f.write(f"{i} {x} {y} 0 0 0 {math.sin(yaw / 2)} {math.cos(yaw / 2)}\n")
    with open(os.path.join(folder, "pose_estimates.csv"), "w") as f:
        f.write("t_s,x_m,y_m,theta_rad\n")
        for i in range(80):
            f.write(f"{i},0,0,0\n")
    with open(os.path.join(folder, "loop_closures.csv"), "w") as f:
        f.write(header + "".join(closure_rows))


def run(folder, *extra):
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        status = ct.main([folder, os.path.join(folder, "truth.tum"), "--revisit-radius-m", "0.5", *extra])
    return status, dict(line.split("=") for line in out.getvalue().split())


def run_failing(folder):
    """(exit status, stderr) of a run with default options."""
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        status = ct.main([folder, os.path.join(folder, "truth.tum")])
    return status, err.getvalue()


class ClosureTruth(unittest.TestCase):
    def test_errors_bad_closures_and_revisit_recall(self):
        with tempfile.TemporaryDirectory() as d:
            # scan q revisits scan q - 40 exactly: the true relative pose is 0
            write_run(d, ["45,5,1,accepted,0,0,0\n",          # exact
                          "65,25,1,accepted,0.1,0,3\n",       # 3 deg off: bad
                          "75,35,1,accepted,0.25,0,0\n",      # 0.25 m off: bad
                          "55,15,0,low score,5,0,0\n"])       # rejected: ignored
            status, r = run(d)
            self.assertEqual(status, 0)
            self.assertEqual(r["closures_accepted"], "3")
            self.assertEqual(r["closures_without_truth"], "0")
            self.assertEqual(r["closures_bad"], "2")
            self.assertAlmostEqual(float(r["worst_xy_m"]), 0.25, places=3)
            self.assertAlmostEqual(float(r["worst_yaw_deg"]), 3.0, places=2)
            # the second lap (scans 40-79) revisits; 10 m pieces: 40-49,
            # 50-59, 60-69, 70-79; closures at 45, 65, 75 close three
            self.assertEqual(r["revisit_passes"], "4")
            self.assertEqual(r["revisit_passes_closed"], "3")
            self.assertAlmostEqual(float(r["revisit_recall"]), 0.75)

    def test_a_missing_column_names_the_file(self):
        with tempfile.TemporaryDirectory() as d:
            write_run(d, ["45,5,1,accepted,0,0\n"], header="query_keyframe,anchor_keyframe,accepted,reason,rel_x_m,rel_y_m\n")
            status, err = run_failing(d)
            self.assertEqual(status, 2)
            self.assertIn("loop_closures.csv", err)
            self.assertIn("rel_yaw_deg", err)

    def test_a_truth_of_another_run_is_an_error(self):
        with tempfile.TemporaryDirectory() as d:
            write_run(d, ["45,5,1,accepted,0,0,0\n"])
            with open(os.path.join(d, "truth.tum"), "w") as f:
                f.write("1000 0 0 0 0 0 0 1\n1001 1 0 0 0 0 0 1\n")
            status, err = run_failing(d)
            self.assertEqual(status, 2)
            self.assertIn("truth.tum", err)

    def test_an_unreadable_number_names_the_line(self):
        with tempfile.TemporaryDirectory() as d:
            write_run(d, ["45,5,1,accepted,0,zero,0\n"])
            status, err = run_failing(d)
            self.assertEqual(status, 2)
            self.assertIn("loop_closures.csv:2", err)

    def test_a_keyframe_outside_the_run_is_an_error(self):
        with tempfile.TemporaryDirectory() as d:
            write_run(d, ["95,5,1,accepted,0,0,0\n"])
            status, _ = run(d)
            self.assertEqual(status, 2)


if __name__ == "__main__":
    unittest.main()
