#!/usr/bin/env python3
"""How far each point of a scene's samplers reads from the converged value, by path count.

    scripts/default-accuracy.py build/luxplan scenes/checks/window-lit-room.json

runs `luxplan measure SCENE --json --seed S [--paths N]` for each count (default: 1000
and the scene's own default, `measure` without --paths) and seed, and a reference of
many seeds at many paths (the converged value: their mean, per point). Per count it
prints the worst point's relative deviation from the reference (the largest over the
seeds and its mean over them), the largest per-point seed-to-seed standard deviation
sigma (relative), 3 sigma, the count at which 3 sigma would be 1% (as 1/sqrt(N)), how far
the seeds' mean lies from the reference at its worst point (noise shrinks in that mean,
a bias stays), and measure's time (median of the runs' own seconds, and CPU seconds of
the process). docs/light-transport.md, "How accurate a default measurement is".
"""
import argparse
import json
import math
import resource
import statistics
import subprocess


def seed_range(text):
    lo, _, hi = text.partition("-")
    return list(range(int(lo), int(hi or lo) + 1))


def measure(luxplan, scene, seed, paths, threads):
    cmd = [luxplan, "measure", scene, "--json", "--seed", str(seed), "--threads", str(threads)]
    if paths:
        cmd += ["--paths", str(paths)]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    d = json.loads(out)
    points = [p for s in d["samplers"] for p in s["points"]]
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return points, d["paths_per_point"], d["seconds"], cpu


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("luxplan")
    p.add_argument("scene")
    p.add_argument("--paths", default="1000,default", help="counts, 'default' for measure without --paths")
    p.add_argument("--seeds", default="1-16")
    p.add_argument("--reference-paths", type=int, default=64000)
    p.add_argument("--reference-seeds", default="1001-1012")
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--target", type=float, default=0.01, help="relative error asked of 3 sigma")
    args = p.parse_args()

    seeds, ref_seeds = seed_range(args.seeds), seed_range(args.reference_seeds)
    if set(seeds) & set(ref_seeds):
        p.error("the reference's seeds must differ from the runs'")
    ref_runs = [measure(args.luxplan, args.scene, s, args.reference_paths, args.threads)[0] for s in ref_seeds]
    ref = [statistics.mean(x) for x in zip(*ref_runs)]
    ref_se = [statistics.stdev(x) / math.sqrt(len(ref_runs)) for x in zip(*ref_runs)]
    lit = [i for i, r in enumerate(ref) if r == r and r > 0]  # covered (NaN) and dark points left out
    print(f"reference: {len(ref_seeds)} seeds ({args.reference_seeds}) x {args.reference_paths} paths per point; "
          f"its largest relative standard error {100 * max(ref_se[i] / ref[i] for i in lit):.3f}%; {len(lit)} points")
    print("paths  seeds  worst point off: max / mean over seeds  sigma max  3 sigma  paths for 3 sigma = "
          f"{100 * args.target:g}%  mean of seeds off (z)  measure s  CPU s")
    for count in args.paths.split(","):
        paths = None if count == "default" else int(count)
        runs = [measure(args.luxplan, args.scene, s, paths, args.threads) for s in seeds]
        n = runs[0][1]
        worst = [max(abs(r[0][i] / ref[i] - 1) for i in lit) for r in runs]
        sd = [statistics.stdev(x) for x in zip(*[r[0] for r in runs])]
        sigma = max(sd[i] / ref[i] for i in lit)
        mean = [statistics.mean(x) for x in zip(*[r[0] for r in runs])]
        off, at = max((abs(mean[i] / ref[i] - 1), i) for i in lit)
        z = abs(mean[at] - ref[at]) / math.sqrt(sd[at] ** 2 / len(runs) + ref_se[at] ** 2)
        label = f"{n}" + (" (default)" if paths is None else "")
        print(f"{label:>15}  {len(seeds):5}  {100 * max(worst):6.2f}% / {100 * statistics.mean(worst):5.2f}%"
              f"  {100 * sigma:7.3f}%  {300 * sigma:6.2f}%  {n * (3 * sigma / args.target) ** 2:9.0f}"
              f"  {100 * off:6.3f}% ({z:.1f})  {statistics.median(r[2] for r in runs):6.2f}"
              f"  {statistics.median(r[3] for r in runs):6.2f}", flush=True)


if __name__ == "__main__":
    main()
