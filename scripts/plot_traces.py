#!/usr/bin/env python3
"""Average the best-cost curves of several luxplan trace.csv files and draw them as SVG.

Usage:
    python3 scripts/plot_traces.py -o chart.svg \
        --group "hierarchical" out/fig6/hier-*/trace.csv \
        --group "flat" out/fig6/flat-*/trace.csv \
        [--title TEXT] [--linear] [--floor 1e-4]

Each trace.csv has the columns iteration,current,best,feasible (docs/optimizer.md).
Per group, every run's `best` column is read as a step function of the iteration:
the value of the last row at or before the iteration is carried forward (also past
the run's last row, e.g. when it stopped at C = 0); `best` is empty until the first
feasible layout (none has passed the geometric rules yet). At each iteration of the
common grid (the union of every row's iteration) the chart's upper panel shows the
mean best C over the seeds, drawn only where every seed has a feasible layout (a
mean over the lucky seeds alone would flatter a mode), with a light band from the
min to the max over the seeds that have one; the y axis is logarithmic by default
(costs of 0 are drawn at --floor). The lower panel shows the fraction of seeds with
a feasible layout. A table at a few iterations (--at, default 10/25/50/100% of the
run) is printed on standard output: seeds feasible, mean (when all are) and median
(an infeasible seed counts as worse than any feasible one) of the best C.

Python 3 standard library only.
"""

import argparse
import bisect
import csv
import math
import sys

COLOURS = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf"]


def read_trace(path):
    """Return sorted lists (iterations, best values or None)."""
    its, best = [], []
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            it = int(float(row["iteration"]))
            b = row.get("best", "")
            b = b.strip() if b is not None else ""
            val = None
            if b not in ("", "null", "nan", "inf"):
                val = float(b)
                if not math.isfinite(val):
                    val = None
            its.append(it)
            best.append(val)
    order = sorted(range(len(its)), key=lambda i: its[i])
    return [its[i] for i in order], [best[i] for i in order]


def value_at(trace, it):
    its, best = trace
    k = bisect.bisect_right(its, it) - 1
    if k < 0:
        return None
    return best[k]


def group_curve(traces, grid):
    rows = []
    for it in grid:
        vals = [v for v in (value_at(t, it) for t in traces) if v is not None]
        mean = sum(vals) / len(vals) if vals and len(vals) == len(traces) else None
        if vals:
            rows.append((it, mean, min(vals), max(vals), len(vals) / len(traces)))
        else:
            rows.append((it, None, None, None, 0.0))
    return rows


def nice_ticks(lo, hi, n=5):
    span = hi - lo
    if span <= 0:
        return [lo]
    raw = span / n
    mag = 10 ** math.floor(math.log10(raw))
    step = min((m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw), default=10 * mag)
    first = math.ceil(lo / step) * step
    ticks = []
    t = first
    while t <= hi + 1e-9 * span:
        ticks.append(round(t, 10))
        t += step
    return ticks


def fmt(v):
    if v == 0:
        return "0"
    if abs(v) >= 1000 or abs(v) < 1e-3:
        return "%.0e" % v if abs(v) < 1e-3 else "%g" % v
    return "%g" % float("%.3g" % v)


