#!/usr/bin/env python3
"""The paper's experiments (section 7) with statistics: runs every search, re-measures
every result with a seed no search used, and writes docs/experiments.md.

    scripts/experiments.py [--luxplan build/luxplan] [--out out/experiments]
                           [--jobs N] [--scheduler ADDRESS] [--only fig6,fig7,fig8,fig9,fig10]
                           [--doc docs/experiments.md]

Every table of docs/experiments.md comes from this script: run it again to
regenerate them (runs already in OUT are reused, so a second call only re-measures
and rewrites; delete OUT to start afresh). The searches and measurements run through
the Python module's luxplan.batch (docs/python.md; build it with `make python`) on a
dask.distributed cluster: a LocalCluster of JOBS single-threaded workers (default: the
number of cores), or the scheduler at ADDRESS (`dask scheduler`, with `dask worker`s on
other machines). Each search runs single-threaded, JOBS at a time; times are each
job's wall time as the client sees it, so they grow when JOBS exceeds the idle cores.
The plans (plan.png) are drawn by the CLI, --luxplan. With --only, the other
experiments are read from OUT if there, and left out of the page otherwise.

  fig6   hierarchical against the groupless flat baseline (--set flat=true), 16 seeds, on the three
         hierarchy scenes: the best-so-far layout (optimize --set snapshots=N) re-measured
         with an independent seed, against iterations, wall time and lighting
         evaluations, with bootstrap intervals over the seeds.
  fig7   the six-workstation office at three times of day, 8 seeds each, with a
         lighting-weight-0 control and an attainable daylight variant.
  fig8   the computer lab optimized (4 seeds) against both symmetric arrangements.
  fig9   the apartment by night with and without its movable lamps, 8 seeds each.
  fig10  the event hall by day and by night, 4 seeds each: dance-floor occupancy and
         the smallest gap between tables.

The standard library, the module luxplan (from build/python) and dask.distributed.
"""
import argparse
import concurrent.futures
import copy
import json
import math
import os
import platform
import random
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
PAPER = os.path.join(ROOT, "scenes", "paper")
SNAPSHOTS = 10          # checkpoints per fig6 run
REMEASURE_OFFSET = 500000  # independent seeds: the run's seed + this (the search's streams never reach it)


# ---------------------------------------------------------------- running luxplan

class Runner:
    """The experiments' jobs on a dask.distributed cluster through luxplan.batch, JOBS
    submitted at a time (one per worker); the CLI for the plans' pictures."""

    def __init__(self, luxplan, out, jobs, scheduler=None):
        self.luxplan, self.out, self.jobs = luxplan, out, jobs
        self.pool = concurrent.futures.ThreadPoolExecutor(max_workers=jobs)
        sys.path.insert(0, os.path.join(os.path.dirname(luxplan), "python"))
        import distributed
        global luxplan_module
        import luxplan as luxplan_module
        if scheduler:
            self.cluster, self.client = None, distributed.Client(scheduler)
        else:
            self.cluster = distributed.LocalCluster(n_workers=jobs, threads_per_worker=1, processes=True,
                                                    dashboard_address=":0")
            self.client = distributed.Client(self.cluster)

    def close(self):
        self.client.close()
        if self.cluster:
            self.cluster.close()

    def job(self, job):
        """One job through luxplan.batch: its result and wall seconds, or RuntimeError."""
        t0 = time.monotonic()
        result = luxplan_module.batch([job], self.client)[0]
        if isinstance(result, luxplan_module.JobError):
            raise RuntimeError("luxplan %s failed: %s" % (job["command"], result))
        return result, time.monotonic() - t0

    def run(self, args):
        """The CLI (the plans' pictures): its stdout and wall seconds."""
        t0 = time.monotonic()
        p = subprocess.run([self.luxplan] + args, capture_output=True, text=True)
        if p.returncode != 0:
            raise RuntimeError("luxplan %s failed (%d):\n%s" % (" ".join(args), p.returncode, p.stderr[-2000:]))
        return p.stdout, time.monotonic() - t0

    def optimize(self, scene, out, seed, settings=()):
        """optimize once into `out` (kept: a later call reuses it), `settings` as --set's
        KEY=VALUE; returns the report."""
        report = os.path.join(out, "report.json")
        if not os.path.exists(report):
            os.makedirs(out, exist_ok=True)
            _, wall = self.job({"command": "optimize", "scene": scene, "out": out, "seed": seed, "threads": 1,
                                "settings": list(settings)})
            with open(os.path.join(out, "wall.json"), "w") as f:
                json.dump({"wall_seconds": wall}, f)
        return load(report)

    def measure(self, scene, layout, seed, paths, flat=False, cache=None):
        """measure --json's object of a layout (cached in `cache` when given)."""
        if cache and os.path.exists(cache):
            return load(cache)
        job = {"command": "measure", "scene": scene, "seed": seed, "paths": paths, "threads": 1,
               "settings": ["flat=true"] if flat else []}
        if layout:
            job["layout"] = layout
        result, _ = self.job(job)
        if cache:
            write_json(cache, result)
        return result

    def map(self, fn, items):
        return list(self.pool.map(fn, items))


def load(path):
    with open(path) as f:
        return json.load(f)


def write_json(path, value):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        json.dump(value, f, indent=1)
    os.replace(tmp, path)


def variant(out, name, source, change):
    """A scene written beside the outputs: `source` changed by `change(scene)`."""
    scene = load(os.path.join(PAPER, source))
    change(scene)
    path = os.path.join(out, "scenes", name + ".json")
    write_json(path, scene)
    return path


def paper(name):
    return os.path.join(PAPER, name + ".json")


# ---------------------------------------------------------------- statistics

