#!/usr/bin/env python3
"""Tests of scripts/compare_slam.py: the path conversions of MRPT's outputs,
the config rewriting and the tables, on hand-made inputs with hand-derived
numbers."""
import math
import os
import sys
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import compare_slam as cs  # noqa: E402


class PoseAlgebra(unittest.TestCase):
    def test_compose_and_relative_are_inverse(self):
        a, d = (1.0, 2.0, math.pi / 2), (0.5, 0.0, 0.1)
        b = cs.compose(a, d)
        # Heading +90 deg: 0.5 m forward is +y.
        self.assertAlmostEqual(b[0], 1.0)
        self.assertAlmostEqual(b[1], 2.5)
        self.assertAlmostEqual(b[2], math.pi / 2 + 0.1)
        for got, want in zip(cs.relative(a, b), d):
            self.assertAlmostEqual(got, want)

    def test_angles_wrap(self):
        self.assertAlmostEqual(cs.compose((0, 0, 3.0), (0, 0, 0.5))[2], 3.5 - 2 * math.pi)

    def test_tum_round_trip(self):
        rows = [(1.5, 1.0, -2.0, 0.3), (2.5, 1.1, -2.1, -3.0)]
        back = cs.tum_rows(cs.tum_text(rows).splitlines())
        for r, b in zip(rows, back):
            for x, y in zip(r, b):
                self.assertAlmostEqual(x, y, places=6)


class MrptOutputs(unittest.TestCase):
    LISTING = ["10.0 ODOMETRY mrpt::obs::CObservationOdometry",
               "10.0 LASER mrpt::obs::CObservation2DRangeScan",
               "10.5 mrpt::obs::CObservationComment",
               "11.0 LASER mrpt::obs::CObservation2DRangeScan",
               "11.0 REAR_LASER mrpt::obs::CObservation2DRangeScan"]

    def test_listing_with_and_without_labels(self):
        listing = cs.read_listing(self.LISTING)
        self.assertEqual(listing[2], (10.5, "", "mrpt::obs::CObservationComment"))
        self.assertEqual(cs.scan_entries(listing, "LASER"), [(1, 10.0), (3, 11.0)])

    def test_icp_path_gives_the_pose_after_each_scan_entry(self):
        listing = cs.read_listing(self.LISTING)
        path = cs.numeric_rows(["% step x y yaw", "1 0.1 0.2 0.3", "2 9 9 9", "3 1.1 1.2 1.3"])
        self.assertEqual(cs.icp_scan_poses(path, listing, "LASER"),
                         [(10.0, 0.1, 0.2, 0.3), (11.0, 1.1, 1.2, 1.3)])

    def test_rbpf_steps_without_update_follow_odometry(self):
        log = ["---------------- STEP 0 ----", "New pose=[0 0 0]", "--- STEP 1 ---",
               "--- STEP 2 ---", "[INFO] New pose=[1 0 0]"]
        updated = cs.rbpf_updated_steps(log, 3)
        self.assertEqual(updated, [True, False, True])
        odometry = [(0.0, 0, 0, 0), (1.0, 0.5, 0, math.pi / 2), (2.0, 0.5, 1.0, math.pi / 2)]
        path = [[0, 0, 0], [0.1, 0.0, 0.0], [3.0, 4.0, 0.5]]
        rows = cs.rbpf_scan_poses(path, updated, odometry)
        self.assertEqual(rows[0], (0.0, 0.1, 0.0, 0.0))
        # Step 1: from (0.1, 0, 0) the odometry increment (0.5, 0, +90 deg).
        self.assertAlmostEqual(rows[1][1], 0.6)
        self.assertAlmostEqual(rows[1][2], 0.0)
        self.assertAlmostEqual(rows[1][3], math.pi / 2)
        self.assertEqual(rows[2], (2.0, 3.0, 4.0, 0.5))

    def test_odometry_per_scan_keeps_the_pose_at_a_gap(self):
        exported = [[10.0, 1.0, 2.0, 0.5, 0, 0, 0, 1], [12.0, 1.5, 2.0, 0.5, 0, 0, 0, 1]]
        rows = cs.odometry_per_scan(exported, [10.0, 11.0, 12.0])
        self.assertEqual(rows, [(10.0, 1.0, 2.0, 0.5), (11.0, 1.0, 2.0, 0.5), (12.0, 1.5, 2.0, 0.5)])

    def test_rbpf_path_and_log_that_disagree_are_an_error(self):
        with self.assertRaises(cs.CompareError):
            cs.rbpf_scan_poses([[0, 0, 0]], [True], [(0.0, 0, 0, 0)])

    def test_config_keeps_stock_values_and_marks_changes(self):
        stock = "[Other]\nrawlog_file=x\n[MappingApplication]\nrawlog_file=stock.rawlog\nSAVE_3D_SCENE=1\n"
        text = cs.mrpt_ini_with(stock, {"rawlog_file": "/d/a.rawlog", "RANDOM_SEED": "1"})
        lines = text.splitlines()
        self.assertEqual(lines[1], "rawlog_file=x")  # other sections untouched
        self.assertEqual(lines[3], "RANDOM_SEED=1   // added by compare_slam.py")
        self.assertTrue(lines[4].startswith("rawlog_file=/d/a.rawlog   // changed"))
        self.assertIn("(stock: stock.rawlog)", lines[4])
        self.assertEqual(lines[5], "SAVE_3D_SCENE=1")
        with self.assertRaises(cs.CompareError):
            cs.mrpt_ini_with("[A]\nx=1\n", {"x": "2"})


