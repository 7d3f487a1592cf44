#!/usr/bin/env python3
"""The hierarchy's schedules against each other (issue: the hierarchy as the paper
means it): the plain cycle of 4 object-level proposals per group-level one, the cycle
with its length set by the levels' degrees of freedom, and the nested schedule (the
object-level proposals move the members of the group just proposed) with both
lengths. Each runs from a uniform start over SEEDS seeds at ITERATIONS, one thread
per run, two runs at a time. Per schedule: how many runs reached a confirmed C = 0,
the mean proposals to get there (an unsolved run counts ITERATIONS) with a 95%
bootstrap interval, the mean lighting evaluations, and the mean reported C (an
independent measurement of each run's result).

    scripts/compare-schedules.py BINARY SCENE [ITERATIONS] [SEEDS]
"""
import concurrent.futures
import json
import os
import random
import statistics
import subprocess
import sys
import tempfile

SCHEDULES = {
    "cycle 4": ["--set", "cycle=true", "--set", "inner_iterations=4"],
    "cycle by DOF": ["--set", "cycle=true", "--set", "inner_iterations=0"],
    "nested 4": ["--set", "nested=true", "--set", "inner_iterations=4"],
    "nested by DOF": ["--set", "nested=true", "--set", "inner_iterations=0"],
}


def run(binary, scene, iterations, seed, flags, folder):
    out = os.path.join(folder, f"{'-'.join(flags)}-{seed}")
    args = [binary, "optimize", scene, "-o", out, "--iterations", str(iterations), "--seed", str(seed),
            "--threads", "1", "-q", "--no-pictures"] + flags
    text = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    report = json.load(open(os.path.join(out, "report.json")))
    evaluations = int(text.split("lighting: ")[1].split()[0]) if "lighting: " in text else 0
    solved = report["stop_reason"] == "zero_cost"
    return {"solved": solved, "iterations": report["iterations"] if solved else iterations,
            "evaluations": evaluations, "C": report["C"], "seconds": report["seconds"]}


def bootstrap(values, rounds=2000, seed=1):
    rng = random.Random(seed)
    means = sorted(statistics.fmean(rng.choices(values, k=len(values))) for _ in range(rounds))
    return means[int(0.025 * rounds)], means[int(0.975 * rounds) - 1]


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    binary, scene = sys.argv[1], sys.argv[2]
    iterations = int(sys.argv[3]) if len(sys.argv) > 3 else 10000
    seeds = int(sys.argv[4]) if len(sys.argv) > 4 else 16
    with tempfile.TemporaryDirectory() as folder, concurrent.futures.ThreadPoolExecutor(2) as pool:
        jobs = {name: [pool.submit(run, binary, scene, iterations, s, flags, folder) for s in range(1, seeds + 1)]
                for name, flags in SCHEDULES.items()}
        print(f"{scene}, {iterations} iterations, seeds 1-{seeds}\n")
        print("| schedule | solved | mean proposals to C = 0 (95% CI) | mean lighting evaluations | mean reported C | mean s |")
        print("|---|---|---|---|---|---|")
        for name, futures in jobs.items():
            runs = [f.result() for f in futures]
            its = [r["iterations"] for r in runs]
            lo, hi = bootstrap(its)
            print(f"| {name} | {sum(r['solved'] for r in runs)}/{seeds} | {statistics.fmean(its):.0f} ({lo:.0f}-{hi:.0f}) "
                  f"| {statistics.fmean(r['evaluations'] for r in runs):.0f} | {statistics.fmean(r['C'] for r in runs):.4f} "
                  f"| {statistics.fmean(r['seconds'] for r in runs):.1f} |")


if __name__ == "__main__":
    main()
