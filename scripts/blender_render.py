# Run by check-blender.sh inside Blender: import a luxplan scene.glb, light the world
# with its sky, render it from its first camera (or from a corner of the room) and
# print the picture's mean brightness; exit 1 when the picture is black.
import json
import struct
import sys

import bpy
import numpy
from mathutils import Vector

# Debian 12's Blender 3.4 glTF importer still uses numpy.bool, which Debian's numpy
# 1.24 removed: give it back as the builtin it always was.
if not hasattr(numpy, "bool") or numpy.bool is not bool:
    try:
        numpy.bool = bool
    except Exception:
        pass

glb, out = sys.argv[sys.argv.index("--") + 1:][:2]

# The sky from the file's scene extras (read from the GLB's JSON chunk, which does not
# depend on how the importer maps extras).
with open(glb, "rb") as f:
    f.read(12)
    length, kind = struct.unpack("<II", f.read(8))
    doc = json.loads(f.read(length))
scene_doc = doc["scenes"][doc.get("scene", 0)]
sky = scene_doc.get("extras", {}).get("sky")

bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=glb)
scene = bpy.context.scene

world = bpy.data.worlds.new("luxplan sky")
world.use_nodes = True
background = world.node_tree.nodes["Background"]
if sky:
    # Blender's photometric convention: 683 lm per W, so L cd/m2 is L / 683 W/m2/sr.
    background.inputs["Color"].default_value = (*sky["color"], 1)
    background.inputs["Strength"].default_value = sky["luminance_cd_m2"] / 683
else:
    background.inputs["Strength"].default_value = 0
scene.world = world

cameras = [o for o in scene.objects if o.type == "CAMERA"]
if cameras:
    scene.camera = cameras[0]
else:
    corners = [o.matrix_world @ Vector(v) for o in scene.objects if o.type == "MESH" for v in o.bound_box]
    lo = Vector([min(c[i] for c in corners) for i in range(3)])
    hi = Vector([max(c[i] for c in corners) for i in range(3)])
    data = bpy.data.cameras.new("corner")
    data.angle = 1.2
    cam = bpy.data.objects.new("corner", data)
    scene.collection.objects.link(cam)
    cam.location = Vector((lo.x + 0.3, lo.y + 0.3, lo.z + 0.65 * (hi.z - lo.z)))
    target = Vector((hi.x, hi.y, lo.z + 0.3 * (hi.z - lo.z)))
    cam.rotation_euler = (target - cam.location).to_track_quat("-Z", "Y").to_euler()
    scene.camera = cam

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 16
scene.cycles.use_denoising = False  # Debian builds Cycles without OpenImageDenoise
scene.render.resolution_x, scene.render.resolution_y = 320, 240
scene.render.film_transparent = False
scene.view_settings.view_transform = "Filmic"
scene.view_settings.exposure = -4  # daylight is tens of klx: bring a room's hundreds of lux into view


def render(path):
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(path)
    pixels = list(image.pixels)
    bpy.data.images.remove(image)
    return sum(pixels[i] + pixels[i + 1] + pixels[i + 2] for i in range(0, len(pixels), 4)) / (len(pixels) / 4 * 3)


lit = render(out)
# The same without the daylight (sky and sun off): what the daylight adds.
sun = [o for o in scene.objects if o.type == "LIGHT" and o.name.startswith("sun")]
strength = background.inputs["Strength"].default_value
background.inputs["Strength"].default_value = 0
for o in sun:
    o.hide_render = True
dark = render(out[:-4] + "_no_daylight.png")
lights = [o.name for o in scene.objects if o.type == "LIGHT"]
print(f"check-blender: {out}: mean brightness {lit:.3f} with daylight, {dark:.3f} without (0 black, 1 white); "
      f"lights: {', '.join(lights) or 'none'}; sky: {'%.0f cd/m2' % sky['luminance_cd_m2'] if sky else 'none'}")
daylit = bool(sun) or (sky is not None and strength > 0)
ok = lit > 0.02 and (not daylit or lit > 1.2 * dark)
sys.exit(0 if ok else 1)
