#!/usr/bin/env python3
"""Summarize the report.json files of several luxplan optimize runs, per group.

Usage:
    python3 scripts/report_table.py --group hierarchical out/fig6/S/hierarchical-*/report.json \
                                    --group flat out/fig6/S/flat-*/report.json

Prints a Markdown table: runs, runs with a feasible layout, the re-measured C of the
best layout (report_paths_per_point paths per point: mean, median, min, max over the
feasible runs), how many runs stopped at a confirmed C = 0, and the mean iterations
and seconds. Python 3 standard library only.
"""

import argparse
import json
import statistics
import sys


def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--group", nargs="+", action="append", metavar=("NAME", "REPORT"), required=True)
    a = p.parse_args(argv)
    print("| group | runs | feasible | re-measured C: mean | median | min | max | stopped at C = 0 | iterations (mean) | seconds (mean) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for name, *files in a.group:
        reports = [json.load(open(f)) for f in files]
        costs = [r["C"] for r in reports if r.get("feasible")]
        zero = sum(1 for r in reports if r.get("stop_reason") == "zero_cost")
        iters = statistics.mean(r["iterations"] for r in reports)
        secs = statistics.mean(r["seconds"] for r in reports)
        if costs:
            print("| %s | %d | %d | %.4f | %.4f | %.4f | %.4f | %d | %.0f | %.1f |" % (
                name, len(reports), len(costs), statistics.mean(costs), statistics.median(costs),
                min(costs), max(costs), zero, iters, secs))
        else:
            print("| %s | %d | 0 | – | – | – | – | %d | %.0f | %.1f |" % (name, len(reports), zero, iters, secs))
    return 0


if __name__ == "__main__":
    sys.exit(main())
