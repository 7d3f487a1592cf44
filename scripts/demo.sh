#!/usr/bin/env bash
# `make demo`: the main job on the bundled office scene. For now (until the light
# transport and optimizer land) it validates the scene and prints its summary.
set -euo pipefail
luxplan=${1:?luxplan binary}
scene=${2:?scene file}
out=${3:?output folder}
mkdir -p "$out"
"$luxplan" validate "$scene"
"$luxplan" info "$scene" | tee "$out/summary.txt"
echo
echo "demo: summary written to $out/summary.txt"
