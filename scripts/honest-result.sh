#!/usr/bin/env bash
# Whether report.json's C is honest: for each seed, optimize SCENE at its own settings,
# then measure layout.json again with a seed neither the search nor the report used,
# at the report's paths per point. Prints the search's estimate of the result, the
# reported C, the independent C and their difference in standard errors (z).
#
#   scripts/honest-result.sh SCENE.json SEED...
#   e.g. scripts/honest-result.sh scenes/paper/fig4-glare.json 1 2 3 4
set -euo pipefail
scene=${1:?usage: $0 SCENE.json SEED...}
shift
luxplan=${LUXPLAN:-build/luxplan}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
for seed in "$@"; do
  "$luxplan" optimize "$scene" -o "$out/$seed" --seed "$seed" -q --no-pictures --threads 2 > "$out/$seed.log"
  paths=$(python3 -c "import json,sys; print(json.load(open(sys.argv[1]))['report_measurement']['paths_per_point'])" "$out/$seed/report.json")
  "$luxplan" measure "$scene" --layout "$out/$seed/layout.json" --seed $((seed + 100000)) --paths "$paths" --json \
    --threads 2 > "$out/$seed.measure.json"
  python3 - "$out/$seed/report.json" "$out/$seed.measure.json" "$seed" <<'PY'
import json, sys
r, m, seed = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), sys.argv[3]
se = (r["C_std_error"] ** 2 + m["C_std_error"] ** 2) ** 0.5
z = (r["C"] - m["C"]) / se if se > 0 else 0.0
print(f"| {seed} | {r['search_estimate']['C']:.4f} | {r['C']:.4f} ± {r['C_std_error']:.4f} | "
      f"{m['C']:.4f} ± {m['C_std_error']:.4f} | {z:+.2f} | {r['seconds']:.0f} |")
PY
done
