#!/usr/bin/env python3
"""scripts/search-regret.py on a tiny chain (the paper's Figure 4 glare room at 30
iterations): the best long chain is the one the choice's measurement (seed 990001)
reads lowest; it and every run are judged by another (seed 990002, --judge-paths),
which `luxplan measure` repeats; each regret is the run's judged C minus the chosen
chain's, and the summary's median is theirs. --judge-paths 0 is an error.

    python3 tests/scripts/search_regret_test.py SCRIPT LUXPLAN SCENE
"""
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile


def main():
    script, luxplan, source = sys.argv[1], sys.argv[2], sys.argv[3]
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    with tempfile.TemporaryDirectory() as work:
        with open(source) as f:
            scene = json.load(f)
        scene["optimizer"].update(iterations=30, paths_per_point=8, report_paths_per_point=16, plans=1,
                                  plan_iterations=200)
        tiny = os.path.join(work, "tiny.json")
        with open(tiny, "w") as f:
            json.dump(scene, f)
        out = os.path.join(work, "out")
        r = subprocess.run([sys.executable, script, tiny, "--chains", "2", "--factor", "2", "--seeds", "1-2",
                            "--judge-paths", "32", "--jobs", "2", "--luxplan", luxplan, "--out", out],
                           capture_output=True, text=True, timeout=300)
        check(r.returncode == 0, f"search-regret.py failed: {r.stderr[-500:]}")
        text = r.stdout
        choice = {int(k): float(c) for k, c in re.findall(r"^long chain (\d+) \(60 iterations\): C ([\d.]+)", text, re.M)}
        judged = {int(k): float(c) for k, c in re.findall(r"^long chain (\d+) judged at 32 paths \(seed 990002\): C ([\d.]+)",
                                                          text, re.M)}
        chosen = [int(k) for k in re.findall(r"^long chain (\d+) judged .*\(chosen\)$", text, re.M)]
        check(len(choice) == 2 and len(judged) == 2, f"two chains chosen among and judged:\n{text}")
        check(chosen == [min(choice, key=choice.get)] if choice else False, f"the chain the choice reads lowest:\n{text}")
        if chosen and judged:
            best = judged[chosen[0]]
            m = subprocess.run([luxplan, "measure", tiny, "--layout", os.path.join(out, f"long-{chosen[0]}", "layout.json"),
                                "--paths", "32", "--seed", "990002", "--threads", "1", "--json"],
                               capture_output=True, text=True, check=True)
            check(abs(json.loads(m.stdout)["C"] - best) < 1e-4, "the judgement is `measure --seed 990002 --paths 32`")
            runs = re.findall(r"^seed (\d) \(30 iterations, [\d.]+ s\): C ([\d.]+) \+- [\d.]+, regret ([-+][\d.]+)", text, re.M)
            check(len(runs) == 2, f"two runs:\n{text}")
            regrets = []
            for seed, c, regret in runs:
                regrets.append(float(regret))
                check(abs(float(c) - best - float(regret)) < 2e-4, f"seed {seed}: regret = C - the chosen chain's C")
            summary = re.search(r"regret over 2 seeds: median ([-+][\d.]+)", text)
            check(summary and regrets and abs(float(summary.group(1)) - statistics.median(regrets)) < 2e-4,
                  f"the summary's median:\n{text}")
        bad = subprocess.run([sys.executable, script, tiny, "--judge-paths", "0", "--luxplan", luxplan],
                             capture_output=True, text=True, timeout=60)
        check(bad.returncode != 0 and "--judge-paths" in bad.stderr, f"--judge-paths 0 is an error: {bad.stderr}")

    for f in failures:
        print("FAIL:", f)
    print("search_regret_test:", "FAILED" if failures else "passed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
