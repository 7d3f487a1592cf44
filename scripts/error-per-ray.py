#!/usr/bin/env python3
"""Empirical error per ray of two path estimators, on every bundled scene: scrambled
Sobol (the default) against PCG (`--set sampling=random`), or, with `--sun-patches`, the
sunlit patches sampled (the default of `measure`) against BSDF sampling alone
(`--set sun_patches=off`).

A low-discrepancy estimate's reported standard error comes from the spread of its
paths, which overstates its real error (the paths are not independent), so this
measures the real one: the spread of each sampler's value over SEEDS seeds, for both
estimators, at PATHS paths per point, one thread. Per scene: the rays ratio, the time
ratio and the median over samplers of the variance ratio first/second; efficiency
(1 / (variance x time)) of the first is 1 / (time ratio x variance ratio).

    scripts/error-per-ray.py BINARY [PATHS] [SEEDS] [--sun-patches | --vs OTHER_BINARY] [--scenes A.json,B.json]

With `--vs OTHER_BINARY`, the two estimators are BINARY's (new) and OTHER_BINARY's
(old) defaults: a change to the path tracer measured the same way. `--scenes` takes
those scenes instead of the bundled ones.
"""
import glob
import json
import statistics
import subprocess
import sys
import time


def measure(binary, scene, paths, seed, extra):
    args = [binary, "measure", scene, "--paths", str(paths), "--seed", str(seed), "--threads", "1"] + extra
    start = time.perf_counter()
    data = json.loads(subprocess.run(args + ["--json"], capture_output=True, text=True, check=True).stdout)
    seconds = time.perf_counter() - start
    table = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    rays = int(table.strip().split("\n")[-1].split(",")[1].split()[0])  # "N paths (...), R rays in S s"
    return [s["value"] for s in data["samplers"]], [s["type"] for s in data["samplers"]], rays, seconds


def main():
    argv = sys.argv[1:]
    other = None
    if "--vs" in argv:
        i = argv.index("--vs")
        if i + 1 >= len(argv):
            sys.exit(__doc__)
        other = argv[i + 1]
        del argv[i:i + 2]
    chosen = None
    if "--scenes" in argv:
        i = argv.index("--scenes")
        if i + 1 >= len(argv):
            sys.exit(__doc__)
        chosen = argv[i + 1].split(",")
        del argv[i:i + 2]
    args = [a for a in argv if not a.startswith("--")]
    if not args:
        sys.exit(__doc__)
    binary = args[0]
    paths = int(args[1]) if len(args) > 1 else 64
    seeds = int(args[2]) if len(args) > 2 else 8
    binaries = None
    if other:
        names, options, binaries = ("new", "old"), {"new": [], "old": []}, {"new": binary, "old": other}
    elif "--sun-patches" in argv:
        names, options = ("patches", "off"), {"patches": ["--set", "sun_patches=on"], "off": ["--set", "sun_patches=off"]}
    else:
        names, options = ("sobol", "random"), {"sobol": ["--set", "sampling=sobol"], "random": ["--set", "sampling=random"]}
    binaries = binaries or {m: binary for m in names}
    first, second = names
    scenes = chosen or ["scenes/demo/office.json"] + sorted(glob.glob("scenes/paper/*.json"))
    print(f"{paths} paths per point, {seeds} seeds")
    print(f"| scene | rays {first}/{second} | time {first}/{second} | directional: median var {first}/{second} "
          f"| others: median var {first}/{second} |")
    print("|---|---|---|---|---|")
    all_dir, all_other = [], []
    for scene in scenes:
        runs = {m: [measure(binaries[m], scene, paths, seed, options[m]) for seed in range(1, seeds + 1)] for m in names}
        types = runs[first][0][1]
        rays = {m: sum(r[2] for r in runs[m]) for m in runs}
        seconds = {m: sum(r[3] for r in runs[m]) for m in runs}
        directional, others = [], []
        for k, kind in enumerate(types):
            var = {m: statistics.variance([r[0][k] for r in runs[m]]) for m in runs}
            if var[second] > 0 and var[first] >= 0:
                (directional if kind == "directional" else others).append(var[first] / var[second])
        all_dir += directional
        all_other += others
        cell = lambda v: f"{statistics.median(v):.2f} ({len(v)})" if v else "-"
        print(f"| {scene} | {rays[first] / rays[second]:.3f} | {seconds[first] / seconds[second]:.2f} "
              f"| {cell(directional)} | {cell(others)} |")
    cell = lambda v: f"{statistics.median(v):.2f} ({len(v)})" if v else "-"
    print(f"| all | | | {cell(all_dir)} | {cell(all_other)} |")


if __name__ == "__main__":
    main()
