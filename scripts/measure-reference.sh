#!/usr/bin/env bash
# Regenerates tests/reference/measure/*.json: `luxplan measure --json` of every
# bundled scene at a fixed seed and path count. tests/cli/measure_reference_test.cpp
# z-tests a fresh measurement (another seed, fewer paths) against these means and
# standard errors, so any change to the light transport that moves a value by more
# than its noise is caught. Run it only when a change of the estimate is intended,
# and say why in the commit.
#   scripts/measure-reference.sh [LUXPLAN_BINARY] [PATHS]
set -euo pipefail
cd "$(dirname "$0")/.."
bin=${1:-build/luxplan}
paths=${2:-512}
out=tests/reference/measure
mkdir -p "$out"
for scene in scenes/demo/office.json scenes/paper/*.json; do
    name=$(basename "$scene" .json)
    tmp="$out/.$name.json.tmp"
    "$bin" measure "$scene" --json --seed 1 --paths "$paths" --threads 2 |
        python3 -c 'import json,sys; d=json.load(sys.stdin); d.pop("seconds", None); json.dump(d, sys.stdout, indent=1); print()' > "$tmp"
    mv "$tmp" "$out/$name.json"
    echo "$out/$name.json"
done
