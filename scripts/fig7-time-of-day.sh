#!/usr/bin/env bash
# The paper's Figure 7: the office's six workstations at three times of day, over
# several seeds. Writes OUT/<time>-<seed>/ (layout.json, report.json, trace.csv) and
# prints, per time of day, how far the desks keep from the east windows (9 m - x of
# each workstation) and how many desk and screen goals hold (re-measured values).
#
#   scripts/fig7-time-of-day.sh [SEEDS] [ITERATIONS] [OUT]     e.g. 4 4000 out/fig7
#
# Runs are single-threaded, JOBS (default: the number of cores) at a time.
set -euo pipefail
seeds=${1:-4}
iterations=${2:-4000}
out=${3:-out/fig7}
jobs=${JOBS:-$(nproc)}
luxplan=${LUXPLAN:-build/luxplan}
here=$(dirname "$0")
mkdir -p "$out"

running=0
for seed in $(seq 1 "$seeds"); do
  for t in morning afternoon evening; do
    if [ "$running" -ge "$jobs" ]; then wait -n; running=$((running - 1)); fi
    ( "$luxplan" optimize "$here/../scenes/paper/fig7-office-$t.json" -o "$out/$t-$seed" \
        --iterations "$iterations" --seed "$seed" --threads 1 -q --no-pictures > "$out/$t-$seed.log" 2>&1 \
      && echo "  $t seed $seed: $(grep '^optimize:' "$out/$t-$seed.log")" ) &
    running=$((running + 1))
  done
done
while [ "$running" -gt 0 ]; do wait -n; running=$((running - 1)); done

python3 - "$out" "$seeds" <<'PY'
import json, statistics, sys
out, seeds = sys.argv[1], int(sys.argv[2])
print("| time of day | seed | distance from the windows: mean (min-max) | desks within 2.5 m | desks in 300-500 lx | screens < 100 cd/m2 | C |")
print("|---|---|---|---|---|---|---|")
for t in ("morning", "afternoon", "evening"):
    means = []
    for seed in range(1, seeds + 1):
        layout = json.load(open(f"{out}/{t}-{seed}/layout.json"))["entities"]
        report = json.load(open(f"{out}/{t}-{seed}/report.json"))
        d = [9.0 - layout[f"ws{i}"]["position"][0] for i in range(1, 7)]
        means.append(statistics.mean(d))
        s = {x["name"]: x for x in report["samplers"]}
        desks = sum(1 for i in range(1, 7) if s[f"ws{i}.desk.task"]["penalty"] == 0)
        screens = sum(1 for i in range(1, 7) if s[f"ws{i}.monitor.glare"]["penalty"] == 0)
        print("| %s | %d | %.2f m (%.2f-%.2f) | %d / 6 | %d / 6 | %d / 6 | %.3f |" % (
            t, seed, means[-1], min(d), max(d), sum(1 for x in d if x <= 2.5), desks, screens, report["C"]))
    sd = statistics.stdev(means) if len(means) > 1 else 0.0
    print("| **%s** | all | **%.2f m** (sd over seeds %.2f) | | | | |" % (t, statistics.mean(means), sd))
PY