def bootstrap(values, stat=statistics.mean, resamples=2000, seed=12345):
    """stat and its 95% percentile bootstrap interval over `values` (None if empty)."""
    if not values:
        return None
    rng = random.Random(seed)
    n = len(values)
    boots = sorted(stat([values[rng.randrange(n)] for _ in range(n)]) for _ in range(resamples))
    return stat(values), boots[int(0.025 * resamples)], boots[int(0.975 * resamples) - 1]


def ci(values, digits=3, stat=statistics.mean):
    b = bootstrap(values, stat)
    if b is None:
        return "–"
    return "%.*f [%.*f, %.*f]" % (digits, b[0], digits, b[1], digits, b[2])


def fmt(x, digits=3):
    return "–" if x is None else "%.*f" % (digits, x)


def samplers_by_name(result):
    return {s["name"]: s for s in result["samplers"]}


def in_range(sampler):
    return sampler["penalty"] == 0


# ---------------------------------------------------------------- fig6: hierarchy

FIG6_SCENES = [("fig6-hierarchy", "living and dining room"), ("fig9-apartment-night", "apartment at night"),
               ("fig9-apartment-day", "apartment by day")]
FIG6_SEEDS = 16


def fig6(r, out):
    rows = {}
    for name, _ in FIG6_SCENES:
        scene = paper(name)
        paths = load(scene)["optimizer"]["report_paths_per_point"]
        runs = [(mode, seed) for mode in ("hierarchical", "flat") for seed in range(1, FIG6_SEEDS + 1)]

        def one(run):
            mode, seed = run
            folder = os.path.join(out, "fig6", name, "%s-%d" % (mode, seed))
            settings = ["snapshots=%d" % SNAPSHOTS] + (["flat=true"] if mode == "flat" else [])
            r.optimize(scene, folder, seed, settings)
            snaps = load(os.path.join(folder, "snapshots.json"))["snapshots"]
            points = []
            for k, s in enumerate(snaps):
                layout = os.path.join(folder, "snapshot-%d.json" % k)
                if not os.path.exists(layout):
                    write_json(layout, s["layout"])
                m = r.measure(scene, layout, seed + REMEASURE_OFFSET, paths, flat=(mode == "flat"),
                              cache=os.path.join(folder, "snapshot-%d.measured.json" % k)) if s["feasible"] else None
                points.append({"iteration": s["iteration"], "seconds": s["seconds"],
                               "evaluations": s["lighting_evaluations"], "search_C": s["search_C"],
                               "C": m["C"] if m and m["geometric_rules_pass"] else None})
            return (mode, seed, points)

        rows[name] = r.map(one, runs)
    return rows


def best_at(points, key, limit):
    """The re-measured C of the run's best-so-far at `limit` of `key` (None: not feasible yet)."""
    c = None
    for p in points:
        if p[key] <= limit + 1e-12:
            c = p["C"] if p["C"] is not None else c
    return c


