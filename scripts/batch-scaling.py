#!/usr/bin/env python3
"""How luxplan.batch scales on this machine (docs/python.md, "Scaling").

    PYTHONPATH=build/python /usr/bin/python3 scripts/batch-scaling.py [--jobs 8] [--iterations 3000]
        [--scene scenes/paper/fig4-presenter.json] [--tiny 40]

1. JOBS optimize runs of SCENE (seeds 1..JOBS, one thread each): the CLI one after the
   other, against luxplan.batch on a LocalCluster of 2 single-threaded worker processes
   (the cluster's start counted), as the ratio of their wall times.
2. The cluster's cost per job: TINY measurements of one path per point through batch,
   against the same calls in this process: (batch wall x workers - the calls' own
   seconds) / TINY.
"""
import argparse
import os
import subprocess
import tempfile
import time
import warnings

import distributed

import luxplan

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--jobs", type=int, default=8)
    ap.add_argument("--iterations", type=int, default=3000)
    ap.add_argument("--scene", default="scenes/paper/fig4-presenter.json")
    ap.add_argument("--tiny", type=int, default=40)
    ap.add_argument("--luxplan", default=os.path.join(ROOT, "build", "luxplan"))
    args = ap.parse_args()
    warnings.simplefilter("ignore", luxplan.SceneWarning)  # one path per point, meant
    os.chdir(ROOT)
    seeds = range(1, args.jobs + 1)
    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.monotonic()
        for s in seeds:
            subprocess.run([args.luxplan, "optimize", args.scene, "-o", os.path.join(tmp, f"cli-{s}"), "--iterations",
                            str(args.iterations), "--paths", "4", "--seed", str(s), "--threads", "1", "-q", "--no-pictures"],
                           check=True, capture_output=True)
        serial = time.monotonic() - t0
        jobs = [{"command": "optimize", "scene": args.scene, "iterations": args.iterations, "paths": 4, "seed": s}
                for s in seeds]
        t0 = time.monotonic()
        with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
                distributed.Client(cluster) as client:
            started = time.monotonic() - t0
            results = luxplan.batch(jobs, client)
            clustered = time.monotonic() - t0
            failed = [r for r in results if isinstance(r, luxplan.JobError)]
            if failed:
                raise SystemExit(f"batch-scaling.py: {failed[0]}")

            tiny = [{"command": "measure", "scene": args.scene, "paths": 1, "seed": k} for k in range(args.tiny)]
            t0 = time.monotonic()
            luxplan.batch(tiny, client)
            tiny_batch = time.monotonic() - t0
    scene = luxplan.Scene(args.scene)
    t0 = time.monotonic()
    for k in range(args.tiny):
        scene.measure(paths=1, seed=k, threads=1)
    tiny_local = time.monotonic() - t0
    print(f"{args.jobs} optimize runs of {args.scene} at {args.iterations} iterations, one thread each:")
    print(f"  the CLI one after the other: {serial:.1f} s")
    print(f"  luxplan.batch on a LocalCluster of 2 worker processes: {clustered:.1f} s "
          f"(the cluster's start {started:.1f} s of it)")
    print(f"  ratio serial / batch: {serial / clustered:.2f}")
    print(f"{args.tiny} one-path measurements: batch {tiny_batch:.2f} s on 2 workers, in this process {tiny_local:.2f} s")
    print(f"  the cluster's cost per job: {(tiny_batch * 2 - tiny_local) / args.tiny * 1000:.0f} ms of a worker's time")


if __name__ == "__main__":
    main()
