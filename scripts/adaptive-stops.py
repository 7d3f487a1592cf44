#!/usr/bin/env python3
"""How often adaptive stopping stops in the wrong linear piece of a sampler's penalty.

usage: scripts/adaptive-stops.py BINARY SCENE LAYOUT [SEEDS] [--sun-patches on|off] [--exterior-sun on|off]
                                 [--near-bound DELTA]

The truth of every sampler is the mean of four fixed runs at 16000 paths per point
(with the sunlit patches: the lowest noise). Then SEEDS adaptive runs at the search's
most, 1000 paths per point (`measure --set adaptive=true`, the patches as the search traces
them: off unless asked; the sun off surfaces outside as measure takes it: on unless
asked), are compared with it: an early stop (fewer than 1000 paths)
whose value lies in another piece than the truth's (below, inside or above the target
band) is a wrong stop. Also reported: values beyond 3 of their standard errors from
the truth (4.53 for an error from eight fold values, Student's t with 7 degrees of
freedom: the ugr and dgp samplers; a directional sampler's reported error is a bootstrap
of its whole estimate, read at 3) and the paths a run traced.

LAYOUT "-" measures the scene as it is. --near-bound DELTA (repeatable) moves each
sampler's band top to its truth times 1 + DELTA (the band's bottom stays, or becomes 0
where it was above the new top) and checks the stops there: the hardest place for them.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile


def measure(binary, scene, layout, paths, seed, patches, adaptive, exterior="on"):
    cmd = [binary, "measure", scene, "--paths", str(paths), "--threads", "2", "--json", "--set", "sun_patches=" + patches,
           "--set", "exterior_sun=" + exterior, "--seed", str(seed)] + ([] if layout == "-" else ["--layout", layout])
    if adaptive:
        cmd += ["--set", "adaptive=true"]
    return json.loads(subprocess.run(cmd, capture_output=True, text=True, check=True).stdout)["samplers"]


def piece(value, target):
    lo, hi = (float("-inf") if target[0] is None else target[0]), (float("inf") if target[1] is None else target[1])
    return 0 if value < lo else (1 if value <= hi else 2)


def sampler_specs(scene):
    """The scene's sampler objects by their measured names (entity path, dots between)."""
    specs = {s["name"]: s for s in scene.get("samplers", [])}

    def walk(entities, prefix):
        for e in entities:
            name = prefix + e["name"]
            for s in e.get("samplers", []):
                specs[name + "." + s["name"]] = s
            walk(e.get("children", []), name + ".")

    walk(scene.get("entities", []), "")
    return specs


def check(a, scene, truth):
    runs = [measure(a.binary, scene, a.layout, 1000, s, a.sun_patches, True, a.exterior_sun) for s in range(1, a.seeds + 1)]
    wrong_total = beyond_total = early_total = 0
    paths = [0] * len(runs)
    print(f"{'sampler':24s} {'truth':>9s} {'mean':>9s} {'paths/pt':>9s} {'beyond':>7s} {'early':>6s} {'wrong':>6s}")
    for i, s in enumerate(runs[0]):
        k = 4.53 if s["type"] in ("ugr", "dgp") else 3.0
        values = [r[i]["value"] for r in runs]
        beyond = sum(abs(r[i]["value"] - truth[i]) > k * r[i]["std_error"] for r in runs)
        early = [r for r in runs if r[i]["paths_per_point"] < 1000]
        wrong_runs = [(seed, r) for seed, r in enumerate(runs, 1)
                      if r[i]["paths_per_point"] < 1000 and piece(r[i]["value"], s["target"]) != piece(truth[i], s["target"])]
        wrong = len(wrong_runs)
        for j, r in enumerate(runs):
            points = r[i]["points"]
            paths[j] += r[i]["paths_per_point"] * (len(points) if isinstance(points, list) else points)
        wrong_total += wrong
        beyond_total += beyond
        early_total += len(early)
        print(f"{s['name']:24s} {truth[i]:9.4g} {statistics.mean(values):9.4g} "
              f"{statistics.mean(r[i]['paths_per_point'] for r in runs):9.0f} {beyond:7d} {len(early):6d} {wrong:6d}")
        for seed, r in wrong_runs:
            x = r[i]
            print(f"    wrong: seed {seed}, {x['value']:.4g} +- {x['std_error']:.3g} after {x['paths_per_point']} paths per point")
    n = len(runs) * len(truth)
    print(f"{n} measurements: {early_total} early stops, {wrong_total} of them in the wrong piece; "
          f"{beyond_total} values beyond their interval; paths per run {statistics.mean(paths):.0f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("binary")
    parser.add_argument("scene")
    parser.add_argument("layout")
    parser.add_argument("seeds", nargs="?", type=int, default=16)
    parser.add_argument("--sun-patches", choices=["on", "off"], default="off")
    parser.add_argument("--exterior-sun", choices=["on", "off"], default="on")
    parser.add_argument("--near-bound", type=float, action="append", default=[])
    a = parser.parse_args()
    refs = [measure(a.binary, a.scene, a.layout, 16000, 1000 + s, "on", False) for s in range(4)]
    truth = [statistics.mean(r[i]["value"] for r in refs) for i in range(len(refs[0]))]
    if not a.near_bound:
        check(a, a.scene, truth)
        return
    with open(a.scene) as f:
        original = json.load(f)
    for delta in a.near_bound:
        scene = json.loads(json.dumps(original))
        specs = sampler_specs(scene)
        for i, s in enumerate(refs[0]):
            if s["name"] not in specs:
                sys.exit(f"adaptive-stops.py: no sampler named {s['name']!r} in {a.scene}")
            target = specs[s["name"]]["target"]
            target[1] = truth[i] * (1 + delta)
            if target[0] is not None and target[0] > target[1]:
                target[0] = 0  # a band that started above the new top
        # Beside the original, so that its relative paths (meshes, photometry) still resolve.
        fd, path = tempfile.mkstemp(prefix=".adaptive-stops-", suffix=".json", dir=os.path.dirname(os.path.abspath(a.scene)))
        try:
            with os.fdopen(fd, "w") as f:
                json.dump(scene, f)
            print(f"band tops at the truth x {1 + delta:g}:")
            check(a, path, truth)
        finally:
            os.remove(path)


if __name__ == "__main__":
    main()
