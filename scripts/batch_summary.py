#!/usr/bin/env python3
"""Collects the summary.json of every run of a batch (scripts/batch-process.sh)
into OUT_ROOT/summary.csv and OUT_ROOT/summary.md (one row per manifest line,
in manifest order, linking each run's report.html). A run without summary.json
(crashed, or stopped before writing) is listed with its exit code and the last
line of its log. Exit code 1 if any run did not exit 0."""
import csv
import json
import os
import sys

COLUMNS = ["name", "exit_code", "scans", "ms_per_scan", "wall_s", "ate_rmse_m", "ate_online_rmse_m",
           "closures_accepted", "warnings", "report"]


def last_log_line(run_dir):
    try:
        with open(os.path.join(run_dir, "log.txt"), encoding="utf-8", errors="replace") as f:
            lines = [line.strip() for line in f if line.strip()]
        return lines[-1] if lines else ""
    except OSError:
        return "no log.txt"


def row_of(out_root, name):
    run_dir = os.path.join(out_root, name)
    row = {"name": name, "exit_code": "not run", "scans": "", "ms_per_scan": "", "wall_s": "",
           "ate_rmse_m": "", "ate_online_rmse_m": "", "closures_accepted": "", "warnings": "", "report": ""}
    try:
        with open(os.path.join(run_dir, "exit_code")) as f:
            row["exit_code"] = f.read().strip()
    except OSError:
        pass
    try:
        with open(os.path.join(run_dir, "summary.json"), encoding="utf-8") as f:
            s = json.load(f)
    except (OSError, ValueError):
        row["warnings"] = "no summary.json: " + last_log_line(run_dir)
        return row
    row.update(scans=s["scans"], ms_per_scan=f"{s['ms_per_scan']:.2f}", wall_s=f"{s['wall_s']:.1f}",
               ate_rmse_m="" if s["ate_rmse_m"] is None else f"{s['ate_rmse_m']:.3f}",
               warnings="; ".join(s["warnings"]), report=f"{name}/report.html")
    loop = s.get("loop_closure")  # null with the back-end off
    if loop:
        online = loop["ate_online_rmse_m"]
        row.update(ate_online_rmse_m="" if online is None else f"{online:.3f}",
                   closures_accepted=loop["closures_accepted"])
    return row


def main(out_root):
    with open(os.path.join(out_root, "manifest.tsv"), encoding="utf-8") as f:
        names = [line.split("\t")[0] for line in f if line.strip()]
    rows = [row_of(out_root, name) for name in names]
    with open(os.path.join(out_root, "summary.csv"), "w", newline="", encoding="utf-8") as f:
        writer = csv.DictWriter(f, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    wall = ""
    if os.path.exists(os.path.join(out_root, "batch_wall_s")):
        with open(os.path.join(out_root, "batch_wall_s")) as f:
            wall = f" Batch wall time {f.read().strip()} s."
    md = [f"# Batch summary\n\n{len(rows)} runs.{wall} Columns: laser scans used, wall time per scan "
          "(outputs included), run wall time, ATE RMSE against the reference (if given) after and before "
          "the pose graph, loop closures accepted, warnings.\n",
          "| run | exit | scans | ms/scan | wall s | ATE RMSE m | ATE before graph m | closures | warnings | report |",
          "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | --- | --- |"]
    for r in rows:
        link = f"[report]({r['report']})" if r["report"] else ""
        warnings = r["warnings"].replace("|", "\\|")
        md.append(f"| {r['name']} | {r['exit_code']} | {r['scans']} | {r['ms_per_scan']} | {r['wall_s']} | "
                  f"{r['ate_rmse_m']} | {r['ate_online_rmse_m']} | {r['closures_accepted']} | {warnings} | {link} |")
    with open(os.path.join(out_root, "summary.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md[1:]))
    print(f"\nTable: {out_root}/summary.csv and {out_root}/summary.md")
    return 0 if all(r["exit_code"] == "0" for r in rows) else 1


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: batch_summary.py OUT_ROOT")
    sys.exit(main(sys.argv[1]))
