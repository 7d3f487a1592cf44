#!/usr/bin/env python3
"""The search's regret where goals conflict: its result against the best of long runs.

    scripts/search-regret.py SCENE [--seeds 1-8] [--chains 8] [--factor 10] [--luxplan build/luxplan] [--out DIR]

Runs `luxplan optimize SCENE` at the scene's own settings for each seed, and `--chains`
chains of `--factor` times the scene's iterations (seeds 101, 102, ...), measures every
result again with a seed no search used (`measure --layout --seed 990001`, at the
scene's report paths), and prints, per seed, the regret: C of the run minus the lowest C
of the long chains, both re-measured. A regret at or below 0 means the run is no worse
than the best of the long chains. Standard library only.
"""
import argparse
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


def optimize(luxplan, scene, out, seed, iterations=None):
    cmd = [luxplan, "optimize", scene, "-o", out, "--seed", str(seed), "--threads", "1", "-q", "--no-pictures"]
    if iterations:
        cmd += ["--iterations", str(iterations)]
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
    args = p.parse_args()
    with open(args.scene) as f:
        scene = json.load(f)
    settings = scene.get("optimizer", {})
    iterations = settings.get("iterations", 10000)
    paths = settings.get("report_paths_per_point", max(32000, settings.get("paths_per_point", 1000)))  # measure's default
    out = args.out or tempfile.mkdtemp(prefix="regret-")
    long_runs = []
    for k in range(args.chains):
        folder = os.path.join(out, f"long-{k + 1}")
        optimize(args.luxplan, args.scene, folder, 101 + k, iterations * args.factor)
        c, se = remeasure(args.luxplan, args.scene, os.path.join(folder, "layout.json"), paths)
        long_runs.append(c)
        print(f"long chain {k + 1} ({iterations * args.factor} iterations): C {c:.4f} +- {se:.4f}", flush=True)
    best_long = min(long_runs)
    regrets = []
    for seed in seeds_of(args.seeds):
        folder = os.path.join(out, f"run-{seed}")
        report = optimize(args.luxplan, args.scene, folder, seed)
        c, se = remeasure(args.luxplan, args.scene, os.path.join(folder, "layout.json"), paths)
        regrets.append(c - best_long)
        print(f"seed {seed} ({report['iterations']} iterations, {report['seconds']:.1f} s): C {c:.4f} +- {se:.4f}, "
              f"regret {c - best_long:+.4f}", flush=True)
    print(f"best of {args.chains} chains of {iterations * args.factor} iterations: C {best_long:.4f}; "
          f"regret over {len(regrets)} seeds: median {statistics.median(regrets):+.4f}, "
          f"worst {max(regrets):+.4f}, at or below 0 in {sum(r <= 0 for r in regrets)}")


if __name__ == "__main__":
    main()