class Tables(unittest.TestCase):
    @staticmethod
    def run_record(log, method, ate, wall_s=1.0, scans=100, matched=100):
        ev = {"ate_rmse_m": ate, "rpe_consecutive_trans_rmse_m": 0.05, "rpe_consecutive_rot_rmse_deg": 1.5,
              "rpe_1m_trans_rmse_m": 0.07, "matched": matched, "reference_poses": 100}
        return {"log": log, "method": method, "scans": scans, "wall_s": wall_s, "cpu_s": wall_s / 2, "eval": ev,
                "note": ""}

    def test_comparison_rows_times_and_notes(self):
        runs = [self.run_record("x", "odometry", 2.0), self.run_record("x", "lines", 3.0, matched=90),
                {"log": "x", "method": "mrpt rbpf-slam", "scans": 100, "eval": None, "note": "crashed"}]
        table = cs.comparison_table(runs)
        self.assertEqual(table[0][2], "ATE RMSE (m)")
        self.assertEqual(table[1][2:8], ["2.000", "0.0500", "1.500", "0.0700", "10.00", "5.00"])
        self.assertEqual(table[2][-1], "90/100 poses matched; ATE worse than odometry")
        self.assertEqual(table[3][2:], ["-"] * 6 + ["crashed"])

    def test_ate_table_three_significant_digits(self):
        runs = [self.run_record("intel", m, a) for m, a in zip(cs.HSLAM_METHODS, [24.017, 13.438, 1.039, 0.0066])]
        table = cs.ate_table(runs, ["intel", "aces"])
        self.assertEqual(table[1], ["intel", "24.02", "13.44", "1.04", "0.00660", "-"])
        self.assertEqual(table[2], ["aces", "-", "-", "-", "-", "-"])

    def test_timing_table_per_scan(self):
        csv_lines = ["stage,count,mean_ms,p95_ms,max_ms,total_ms", "icp,50,2.0,3,4,100", "ukf,100,0.01,0,0,3",
                     "pose_estimation,100,1,1,1,110"]
        totals = {"icp": cs.read_timing_csv(csv_lines)}
        table = cs.timing_table(totals, 50)
        self.assertEqual(table[0], ["stage", "lines", "icp", "lines+icp", "default"])
        rows = {r[0]: r for r in table[1:]}
        self.assertEqual(rows["icp"][2], "2.00 ms")
        self.assertEqual(rows["ukf"][2], "0.06 ms")
        self.assertEqual(rows["whole pose_estimation"][2], "2.20 ms")
        self.assertEqual(rows["line_extraction"][1:], ["-", "-", "-", "-"])

    def test_front_ends_run_without_the_back_end_and_the_default_as_shipped(self):
        self.assertEqual(cs.hslam_overrides("icp"),
                         ["--set", "pose_estimation.method=icp", "--set", "loop_closure.enabled=false"])
        self.assertEqual(cs.hslam_overrides(cs.DEFAULT_METHOD), [])

    def test_markdown_alignment(self):
        text = cs.markdown([["log", "method", "v", "notes"], ["a", "b", "1", ""]], 2)
        self.assertEqual(text.splitlines()[1], "|---|---|---:|---|")


class CommandLine(unittest.TestCase):
    def test_missing_programs_are_a_clear_error(self):
        code = cs.main(["--bin", "/nonexistent", "--logs", "intel", "--samples", ""])
        self.assertEqual(code, 1)


if __name__ == "__main__":
    unittest.main()
