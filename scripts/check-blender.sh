#!/usr/bin/env bash
# The documented check that a luxplan scene.glb is usable in Blender: imports it
# headless with Blender's own glTF importer, makes the sky in the file's extras the
# world colour, renders one picture with Cycles on the CPU and says how bright it is.
# A daylit scene must come out lit, not black. Not part of `make test` (Blender is a
# large package): run it by hand, e.g.
#   luxplan report scenes/demo/office.json -o out/office
#   scripts/check-blender.sh out/office/scene.glb out/office/blender.png
# Installs Debian's blender if it is missing (needs root).
set -euo pipefail
glb=${1:?usage: check-blender.sh SCENE.glb [OUT.png]}
out=${2:-${glb%.glb}_blender.png}
if ! command -v blender > /dev/null || ! dpkg -s python3-numpy > /dev/null 2>&1; then
    echo "check-blender: installing Debian's blender"
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends blender python3-numpy > /dev/null
fi
here=$(cd "$(dirname "$0")" && pwd)
blender -b --factory-startup --python-exit-code 1 --python "$here/blender_render.py" -- "$glb" "$out"
