#!/usr/bin/env python3
"""Tests of scripts/batch-process.sh with the real hslam-process
(HSLAM_PROCESS) on the shipped lab sample: every run of a manifest is
written and summarised, a second batch into the same folder works, and runs
sharing the cores are single-threaded (-j > 1) while a lone run is not."""
import csv
import os
import subprocess
import tempfile
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
SCRIPT = os.path.join(ROOT, "scripts", "batch-process.sh")
LAB = os.path.join(ROOT, "rawlog_samples", "lab")


def batch(manifest_lines, out, jobs):
    manifest = os.path.join(os.path.dirname(out), "manifest.txt")
    with open(manifest, "w") as f:
        f.write("".join(line + "\n" for line in manifest_lines))
    return subprocess.run(["bash", SCRIPT, manifest, out, "-j", str(jobs), "--", "--set", "output.write_tiles=false"],
                          capture_output=True, text=True, timeout=300)


def setting(run_dir, key):
    with open(os.path.join(run_dir, "config_used.ini")) as f:
        for line in f:
            if line.split("=")[0].strip() == key:
                return line.split("=", 1)[1].strip()
    return None


class BatchProcess(unittest.TestCase):
    def test_runs_summarises_and_reruns(self):
        rawlog, truth = os.path.join(LAB, "sim.rawlog"), os.path.join(LAB, "ground_truth.tum")
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "out")
            lines = [f"first {rawlog} {truth}", f"second {rawlog} {truth}"]
            for attempt in range(2):  # the second batch goes into the folder the first wrote
                r = batch(lines, out, 2)
                self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
                with open(os.path.join(out, "summary.csv")) as f:
                    rows = list(csv.DictReader(f))
                self.assertEqual([row["name"] for row in rows], ["first", "second"])
                for row in rows:
                    self.assertEqual(row["exit_code"], "0", f"attempt {attempt}: {row}")
                    self.assertLess(float(row["ate_rmse_m"]), 0.05)  # lab: about 0.01 m
                    # the back-end's figures: the ATE before the graph, closures accepted
                    self.assertLess(float(row["ate_online_rmse_m"]), 0.1)
                    self.assertGreater(int(row["closures_accepted"]), 10)  # lab: about 70
                    run = os.path.join(out, row["name"])
                    self.assertTrue(os.path.exists(os.path.join(run, "trajectory.tum")))
                    self.assertTrue(os.path.exists(os.path.join(run, "log.txt")))
                    # two runs share the cores: one thread each
                    self.assertEqual(setting(run, "background_thread"), "false")
                    self.assertEqual(setting(run, "parallel_restarts"), "false")
            alone = os.path.join(tmp, "alone")
            r = batch([f"only {rawlog} {truth}"], alone, 1)
            self.assertEqual(r.returncode, 0, r.stdout + r.stderr)
            self.assertEqual(setting(os.path.join(alone, "only"), "background_thread"), "true")


if __name__ == "__main__":
    unittest.main()