def convergence_svg(path, title, by_mode):
    """Each run's best-so-far C (independent) against wall time, log-log: a line per run."""
    w, h, left, right, top, bottom = 640, 360, 64, 16, 28, 44
    points = [(p["seconds"], p["C"]) for runs in by_mode.values() for run in runs for p in run if p["C"] is not None]
    if not points:
        return False
    floor = 1e-4  # C = 0 drawn on the floor line
    t0, t1 = min(max(t, 1e-3) for t, _ in points), max(t for t, _ in points)
    c0, c1 = floor, max(max(c for _, c in points), floor * 10)
    t0, t1 = 10 ** math.floor(math.log10(t0)), 10 ** math.ceil(math.log10(max(t1, t0 * 10)))
    c1 = 10 ** math.ceil(math.log10(c1))

    def x(t):
        return left + (w - left - right) * (math.log10(max(t, t0)) - math.log10(t0)) / (math.log10(t1) - math.log10(t0))

    def y(c):
        c = max(c, c0)
        return top + (h - top - bottom) * (1 - (math.log10(c) - math.log10(c0)) / (math.log10(c1) - math.log10(c0)))

    out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" font-size="11">' % (w, h),
           '<rect width="100%" height="100%" fill="white"/>',
           '<text x="%d" y="16" font-size="13">%s</text>' % (left, title)]
    decade = t0
    while decade <= t1 * 1.001:
        out.append('<line x1="%.1f" y1="%d" x2="%.1f" y2="%d" stroke="#ddd"/>' % (x(decade), top, x(decade), h - bottom))
        out.append('<text x="%.1f" y="%d" text-anchor="middle">%g s</text>' % (x(decade), h - bottom + 14, decade))
        decade *= 10
    decade = c0
    while decade <= c1 * 1.001:
        out.append('<line x1="%d" y1="%.1f" x2="%d" y2="%.1f" stroke="#ddd"/>' % (left, y(decade), w - right, y(decade)))
        out.append('<text x="%d" y="%.1f" text-anchor="end">%s</text>' % (left - 4, y(decade) + 4,
                                                                          "0" if decade == c0 else "%g" % decade))
        decade *= 10
    out.append('<text x="%d" y="%d" text-anchor="middle">wall time of the run (log)</text>' % ((left + w - right) // 2, h - 8))
    out.append('<text x="12" y="%d" transform="rotate(-90 12 %d)" text-anchor="middle">best-so-far C, '
               'independent (log; 0 at the bottom)</text>' % ((top + h - bottom) // 2, (top + h - bottom) // 2))
    colours = {"hierarchical": "#1f77b4", "flat": "#ff7f0e"}
    for m, runs in by_mode.items():
        for run in runs:
            line = ["%.1f,%.1f" % (x(p["seconds"]), y(p["C"])) for p in run if p["C"] is not None]
            if len(line) == 1:
                out.append('<circle cx="%s" cy="%s" r="2.5" fill="%s"/>' % (*line[0].split(","), colours[m]))
            elif line:
                out.append('<polyline points="%s" fill="none" stroke="%s" stroke-opacity="0.6"/>' % (" ".join(line), colours[m]))
    for k, m in enumerate(by_mode):
        out.append('<text x="%d" y="%d" fill="%s">%s (%d runs)</text>' % (w - right - 150, top + 14 + 14 * k, colours[m], m,
                                                                         len(by_mode[m])))
    out.append("</svg>")
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write("\n".join(out) + "\n")
    os.replace(tmp, path)
    return True


def fig6_page(rows):
    lines = ["## Figure 6: the hierarchy against the flat baseline (%d seeds)" % FIG6_SEEDS, "",
             "Each scene at its own settings (iterations, paths), hierarchical and flat (`--set flat=true`: the groups "
             "dissolved, members held to their anchors by cohesion constraints: the same objective, "
             "[optimizer.md](optimizer.md#hierarchy)), seeds 1–%d, `--set snapshots=%d`. Every snapshot's "
             "best-so-far layout is measured again with seed + %d at the scene's `report_paths_per_point` "
             "(`measure --layout`, `--set flat=true` for the flat runs): **C below is that independent measurement**, "
             "not the search's estimate. A run that stops at a confirmed C = 0 keeps its last value. "
             "Intervals: 95%% percentile bootstrap over the seeds (2000 resamples). \"feasible\": runs "
             "with a layout that passes the geometric rules; means are over those runs (¹: not every run, so "
             "the mean flatters that mode). A budget of wall time or lighting evaluations reads each run's "
             "last checkpoint within it (the best so far at the budget is at least that good); the budgets "
             "are fractions of the hierarchical runs' mean totals." % (FIG6_SEEDS, SNAPSHOTS, REMEASURE_OFFSET), ""]
    claims = []
    for name, title in FIG6_SCENES:
        runs = rows[name]
        lines += ["### %s (`%s`)" % (title, name), "",
                  "| budget | hierarchical: feasible | C | flat: feasible | C |", "|---|---|---|---|---|"]
        by_mode = {m: [p for (mm, _, p) in runs if mm == m] for m in ("hierarchical", "flat")}
        horizon = {m: max(p[-1]["iteration"] for p in by_mode[m]) for m in by_mode}
        n_iter = max(horizon.values())
        budgets = []
        for f in (0.1, 0.25, 0.5, 1.0):
            budgets.append(("%d iterations" % math.ceil(f * n_iter), "iteration", math.ceil(f * n_iter)))
        t_end = statistics.mean(p[-1]["seconds"] for p in by_mode["hierarchical"])
        for f in (0.25, 1.0):
            budgets.append(("%.2f s (wall)" % (f * t_end), "seconds", f * t_end))
        e_end = statistics.mean(p[-1]["evaluations"] for p in by_mode["hierarchical"])
        for f in (0.25, 1.0):
            budgets.append(("%d lighting evaluations" % round(f * e_end), "evaluations", f * e_end))
        summary = {}
        for label, key, limit in budgets:
            cells = []
            for m in ("hierarchical", "flat"):
                cs = [best_at(p, key, limit) for p in by_mode[m]]
                feasible = [c for c in cs if c is not None]
                cells.append("%d / %d" % (len(feasible), len(cs)))
                partial = 0 < len(feasible) < len(cs)
                cells.append(ci(feasible, 4) + (" ¹" if partial else "") if feasible else "–")
                summary[(label, m)] = (len(feasible), len(cs), statistics.mean(feasible) if feasible else None)
            lines.append("| %s | %s |" % (label, " | ".join(cells)))
        for m in ("hierarchical", "flat"):
            finals = [p[-1] for p in by_mode[m]]
            solved = sum(1 for p in finals if p["C"] == 0)
            lines += ["", "%s: %d of %d runs end at C = 0 (independent); mean %.1f s and %d lighting "
                      "evaluations per run, %d iterations on average." % (
                          m.capitalize(), solved, len(finals), statistics.mean(p["seconds"] for p in finals),
                          round(statistics.mean(p["evaluations"] for p in finals)),
                          round(statistics.mean(p["iteration"] for p in finals)))]
        lines.append("")
        # The claim: at each budget, is the hierarchy's mean lower (or more runs feasible)?
        ahead = 0
        for label, _, _ in budgets:
            (fh, nh, ch), (ff, nf, cf) = summary[(label, "hierarchical")], summary[(label, "flat")]
            if fh > ff or (fh == ff and ch is not None and cf is not None and ch <= cf):
                ahead += 1
        image = "fig6-chart-%s.svg" % name
        if convergence_svg(os.path.join(ROOT, "docs", "images", image), "%s: each run's best so far" % title, by_mode):
            lines += ["![%s: each run's best-so-far C against wall time](images/%s)" % (title, image),
                      "", "(A line per run, from its first feasible checkpoint; a run that is never feasible has none.)", ""]
        ends = {m: [p[-1] for p in by_mode[m]] for m in by_mode}
        claims.append("%s: ahead at %d of %d budgets; by the end %d of %d hierarchical runs and %d of %d flat runs "
                      "have a feasible layout, %d and %d reach C = 0" % (
                          title, ahead, len(budgets), sum(1 for p in ends["hierarchical"] if p["C"] is not None),
                          len(ends["hierarchical"]), sum(1 for p in ends["flat"] if p["C"] is not None), len(ends["flat"]),
                          sum(1 for p in ends["hierarchical"] if p["C"] == 0), sum(1 for p in ends["flat"] if p["C"] == 0)))
    lines += ["**What it shows.** The hierarchy is \"ahead\" at a budget when more of its runs are feasible, or as "
              "many and its mean C is no higher. " + "; ".join(claims) + ". The paper reports convergence \"orders "
              "of magnitude\" faster; that ratio is not measurable here, because the flat baseline mostly never "
              "reaches what the hierarchy reaches within the same iterations.", ""]
    return lines


# ---------------------------------------------------------------- fig7: time of day

FIG7_SEEDS = 8
WINDOW_X = 9.0  # the office's east wall, where its windows are


def attainable(scene):
    """Daylight goals the morning sun allows: desks 300-1500 lx, screens up to 400 cd/m2."""
    for e in scene["entities"]:
        for c in e.get("children", []):
            for s in c.get("samplers", []):
                s["target"] = [300, 1500] if s["type"] == "planar" else [0, 400]


def no_light(scene):
    scene["objective"]["lighting_weight"] = 0


def office_summary(layout, measured):
    ents = layout["entities"]
    d = [WINDOW_X - ents["ws%d" % i]["position"][0] for i in range(1, 7)]
    s = samplers_by_name(measured)
    return {"distance": statistics.mean(d), "near": sum(1 for x in d if x <= 2.5),
            "desks": sum(1 for i in range(1, 7) if in_range(s["ws%d.desk.task" % i])),
            "screens": sum(1 for i in range(1, 7) if in_range(s["ws%d.monitor.glare" % i])),
            "lux": [s["ws%d.desk.task" % i]["value"] for i in range(1, 7)], "C": measured["C"]}


def fig7(r, out):
    cases = [("morning", paper("fig7-office-morning"), paper("fig7-office-morning")),
             ("afternoon", paper("fig7-office-afternoon"), paper("fig7-office-afternoon")),
             ("evening", paper("fig7-office-evening"), paper("fig7-office-evening")),
             ("morning, lighting weight 0", variant(out, "fig7-morning-w0", "fig7-office-morning.json", no_light),
              paper("fig7-office-morning")),
             ]
    goals = variant(out, "fig7-morning-attainable", "fig7-office-morning.json", attainable)
    cases.append(("morning, attainable goals", goals, goals))

    def one(job):
        label, scene, judge, seed = job
        folder = os.path.join(out, "fig7", label.replace(",", "").replace(" ", "-"), str(seed))
        report = r.optimize(scene, folder, seed)
        paths = load(judge)["optimizer"]["report_paths_per_point"]
        m = r.measure(judge, os.path.join(folder, "layout.json"), seed + REMEASURE_OFFSET, paths,
                      cache=os.path.join(folder, "measured.json"))
        summary = office_summary(load(os.path.join(folder, "layout.json")), m)
        summary.update(seconds=report["seconds"], reported=report["C"], reported_se=report.get("C_std_error", 0.0),
                       C_se=m["C_std_error"], same_scene=judge == scene, stopped=report["stop_reason"] == "zero_cost",
                       worst=max((abs(x["value"] - min(max(x["value"], x["target"][0]),
                                                        x["target"][1] if x["target"][1] is not None else math.inf))
                                  / x["target"][0 if x["value"] < x["target"][0] else 1]
                                  for x in m["samplers"] if x["penalty"] > 0), default=0.0))
        if seed == 1 and label in ("morning", "afternoon", "evening"):
            plan(r, scene, os.path.join(folder, "layout.json"), os.path.join(folder, "pictures"),
                 os.path.join(ROOT, "docs", "images", "fig7-%s-plan.png" % label))
        return label, seed, summary

    jobs = [(label, scene, judge, seed) for label, scene, judge in cases for seed in range(1, FIG7_SEEDS + 1)]
    return r.map(one, jobs)


def plan(r, scene, layout, folder, image):
    """The layout's plan (luxplan render's plan.png) copied to `image`."""
    if not os.path.exists(os.path.join(folder, "plan.png")):
        r.run(["render", scene, "--layout", layout, "-o", folder, "--width", "96", "--height", "64", "--spp", "1",
               "--threads", "1"])
    shutil.copyfile(os.path.join(folder, "plan.png"), image)


def fig7_page(rows):
    labels = []
    for label, _, _ in rows:
        if label not in labels:
            labels.append(label)
    lines = ["## Figure 7: the office at three times of day (%d seeds)" % FIG7_SEEDS, "",
             "`fig7-office-{morning,afternoon,evening}.json` at their own settings, seeds 1–%d; a control "
             "with lighting weight 0 (the morning scene, rules only) and a variant whose daylight goals the "
             "morning allows (desks 300–1500 lx, screens ≤ 400 cd/m²). Every final layout is measured again "
             "with seed + %d at 512 paths per point, in the morning scene for the control (its C is the "
             "morning's w = 0.5 cost of a layout that ignored the light). Distance: 9 m − x of each "
             "workstation (the east windows), mean over the six. Intervals: 95%% bootstrap over seeds."
             % (FIG7_SEEDS, REMEASURE_OFFSET), "",
             "| case | distance from the windows (m) | desks within 2.5 m | desks in range | screens in range | C (independent) | runs at C = 0 | stopped at a confirmed C = 0 | largest miss | search time (s) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    means = {}
    for label in labels:
        rs = [s for (l, _, s) in rows if l == label]
        means[label] = statistics.mean(s["distance"] for s in rs)
        lines.append("| %s | %s | %.1f | %.1f / 6 | %.1f / 6 | %s | %d / %d | %d / %d | %.1f%% | %.1f (%.1f–%.1f) |" % (
            label, ci([s["distance"] for s in rs], 2), statistics.mean(s["near"] for s in rs),
            statistics.mean(s["desks"] for s in rs), statistics.mean(s["screens"] for s in rs),
            ci([s["C"] for s in rs], 3), sum(1 for s in rs if s["C"] == 0), len(rs),
            sum(1 for s in rs if s["stopped"]), len(rs), 100 * max(s["worst"] for s in rs),
            statistics.mean(s["seconds"] for s in rs), min(s["seconds"] for s in rs), max(s["seconds"] for s in rs)))
    lines += ["", "\"Largest miss\": over the runs, the farthest any sampler of the independent measurement is from "
              "its range, as a share of the bound it misses. \"Stopped at a confirmed C = 0\": the search's own "
              "estimate reached 0 and a measurement with a seed of its own at 512 paths confirmed it (optimize's "
              "stop rule); the independent measurement may still find a desk a lux or two short of 300."]
    lines += ["", "| morning (sun in the east windows) | afternoon (sky light) | evening (panels only) |", "|---|---|---|",
              "| ![morning plan](images/fig7-morning-plan.png) | ![afternoon plan](images/fig7-afternoon-plan.png) "
              "| ![evening plan](images/fig7-evening-plan.png) |", "", "(Seed 1 of each, `luxplan render --layout`'s "
              "plan: the work plane in false colour against the desks' target, the windows on the right.)"]
    order = sorted(["morning", "afternoon", "evening"], key=lambda l: -means[l])
    distances = {l: [s["distance"] for (ll, _, s) in rows if ll == l] for l in labels}
    diff = bootstrap_difference(distances["morning"], distances["evening"])
    holds = diff[1] > 0
    lines += ["", "**What it shows.** Mean distance from the windows: morning %.2f m, afternoon %.2f m, evening "
              "%.2f m, and %.2f m with the light ignored (the control); ordered from farthest: %s. Morning minus "
              "evening: %.2f m [%.2f, %.2f]. The paper's claim, that desks keep away from the windows when the "
              "sun comes in and use the whole room at night, %s." % (
                  means["morning"], means["afternoon"], means["evening"], means["morning, lighting weight 0"],
                  ", ".join(order), diff[0], diff[1], diff[2],
                  "holds here (the interval is above 0)" if holds else
                  "is not borne out here at the scenes' own settings (the interval reaches 0 or below)"), ""]
    night = [s for (l, _, s) in rows if l == "evening"]
    stopped = [s for s in night if s["stopped"]]
    if stopped:
        lines += ["The evening office (every goal attainable, the paper's \"late evening\" run: 15 s on a GPU) from a "
                  "uniform start: %d of %d runs stop at a confirmed C = 0, after %.1f s on average (%.1f–%.1f s, one "
                  "thread each, two runs at a time); on the independent measurement %d of %d are exactly 0 and no "
                  "sampler of any run misses its range by more than %.1f%%." % (
                      len(stopped), len(night), statistics.mean(s["seconds"] for s in stopped),
                      min(s["seconds"] for s in stopped), max(s["seconds"] for s in stopped),
                      sum(1 for s in night if s["C"] == 0), len(night), 100 * max(s["worst"] for s in night)), ""]
    return lines + ATTAINABLE + honest_page(rows)


# Not run by this script: the attainable variant `make demo` runs, measured with the
# commands it names (docs/optimizer.md, "Measured"); kept here so the page keeps it.
ATTAINABLE = """### Attainable variants of the morning office

The paper's morning office stays as it is: six desks cannot all keep out of the sun that
the clear east windows let in, and its verdicts say so ("out of reach", "reached: a
trade-off"); the table's "attainable goals" row widens its bands (desks 300–1500 lx,
screens ≤ 400 cd/m²) and still meets no run's every goal. The daylit office changes the
room instead, as a designer would, and every goal becomes attainable at once:

- `scenes/demo/daylit-office.json` (`make demo`; written by `scenes/demo/generate.py`):
  solar-control glazing (45%), six 2400 lm panels, five workstations, desks 300–750 lx,
  screens at most 150 cd/m². Seeds 1–5 at up to 1000 paths per point: every run ends
  with every goal met and every rule held in a measurement with a seed no search used
  (5 of 5, 66–93 s each on 2 cores, 5358–6937 iterations; commit c834c36,
  [optimizer.md](optimizer.md), "Measured"); the search moves the desks out of the sun
  band by the windows and turns the screens away from them.
- With six workstations, the same glazing, panels at 3200 lm and desks at 300–750 lx,
  no search found a solution: desks read 750 lx about 3.8 m from the west wall, where
  five workstations 2 m apart fit, and a search of 10⁴ iterations left the sixth at
  1591 lx in the sun band with every other goal met. Hence five in the demo. A variant's
  goals are best checked for a solution first: `scripts/scene-family.py` plants one.
""".split("\n")


def honest_page(rows):
    """The reported C (optimize's report.json) against the independent re-measure."""
    lines = ["## The reported C is honest", "",
             "`optimize` reports C measured again with a seed of its own (the best few layouts re-measured, "
             "the chosen one once more: [optimizer.md](optimizer.md)). Here it is set against the independent "
             "measurement of the same `layout.json` above (seed + %d), on the daylit offices with their six glare "
             "samplers and on the evening office: z = (reported − independent) / √(se² + se²). Within noise, |z| "
             "stays mostly below 2." % REMEASURE_OFFSET, "",
             "| case | runs | mean reported C | mean independent C | mean z | largest abs(z) | runs with abs(z) < 2 |",
             "|---|---|---|---|---|---|---|"]
    for label in ("morning", "afternoon", "evening", "morning, attainable goals"):
        rs = [s for (l, _, s) in rows if l == label and s.get("same_scene")]
        if not rs:
            continue
        z = [(s["reported"] - s["C"]) / math.sqrt(s["reported_se"] ** 2 + s["C_se"] ** 2)
             if (s["reported_se"] > 0 or s["C_se"] > 0) else 0.0 for s in rs]
        lines.append("| %s | %d | %.4f | %.4f | %+.2f | %.2f | %d / %d |" % (
            label, len(rs), statistics.mean(s["reported"] for s in rs), statistics.mean(s["C"] for s in rs),
            statistics.mean(z), max(abs(x) for x in z), sum(1 for x in z if abs(x) < 2), len(rs)))
    return lines + [""]


def bootstrap_difference(a, b, resamples=2000, seed=54321):
    """mean(a) - mean(b) with a 95% percentile bootstrap interval (independent samples)."""
    rng = random.Random(seed)
    boots = sorted(statistics.mean(rng.choice(a) for _ in a) - statistics.mean(rng.choice(b) for _ in b)
                   for _ in range(resamples))
    return statistics.mean(a) - statistics.mean(b), boots[int(0.025 * resamples)], boots[int(0.975 * resamples) - 1]


# ---------------------------------------------------------------- fig8: lab

FIG8_SEEDS = 4


def fig8(r, out):
    scene = paper("fig8-lab")
    paths = load(scene)["optimizer"]["report_paths_per_point"]
    sym = load(paper("layouts/fig8-lab-symmetric"))
    turned = copy.deepcopy(sym)
    for name in ("i1", "i2", "i3", "i4"):
        turned["entities"][name]["rotation"] = 90
    layouts = {"symmetric, desks facing the windows (0°)": paper("layouts/fig8-lab-symmetric"),
               "symmetric, islands turned 90°": os.path.join(out, "fig8", "symmetric-90.json")}
    write_json(layouts["symmetric, islands turned 90°"], turned)

    def one(job):
        label, layout, seed = job
        if layout is None:
            folder = os.path.join(out, "fig8", "optimized-%d" % seed)
            r.optimize(scene, folder, seed)
            layout = os.path.join(folder, "layout.json")
            cache = os.path.join(folder, "measured.json")
        else:
            cache = os.path.join(out, "fig8", "%s-%d.measured.json" % (label[:20].replace(" ", "_").replace(",", ""), seed))
        m = r.measure(scene, layout, seed + REMEASURE_OFFSET, paths, cache=cache)
        s = m["samplers"]
        glare = [x["value"] for x in s if x["type"] == "directional"]
        return label, seed, {"peak": max(glare), "mean": statistics.mean(glare),
                             "desks": sum(1 for x in s if x["type"] == "planar" and in_range(x)),
                             "screens": sum(1 for x in s if x["type"] == "directional" and in_range(x)),
                             "C": m["C"]}

    jobs = [(label, path, 1) for label, path in layouts.items()]
    jobs += [("optimized", None, seed) for seed in range(1, FIG8_SEEDS + 1)]
    return r.map(one, jobs)


def fig8_page(rows):
    lines = ["## Figure 8: the computer lab against its symmetric arrangements", "",
             "`fig8-lab.json` (8 desks, 8 screens, low November sun through three south windows) optimized "
             "with seeds 1–%d at its own settings, against the usual 2 × 2 grid of islands in both "
             "symmetric orientations (`layouts/fig8-lab-symmetric.json`, and the same islands turned 90°). "
             "Each layout measured with seed + %d at 512 paths per point." % (FIG8_SEEDS, REMEASURE_OFFSET), "",
             "| layout | peak glare (cd/m², max over 8 screens) | mean glare (cd/m²) | desks in 300–500 lx | screens < 100 cd/m² | C |",
             "|---|---|---|---|---|---|"]
    labels = []
    for label, _, _ in rows:
        if label not in labels:
            labels.append(label)
    peak = {}
    for label in labels:
        rs = [s for (l, _, s) in rows if l == label]
        peak[label] = statistics.mean(s["peak"] for s in rs)
        name = label if len(rs) == 1 else "%s (%d seeds; mean [95%% bootstrap])" % (label, len(rs))
        lines.append("| %s | %s | %s | %.1f / 8 | %.1f / 8 | %s |" % (
            name, ci([s["peak"] for s in rs], 0) if len(rs) > 1 else fmt(rs[0]["peak"], 0),
            ci([s["mean"] for s in rs], 0) if len(rs) > 1 else fmt(rs[0]["mean"], 0),
            statistics.mean(s["desks"] for s in rs), statistics.mean(s["screens"] for s in rs),
            ci([s["C"] for s in rs], 3) if len(rs) > 1 else fmt(rs[0]["C"], 3)))
    best_sym = min(v for k, v in peak.items() if k != "optimized")
    lines += ["", "**What it shows.** The optimized layouts' mean peak glare is %.0f cd/m² against %.0f for the "
              "better symmetric arrangement (%.1f× lower)." % (peak["optimized"], best_sym,
                                                              best_sym / max(peak["optimized"], 1e-9)), ""]
    return lines


# ---------------------------------------------------------------- fig9: lamps

FIG9_SEEDS = 8


def without_lamps(scene):
    for e in scene["entities"]:
        e.pop("emitters", None)
        for c in e.get("children", []):
            c.pop("emitters", None)


def fig9(r, out):
    cases = {"with the movable lamps": paper("fig9-apartment-night"),
             "without them": variant(out, "fig9-night-without-lamps", "fig9-apartment-night.json", without_lamps)}

    def one(job):
        label, scene, seed = job
        folder = os.path.join(out, "fig9", label.replace(" ", "-"), str(seed))
        report = r.optimize(scene, folder, seed)
        m = r.measure(scene, os.path.join(folder, "layout.json"), seed + REMEASURE_OFFSET, 512,
                      cache=os.path.join(folder, "measured.json"))
        s = samplers_by_name(m)
        return label, seed, {"C": m["C"], "in_range": sum(1 for x in m["samplers"] if in_range(x)),
                             "dining": s["dining.table"]["value"], "reading": s["reading.book"]["value"],
                             "tv": s["living.tv.glare"]["value"], "iterations": report["iterations"]}

    jobs = [(label, scene, seed) for label, scene in cases.items() for seed in range(1, FIG9_SEEDS + 1)]
    # The lamps' own light: the scene's placement measured with and without them.
    start = {label: r.measure(scene, None, 1, 16384, cache=os.path.join(out, "fig9", label.replace(" ", "-") + "-start.json"))
             for label, scene in cases.items()}
    return {"runs": r.map(one, jobs), "start": start}


def fig9_page(data):
    rows, start = data["runs"], data["start"]
    lines = ["## Figure 9: the apartment by night, with and without its movable lamps (%d seeds)" % FIG9_SEEDS, "",
             "`fig9-apartment-night.json` (a floor lamp and a reading lamp, each a 3500 lm sphere in an open, "
             "translucent `stand_lamp` shade, carried by movable entities) against the same scene with the lamps' "
             "emitters removed. Targets: dining table 200–400 lx, book 300–500 lx, TV ≤ 60 cd/m². Each final "
             "layout measured with seed + %d at 512 paths per point." % REMEASURE_OFFSET, "",
             "| case | samplers in range | dining table (lx) | book (lx) | TV glare (cd/m²) | C (independent) | runs at C = 0 |",
             "|---|---|---|---|---|---|---|"]
    for label in ("with the movable lamps", "without them"):
        rs = [s for (l, _, s) in rows if l == label]
        lines.append("| %s | %.1f / 3 | %s | %s | %s | %s | %d / %d |" % (
            label, statistics.mean(s["in_range"] for s in rs), ci([s["dining"] for s in rs], 0),
            ci([s["reading"] for s in rs], 0), ci([s["tv"] for s in rs], 1), ci([s["C"] for s in rs], 3),
            sum(1 for s in rs if s["C"] == 0), len(rs)))
    a, b = (samplers_by_name(start[l]) for l in ("with the movable lamps", "without them"))
    lit = all(a[k]["value"] > b[k]["value"] + 3 * math.hypot(a[k]["std_error"], b[k]["std_error"])
              for k in ("dining.table", "reading.book"))
    lines += ["", "In the scene's own placement (`measure --paths 16384 --seed 1`) the lamps give the dining table "
              "%.1f lx against %.1f without them, and the book %.0f lx against %.0f: %s" % (
                  a["dining.table"]["value"], b["dining.table"]["value"], a["reading.book"]["value"],
                  b["reading.book"]["value"], "**they measurably light the room.**" if lit else
                  "**they do not measurably light the room.**"), ""]
    return lines


# ---------------------------------------------------------------- fig10: hall

FIG10_SEEDS = 4
DANCE_FLOOR = (9.0, 5.0, 15.0, 11.0)  # x0, y0, x1, y1 (scenes/paper/README.md)


def table_radius(entity):
    """The table set's reach from its centre in plan (its parts' farthest corner)."""
    reach = 0.0
    for p in entity["parts"]:
        (sx, sy, _), (cx, cy, _) = p["box"]["size"], p["box"]["center"]
        reach = max(reach, math.hypot(abs(cx) + sx / 2, abs(cy) + sy / 2))
    return reach


def hall_summary(scene, layout, measured):
    ents = {e["name"]: e for e in scene["entities"]}
    names = sorted(ents, key=lambda n: int(n[1:]))
    centres = [tuple(layout["entities"][n]["position"][:2]) for n in names]
    radius = max(table_radius(ents[n]) for n in names)
    x0, y0, x1, y1 = DANCE_FLOOR
    step, covered, cells = 0.05, 0, 0
    y = y0 + step / 2
    while y < y1:
        x = x0 + step / 2
        while x < x1:
            cells += 1
            covered += any((x - cx) ** 2 + (y - cy) ** 2 <= radius * radius for cx, cy in centres)
            x += step
        y += step
    gap = min(math.dist(a, b) for i, a in enumerate(centres) for b in centres[i + 1:])
    tops = [s for s in measured["samplers"]]
    return {"occupancy": covered / cells, "on_floor": sum(1 for cx, cy in centres if x0 <= cx <= x1 and y0 <= cy <= y1),
            "gap": gap, "in_range": sum(1 for s in tops if in_range(s)), "tables": len(tops), "C": measured["C"],
            "radius": radius}


def fig10(r, out):
    def one(job):
        name, seed = job
        scene = paper(name)
        folder = os.path.join(out, "fig10", name, str(seed))
        r.optimize(scene, folder, seed)
        paths = load(scene)["optimizer"]["report_paths_per_point"]
        m = r.measure(scene, os.path.join(folder, "layout.json"), seed + REMEASURE_OFFSET, paths,
                      cache=os.path.join(folder, "measured.json"))
        return name, seed, hall_summary(load(scene), load(os.path.join(folder, "layout.json")), m)

    jobs = [(name, seed) for name in ("fig10-event-hall-night", "fig10-event-hall-day") for seed in range(1, FIG10_SEEDS + 1)]
    return r.map(one, jobs)


def fig10_page(rows):
    radius = rows[0][2]["radius"]
    lines = ["## Figure 10: the event hall (%d seeds each)" % FIG10_SEEDS, "",
             "Ten table sets (table and eight chairs, one entity), 150–350 lx on each table, centres ≥ 3.2 m "
             "apart, no blocker on the dance floor (x 9–15 m, y 5–11 m). Occupancy: the share of the dance "
             "floor under a table set (a disk of its reach, %.2f m, on a 5 cm grid). Gap: the smallest "
             "distance between two table centres. Each final layout measured with seed + %d at 256 paths "
             "per point." % (radius, REMEASURE_OFFSET), "",
             "| scene | tables in range | tables centred on the dance floor | dance-floor occupancy | smallest centre gap (m) | C (independent) |",
             "|---|---|---|---|---|---|"]
    for name, title in (("fig10-event-hall-night", "night"), ("fig10-event-hall-day", "day")):
        rs = [s for (n, _, s) in rows if n == name]
        lines.append("| %s | %.1f / %d | %.2f | %s | %s (min %.2f) | %s |" % (
            title, statistics.mean(s["in_range"] for s in rs), rs[0]["tables"],
            statistics.mean(s["on_floor"] for s in rs), ci([s["occupancy"] for s in rs], 3),
            ci([s["gap"] for s in rs], 2), min(s["gap"] for s in rs), ci([s["C"] for s in rs], 3)))
    night = [s for (n, _, s) in rows if n == "fig10-event-hall-night"]
    occupied = statistics.mean(s["occupancy"] for s in night)
    gaps = [s["gap"] for (_, _, s) in rows]
    below = sum(1 for g in gaps if g < 3.2 - 1e-3)
    lines += ["", "**What it shows.** By night %.1f%% of the dance floor is under a table on average, with no "
              "blocker there: %s. %s" % (
                  100 * occupied,
                  "the spotlights' light (far above 350 lx) keeps the tables off it, as the paper says" if occupied < 0.05
                  else "the light alone does not keep the tables off it, against the paper's claim",
                  "Every run keeps its table centres at least 3.2 m apart." if below == 0 else
                  "%d of %d runs have two table centres closer than 3.2 m (the smallest %.2f m): the clearance is a "
                  "soft minimum (Eq. 2's tolerance), which the search trades against the light." % (
                      below, len(gaps), min(gaps))), ""]
    return lines


# ---------------------------------------------------------------- the page

EXPERIMENTS = {"fig6": (fig6, fig6_page), "fig7": (fig7, fig7_page), "fig8": (fig8, fig8_page),
               "fig9": (fig9, fig9_page), "fig10": (fig10, fig10_page)}


def machine():
    model = platform.processor() or "unknown CPU"
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return "%s, %d cores, %s" % (model, os.cpu_count() or 0, platform.platform())


def commit():
    def git(*args):
        return subprocess.run(["git", "-C", ROOT] + list(args), capture_output=True, text=True).stdout.strip()
    head = git("rev-parse", "--short", "HEAD") or "unknown"
    # Only what builds luxplan and runs it counts (this script rewrites docs/ itself).
    changed = git("status", "--porcelain", "--untracked-files=no", "--", "src", "apps", "scripts", "scenes", "CMakeLists.txt")
    return head + (" (with uncommitted changes)" if changed else "")


HEADER = """# Experiments: the paper's section 7 with statistics

Every table on this page is written by `scripts/experiments.py` (run it to regenerate
them, on this machine or a dask cluster: [python.md](python.md); docs/performance.md has
the speed figures). Each search is a plain `luxplan
optimize` at the scene's own settings unless a table says otherwise, and **every cost
below is an independent measurement** (`luxplan measure --layout` with a seed no
search used), not the search's own estimate, which is low by the luck of its noise
([optimizer.md](optimizer.md), *The result*).

Generated on {date} on {machine}, {jobs} single-threaded runs at a time. Each
experiment's runs (commit of the binary's sources, wall time of all its runs and
measurements): {provenance}. The scenes are in
[scenes/paper/](../scenes/paper/README.md).

"""


def provenance(saved):
    """Where and how long each experiment's numbers were made."""
    parts = []
    for name in EXPERIMENTS:
        path = saved(name)
        if os.path.exists(path):
            d = load(path)
            parts.append("%s: commit %s, %.0f s" % (name, d["commit"], d["seconds"]))
    return "; ".join(parts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--luxplan", default=os.path.join(ROOT, "build", "luxplan"))
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "experiments"))
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--scheduler", help="a dask scheduler's address (default: a LocalCluster of JOBS workers)")
    ap.add_argument("--only", default=",".join(EXPERIMENTS))
    ap.add_argument("--doc", default=os.path.join(ROOT, "docs", "experiments.md"))
    args = ap.parse_args()
    only = [x for x in args.only.split(",") if x]
    for x in only:
        if x not in EXPERIMENTS:
            sys.exit("experiments.py: unknown experiment %r (known: %s)" % (x, ", ".join(EXPERIMENTS)))
    if not os.access(args.luxplan, os.X_OK):
        sys.exit("experiments.py: %s is not an executable (build it first: make build)" % args.luxplan)
    runner = Runner(os.path.abspath(args.luxplan), os.path.abspath(args.out), args.jobs, args.scheduler)
    page = []
    saved = lambda name: os.path.join(args.out, name + ".json")
    for name, (run, render) in EXPERIMENTS.items():
        if name in only:
            t0 = time.monotonic()
            print("experiments.py: %s ..." % name, file=sys.stderr, flush=True)
            data = run(runner, args.out)
            previous = load(saved(name)) if os.path.exists(saved(name)) else None
            elapsed = time.monotonic() - t0
            # Runs reused from OUT keep the commit and time of the call that made them.
            if previous and previous.get("data") == json.loads(json.dumps(data)):
                elapsed, made = previous["seconds"], previous["commit"]
            else:
                made = commit()
            write_json(saved(name), {"commit": made, "seconds": elapsed, "data": data})
            print("experiments.py: %s done in %.0f s" % (name, time.monotonic() - t0), file=sys.stderr, flush=True)
        if os.path.exists(saved(name)):
            page += render(load(saved(name))["data"])
    runner.close()
    text = HEADER.format(date=time.strftime("%Y-%m-%d"), provenance=provenance(saved), machine=machine(),
                         jobs=args.jobs) + "\n".join(page)
    tmp = args.doc + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, args.doc)
    print("experiments.py: wrote %s" % args.doc, file=sys.stderr)


if __name__ == "__main__":
    main()
