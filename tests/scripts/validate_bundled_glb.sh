#!/usr/bin/env bash
# Every bundled scene's scene.glb (scenes/demo/*.json, scenes/paper/*.json; written by
# `luxplan render --glb-only`, no light transport) through the Khronos glTF validator
# (scripts/validate-gltf.js, npm's gltf-validator): each must have 0 errors.
#   tests/scripts/validate_bundled_glb.sh build/luxplan OUTDIR
set -euo pipefail
luxplan=${1:?usage: validate_bundled_glb.sh LUXPLAN OUTDIR}
out=${2:?usage: validate_bundled_glb.sh LUXPLAN OUTDIR}
root=$(cd "$(dirname "$0")/../.." && pwd)
if ! command -v node > /dev/null; then
    echo "validate_bundled_glb: node is missing (scripts/install-deps.sh installs Node.js and the validator)"
    exit 1
fi
rm -rf "$out"
mkdir -p "$out"
files=()
for scene in "$root"/scenes/demo/*.json "$root"/scenes/paper/*.json; do
    name=$(basename "$(dirname "$scene")")-$(basename "$scene" .json)
    if ! "$luxplan" render "$scene" -o "$out/$name" --glb-only --threads 2 > "$out/$name.log" 2>&1; then
        echo "validate_bundled_glb: luxplan render $scene --glb-only failed:"
        cat "$out/$name.log"
        exit 1
    fi
    files+=("$out/$name/scene.glb")
done
node "$root/scripts/validate-gltf.js" "${files[@]}"
