#!/usr/bin/env python3
"""The search's regret where goals conflict: its result against the best of long runs.

    scripts/search-regret.py SCENE [--seeds 1-8] [--chains 8] [--factor 10] [--luxplan build/luxplan] [--out DIR]
                             [--reuse] [--jobs N] [--judge-paths N] [--set KEY=VALUE ...]

Runs `luxplan optimize SCENE` at the scene's own settings for each seed, and `--chains`
chains of `--factor` times the scene's iterations (seeds 101, 102, ...), and measures
every result again with seeds no search used:

1. the choice: every layout at the scene's report paths with seed 990001
   (`measure --layout --seed 990001`); the best of the long chains is the one this reads
   lowest;
2. the judgement: each run and that chosen chain at `--judge-paths` (default 16 times the
   report paths) with seed 990002.

The regret is C of the run minus C of the chosen chain, both from the judgement, with
its standard error. A regret at or below 0 means the run is no worse than the best of
the long chains. The lowest of eight noisy measurements is low by luck (the winner's
curse: at 512 paths a C of 0.3 reads +-0.012, and the lowest of eight equal ones reads
about 1.4 sigma low), so the chain is chosen by one measurement and judged by another;
the choice's own regret is printed too, for comparison. Standard library only.

To try a setting against the same long chains: `--out DIR --reuse` measures again the
long chains DIR already holds (run with the same scene and iterations) instead of
running them, and `--set KEY=VALUE` (repeatable) goes to the runs only. `--jobs N` runs
N optimizations at a time, each on one thread.
"""
import argparse
import concurrent.futures
import json
import math
import os
import statistics
import subprocess
import tempfile

CHOICE_SEED, JUDGEMENT_SEED = 990001, 990002


def seeds_of(text):
    if "-" in text:
        a, b = text.split("-")
        return list(range(int(a), int(b) + 1))
    return [int(s) for s in text.split(",")]


def optimize(luxplan, scene, out, seed, iterations=None, settings=()):
    cmd = [luxplan, "optimize", scene, "-o", out, "--seed", str(seed), "--threads", "1", "-q", "--no-pictures"]
    if iterations:
        cmd += ["--iterations", str(iterations)]
    for setting in settings:
        cmd += ["--set", setting]
    subprocess.run(cmd, check=True, capture_output=True)
    with open(os.path.join(out, "report.json")) as f:
        return json.load(f)


def remeasure(luxplan, scene, layout, paths, seed=CHOICE_SEED):
    out = subprocess.run([luxplan, "measure", scene, "--layout", layout, "--paths", str(paths), "--seed",
                          str(seed), "--threads", "1", "--json"], check=True, capture_output=True, text=True)
    m = json.loads(out.stdout)
    return m["C"], m["C_std_error"]


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("scene")
    p.add_argument("--seeds", default="1-8")
    p.add_argument("--chains", type=int, default=8)
    p.add_argument("--factor", type=int, default=10)
    p.add_argument("--luxplan", default="build/luxplan")
    p.add_argument("--out", default=None)
    p.add_argument("--reuse", action="store_true", help="measure the long chains --out holds again instead of running them")
    p.add_argument("--jobs", type=int, default=1, help="optimizations at a time (each on one thread)")
    p.add_argument("--judge-paths", type=int, default=None,
                   help="paths per point of the judgement (default 16 times the scene's report paths)")
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="a setting for the runs only")
    args = p.parse_args()
    if args.reuse and not args.out:
        p.error("--reuse needs --out DIR, the folder of an earlier run")
    with open(args.scene) as f:
        scene = json.load(f)
    settings = scene.get("optimizer", {})
    iterations = settings.get("iterations", 10000)
    paths = settings.get("report_paths_per_point", max(32000, settings.get("paths_per_point", 1000)))  # measure's default
    judge_paths = args.judge_paths if args.judge_paths is not None else 16 * paths
    if judge_paths < 1:
        p.error("--judge-paths must be >= 1")
    out = args.out or tempfile.mkdtemp(prefix="regret-")
    long_iterations = iterations * args.factor

    def long_chain(k):
        folder = os.path.join(out, f"long-{k + 1}")
        report_file = os.path.join(folder, "report.json")
        if args.reuse:
            if not os.path.exists(report_file):
                raise SystemExit(f"search-regret.py: --reuse: {report_file} does not exist")
            with open(report_file) as f:
                report = json.load(f)
            if report.get("settings", {}).get("iterations") != long_iterations or \
                    os.path.basename(report.get("file", "")) != os.path.basename(args.scene):
                raise SystemExit(f"search-regret.py: --reuse: {report_file} is not a chain of {long_iterations} "
                                 f"iterations on {args.scene}")
        else:
            optimize(args.luxplan, args.scene, folder, 101 + k, long_iterations)
        return remeasure(args.luxplan, args.scene, os.path.join(folder, "layout.json"), paths)

    def run(seed):
        folder = os.path.join(out, f"run-{seed}")
        report = optimize(args.luxplan, args.scene, folder, seed, settings=args.set)
        return report, remeasure(args.luxplan, args.scene, os.path.join(folder, "layout.json"), paths)

    def judge(folder):
        return remeasure(args.luxplan, args.scene, os.path.join(out, folder, "layout.json"), judge_paths, JUDGEMENT_SEED)

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        long_runs = []
        for k, (c, se) in enumerate(pool.map(long_chain, range(args.chains))):
            long_runs.append(c)
            print(f"long chain {k + 1} ({long_iterations} iterations): C {c:.4f} +- {se:.4f}", flush=True)
        chosen = min(range(len(long_runs)), key=lambda k: long_runs[k])
        best_choice = long_runs[chosen]
        # Every chain is judged, to show how much of the choice's spread was noise.
        judged = list(pool.map(judge, [f"long-{k + 1}" for k in range(args.chains)]))
        for k, (c, se) in enumerate(judged):
            print(f"long chain {k + 1} judged at {judge_paths} paths (seed {JUDGEMENT_SEED}): C {c:.4f} +- {se:.4f}"
                  + (" (chosen)" if k == chosen else ""), flush=True)
        best, best_se = judged[chosen]
        seeds = seeds_of(args.seeds)
        regrets, errors, choice_regrets = [], [], []

        def run_and_judge(seed):
            report, choice = run(seed)
            return report, choice, judge(f"run-{seed}")

        for seed, (report, (c1, _), (c, se)) in zip(seeds, pool.map(run_and_judge, seeds)):
            regrets.append(c - best)
            errors.append(math.hypot(se, best_se))
            choice_regrets.append(c1 - best_choice)
            print(f"seed {seed} ({report['iterations']} iterations, {report['seconds']:.1f} s): C {c:.4f} +- {se:.4f}, "
                  f"regret {c - best:+.4f} +- {errors[-1]:.4f} (by the choice's measurement "
                  f"{c1 - best_choice:+.4f})", flush=True)
    print(f"best of {args.chains} chains of {long_iterations} iterations: C {best:.4f} +- {best_se:.4f} "
          f"(the choice read {best_choice:.4f}); regret over {len(regrets)} seeds: median "
          f"{statistics.median(regrets):+.4f}, worst {max(regrets):+.4f}, at or below 0 in "
          f"{sum(r <= 0 for r in regrets)}, within two standard errors of 0 in "
          f"{sum(r <= 2 * e for r, e in zip(regrets, errors))}; by the choice's measurement: median "
          f"{statistics.median(choice_regrets):+.4f}")


if __name__ == "__main__":
    main()