def esc(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def svg_chart(groups, curves, title, log_y, floor, width=760, height=560):
    left, right, top, bottom = 80, 20, 40, 60
    panel = 110  # the feasible-fraction panel below the cost panel
    pw, ph = width - left - right, height - top - bottom - panel - 20
    x_max = max(r[0] for c in curves for r in c) or 1
    vals = [v for c in curves for r in c for v in r[1:4] if v is not None]
    if log_y:
        vals = [max(v, floor) for v in vals]
        y_lo = 10 ** math.floor(math.log10(min(vals)))
        y_hi = 10 ** math.ceil(math.log10(max(vals)))
        if y_hi <= y_lo:
            y_hi = y_lo * 10

        def ty(v):
            v = max(v, floor)
            return top + ph * (1 - (math.log10(v) - math.log10(y_lo)) / (math.log10(y_hi) - math.log10(y_lo)))
        yticks = [10 ** e for e in range(int(round(math.log10(y_lo))), int(round(math.log10(y_hi))) + 1)]
    else:
        y_lo, y_hi = 0.0, max(vals) * 1.05 or 1.0

        def ty(v):
            return top + ph * (1 - (v - y_lo) / (y_hi - y_lo))
        yticks = nice_ticks(y_lo, y_hi)

    def tx(it):
        return left + pw * it / x_max

    out = [
        '<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d" '
        'font-family="sans-serif" font-size="12">' % (width, height, width, height),
        '<rect width="100%" height="100%" fill="white"/>',
        '<text x="%g" y="22" text-anchor="middle" font-size="14">%s</text>' % (left + pw / 2, esc(title)),
    ]
    # grid and ticks
    for t in yticks:
        y = ty(t)
        out.append('<line x1="%g" y1="%.1f" x2="%g" y2="%.1f" stroke="#e6e6e6"/>' % (left, y, left + pw, y))
        out.append('<line x1="%g" y1="%.1f" x2="%g" y2="%.1f" stroke="black"/>' % (left - 5, y, left, y))
        label = ("1e%d" % round(math.log10(t))) if log_y else fmt(t)
        out.append('<text x="%g" y="%.1f" text-anchor="end">%s</text>' % (left - 8, y + 4, label))
    for t in nice_ticks(0, x_max, 6):
        x = tx(t)
        out.append('<line x1="%.1f" y1="%g" x2="%.1f" y2="%g" stroke="#e6e6e6"/>' % (x, top, x, top + ph))
        out.append('<line x1="%.1f" y1="%g" x2="%.1f" y2="%g" stroke="black"/>' % (x, top + ph, x, top + ph + 5))
        out.append('<text x="%.1f" y="%g" text-anchor="middle">%s</text>' % (x, top + ph + 19, fmt(t)))
        fb = top + ph + 40 + panel
        out.append('<line x1="%.1f" y1="%g" x2="%.1f" y2="%g" stroke="black"/>' % (x, fb, x, fb + 5))
        out.append('<text x="%.1f" y="%g" text-anchor="middle">%s</text>' % (x, fb + 19, fmt(t)))
    out.append('<rect x="%g" y="%g" width="%g" height="%g" fill="none" stroke="black"/>' % (left, top, pw, ph))
    out.append('<text x="%g" y="%g" text-anchor="middle">iteration</text>' % (left + pw / 2, height - 12))
    ylab = "best cost C (mean over seeds%s)" % (", log scale" if log_y else "")
    out.append('<text transform="translate(18,%g) rotate(-90)" text-anchor="middle">%s</text>' % (top + ph / 2, ylab))
    # bands, then lines
    for gi, c in enumerate(curves):
        col = COLOURS[gi % len(COLOURS)]
        pts = [r for r in c if r[2] is not None]
        if not pts:
            continue
        upper = ["%.1f,%.1f" % (tx(r[0]), ty(r[3])) for r in pts]
        lower = ["%.1f,%.1f" % (tx(r[0]), ty(r[2])) for r in reversed(pts)]
        out.append('<polygon points="%s" fill="%s" fill-opacity="0.15" stroke="none"/>' % (" ".join(upper + lower), col))
    for gi, c in enumerate(curves):
        col = COLOURS[gi % len(COLOURS)]
        pts = [r for r in c if r[1] is not None]
        if not pts:
            continue
        line = " ".join("%.1f,%.1f" % (tx(r[0]), ty(r[1])) for r in pts)
        out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="2"/>' % (line, col))
    # legend
    lx, ly = left + pw - 230, top + 12
    out.append('<rect x="%g" y="%g" width="222" height="%d" fill="white" fill-opacity="0.85" stroke="#999"/>'
               % (lx, ly - 4, 22 * len(groups) + 26))
    for gi, (name, paths) in enumerate(groups):
        col = COLOURS[gi % len(COLOURS)]
        y = ly + 12 + 22 * gi
        out.append('<rect x="%g" y="%g" width="26" height="10" fill="%s" fill-opacity="0.15"/>' % (lx + 8, y - 5, col))
        out.append('<line x1="%g" y1="%g" x2="%g" y2="%g" stroke="%s" stroke-width="2"/>' % (lx + 8, y, lx + 34, y, col))
        out.append('<text x="%g" y="%g">%s (n = %d)</text>' % (lx + 42, y + 4, esc(name), len(paths)))
    out.append('<text x="%g" y="%g" fill="#555">line: mean; band: min..max</text>' % (lx + 8, ly + 16 + 22 * len(groups)))
    # feasible fraction
    ftop = top + ph + 40
    out.append('<rect x="%g" y="%g" width="%g" height="%g" fill="none" stroke="black"/>' % (left, ftop, pw, panel))
    for frac in (0, 0.5, 1):
        y = ftop + panel * (1 - frac)
        out.append('<line x1="%g" y1="%.1f" x2="%g" y2="%.1f" stroke="#e6e6e6"/>' % (left, y, left + pw, y))
        out.append('<text x="%g" y="%.1f" text-anchor="end">%g</text>' % (left - 8, y + 4, frac))
    out.append('<text transform="translate(18,%g) rotate(-90)" text-anchor="middle">seeds feasible</text>'
               % (ftop + panel / 2))
    for gi, c in enumerate(curves):
        col = COLOURS[gi % len(COLOURS)]
        line = " ".join("%.1f,%.1f" % (tx(r[0]), ftop + panel * (1 - r[4])) for r in c)
        out.append('<polyline points="%s" fill="none" stroke="%s" stroke-width="2"/>' % (line, col))
    out.append("</svg>")
    return "\n".join(out) + "\n"


def parse_args(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("-o", "--output", required=True, help="SVG file to write")
    p.add_argument("--title", default="Best cost vs iteration")
    p.add_argument("--linear", action="store_true", help="linear y axis (default: log)")
    p.add_argument("--floor", type=float, default=1e-4, help="value drawn for C = 0 on a log axis")
    p.add_argument("--at", type=int, nargs="+", help="iterations for the printed table")
    p.add_argument("--group", nargs="+", action="append", metavar=("NAME", "TRACE"), required=True,
                   help="a group name followed by its trace.csv files")
    a = p.parse_args(argv)
    for g in a.group:
        if len(g) < 2:
            p.error("--group needs a name and at least one trace.csv")
    return a


def main(argv=None):
    a = parse_args(sys.argv[1:] if argv is None else argv)
    groups = [(g[0], g[1:]) for g in a.group]
    traces = [[read_trace(f) for f in paths] for _, paths in groups]
    grid = sorted({it for ts in traces for t in ts for it in t[0]})
    curves = [group_curve(ts, grid) for ts in traces]
    with open(a.output, "w") as f:
        f.write(svg_chart(groups, curves, a.title, not a.linear, a.floor))
    last_it = grid[-1]
    at = a.at or sorted({max(1, last_it // 10), last_it // 4, last_it // 2, last_it})
    print("| iteration | group | seeds feasible | mean best C | median best C | min | max | seeds at C = 0 |")
    print("|---|---|---|---|---|---|---|---|")
    for it in at:
        for (name, paths), ts in zip(groups, traces):
            vals = [value_at(t, it) for t in ts]
            ok = sorted(v for v in vals if v is not None)
            ranked = ok + [math.inf] * (len(vals) - len(ok))
            median = ranked[(len(ranked) - 1) // 2] if len(ranked) % 2 else 0.5 * (ranked[len(ranked) // 2 - 1] + ranked[len(ranked) // 2])
            cell = lambda v: "%.4f" % v if v is not None and math.isfinite(v) else "–"
            print("| %d | %s | %d / %d | %s | %s | %s | %s | %d |" % (
                it, name, len(ok), len(vals), cell(sum(ok) / len(ok) if ok and len(ok) == len(vals) else None),
                cell(median), cell(ok[0] if ok else None), cell(ok[-1] if ok else None), sum(1 for v in ok if v == 0)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
