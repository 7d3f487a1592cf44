#!/usr/bin/env python3
"""The paper's event hall by day (scenes/paper/fig10-event-hall-day.json) over seeds and
times of day, on a dask.distributed cluster through luxplan.batch: each seed's layout
optimized for the scene's own period, then measured again at each time of day with a
seed no search used; a table of C and tables in range per seed and time.

    PYTHONPATH=build/python /usr/bin/python3 examples/event_hall_sweep.py \\
        [--seeds 1,2,3,4] [--times 10:00,12:30,15:00] [--iterations N] [--scheduler ADDRESS] [--out out/hall-sweep]

Without --scheduler it starts a LocalCluster of one worker per core (docs/python.md
says how to run it on several machines). Writes OUT/table.md and OUT/seed-N/ (each
run's layout.json, report.json, trace.csv).
"""
import argparse
import os

import distributed

import luxplan

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
SCENE = os.path.join(ROOT, "scenes", "paper", "fig10-event-hall-day.json")
DAY = "2026-12-15"   # the scene's day
OFFSET = "+02:00"    # its time zone
REMEASURE = 500000   # the re-measure's seed: the run's + this


def in_range(sampler):
    low, high = sampler["target"]
    return (low is None or sampler["value"] >= low) and (high is None or sampler["value"] <= high)


def sweep(client, seeds, times, iterations, out):
    runs = [{"command": "optimize", "scene": SCENE, "seed": s, "out": os.path.join(out, f"seed-{s}")} for s in seeds]
    if iterations is not None:
        for job in runs:
            job["iterations"] = iterations
    optimized = luxplan.batch(runs, client)
    measures, keys = [], []
    for seed, result in zip(seeds, optimized):
        if isinstance(result, luxplan.JobError):
            print(f"seed {seed}: {result}")
            continue
        for t in times:
            measures.append({"command": "measure", "scene": SCENE, "layout": result["layout"], "at": f"{DAY}T{t}{OFFSET}",
                             "seed": seed + REMEASURE, "paths": 512})
            keys.append((seed, t))
    measured = dict(zip(keys, luxplan.batch(measures, client)))
    lines = [f"# The event hall over the day ({DAY}, {OFFSET})", "",
             "Each seed's layout optimized for the scene's period, measured again at each time with seed + "
             f"{REMEASURE}: C, and the tables whose illuminance lies in their target.", "",
             "| seed | " + " | ".join(times) + " |", "|---|" + "---|" * len(times)]
    for seed in seeds:
        cells = []
        for t in times:
            m = measured.get((seed, t))
            if m is None or isinstance(m, luxplan.JobError):
                cells.append("failed")
                continue
            tables = [s for s in m["samplers"] if s["type"] == "planar"]
            cells.append(f"C {m['C']:.3f}, {sum(in_range(s) for s in tables)} of {len(tables)} tables")
        lines.append(f"| {seed} | " + " | ".join(cells) + " |")
    os.makedirs(out, exist_ok=True)
    with open(os.path.join(out, "table.md"), "w", encoding="utf-8") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    print(f"\nwrote {os.path.join(out, 'table.md')}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seeds", default="1,2,3,4")
    ap.add_argument("--times", default="10:00,12:30,15:00")
    ap.add_argument("--iterations", type=int, help="the search's (default: the scene's)")
    ap.add_argument("--scheduler", help="a dask scheduler's address (default: a LocalCluster)")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "hall-sweep"))
    args = ap.parse_args()
    seeds = [int(s) for s in args.seeds.split(",") if s]
    times = [t for t in args.times.split(",") if t]
    if args.scheduler:
        with distributed.Client(args.scheduler) as client:
            sweep(client, seeds, times, args.iterations, args.out)
    else:
        with distributed.LocalCluster(n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True,
                                      dashboard_address=":0") as cluster, distributed.Client(cluster) as client:
            sweep(client, seeds, times, args.iterations, args.out)


if __name__ == "__main__":
    main()
