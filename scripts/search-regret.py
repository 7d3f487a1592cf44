#!/usr/bin/env python3
"""The search's regret where goals conflict: its result against the best of long runs.

    scripts/search-regret.py SCENE [--seeds 1-8] [--chains 8] [--factor 10] [--luxplan build/luxplan] [--out DIR]
                             [--reuse] [--jobs N] [--set KEY=VALUE ...]

Runs `luxplan optimize SCENE` at the scene's own settings for each seed, and `--chains`
chains of `--factor` times the scene's iterations (seeds 101, 102, ...), measures every
result again with a seed no search used (`measure --layout --seed 990001`, at the
scene's report paths), and prints, per seed, the regret: C of the run minus the lowest C
of the long chains, both re-measured. A regret at or below 0 means the run is no worse
than the best of the long chains. Standard library only.

To try a setting against the same long chains: `--out DIR --reuse` measures again the
long chains DIR already holds (run with the same scene and iterations) instead of
running them, and `--set KEY=VALUE` (repeatable) goes to the runs only. `--jobs N` runs
N optimizations at a time, each on one thread.
"""
import argparse
import concurrent.futures
import json
import os
import statistics
import subprocess
import tempfile

REMEASURE_SEED = 990001


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


def remeasure(luxplan, scene, layout, paths):
    out = subprocess.run([luxplan, "measure", scene, "--layout", layout, "--paths", str(paths), "--seed",
                          str(REMEASURE_SEED), "--threads", "1", "--json"], check=True, capture_output=True, text=True)
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
    p.add_argument("--set", action="append", default=[], metavar="KEY=VALUE", help="a setting for the runs only")
    args = p.parse_args()
    if args.reuse and not args.out:
        p.error("--reuse needs --out DIR, the folder of an earlier run")
    with open(args.scene) as f:
        scene = json.load(f)
    settings = scene.get("optimizer", {})
    iterations = settings.get("iterations", 10000)
    paths = settings.get("report_paths_per_point", max(32000, settings.get("paths_per_point", 1000)))  # measure's default
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

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        long_runs = []
        for k, (c, se) in enumerate(pool.map(long_chain, range(args.chains))):
            long_runs.append(c)
            print(f"long chain {k + 1} ({long_iterations} iterations): C {c:.4f} +- {se:.4f}", flush=True)
        best_long = min(long_runs)
        regrets = []
        seeds = seeds_of(args.seeds)
        for seed, (report, (c, se)) in zip(seeds, pool.map(run, seeds)):
            regrets.append(c - best_long)
            print(f"seed {seed} ({report['iterations']} iterations, {report['seconds']:.1f} s): C {c:.4f} +- {se:.4f}, "
                  f"regret {c - best_long:+.4f}", flush=True)
    print(f"best of {args.chains} chains of {iterations * args.factor} iterations: C {best_long:.4f}; "
          f"regret over {len(regrets)} seeds: median {statistics.median(regrets):+.4f}, "
          f"worst {max(regrets):+.4f}, at or below 0 in {sum(r <= 0 for r in regrets)}")


if __name__ == "__main__":
    main()
