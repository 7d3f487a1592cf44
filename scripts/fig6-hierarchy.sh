#!/usr/bin/env bash
# The paper's Figure 6: hierarchical against flat optimization at equal iterations,
# over several seeds, on one scene. Writes OUT/<scene>/{hierarchical,flat}-<seed>/
# (every run's layout.json, report.json, trace.csv), the chart OUT/<scene>.svg and
# the tables OUT/<scene>.md: the search's best C at several iterations
# (scripts/plot_traces.py) and the final layouts' re-measured C (scripts/report_table.py).
#
#   scripts/fig6-hierarchy.sh SCENE.json [ITERATIONS] [SEEDS] [OUT]
#   e.g. scripts/fig6-hierarchy.sh scenes/paper/fig9-apartment-night.json 5000 8 out/fig6
#
# Runs are single-threaded, JOBS (default: the number of cores) at a time.
set -euo pipefail
scene=${1:?usage: $0 SCENE.json [ITERATIONS] [SEEDS] [OUT]}
iterations=${2:-5000}
seeds=${3:-8}
out=${4:-out/fig6}
jobs=${JOBS:-$(nproc)}
luxplan=${LUXPLAN:-build/luxplan}
name=$(basename "$scene" .json)
mkdir -p "$out/$name"

run() {  # mode seed [flag]
  local dir="$out/$name/$1-$2"
  if ! "$luxplan" optimize "$scene" -o "$dir" --iterations "$iterations" --seed "$2" --threads 1 -q \
      --no-pictures ${3:+"$3"} > "$dir.log" 2>&1; then
    echo "run $1 $2 failed: see $dir.log" >&2
    return 1
  fi
  echo "  $1 seed $2: $(grep '^optimize:' "$dir.log")"
}
running=0
for seed in $(seq 1 "$seeds"); do
  for mode in hierarchical flat; do
    if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
    run "$mode" "$seed" $([ "$mode" = flat ] && echo --flat) &
    running=$((running + 1))
  done
done
while [ "$running" -gt 0 ]; do wait -n; running=$((running - 1)); done

python3 "$(dirname "$0")/plot_traces.py" -o "$out/$name.svg" \
  --title "$name: best C vs iteration ($seeds seeds)" \
  --group hierarchical "$out/$name"/hierarchical-*/trace.csv \
  --group "flat (--flat)" "$out/$name"/flat-*/trace.csv | tee "$out/$name.md"
echo >> "$out/$name.md"
python3 "$(dirname "$0")/report_table.py" \
  --group hierarchical "$out/$name"/hierarchical-*/report.json \
  --group "flat (--flat)" "$out/$name"/flat-*/report.json | tee -a "$out/$name.md"
echo "wrote $out/$name.svg and $out/$name.md"
