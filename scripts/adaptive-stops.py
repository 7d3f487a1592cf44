#!/usr/bin/env python3
"""How often adaptive stopping stops in the wrong linear piece of a sampler's penalty.

usage: scripts/adaptive-stops.py BINARY SCENE LAYOUT [SEEDS] [--sun-patches on|off]

The truth of every sampler is the mean of four fixed runs at 16000 paths per point
(with the sunlit patches: the lowest noise). Then SEEDS adaptive runs at the search's
most, 1000 paths per point (`measure --adaptive`, the patches as the search traces
them: off unless asked), are compared with it: an early stop (fewer than 1000 paths)
whose value lies in another piece than the truth's (below, inside or above the target
band) is a wrong stop. Also reported: values beyond 3 of their standard errors from
the truth (4.53 for a directional sampler's fold error, Student's t with 7 degrees of
freedom) and the paths a run traced.
"""
import json
import statistics
import subprocess
import sys


def measure(binary, scene, layout, paths, seed, patches, adaptive):
    cmd = [binary, "measure", scene, "--layout", layout, "--paths", str(paths), "--threads", "2", "--json",
           "--sun-patches", patches, "--seed", str(seed)]
    if adaptive:
        cmd.append("--adaptive")
    return json.loads(subprocess.run(cmd, capture_output=True, text=True, check=True).stdout)["samplers"]


def piece(value, target):
    lo, hi = (float("-inf") if target[0] is None else target[0]), (float("inf") if target[1] is None else target[1])
    return 0 if value < lo else (1 if value <= hi else 2)


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    patches = "on" if "--sun-patches" in sys.argv and sys.argv[sys.argv.index("--sun-patches") + 1] == "on" else "off"
    args = [a for a in args if a not in ("on", "off")]
    binary, scene, layout = args[:3]
    seeds = int(args[3]) if len(args) > 3 else 16
    refs = [measure(binary, scene, layout, 16000, 1000 + s, "on", False) for s in range(4)]
    truth = [statistics.mean(r[i]["value"] for r in refs) for i in range(len(refs[0]))]
    runs = [measure(binary, scene, layout, 1000, s, patches, True) for s in range(1, seeds + 1)]
    wrong_total = beyond_total = 0
    paths = [0] * len(runs)
    print(f"{'sampler':24s} {'truth':>9s} {'mean':>9s} {'paths/pt':>9s} {'beyond':>7s} {'wrong stops':>11s}")
    for i, s in enumerate(refs[0]):
        k = 4.53 if s["type"] == "directional" else 3.0
        values = [r[i]["value"] for r in runs]
        beyond = sum(abs(r[i]["value"] - truth[i]) > k * r[i]["std_error"] for r in runs)
        wrong = sum(r[i]["paths_per_point"] < 1000 and piece(r[i]["value"], s["target"]) != piece(truth[i], s["target"])
                    for r in runs)
        for j, r in enumerate(runs):
            paths[j] += r[i]["paths_per_point"] * (len(r[i]["points"]) if isinstance(r[i]["points"], list) else r[i]["points"])
        wrong_total += wrong
        beyond_total += beyond
        print(f"{s['name']:24s} {truth[i]:9.1f} {statistics.mean(values):9.1f} "
              f"{statistics.mean(r[i]['paths_per_point'] for r in runs):9.0f} {beyond:7d} {wrong:11d}")
    n = len(runs) * len(truth)
    print(f"wrong stops {wrong_total} of {n}, beyond {beyond_total} of {n}, paths per run {statistics.mean(paths):.0f}")


if __name__ == "__main__":
    main()
