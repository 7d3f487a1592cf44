#!/usr/bin/env bash
# `make demo`: the main job on the daylit office (scenes/demo/daylit-office.json: the
# paper's Figure 7 office under the equinox morning sun, solar-control glazing, ceiling
# panels, five workstations, every goal attainable): validate it, summarize it, optimize
# its layout, and measure the result with a seed no search used.
set -euo pipefail
luxplan=${1:?luxplan binary}
scene=${2:?scene file}
out=${3:?output folder}
mkdir -p "$out"
"$luxplan" validate "$scene"
"$luxplan" info "$scene" | tee "$out/summary.txt"
echo
echo "== optimizing (Ctrl-C stops and keeps the best layout so far)"
"$luxplan" optimize "$scene" -o "$out"
echo
echo "== the optimized layout, measured"
"$luxplan" measure "$scene" --layout "$out/layout.json" --paths 1000 --seed 20261206 | tee "$out/measure.txt"
echo
echo "demo: outputs in $out/"
echo "  layout.json   the optimized placement (read back with --layout)"
echo "  report.json   costs, every sampler against its target, every constraint's penalty"
echo "  trace.csv     current and best cost per iteration"
echo "  plan.png, plan_initial_vs_optimized.png, render.png, render_luminance.png, convergence.png, scene.glb"
echo "  report.html   everything on one page: open it in a browser (report.pdf: the same, printed on A4)"
echo "  summary.txt, measure.txt"
