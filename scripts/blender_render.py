# Run by check-blender.sh inside Blender: import a luxplan scene.glb, light the world
# with its sky, render it from its first camera (or from a corner of the room) and
# print the picture's mean brightness. Exit 1 when the picture is black or blank, when
# it is mostly background (check_image.py), when the camera is outside the room (the
# file's extras.room) or its view does not fall on the room's surfaces (rays cast
# through the frame), or when the daylight does not brighten it.
import json
import os
import struct
import sys

import bpy
import numpy
from mathutils import Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import check_image  # noqa: E402 (scripts/check_image.py, beside this file)

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

# The room's inside (the file's extras.room, glTF y-up; the importer turns glTF's
# (x, y, z) into Blender's (x, -z, y), which is luxplan's frame again).
room = scene_doc.get("extras", {}).get("room")
room_lo = room_hi = None
if room:
    room_lo = Vector((room["min"][0], -room["max"][2], room["min"][1]))
    room_hi = Vector((room["max"][0], -room["min"][2], room["max"][1]))

# The file's first camera (glTF's cameras[0]; Blender names the object after its node).
cameras = [o for o in scene.objects if o.type == "CAMERA"]
first = next((n.get("name") for n in doc.get("nodes", []) if n.get("camera") == 0), None)
chosen = next((o for o in cameras if o.name == first), cameras[0] if cameras else None)
if chosen:
    scene.camera = chosen
else:
    corners = [o.matrix_world @ Vector(v) for o in scene.objects if o.type == "MESH" for v in o.bound_box]
    lo = room_lo if room_lo is not None else Vector([min(c[i] for c in corners) for i in range(3)])
    hi = room_hi if room_hi is not None else Vector([max(c[i] for c in corners) for i in range(3)])
    data = bpy.data.cameras.new("corner")
    data.angle = 1.2
    cam = bpy.data.objects.new("corner", data)
    scene.collection.objects.link(cam)
    cam.location = Vector((lo.x + 0.3, lo.y + 0.3, lo.z + 0.65 * (hi.z - lo.z)))
    target = Vector((hi.x, hi.y, lo.z + 0.3 * (hi.z - lo.z)))
    cam.rotation_euler = (target - cam.location).to_track_quat("-Z", "Y").to_euler()
    scene.camera = cam
camera = scene.camera
bpy.context.view_layer.update()

scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 16
scene.cycles.use_denoising = False  # Debian builds Cycles without OpenImageDenoise
scene.render.resolution_x, scene.render.resolution_y = 320, 240
scene.render.film_transparent = False
scene.view_settings.view_transform = "Filmic"
# The daylight: the sun light and the sky's world strength (off again for the second
# picture).
sun = [o for o in scene.objects if o.type == "LIGHT" and o.name.startswith("sun")]
strength = background.inputs["Strength"].default_value
daylit = bool(sun) or (sky is not None and strength > 0)
# Daylight is tens of klx: -4 brings a daylit room's hundreds of lux into view; a room
# lit by its lamps alone (hundreds of lux, no sun) would come out nearly black at -4.
scene.view_settings.exposure = -4 if daylit else 0


scene.render.image_settings.file_format = "PNG"


def render(path):
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    image = bpy.data.images.load(path)
    pixels = list(image.pixels)
    bpy.data.images.remove(image)
    return sum(pixels[i] + pixels[i + 1] + pixels[i + 2] for i in range(0, len(pixels), 4)) / (len(pixels) / 4 * 3)


def room_share(camera, lo, hi, columns=16, rows=12, margin=0.05):
    """The share of rays through a grid over the camera's frame whose first hit lies in the room."""
    depsgraph = bpy.context.evaluated_depsgraph_get()
    frame = camera.data.view_frame(scene=scene)  # top-right, bottom-right, bottom-left, top-left
    to_world = camera.matrix_world.to_3x3()
    origin = camera.matrix_world.translation.copy()
    inside = 0
    for r in range(rows):
        v = (r + 0.5) / rows
        left = frame[3].lerp(frame[2], v)
        right = frame[0].lerp(frame[1], v)
        for c in range(columns):
            direction = (to_world @ left.lerp(right, (c + 0.5) / columns)).normalized()
            hit, location, *_ = scene.ray_cast(depsgraph, origin, direction)
            if hit and all(lo[i] - margin <= location[i] <= hi[i] + margin for i in range(3)):
                inside += 1
    return inside / (columns * rows)


problems = []
position = camera.matrix_world.translation
if room_lo is not None:
    if not all(room_lo[i] <= position[i] <= room_hi[i] for i in range(3)):
        problems.append(f"the camera {camera.name} at ({position.x:.2f}, {position.y:.2f}, {position.z:.2f}) is outside the room")
    share = room_share(camera, room_lo, room_hi)
    if share < 0.75:
        problems.append(f"{100 * share:.0f}% of the view falls on the room (under 75%)")
    view = f"{100 * share:.0f}% of the view on the room"
else:
    view = "no extras.room in the file: view not checked against the room"

lit = render(out)
ok_image, image_message = check_image.check(out)
if not ok_image:
    problems.append(image_message)
# The same without the daylight (sky and sun off): what the daylight adds.
background.inputs["Strength"].default_value = 0
for o in sun:
    o.hide_render = True
dark = render(out[:-4] + "_no_daylight.png")
lights = [o.name for o in scene.objects if o.type == "LIGHT"]
print(f"check-blender: {out}: mean brightness {lit:.3f} with daylight, {dark:.3f} without (0 black, 1 white); "
      f"camera: {camera.name}, {view}; lights: {', '.join(lights) or 'none'}; "
      f"sky: {'%.0f cd/m2' % sky['luminance_cd_m2'] if sky else 'none'}")
if not lit > 0.02:
    problems.append(f"black (mean brightness {lit:.3f})")
elif daylit and not lit > 1.2 * dark:
    problems.append(f"the daylight does not brighten the picture ({lit:.3f} vs {dark:.3f} without)")
for p in problems:
    print(f"check-blender: FAIL: {p}")
sys.exit(1 if problems else 0)
