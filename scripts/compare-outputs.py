#!/usr/bin/env python3
"""Check that two luxplan binaries give the same numbers on every bundled scene.

A refactoring must not change what luxplan computes. For each scene under scenes/
this runs, with each binary, at the same seed and thread count:

    luxplan measure SCENE --json --paths P --seed S --threads T
    luxplan optimize SCENE -o DIR --iterations N --seed S --threads T -q --no-pictures

(a scene without furniture has optimize's refusal compared instead) and compares
the measurement's JSON, layout.json, trace.csv and report.json bit for
bit, times aside (keys that hold wall-clock seconds, and trace.csv's time column if
it has one). Exit status 0 when every file agrees, 1 with the first difference of
each file that does not.

    python3 scripts/compare-outputs.py BEFORE_BINARY AFTER_BINARY [--scenes GLOB ...] [--ignore KEY ...]

Build BEFORE_BINARY from the commit before the change (a git worktree and its own
build folder) and AFTER_BINARY from the change.
"""

import argparse
import glob
import json
import os
import subprocess
import sys
import tempfile

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# Keys whose values are wall-clock times or depend on the machine, not the numbers.
TIME_KEYS = ("seconds", "wall", "eta", "elapsed", "time_s", "per_second", "date")


def is_time_key(key):
    k = key.lower()
    return any(t in k for t in TIME_KEYS)


def strip_times(value):
    if isinstance(value, dict):
        return {k: strip_times(v) for k, v in value.items() if not is_time_key(k)}
    if isinstance(value, list):
        return [strip_times(v) for v in value]
    return value


def first_difference(a, b, path=""):
    """The JSON path of the first place where a and b differ, or None."""
    if type(a) is not type(b):
        return f"{path or '/'}: {a!r:.80} against {b!r:.80}"
    if isinstance(a, dict):
        for k in list(a) + [k for k in b if k not in a]:
            if k not in a or k not in b:
                return f"{path}/{k}: only in {'before' if k in a else 'after'}"
            d = first_difference(a[k], b[k], f"{path}/{k}")
            if d:
                return d
        if list(a) != list(b):
            return f"{path or '/'}: keys in another order"
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{path or '/'}: {len(a)} items against {len(b)}"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{path}/{i}")
            if d:
                return d
        return None
    if a != b:
        return f"{path or '/'}: {a!r:.80} against {b!r:.80}"
    return None


def read_csv_without_times(path):
    with open(path) as f:
        rows = [line.rstrip("\n").split(",") for line in f]
    if not rows:
        return rows
    keep = [i for i, name in enumerate(rows[0]) if not is_time_key(name)]
    return [[r[i] for i in keep if i < len(r)] for r in rows]


def run(cmd, log):
    result = subprocess.run(cmd, capture_output=True, text=True)
    if result.returncode != 0:
        log.write(f"failed ({result.returncode}): {' '.join(cmd)}\n{result.stderr[-2000:]}\n")
    return result


def outputs(binary, scene, work, args):
    """The files one binary writes for one scene: {name: parsed content}."""
    os.makedirs(work, exist_ok=True)
    common = ["--seed", str(args.seed), "--threads", str(args.threads)]
    got = {}
    m = run([binary, "measure", scene, "--json", "--paths", str(args.paths)] + common,
            sys.stderr)
    got["measure --json"] = (strip_times(json.loads(m.stdout)) if m.returncode == 0
                             else f"exit {m.returncode}: {m.stderr.strip()[-300:]}")
    out = os.path.join(work, "optimize")
    o = run([binary, "optimize", scene, "-o", out, "--iterations", str(args.iterations),
             "-q", "--no-pictures"] + common, sys.stderr)
    if o.returncode != 0:
        got["optimize"] = f"exit {o.returncode}: {o.stderr.strip()[-300:]}"
        return got
    for name in ("layout.json", "report.json"):
        with open(os.path.join(out, name)) as f:
            got[name] = {k: v for k, v in strip_times(json.load(f)).items() if k not in args.ignore}
    got["trace.csv"] = read_csv_without_times(os.path.join(out, "trace.csv"))
    return got


def bundled_scenes():
    found = []
    for path in sorted(glob.glob(os.path.join(REPO, "scenes", "**", "*.json"), recursive=True)):
        if os.sep + "layouts" + os.sep in path:
            continue
        with open(path) as f:
            try:
                if "luxplan" not in json.load(f):
                    continue
            except json.JSONDecodeError:
                continue
        found.append(path)
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("before", help="luxplan binary of the commit before the change")
    parser.add_argument("after", help="luxplan binary of the change")
    parser.add_argument("--scenes", nargs="*", help="scene files (default: every bundled scene)")
    parser.add_argument("--ignore", action="append", default=[], metavar="KEY",
                        help="a top-level key of report.json the change means to alter (repeatable)")
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--threads", type=int, default=2)
    parser.add_argument("--paths", type=int, default=64, help="measure's paths per point")
    parser.add_argument("--iterations", type=int, default=100, help="optimize's iterations")
    args = parser.parse_args()

    # Each --scenes argument is a file or a glob (quoted, so that the shell leaves it).
    scenes = [s for arg in args.scenes or [] for s in (sorted(glob.glob(arg)) or [arg])] or bundled_scenes()
    differing = 0
    with tempfile.TemporaryDirectory(prefix="compare-outputs-") as tmp:
        for scene in scenes:
            name = os.path.relpath(scene, REPO)
            work = os.path.join(tmp, name.replace(os.sep, "_"))
            before = outputs(args.before, scene, os.path.join(work, "before"), args)
            after = outputs(args.after, scene, os.path.join(work, "after"), args)
            for key in before:
                d = first_difference(before[key], after.get(key))
                if d:
                    differing += 1
                    print(f"DIFFERS {name} {key}: {d}")
                else:
                    print(f"same    {name} {key}")
            sys.stdout.flush()
    print(f"{differing} file(s) differ over {len(scenes)} scene(s)")
    return 1 if differing else 0


if __name__ == "__main__":
    sys.exit(main())
