#!/usr/bin/env python3
"""How far a directional sampler's value at few paths lies from its converged value.

The reference is one long run (REF_PATHS paths per stratum, seed 7): the brightest
stratum's mean there, with that stratum's standard error. At each path count the
value is averaged over SEEDS seeds (101, 102, ...; one thread each, two processes at
a time), and the table gives the mean's offset from the reference in percent with its
standard error (the spread of the seeds' values over sqrt(SEEDS)).

    scripts/directional-bias.py BINARY SCENE SAMPLER [PATHS,...] [SEEDS] [REF_PATHS]

e.g. scripts/directional-bias.py build/luxplan scenes/checks/window-lit-wall.json wall
"""
import json
import statistics
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor


def sampler(binary, scene, name, seed, paths, threads):
    args = [binary, "measure", scene, "--json", "--seed", str(seed), "--paths", str(paths), "--threads", str(threads)]
    data = json.loads(subprocess.run(args, capture_output=True, text=True, check=True).stdout)
    for s in data["samplers"]:
        if s["name"] == name:
            if s["type"] != "directional":
                sys.exit(f"{name} in {scene} is a {s['type']} sampler, not a directional one")
            return s
    sys.exit(f"no sampler named {name} in {scene}")


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    binary, scene, name = sys.argv[1:4]
    counts = [int(p) for p in (sys.argv[4] if len(sys.argv) > 4 else "16,32,64,256,1000").split(",")]
    seeds = int(sys.argv[5]) if len(sys.argv) > 5 else 200
    ref_paths = int(sys.argv[6]) if len(sys.argv) > 6 else 100000

    ref = sampler(binary, scene, name, 7, ref_paths, 2)
    best = max(range(len(ref["points"])), key=lambda i: ref["points"][i])
    truth = ref["points"][best]
    print(f"{scene} / {name}: reference {truth:.4g} (stratum {best}, {ref_paths} paths per stratum; "
          f"the cross-fitted value there {ref['value']:.4g} +- {ref['std_error']:.2g})")
    print("paths  mean of %d seeds  offset" % seeds)
    for n in counts:
        with ThreadPoolExecutor(2) as pool:
            values = list(pool.map(lambda s: sampler(binary, scene, name, s, n, 1)["value"], range(101, 101 + seeds)))
        mean = statistics.mean(values)
        error = statistics.stdev(values) / len(values) ** 0.5
        print(f"{n:5d}  {mean:16.4g}  {100 * (mean / truth - 1):+.1f}% +- {100 * error / truth:.1f}%", flush=True)


if __name__ == "__main__":
    main()
