#!/usr/bin/env bash
# The documented check that a luxplan scene.glb is usable in Blender: imports it
# headless with Blender's own glTF importer, makes the sky in the file's extras the
# world colour, renders one picture with Cycles on the CPU from the file's first camera
# and says how bright it is. It fails when the picture is black, blank (near uniform)
# or mostly background, when the camera is outside the room or its view does not fall
# on the room (the file's extras.room), or when the daylight does not brighten a
# daylit scene. Not part of `make test` (Blender is a large package): run it by hand,
# e.g.
#   luxplan report scenes/demo/office.json -o out/office
#   scripts/check-blender.sh out/office/scene.glb out/office/blender.png
# Installs Debian's blender if it is missing (needs root).
#
#   scripts/check-blender.sh --image PICTURE.png
# runs only the picture's check (scripts/check_image.py, Python's standard library
# alone; no Blender): exit 0 when it shows something, 1 when it is blank or mostly one
# flat colour, 2 when it cannot be read. `make test` feeds it a blank picture
# (tests/scripts/check_image_test.py).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
if [ "${1:-}" = "--image" ]; then
    exec python3 "$here/check_image.py" "${2:?usage: check-blender.sh --image PICTURE.png}" "${@:3}"
fi
glb=${1:?usage: check-blender.sh SCENE.glb [OUT.png] | check-blender.sh --image PICTURE.png}
out=${2:-${glb%.glb}_blender.png}
if ! command -v blender > /dev/null || ! dpkg -s python3-numpy > /dev/null 2>&1; then
    echo "check-blender: installing Debian's blender"
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends blender python3-numpy > /dev/null
fi
blender -b --factory-startup --python-exit-code 1 --python "$here/blender_render.py" -- "$glb" "$out"
