#!/usr/bin/env python3
"""Empirical error per ray of the path sampling: scrambled Sobol (the default) against
PCG (`--sampling random`), on every bundled scene.

A low-discrepancy estimate's reported standard error comes from the spread of its
paths, which overstates its real error (the paths are not independent), so this
measures the real one: the spread of each sampler's value over SEEDS seeds, for both
samplings, at PATHS paths per point, one thread. Per scene: the rays ratio and the
median over samplers of the variance ratio sobol/random; efficiency
(1 / (variance x rays)) of sobol is 1 / (rays ratio x variance ratio).

    scripts/error-per-ray.py BINARY [PATHS] [SEEDS]
"""
import glob
import json
import statistics
import subprocess
import sys


def measure(binary, scene, paths, seed, sampling):
    args = [binary, "measure", scene, "--paths", str(paths), "--seed", str(seed), "--threads", "1", "--sampling", sampling]
    data = json.loads(subprocess.run(args + ["--json"], capture_output=True, text=True, check=True).stdout)
    table = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    rays = int(table.strip().split("\n")[-1].split(",")[1].split()[0])  # "N paths (...), R rays in S s"
    return [s["value"] for s in data["samplers"]], [s["type"] for s in data["samplers"]], rays


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    binary = sys.argv[1]
    paths = int(sys.argv[2]) if len(sys.argv) > 2 else 64
    seeds = int(sys.argv[3]) if len(sys.argv) > 3 else 8
    scenes = ["scenes/demo/office.json"] + sorted(s for s in glob.glob("scenes/paper/*.json") if not s.endswith("-layout.json"))
    print(f"{paths} paths per point, {seeds} seeds")
    print("| scene | rays sobol/random | directional: median var sobol/random | others: median var sobol/random |")
    print("|---|---|---|---|")
    all_dir, all_other = [], []
    for scene in scenes:
        runs = {m: [measure(binary, scene, paths, seed, m) for seed in range(1, seeds + 1)] for m in ("sobol", "random")}
        types = runs["sobol"][0][1]
        rays = {m: sum(r[2] for r in runs[m]) for m in runs}
        directional, others = [], []
        for k, kind in enumerate(types):
            var = {m: statistics.variance([r[0][k] for r in runs[m]]) for m in runs}
            if var["random"] > 0 and var["sobol"] >= 0:
                (directional if kind == "directional" else others).append(var["sobol"] / var["random"])
        all_dir += directional
        all_other += others
        cell = lambda v: f"{statistics.median(v):.2f} ({len(v)})" if v else "-"
        print(f"| {scene} | {rays['sobol'] / rays['random']:.3f} | {cell(directional)} | {cell(others)} |")
    cell = lambda v: f"{statistics.median(v):.2f} ({len(v)})" if v else "-"
    print(f"| all | | {cell(all_dir)} | {cell(all_other)} |")


if __name__ == "__main__":
    main()
