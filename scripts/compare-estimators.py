#!/usr/bin/env python3
"""Error per ray of two luxplan binaries on every bundled scene.

For each scene, both binaries measure at the same seed and path count (one thread,
so the rays are the same work) and the table gives the ratio of rays traced and the
median ratio of squared standard errors, directional samplers apart from the rest.
Efficiency (1 / (variance x rays)) of NEW against OLD is 1 / (rays ratio x se^2 ratio).

    scripts/compare-estimators.py OLD_BINARY NEW_BINARY [PATHS]
"""
import glob
import json
import statistics
import subprocess
import sys


def measure(binary, scene, paths):
    args = [binary, "measure", scene, "--paths", str(paths), "--seed", "1", "--threads", "1"]
    data = json.loads(subprocess.run(args + ["--json"], capture_output=True, text=True, check=True).stdout)
    table = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    rays = int(table.strip().split("\n")[-1].split(",")[1].split()[0])  # "N paths (...), R rays in S s"
    return data["samplers"], rays


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    old, new = sys.argv[1], sys.argv[2]
    paths = int(sys.argv[3]) if len(sys.argv) > 3 else 256
    scenes = ["scenes/demo/office.json"] + sorted(glob.glob("scenes/paper/*.json"))
    print("| scene | rays new/old | directional: median se^2 new/old | others: median se^2 new/old |")
    print("|---|---|---|---|")
    for scene in scenes:
        a, rays_a = measure(old, scene, paths)
        b, rays_b = measure(new, scene, paths)
        directional, others = [], []
        for x, y in zip(a, b):
            if x["std_error"] > 0 and y["std_error"] > 0:
                (directional if x["type"] == "directional" else others).append((y["std_error"] / x["std_error"]) ** 2)
        median = lambda v: "%.2f" % statistics.median(v) if v else "-"
        name = scene.rsplit("/", 1)[-1][:-5]
        print("| %s | %.2f | %s | %s |" % (name, rays_b / rays_a, median(directional), median(others)))


if __name__ == "__main__":
    main()
