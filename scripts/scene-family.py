#!/usr/bin/env python3
"""Families of scenes with planted solutions, and the search's success on them.

    scripts/scene-family.py generate OUTDIR [--count N] [--seed S] [--kind office|lab|hall] [--workstations N]
                                            [--daylit] [--designer] [--luxplan build/luxplan]
    scripts/scene-family.py run OUTDIR [--seeds 1-10] [--paths 1000] [--threads 2] [--luxplan build/luxplan]

`generate` draws N scenes (offices, labs and halls of varied size, windows, hour,
reflectances and number of workstations; `--kind`, `--workstations` and `--daylit` narrow
the draw) and plants a solution in each: a layout built
first (workstations on a grid that keeps every rule: aligned with the room, screens
facing their chairs, the clearances with margin; each desk turned the quarter where its
screen reflects least), measured with `luxplan measure` at 2000 paths per point, and
targets set around what it measured so that it meets them with margin (desks: the band
[0.8 min, 1.25 max] of the planted desks' means, at least 150 lx wide; screens: 1.3
times the planted maximum, at least 50 cd/m2; with `--designer`, desks 300-750 lx and
screens up to 150 cd/m2 as in the demo's daylit office, the planted desks on places
the survey puts inside that band and the planted layout inside every target by a
tenth, else the scene is drawn again). The scene file holds the planted
layout as its entities' positions and the search starts from a uniform draw, so the
solution is known but not given. Written: OUTDIR/NAME.json and OUTDIR/NAME.planted.json.

`run` optimizes every scene over the seeds (`luxplan optimize SCENE --seed S --paths P
--threads T`), measures each result again with a seed no search used (`luxplan measure
--layout --seed 990001 --paths P`), and prints one row per scene: success rate (every
lighting goal met in that measurement and every rule's penalty 0), median and worst time
and iterations to solution (a run that fails counts with its whole time), and the time
per iteration after the start (report.json's seconds less its start_seconds: the draws,
the planned start and the start's measurement, which dominate runs of a few dozen
iterations; "–" where the runs average fewer than 100 iterations, as when the plan
alone solves the scene: then there is no pace to measure). It also writes
OUTDIR/results.json. Standard library only.
"""
import argparse
import json
import os
import random
import statistics
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scenes", "paper"))
import generate as g  # noqa: E402  (the paper scenes' building blocks)

REMEASURE_SEED = 990001  # no search uses it: runs use seeds 1..99
# --designer: the targets of scenes/demo/daylit-office.json, a designer's rather than
# the planted layout's (desks in lx, screens in cd/m2).
DESIGNER_DESK, DESIGNER_SCREEN = (300, 750), 150
PLANT_PATHS = 2000
# `run` gives the chain's pace only where its runs average this many iterations (fewer:
# a plan solved the scene, and the confirmations' time is most of what is left).
MIN_TIMED_ITERATIONS = 100


