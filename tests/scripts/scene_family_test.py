#!/usr/bin/env python3
"""scripts/scene-family.py generate, narrowed: one daylit lab of six workstations at a
designer's targets (desks 300-750 lx, screens up to 150 cd/m2) is written with its
planted layout and nothing else (no file of a draw drawn again), the planted layout
measured inside every target; an office that cannot hold six desks in that band is an
error after its draws, leaving no scene behind.

    python3 tests/scripts/scene_family_test.py SCRIPT LUXPLAN
"""
import json
import os
import subprocess
import sys
import tempfile


def generate(script, luxplan, out, *extra):
    return subprocess.run([sys.executable, script, "generate", out, "--count", "1", "--seed", "21", "--threads", "2",
                           "--luxplan", luxplan, *extra], capture_output=True, text=True, timeout=300)


def main():
    script, luxplan = sys.argv[1], sys.argv[2]
    failures = []

    def check(ok, what):
        if not ok:
            failures.append(what)

    with tempfile.TemporaryDirectory() as out:
        r = generate(script, luxplan, out, "--kind", "lab", "--workstations", "6", "--daylit", "--designer")
        check(r.returncode == 0, f"generate failed: {r.stderr[-500:]}")
        files = sorted(os.listdir(out))
        check(len(files) == 2 and files[0].endswith(".json") and files[1].endswith(".planted.json"),
              f"expected one scene and its planted layout, got {files}")
        if len(files) == 2:
            scene = json.load(open(os.path.join(out, files[0])))
            check("daylight" in scene, "a daylit scene has daylight")
            desks = [s["target"] for e in scene["entities"] for c in e["children"] for s in c.get("samplers", [])
                     if s["name"] == "task"]
            screens = [s["target"] for e in scene["entities"] for c in e["children"] for s in c.get("samplers", [])
                       if s["name"] == "glare"]
            check(len(desks) == 6 and all(t == [300, 750] for t in desks), f"desk targets {desks}")
            check(len(screens) == 6 and all(t == [0, 150] for t in screens), f"screen targets {screens}")
            m = json.loads(subprocess.run([luxplan, "measure", os.path.join(out, files[0]), "--layout",
                                           os.path.join(out, files[1]), "--paths", "500", "--seed", "7", "--threads", "2",
                                           "--json"], capture_output=True, text=True, check=True).stdout)
            check(m["G"] == 0 and all(s["penalty"] == 0 for s in m["samplers"]),
                  "the planted layout meets every goal and rule")
    with tempfile.TemporaryDirectory() as out:
        r = generate(script, luxplan, out, "--kind", "office", "--workstations", "6", "--daylit",
                     "--designer")
        check(r.returncode != 0 and "could hold a planted solution" in r.stderr, f"an impossible family: {r.stderr[-300:]}")
        check(os.listdir(out) == [], f"nothing left of the draws: {os.listdir(out)}")
    for f in failures:
        print("FAIL:", f)
    print("scene-family generate:", "ok" if not failures else f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
