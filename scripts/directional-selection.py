#!/usr/bin/env python3
"""What choosing the brightest stratum from few paths costs a directional sampler.

The cross-fitted value at N paths per stratum is the mean, over 8 folds, of the
held-out fold's reading of the stratum chosen from the other 7 folds; its expectation
is the mean true value of the chosen strata, so the shortfall against the true max is
what the choice costs. This emulates the choice with independent runs of
`measure --paths K` (each run one fold of K paths per stratum, so N = 8 K) and scores
each rule by the true value, from one long run, of the strata it picks.

Rules: `max` (the plain max of the other folds' means), `shrunk` (what luxplan does,
PlacedDirectional::brightest: the means shrunk towards their eight neighbours'
by empirical Bayes), `smoothed` (the 3 x 3 weighted mean around each stratum),
`median` (each stratum's median fold value, then shrunk), and `oracle` (the true max:
no choice to get wrong).

    scripts/directional-selection.py BINARY SCENE SAMPLER [K] [TRIALS] [REF_PATHS]

e.g. scripts/directional-selection.py build/luxplan scenes/checks/window-lit-wall.json wall 2 200
"""
import json
import statistics
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

FOLDS = 8


def points(binary, scene, name, seed, paths, threads):
    args = [binary, "measure", scene, "--json", "--seed", str(seed), "--paths", str(paths), "--threads", str(threads)]
    data = json.loads(subprocess.run(args, capture_output=True, text=True, check=True).stdout)
    for s in data["samplers"]:
        if s["name"] == name:
            return s["points"]
    sys.exit(f"no sampler named {name} in {scene}")


def neighbours(side, k):
    j, i = divmod(k, side)
    for dj in (-1, 0, 1):
        for di in (-1, 0, 1):
            x, y = i + di, j + dj
            if (di or dj) and 0 <= x < side and 0 <= y < side:
                yield y * side + x, 2.0 if di == 0 or dj == 0 else 1.0


def shrunk(mean, error, side):
    """PlacedDirectional::brightest's scores."""
    n = len(mean)
    nbr, nbr_var, spread = [0.0] * n, [0.0] * n, 0.0
    for k in range(n):
        total = weight = var = 0.0
        for m, w in neighbours(side, k):
            total += w * mean[m]
            var += w * w * error[m] ** 2
            weight += w
        nbr[k], nbr_var[k] = total / weight, var / weight**2
        spread += (mean[k] - nbr[k]) ** 2 - error[k] ** 2 - nbr_var[k]
    t2 = max(0.0, spread / n)
    return [(t2 * mean[k] + error[k] ** 2 * nbr[k]) / (t2 + error[k] ** 2) if t2 + error[k] ** 2 > 0 else mean[k]
            for k in range(n)]


def smoothed(mean, side):
    out = []
    for k in range(len(mean)):
        pairs = [(k, 4.0)] + list(neighbours(side, k))
        out.append(sum(w * mean[m] for m, w in pairs) / sum(w for _, w in pairs))
    return out


def scores(rule, folds, side, truth):
    n = len(truth)
    columns = [[f[k] for f in folds] for k in range(n)]
    mean = [statistics.mean(c) for c in columns]
    error = [statistics.stdev(c) / len(c) ** 0.5 for c in columns]
    if rule == "max":
        return mean
    if rule == "shrunk":
        return shrunk(mean, error, side)
    if rule == "smoothed":
        return smoothed(mean, side)
    if rule == "median":
        return shrunk([statistics.median(c) for c in columns], error, side)
    return truth


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    binary, scene, name = sys.argv[1:4]
    k = int(sys.argv[4]) if len(sys.argv) > 4 else 2
    trials = int(sys.argv[5]) if len(sys.argv) > 5 else 200
    ref_paths = int(sys.argv[6]) if len(sys.argv) > 6 else 100000

    truth = points(binary, scene, name, 7, ref_paths, 2)
    side = round(len(truth) ** 0.5)
    top = max(truth)
    with ThreadPoolExecutor(2) as pool:
        runs = list(pool.map(lambda s: points(binary, scene, name, s, k, 1), range(1000, 1000 + trials * FOLDS)))
    print(f"{scene} / {name}: {side} x {side} strata, true max {top:.4g} ({ref_paths} paths per stratum); "
          f"{trials} trials of {FOLDS} folds of {k} paths ({FOLDS * k} paths per stratum)")
    print("rule      chosen strata's true value against the max")
    for rule in ("max", "shrunk", "smoothed", "median", "oracle"):
        chosen = []
        for t in range(trials):
            folds = runs[t * FOLDS:(t + 1) * FOLDS]
            for g in range(FOLDS):
                s = scores(rule, folds[:g] + folds[g + 1:], side, truth)
                chosen.append(truth[max(range(len(s)), key=s.__getitem__)])
        print(f"{rule:9s} {100 * (statistics.mean(chosen) / top - 1):+.1f}%")


if __name__ == "__main__":
    main()