def draw_scene(rng, index, kind=None, workstations=None, daylit=False):
    """One scene's geometry, light and furniture, the planted layout as its positions.
    `kind`, `workstations` and `daylit` (morning or afternoon only) narrow the draw."""
    kind = kind or ["office", "lab", "hall"][index % 3]
    if kind == "office":
        W, D, H = rng.uniform(7.5, 10.5), rng.uniform(5.5, 7.5), rng.uniform(2.7, 3.0)
        n = rng.choice([4, 5, 6])
    elif kind == "lab":
        W, D, H = rng.uniform(9.0, 12.0), rng.uniform(7.0, 9.0), rng.uniform(2.9, 3.2)
        n = rng.choice([6, 7, 8])
    else:
        W, D, H = rng.uniform(12.0, 16.0), rng.uniform(8.0, 11.0), rng.uniform(3.2, 4.0)
        n = rng.choice([6, 8])
    n = workstations or n
    walls = rng.sample(["east", "south", "west", "north"], k=rng.choice([1, 2]))
    glass = rng.choice(["glass", "tinted"])
    openings = []
    for wall in walls:
        length = W if wall in ("south", "north") else D
        count = max(1, int(length // 3))
        width = rng.uniform(1.2, 1.8)
        for k in range(count):
            offset = (k + 0.5) * length / count - width / 2
            openings.append(g.window(wall, round(offset, 2), round(width, 2), material=glass))
    hour = rng.choice(["morning", "afternoon"] if daylit else ["morning", "afternoon", "night"])
    mats = g.materials()
    mats["floor"]["reflectance"] = round(rng.uniform(0.15, 0.4), 2)
    mats["wall"]["reflectance"] = round(rng.uniform(0.5, 0.8), 2)
    mats["ceiling"]["reflectance"] = round(rng.uniform(0.7, 0.9), 2)
    scene = {"luxplan": 1, "name": f"family-{index + 1:02d}-{kind}-{hour}", "site": g.ATHENS, "materials": mats}
    date = rng.choice(["2026-03-20", "2026-06-21", "2026-11-16"])
    tz = "+03:00" if date == "2026-06-21" else "+02:00"
    if hour == "morning":
        scene["daylight"] = g.preetham(date, "08:30", "11:30", tz)
    elif hour == "afternoon":
        scene["daylight"] = g.preetham(date, "13:30", "16:30", tz)
    # Ceiling panels on a grid, dimmed by day.
    nx, ny = max(2, round(W / 3)), max(2, round(D / 3))
    flux = rng.uniform(2500, 4000) * (1.0 if hour == "night" else rng.uniform(0.4, 0.8))
    lum = [g.panel(f"panel{i * ny + j + 1}", [round((i + 0.5) * W / nx, 2), round((j + 0.5) * D / ny, 2), round(H - 0.01, 2)],
                   round(flux)) for i in range(nx) for j in range(ny)]
    region = {"min": [0.9, 0.9], "max": [round(W - 0.9, 2), round(D - 0.9, 2)], "rotations": [0, 90, 180, 270]}
    # The grid the planted layout is chosen from: cells about 2.6 x 2.4 m apart (the
    # clearance is 2.0 m between centres) kept 1.4 m from the walls (a workstation's
    # reach, chair included, is 1.3 m).
    margin = 1.4
    cols, rows = int((W - 2 * margin) // 2.6) + 1, int((D - 2 * margin) // 2.4) + 1
    sx = (W - 2 * margin) / max(1, cols - 1) if cols > 1 else 0
    sy = (D - 2 * margin) / max(1, rows - 1) if rows > 1 else 0
    cells = [(round(margin + c * sx if cols > 1 else W / 2, 3), round(margin + r * sy if rows > 1 else D / 2, 3))
             for c in range(cols) for r in range(rows)]
    scene.update({"geometry": [g.room([round(W, 2), round(D, 2), round(H, 2)], openings)], "luminaires": lum,
                  "objective": {"lighting_weight": 0.5}, "optimizer": g.optimizer(10000)})
    return scene, cells, n, region


def furnish(scene, positions, region):
    """The scene with one workstation at each position, and the office's rules."""
    entities = [g.workstation(f"ws{k + 1}", (x, y), 0, [region]) for k, (x, y) in enumerate(positions)]
    return dict(scene, entities=entities, constraints=g.workstation_rules(len(positions)))


def planted_layout(scene):
    entities = {}
    for e in scene["entities"]:
        entities[e["name"]] = {"position": e["position"], "rotation": e["rotation"], "region": 0}
        entities[e["name"] + ".monitor"] = {"position": [0, 0.12], "rotation": 0, "region": 0}
    return {"entities": entities}


def measure(luxplan, scene_file, layout_file, paths, seed, threads):
    out = subprocess.run([luxplan, "measure", scene_file, "--layout", layout_file, "--paths", str(paths),
                          "--seed", str(seed), "--threads", str(threads), "--json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def goals_met(m):
    """Lighting goals met (every term of a sampler at penalty 0) and the rules' cost."""
    met = sum(1 for s in m["samplers"] if s["penalty"] == 0 and all(t["penalty"] == 0 for t in s.get("terms", [])))
    return met, len(m["samplers"]), m["G"]


def discard(*files):
    """A draw that is drawn again leaves no file behind (run would take it for a scene)."""
    for f in files:
        if os.path.exists(f):
            os.remove(f)


def cmd_generate(args):
    os.makedirs(args.out, exist_ok=True)
    rng = random.Random(args.seed)
    made = 0
    draws = 0
    while made < args.count:
        draws += 1
        if draws > 50 * args.count:
            sys.exit(f"scene-family.py: {draws - 1} scenes drawn, {made} of {args.count} could hold a planted solution")
        room, cells, n, region = draw_scene(rng, made, args.kind, args.workstations, args.daylit)
        if n > len(cells):
            if args.workstations:
                continue  # a room too small for the workstations asked for: drawn again
            n = len(cells)
        name = room["name"]
        scene_file = os.path.join(args.out, name + ".json")
        layout_file = os.path.join(args.out, name + ".planted.json")
        # A survey: a desk on every cell (rules aside), and the planted layout drawn
        # among the darker 60% of them (out of the sun patches, which no band of a
        # designer's would hold).
        survey = furnish(room, cells, region)
        for path, content in ((scene_file, survey), (layout_file, planted_layout(survey))):
            with open(path, "w") as f:
                json.dump(content, f, indent=1)
        lux = [s["value"] for s in measure(args.luxplan, scene_file, layout_file, 64, 4040, args.threads)["samplers"]
               if s["name"].endswith("task")]
        if args.designer:
            # A designer's targets: the planted desks among the cells the survey puts
            # well inside the band (a tenth of it each side).
            lo, hi = DESIGNER_DESK
            darker = [i for i in range(len(cells)) if lo * 1.1 <= lux[i] <= hi * 0.9]
            if len(darker) < n:
                print(f"{name}: {len(darker)} of {len(cells)} places in the desks' band, {n} needed; drawn again",
                      file=sys.stderr)
                discard(scene_file, layout_file)
                continue
        else:
            darker = sorted(range(len(cells)), key=lambda i: lux[i])[:max(n, int(0.6 * len(cells) + 0.5))]
        scene = furnish(room, [cells[i] for i in sorted(rng.sample(darker, n))], region)
        with open(scene_file, "w") as f:
            json.dump(scene, f, indent=1)
        # Each desk turned the quarter where its screen reads least (all desks measured
        # at each of the four quarters: a desk's own light depends on its own turn).
        glare_at = {}
        for turn in (0, 90, 180, 270):
            for e in scene["entities"]:
                e["rotation"] = turn
            with open(layout_file, "w") as f:
                json.dump(planted_layout(scene), f, indent=1)
            m = measure(args.luxplan, scene_file, layout_file, 256, 4141, args.threads)
            glare_at[turn] = {s["name"].split(".")[0]: s["value"] for s in m["samplers"] if s["name"].endswith("glare")}
        for e in scene["entities"]:
            e["rotation"] = min(glare_at, key=lambda t: glare_at[t][e["name"]])
        with open(layout_file, "w") as f:
            json.dump(planted_layout(scene), f, indent=1)
        with open(scene_file, "w") as f:
            json.dump(scene, f, indent=1)
        m = measure(args.luxplan, scene_file, layout_file, PLANT_PATHS, 4242, args.threads)
        if m["G"] != 0 or not m["geometric_rules_pass"]:
            print(f"{name}: the planted layout breaks a rule (G {m['G']}); drawn again", file=sys.stderr)
            discard(scene_file, layout_file)
            continue
        desks = [s["value"] for s in m["samplers"] if s["name"].endswith("task")]
        screens = [s["value"] for s in m["samplers"] if s["name"].endswith("glare")]
        if args.designer:
            (lo, hi), glare = DESIGNER_DESK, DESIGNER_SCREEN
            if not (min(desks) >= lo * 1.1 and max(desks) <= hi * 0.9 and max(screens) <= glare * 0.9):
                print(f"{name}: the planted layout is not inside the designer's targets with margin (desks "
                      f"{min(desks):.0f}-{max(desks):.0f} lx, screens up to {max(screens):.0f} cd/m2); drawn again",
                      file=sys.stderr)
                discard(scene_file, layout_file)
                continue
        else:
            lo, hi = 0.8 * min(desks), 1.25 * max(desks)
            if hi - lo < 150:
                mid = (lo + hi) / 2
                lo, hi = mid - 75, mid + 75
            glare = max(50.0, 1.3 * max(screens))
        for e in scene["entities"]:
            for c in e["children"]:
                for s in c.get("samplers", []):
                    s["target"] = [round(lo), round(hi)] if s["name"] == "task" else [0, round(glare)]
        with open(scene_file, "w") as f:
            json.dump(scene, f, indent=1)
        check = measure(args.luxplan, scene_file, layout_file, PLANT_PATHS, 4343, args.threads)
        met, total, G = goals_met(check)
        print(f"{name}: {len(desks)} workstations, desks {lo:.0f}-{hi:.0f} lx (planted {min(desks):.0f}-{max(desks):.0f}), "
              f"screens <= {glare:.0f} cd/m2; the planted layout meets {met} of {total} goals, G {G}")
        made += 1


def seeds_of(text):
    if "-" in text:
        a, b = text.split("-")
        return list(range(int(a), int(b) + 1))
    return [int(s) for s in text.split(",")]


def cmd_run(args):
    scenes = sorted(f for f in os.listdir(args.out) if f.endswith(".json") and not f.endswith(".planted.json")
                    and f != "results.json")
    results = []
    print("| scene | workstations | solved | median s to solution | worst s | median iterations | s per 1000 iterations after the start |")
    print("|---|---|---|---|---|---|---|")
    for name in scenes:
        scene_file = os.path.join(args.out, name)
        with open(scene_file) as f:
            n = len(json.load(f)["entities"])
        runs = []
        for seed in seeds_of(args.seeds):
            out = os.path.join(args.out, "runs", name[:-5], str(seed))
            t0 = time.time()
            subprocess.run([args.luxplan, "optimize", scene_file, "-o", out, "--seed", str(seed), "--paths",
                            str(args.paths), "--threads", str(args.threads), "-q", "--no-pictures"],
                           check=True, capture_output=True)
            seconds = time.time() - t0
            with open(os.path.join(out, "report.json")) as f:
                report = json.load(f)
            m = measure(args.luxplan, scene_file, os.path.join(out, "layout.json"), args.paths, REMEASURE_SEED,
                        args.threads)
            met, total, G = goals_met(m)
            runs.append({"seed": seed, "solved": met == total and G == 0, "goals_met": met, "goals": total, "G": G,
                         "seconds": report["seconds"], "start_seconds": report.get("start_seconds", 0.0), "wall_seconds": seconds, "iterations": report["iterations"],
                         "stop": report["stop_reason"]})
        solved = [r for r in runs if r["solved"]]
        secs = [r["seconds"] for r in runs]
        its = [r["iterations"] for r in runs]
        # The chain's own pace: the start (the draws, the plan, its measurement) left out,
        # as it dominates runs of a few dozen iterations.
        # Below MIN_TIMED_ITERATIONS a run on average, the confirmations and the result's
        # measurements dominate what is left: no pace to report.
        per1000 = 1000 * sum(r["seconds"] - r["start_seconds"] for r in runs) / max(1, sum(its))
        pace = f"{per1000:.2f}" if sum(its) >= MIN_TIMED_ITERATIONS * len(runs) else "–"
        results.append({"scene": name, "workstations": n, "runs": runs})
        print(f"| {name[:-5]} | {n} | {len(solved)}/{len(runs)} | {statistics.median(secs):.1f} | {max(secs):.1f} | "
              f"{statistics.median(its):.0f} | {pace} |", flush=True)
    with open(os.path.join(args.out, "results.json"), "w") as f:
        json.dump(results, f, indent=1)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="command", required=True)
    gen = sub.add_parser("generate")
    gen.add_argument("out")
    gen.add_argument("--count", type=int, default=6)
    gen.add_argument("--seed", type=int, default=1)
    gen.add_argument("--threads", type=int, default=2)
    gen.add_argument("--kind", choices=["office", "lab", "hall"], help="every scene of this kind (default: in turn)")
    gen.add_argument("--workstations", type=int, help="every scene with this many workstations (default: by kind)")
    gen.add_argument("--daylit", action="store_true", help="morning and afternoon only, no night scenes")
    gen.add_argument("--designer", action="store_true",
                     help="a designer's targets (desks 300-750 lx, screens up to 150 cd/m2), the planted layout "
                          "inside them by a tenth; scenes that cannot hold one are drawn again")
    gen.add_argument("--luxplan", default="build/luxplan")
    run = sub.add_parser("run")
    run.add_argument("out")
    run.add_argument("--seeds", default="1-10")
    run.add_argument("--paths", type=int, default=1000)
    run.add_argument("--threads", type=int, default=2)
    run.add_argument("--luxplan", default="build/luxplan")
    args = p.parse_args()
    cmd_generate(args) if args.command == "generate" else cmd_run(args)


if __name__ == "__main__":
    main()
