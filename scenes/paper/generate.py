#!/usr/bin/env python3
"""Generate the scenes of the paper's section 7 (Vitsas et al. 2020) for luxplan.

Run from anywhere: `python3 scenes/paper/generate.py`. It (re)writes every JSON file
of scenes/paper/ next to this script; the JSON files are committed too, so nothing
needs to be generated before use. Standard library only.

Conventions (docs/scene-format.md): z up, metres, degrees; rotations counter-clockwise
seen from above; presets face -y, so rotation 0 faces -y, 90 faces +x, 180 faces +y,
270 faces -x. With site.north_deg = 0, +y is north and the "south" wall is y = min.
"""
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))

# Athens, the site used by every time-dependent scene.
ATHENS = {"latitude": 37.98, "longitude": 23.73, "north_deg": 0}

# Facing rotations for furniture standing against a wall and looking into the room.
FACE_NORTH_WALL = 0     # against the north wall (y = max), faces -y
FACE_SOUTH_WALL = 180   # against the south wall (y = min), faces +y
FACE_WEST_WALL = 90     # against the west wall (x = min), faces +x
FACE_EAST_WALL = 270    # against the east wall (x = max), faces -x


def materials(**extra):
    m = {
        "floor": {"type": "diffuse", "reflectance": 0.3},
        "wall": {"type": "diffuse", "reflectance": 0.7},
        "ceiling": {"type": "diffuse", "reflectance": 0.8},
        "glass": {"type": "glass", "transmittance": 0.8},
        "tinted": {"type": "glass", "transmittance": 0.45},
        "door": {"type": "diffuse", "reflectance": [0.45, 0.35, 0.25]},
        "wood": {"type": "diffuse", "reflectance": [0.55, 0.4, 0.28]},
        "plastic": {"type": "diffuse", "reflectance": 0.1},
        "fabric": {"type": "diffuse", "reflectance": [0.2, 0.25, 0.35]},
        "screen": {"type": "glossy", "reflectance": 0.05, "roughness": 0.1, "base": 0.02},
    }
    m.update(extra)
    return m


def room(size, openings, name="room"):
    return {"name": name, "room": {"min": [0, 0, 0], "max": list(size)},
            "materials": {"floor": "floor", "walls": "wall", "ceiling": "ceiling"},
            "openings": openings}


def window(wall, offset, width, sill=0.9, height=1.5, material="glass"):
    return {"wall": wall, "offset": offset, "width": width, "sill": sill, "height": height,
            "material": material}


def door(wall, offset, width=1.0, height=2.1):
    # A door leaf: an opening holding an opaque diffuse pane.
    return {"wall": wall, "offset": offset, "width": width, "sill": 0, "height": height,
            "material": "door"}


def box(name, lo, hi, material=None):
    b = {"name": name, "box": {"min": list(lo), "max": list(hi)}}
    if material is None:
        b["invisible"] = True
    else:
        b["material"] = material
    return b


def panel(name, center, flux, size=(0.6, 0.6)):
    return {"name": name, "shape": "rect", "center": list(center), "normal": [0, 0, -1],
            "size": list(size), "flux_lm": flux, "cct_k": 4000}


def preetham(date, t0, t1, tz, step=30, turbidity=3.0):
    return {"sky": {"model": "preetham", "turbidity": turbidity}, "sun": True,
            "ground_reflectance": 0.2,
            "from": f"{date}T{t0}{tz}", "to": f"{date}T{t1}{tz}", "step_minutes": step}


def planar(name, center, size, target, grid=(4, 2), tolerance=None, normal=None, up=None):
    s = {"name": name, "type": "planar", "center": list(center), "size": list(size),
         "grid": list(grid), "target": list(target)}
    if normal is not None:
        s["normal"] = list(normal)
    if up is not None:
        s["up"] = list(up)
    if tolerance is not None:
        s["tolerance"] = tolerance
    return s


def directional(name, origin, direction, target, fov=60, strata=4, tolerance=None):
    s = {"name": name, "type": "directional", "origin": list(origin),
         "direction": list(direction), "fov_deg": fov, "strata": strata, "target": list(target)}
    if tolerance is not None:
        s["tolerance"] = tolerance
    return s


def clearance(a, b, minimum):
    # A minimum distance between centres, open above: its elastic limit is 5% of the
    # minimum, not 5% of a made-up maximum.
    return {"type": "distance", "a": a, "b": b, "min": minimum, "max": None}


def optimizer(iterations, paths=32, report=512, **extra):
    o = {"iterations": iterations, "seed": 1, "paths_per_point": paths,
         "report_paths_per_point": report}
    o.update(extra)
    return o


def write(name, scene):
    path = os.path.join(HERE, name)
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
        f.write("\n")
    print("wrote", os.path.relpath(path))


# ---------------------------------------------------------------------------
# Shared pieces: a workstation (desk + monitor + office chair) and its glare sampler.

MONITOR_EYE = [0, -0.7, 0.45]      # in the monitor's frame: 0.7 m in front, eye at 1.2 m
MONITOR_LOOK = [0, 1, -0.32]       # towards the screen's centre


def monitor(name, position, rot_range, region, glare_name, glare_max=100):
    return {"name": name, "position": list(position), "rotation": sum(rot_range) / 2,
            "placement": {"regions": [{"min": region[0], "max": region[1],
                                       "rotation_range": list(rot_range)}]},
            "parts": [{"preset": "monitor", "materials": {"body": "plastic", "screen": "screen"}}],
            "samplers": [directional(glare_name, MONITOR_EYE, MONITOR_LOOK, [0, glare_max],
                                     tolerance=200)]}


def workstation(name, position, rotation, regions, desk_target=(300, 500)):
    """A group: desk at the origin, monitor movable on its back half, chair in front."""
    return {"name": name, "position": list(position), "rotation": rotation,
            "placement": {"regions": regions},
            "children": [
                {"name": "desk", "parts": [{"preset": "desk", "material": "wood"}],
                 "samplers": [planar("task", [0, -0.1, 0.76], [1.2, 0.5],
                                     desk_target, tolerance=200)]},
                monitor("monitor", [0, 0.12, 0.75], [-30, 30],
                        ([-0.4, 0.0], [0.4, 0.2]), "glare"),
                {"name": "chair", "position": [0, -0.75], "parts": [
                    {"preset": "office_chair", "material": "fabric"}]},
            ]}


# ---------------------------------------------------------------------------
# Figure 4, first row: table set and bookshelf around a sun patch.

def fig4_sun_patch():
    W, D, H = 6.0, 5.0, 2.8
    shelf_y = 0.16  # half the bookshelf depth plus 1 cm
    rails = [
        # north wall, whole length
        {"min": [0.6, D - shelf_y], "max": [W - 0.6, D - shelf_y], "rotations": [FACE_NORTH_WALL]},
        # south wall, left and right of the window (x 2.5 .. 3.5)
        {"min": [0.6, shelf_y], "max": [2.05, shelf_y], "rotations": [FACE_SOUTH_WALL]},
        {"min": [3.95, shelf_y], "max": [W - 0.6, shelf_y], "rotations": [FACE_SOUTH_WALL]},
        # west and east walls
        {"min": [shelf_y, 0.6], "max": [shelf_y, D - 0.6], "rotations": [FACE_WEST_WALL]},
        {"min": [W - shelf_y, 0.6], "max": [W - shelf_y, D - 0.6], "rotations": [FACE_EAST_WALL]},
    ]
    scene = {
        "luxplan": 1, "name": "fig4-sun-patch",
        "site": ATHENS,
        # A fixed sun (no time): 35 deg high in the south (25 klx, a hazy day), shining
        # through the tinted south window onto the floor 1.4 m to 2.9 m from the wall.
        "daylight": {"sky": {"model": "preetham", "turbidity": 3.0},
                     "sun": {"altitude_deg": 35, "azimuth_deg": 180,
                             "normal_illuminance_lx": 25000},
                     "ground_reflectance": 0.2},
        "materials": materials(),
        "geometry": [room([W, D, H], [window("south", 2.5, 1.0, sill=1.0, height=1.1,
                                             material="tinted")])],
        "luminaires": [panel("ceiling", [4.5, 3.6, H - 0.01], 3000)],
        "entities": [
            {"name": "dining", "position": [1.5, 3.5], "rotation": 0,
             "placement": {"regions": [{"min": [1.0, 1.0], "max": [W - 1.0, D - 1.0],
                                        "rotation_range": [0, 360]}]},
             "fronts": [[0, -1], [1, 0]],
             "parts": [{"preset": "table", "material": "wood"}],
             "samplers": [planar("top", [0, 0, 0.76], [1.0, 0.6], [400, 600],
                                 grid=(4, 3))],
             # chairs have no degrees of freedom of their own (no placement)
             "children": [
                 {"name": "chair_s1", "position": [-0.3, -0.6], "rotation": 180,
                  "parts": [{"preset": "chair", "material": "wood"}]},
                 {"name": "chair_s2", "position": [0.3, -0.6], "rotation": 180,
                  "parts": [{"preset": "chair", "material": "wood"}]},
                 {"name": "chair_n1", "position": [-0.3, 0.6], "rotation": 0,
                  "parts": [{"preset": "chair", "material": "wood"}]},
                 {"name": "chair_n2", "position": [0.3, 0.6], "rotation": 0,
                  "parts": [{"preset": "chair", "material": "wood"}]},
             ]},
            {"name": "bookshelf", "position": [W - shelf_y, 2.5], "rotation": FACE_EAST_WALL,
             "placement": {"regions": rails},
             "parts": [{"preset": "bookshelf", "material": "wood"}],
             # the front face (entity frame: -y), 0.7 x 1.4 m, facing out of the shelf
             "samplers": [planar("front", [0, -0.17, 1.0], [0.7, 1.4], [400, 600],
                                 grid=(2, 4), normal=[0, -1, 0], up=[0, 0, 1])]},
        ],
        "constraints": [
            {"type": "alignment", "a": "dining", "b": "room", "tolerance_deg": 10},
            {"type": "overlap", "tolerance": 0.05},
        ],
        "objective": {"lighting_weight": 0.5},
        "optimizer": optimizer(2000),
    }
    write("fig4-sun-patch.json", scene)


# ---------------------------------------------------------------------------
# Figure 4, second row: glare on a computer screen.

def fig4_glare():
    W, D, H = 5.0, 4.5, 2.8
    ws = {"name": "workstation", "position": [2.5, 2.5], "rotation": 0,
          "placement": {"regions": [{"min": [1.0, 1.0], "max": [W - 1.0, D - 1.0],
                                     "rotation_range": [0, 360]}]},
          "children": [
              {"name": "desk", "parts": [{"preset": "desk", "material": "wood"}],
               "samplers": [planar("top", [0, -0.1, 0.76], [1.2, 0.5], [300, 500])]},
              monitor("monitor", [0, 0.12, 0.75], [-40, 40], ([-0.45, -0.05], [0.45, 0.2]),
                      "screen_glare"),
              {"name": "chair", "position": [0, -0.75],
               "parts": [{"preset": "office_chair", "material": "fabric"}]},
          ]}
    scene = {
        "luxplan": 1, "name": "fig4-glare",
        "site": ATHENS,
        "daylight": {"sky": {"model": "preetham", "turbidity": 3.0},
                     "sun": {"altitude_deg": 30, "azimuth_deg": 210,
                             "normal_illuminance_lx": 40000},
                     "ground_reflectance": 0.2},
        "materials": materials(),
        "geometry": [room([W, D, H], [window("south", 1.8, 1.4, sill=0.9, height=1.3,
                                             material="tinted")])],
        "luminaires": [panel("ceiling", [2.5, 2.9, H - 0.01], 3200)],
        "entities": [ws],
        "constraints": [
            {"type": "focus", "a": "workstation.monitor", "b": "workstation.chair",
             "tolerance_deg": 15},
            {"type": "overlap", "tolerance": 0.05},
        ],
        "objective": {"lighting_weight": 0.5},
        "optimizer": optimizer(2000),
    }
    write("fig4-glare.json", scene)


# ---------------------------------------------------------------------------
# Figure 4, third row: presenter volume, projection screen, conference table.

def fig4_presenter():
    W, D, H = 8.0, 6.0, 3.0
    sy = 0.06  # half the screen's depth plus 1 cm
    rails = [
        {"min": [1.2, D - sy], "max": [W - 1.2, D - sy], "rotations": [FACE_NORTH_WALL]},
        {"min": [sy, 1.2], "max": [sy, D - 1.2], "rotations": [FACE_WEST_WALL]},
        {"min": [W - sy, 1.2], "max": [W - sy, D - 1.2], "rotations": [FACE_EAST_WALL]},
        {"min": [1.2, sy], "max": [W - 1.2, sy], "rotations": [FACE_SOUTH_WALL]},
    ]
    screen = {
        "name": "screen", "position": [W / 2, D - sy], "rotation": FACE_NORTH_WALL,
        "placement": {"regions": rails},
        "parts": [{"preset": "projection_screen",
                   "materials": {"body": "plastic", "screen": "projection"}}],
        "samplers": [
            # the presenter stands beside/in front of the screen: 2.4 x 1.2 x 1.8 m box
            {"name": "presenter", "type": "volume", "center": [0, -0.9, 1.0],
             "axes": [[2.4, 0, 0], [0, 1.2, 0], [0, 0, 1.8]], "points": 64,
             "target": [100, None]},
            # the audience looks at the screen from 4 m: little reflected light wanted
            directional("screen_washout", [0, -4.0, 1.2], [0, 1, 0.04], [0, 100],
                        fov=40, strata=4),
        ]}
    table = {
        "name": "conference", "position": [W / 2, 2.5], "rotation": 0,
        "placement": {"regions": [{"min": [1.8, 1.4], "max": [W - 1.8, D - 1.4],
                                   "rotations": [0, 90, 180, 270]}]},
        # the table's two short ends: one of them should point at the screen
        "fronts": [[1, 0], [-1, 0]],
        "parts": [{"preset": "conference_table", "material": "wood"}],
        "samplers": [planar("top", [0, 0, 0.76], [2.0, 0.9], [300, 500], grid=(4, 2))]}
    scene = {
        "luxplan": 1, "name": "fig4-presenter",
        "site": ATHENS,
        "daylight": {"sky": {"model": "preetham", "turbidity": 3.0},
                     "sun": {"altitude_deg": 40, "azimuth_deg": 200,
                             "normal_illuminance_lx": 40000},
                     "ground_reflectance": 0.2},
        "materials": materials(projection={"type": "diffuse", "reflectance": 0.8}),
        "geometry": [room([W, D, H], [window("south", 3.2, 1.6, sill=0.9, height=1.4,
                                             material="tinted")])],
        "entities": [screen, table],
        "constraints": [
            {"type": "focus", "a": "conference", "b": "screen", "tolerance_deg": 15},
            {"type": "distance", "a": "conference", "b": "screen", "min": 2.0, "max": 4.5},
            {"type": "overlap", "tolerance": 0.05},
        ],
        "objective": {"lighting_weight": 0.5},
        "optimizer": optimizer(2000),
    }
    write("fig4-presenter.json", scene)


# ---------------------------------------------------------------------------
# Figure 7: office with six workstations at three times of day.

OFFICE = (9.0, 6.5, 2.8)


def workstation_rules(n, minimum=2.0):
    """The office's rules for workstations ws1..wsN: each desk aligned with the room,
    each screen facing its chair, every two workstations `minimum` m apart, no overlap."""
    constraints = []
    for i in range(n):
        constraints.append({"type": "alignment", "a": f"ws{i + 1}.desk", "b": "room",
                            "tolerance_deg": 10})
        constraints.append({"type": "focus", "a": f"ws{i + 1}.monitor", "b": f"ws{i + 1}.chair",
                            "tolerance_deg": 15})
    for i in range(n):
        for j in range(i + 1, n):
            constraints.append(clearance(f"ws{i + 1}", f"ws{j + 1}", minimum))
    constraints.append({"type": "overlap", "tolerance": 0.05})
    return constraints


def office(variant):
    W, D, H = OFFICE
    regions = [{"min": [0.9, 0.9], "max": [W - 0.9, D - 0.9], "rotations": [0, 90, 180, 270]}]
    # (the first desk clear of the door's blocker, x 0 .. 1.4)
    starts = [(2.2, 1.6), (4.5, 1.6), (7.0, 1.6), (2.0, 4.6), (4.5, 4.6), (7.0, 4.6)]
    entities = [workstation(f"ws{i + 1}", p, 0, regions) for i, p in enumerate(starts)]
    constraints = workstation_rules(6)
    geometry = [
        room([W, D, H], [window("east", 0.6, 1.5), window("east", 2.5, 1.5),
                         window("east", 4.4, 1.5), door("west", 0.4)]),
        # the door swing and the way in: kept free of furniture
        box("door_free", [0, 0.2, 0], [1.4, 1.6, 2.1]),
        # the building across the street, 13 m east of the facade: in the afternoon the
        # sun is in the west and reaches the office only off this facade and the ground
        box("building_opposite", [22, -20, 0], [30, 26, 6], material="facade"),
    ]
    mats = materials(facade={"type": "diffuse", "reflectance": [0.6, 0.55, 0.5]})
    scene = {"luxplan": 1, "name": f"fig7-office-{variant}", "site": ATHENS}
    lum = []
    if variant == "morning":
        # equinox morning; Athens is UTC+2 in March (no summer time yet)
        scene["daylight"] = preetham("2026-03-20", "08:30", "11:30", "+02:00")
    elif variant == "afternoon":
        # the sun has moved to the south-west and west: no direct sun on the east windows
        scene["daylight"] = preetham("2026-03-20", "14:00", "17:00", "+02:00")
    else:
        # late evening: no daylight, six 3200 lm ceiling panels
        xs, ys = (1.5, 4.5, 7.5), (1.6, 4.9)
        lum = [panel(f"panel{k + 1}", [x, y, H - 0.01], 3200)
               for k, (y, x) in enumerate((y, x) for y in ys for x in xs)]
    scene.update({"materials": mats, "geometry": geometry, "luminaires": lum,
                  "entities": entities, "constraints": constraints,
                  "objective": {"lighting_weight": 0.5},
                  # by night every target is reachable: the paper's 10^4 proposals, stopping at a confirmed C = 0
                  "optimizer": optimizer(10000 if variant == "evening" else 4000)})
    write(f"fig7-office-{variant}.json", scene)


# ---------------------------------------------------------------------------
# Figure 8: computer lab, islands of two facing desks.

LAB = (11.0, 9.0, 3.0)


def lab_island(name, position, regions):
    ch = []
    for side, sgn, rot in (("a", -1, 0), ("b", 1, 180)):
        ch.append({"name": f"desk_{side}", "position": [0, 0.35 * sgn], "rotation": rot,
                   "parts": [{"preset": "desk", "material": "wood"}],
                   "samplers": [planar("task", [0, -0.1, 0.76], [1.2, 0.5],
                                       [300, 500], tolerance=200)]})
        y_lo, y_hi = sorted((0.12 * sgn, 0.28 * sgn))
        ch.append(monitor(f"monitor_{side}", [0, 0.2 * sgn, 0.75], [rot - 30, rot + 30],
                          ([-0.4, y_lo], [0.4, y_hi]), "glare"))
        ch.append({"name": f"chair_{side}", "position": [0, 1.05 * sgn], "rotation": rot,
                   "parts": [{"preset": "office_chair", "material": "fabric"}]})
    return {"name": name, "position": list(position), "rotation": 0,
            "placement": {"regions": regions}, "children": ch}


def fig8_lab():
    W, D, H = LAB
    regions = [{"min": [1.0, 1.6], "max": [W - 1.0, D - 1.6], "rotations": [0, 90, 180, 270]}]
    sym = [(3.0, 2.6), (8.0, 2.6), (3.0, 6.2), (8.0, 6.2)]
    names = ["i1", "i2", "i3", "i4"]
    entities = [lab_island(n, p, regions) for n, p in zip(names, sym)]
    constraints = []
    for n in names:
        for s in "ab":
            constraints.append({"type": "focus", "a": f"{n}.monitor_{s}", "b": f"{n}.chair_{s}",
                                "tolerance_deg": 15})
        constraints.append({"type": "alignment", "a": f"{n}.desk_a", "b": "room",
                            "tolerance_deg": 10})
    for i in range(4):
        for j in range(i + 1, 4):
            constraints.append(clearance(names[i], names[j], 2.6))
    constraints.append({"type": "overlap", "tolerance": 0.05})
    scene = {
        "luxplan": 1, "name": "fig8-lab", "site": ATHENS,
        # a clear November morning: low sun from the south-east, deep sun patches
        "daylight": preetham("2026-11-16", "09:00", "12:00", "+02:00"),
        "materials": materials(),
        "geometry": [
            # solar-control glazing, three windows on the south wall
            room([W, D, H], [window("south", 1.5, 1.6, height=1.3, material="tinted"),
                             window("south", 4.7, 1.6, height=1.3, material="tinted"),
                             window("south", 7.9, 1.6, height=1.3, material="tinted"),
                             door("north", 0.4, 1.0)]),
            box("door_free", [0.2, D - 1.4, 0], [1.6, D, 2.1]),
        ],
        "entities": entities,
        "constraints": constraints,
        "objective": {"lighting_weight": 0.5},
        "optimizer": optimizer(4000),
    }
    write("fig8-lab.json", scene)
    # The usual symmetric arrangement: a 2 x 2 grid of islands, desks facing the windows
    # and the back wall, monitors centred.
    layout = {"entities": {}}
    for n, p in zip(names, sym):
        layout["entities"][n] = {"position": [p[0], p[1], 0.0], "rotation": 0, "region": 0}
        for s, sgn, rot in (("a", -1, 0), ("b", 1, 180)):
            layout["entities"][f"{n}.monitor_{s}"] = {
                "position": [0.0, 0.2 * sgn, 0.75], "rotation": rot, "region": 0}
    # Beside the scenes, not among them: a layout file is no scene (validate refuses it).
    os.makedirs(os.path.join(HERE, "layouts"), exist_ok=True)
    with open(os.path.join(HERE, "layouts", "fig8-lab-symmetric.json"), "w") as f:
        json.dump(layout, f, indent=1)
        f.write("\n")
    print("wrote layouts/fig8-lab-symmetric.json")


# ---------------------------------------------------------------------------
# Figures 2 and 9: two-room apartment.

APT = (11.0, 5.5, 2.7)
WALL_X = 5.5   # interior wall between the rooms, doorway y 2.2 .. 3.2


def apt_regions(margin_x, margin_y, rotations=(0, 90, 180, 270)):
    W, D, _ = APT
    return [{"min": [margin_x, margin_y], "max": [WALL_X - margin_x, D - margin_y],
             "rotations": list(rotations)},
            {"min": [WALL_X + margin_x, margin_y], "max": [W - margin_x, D - margin_y],
             "rotations": list(rotations)}]


def sphere_lamp(name, flux):
    return {"name": name, "shape": "sphere", "center": [0, 0, 1.45], "radius": 0.12,
            "flux_lm": flux, "cct_k": 2700}


def living_group(position, regions, glare_max, movable_children=False):
    """Sofa (fixed in the group), coffee table, TV, armchair."""
    tv = {"name": "tv", "position": [0, 1.4], "rotation": 0,
          "parts": [{"preset": "tv", "materials": {"body": "plastic", "screen": "screen"}}],
          # a viewer on the sofa (2.7 m away, eyes at 1.0 m) looking at the screen
          "samplers": [directional("glare", [0, -2.7, 1.0], [0, 1, -0.15], [0, glare_max],
                                   fov=40, strata=4)]}
    arm = {"name": "armchair", "position": [1.7, -0.2], "rotation": 270,
           "parts": [{"preset": "armchair", "materials": {"body": "wood", "cushion": "fabric"}}]}
    if movable_children:
        tv["placement"] = {"regions": [{"min": [-0.6, 1.2], "max": [0.6, 1.5],
                                        "rotation_range": [-20, 20]}]}
        arm["placement"] = {"regions": [{"min": [1.4, -1.0], "max": [1.9, 0.4],
                                         "rotation_range": [220, 320]}]}
    return {"name": "living", "position": list(position), "rotation": 0,
            "placement": {"regions": regions},
            "children": [
                {"name": "sofa", "position": [0, -1.3], "rotation": 180,
                 "parts": [{"preset": "sofa", "materials": {"body": "wood", "cushion": "fabric"}}]},
                {"name": "coffee_table", "position": [0, -0.15],
                 "parts": [{"preset": "coffee_table", "material": "wood"}]},
                tv, arm]}


def dining_group(position, regions, target):
    ch = []
    for k, (x, y, r) in enumerate(((-0.3, -0.6, 180), (0.3, -0.6, 180),
                                   (-0.3, 0.6, 0), (0.3, 0.6, 0))):
        ch.append({"name": f"chair{k + 1}", "position": [x, y], "rotation": r,
                   "parts": [{"preset": "chair", "material": "wood"}]})
    return {"name": "dining", "position": list(position), "rotation": 0,
            "placement": {"regions": regions},
            "parts": [{"preset": "table", "material": "wood"}],
            "samplers": [planar("table", [0, 0, 0.76], [1.0, 0.6], target, grid=(3, 2))],
            "children": ch}


def reading_group(position, regions, target, lamp_flux):
    lamp = {"name": "lamp", "position": [0.6, 0.2], "rotation": 0,
            "placement": {"regions": [{"min": [-0.7, -0.3], "max": [0.7, 0.6]}]},
            "parts": [{"preset": "stand_lamp", "materials": {"body": "plastic", "shade": "shade"}}]}
    if lamp_flux:
        lamp["emitters"] = [sphere_lamp("reading_lamp", lamp_flux)]
    return {"name": "reading", "position": list(position), "rotation": 0,
            "placement": {"regions": regions},
            "parts": [{"preset": "armchair", "materials": {"body": "wood", "cushion": "fabric"}}],
            # a book on the lap: 40 x 30 cm at 0.75 m, tilted towards the reader
            "samplers": [planar("book", [0, -0.25, 0.75], [0.4, 0.3], target, grid=(2, 2),
                                normal=[0, 0.5, 0.866])],
            "children": [lamp]}


def apartment(variant):
    W, D, H = APT
    night = variant == "night"
    geometry = [
        room([W, D, H], [window("south", 1.5, 1.6, sill=0.9, height=1.3),
                         window("south", 7.6, 1.6, sill=0.9, height=1.3),
                         window("north", 8.2, 1.2, sill=0.9, height=1.2),
                         door("north", 0.5, 1.0)]),
        # interior wall with a doorway (y 2.2 .. 3.2)
        box("wall_south_part", [WALL_X - 0.05, 0, 0], [WALL_X + 0.05, 2.2, H], material="wall"),
        box("wall_north_part", [WALL_X - 0.05, 3.2, 0], [WALL_X + 0.05, D, H], material="wall"),
        box("wall_lintel", [WALL_X - 0.05, 2.2, 2.1], [WALL_X + 0.05, 3.2, H], material="wall"),
        # keep the doorway and the entrance free
        box("doorway_free", [WALL_X - 0.7, 2.2, 0], [WALL_X + 0.7, 3.2, 2.0]),
        box("entrance_free", [0.3, D - 1.3, 0], [1.7, D, 2.0]),
    ]
    lum = []
    lamp_flux = 0
    if night:
        lum = [{"name": "ceiling_west", "shape": "disk", "center": [2.75, 2.75, H - 0.01],
                "normal": [0, 0, -1], "radius": 0.2, "flux_lm": 2500, "cct_k": 3000},
               {"name": "ceiling_east", "shape": "disk", "center": [8.25, 2.75, H - 0.01],
                "normal": [0, 0, -1], "radius": 0.2, "flux_lm": 2500, "cct_k": 3000}]
        lamp_flux = 3500
    # a movable floor lamp that can go anywhere in either room
    floor_lamp = {"name": "floor_lamp", "position": [10.5, 0.5], "rotation": 0,
                  "placement": {"regions": apt_regions(0.35, 0.35, rotations=[0])},
                  "parts": [{"preset": "stand_lamp",
                             "materials": {"body": "plastic", "shade": "shade"}}]}
    if night:
        floor_lamp["emitters"] = [sphere_lamp("floor_lamp_light", lamp_flux)]
    entities = [
        dining_group([2.0, 2.0], apt_regions(0.9, 1.0), [200, 400]),
        living_group([8.0, 3.0], apt_regions(1.1, 1.2), 60, movable_children=True),
        reading_group([4.5, 4.5], apt_regions(0.6, 0.6), [300, 500], lamp_flux),
        floor_lamp,
    ]
    constraints = [
        {"type": "focus", "a": "living.tv", "b": "living.sofa", "tolerance_deg": 15},
        {"type": "conversation", "a": "living.sofa", "b": "living.armchair", "min": 1.2,
         "max": 3.0, "tolerance_deg": 60},
        {"type": "alignment", "a": "dining", "b": "room", "tolerance_deg": 10},
        {"type": "alignment", "a": "living", "b": "room", "tolerance_deg": 10},
        clearance("dining", "living", 2.5),
        {"type": "overlap", "tolerance": 0.05},
    ]
    scene = {"luxplan": 1, "name": f"fig9-apartment-{variant}", "site": ATHENS}
    if not night:
        # an October afternoon (Athens is UTC+3 until the end of October)
        scene["daylight"] = preetham("2026-10-15", "15:30", "18:00", "+03:00")
    scene.update({
        # a fabric lampshade: it glows with the light of the lamp inside
        "materials": materials(shade={"type": "translucent", "reflectance": [0.5, 0.45, 0.35],
                                      "transmittance": [0.4, 0.38, 0.3]}),
        "geometry": geometry, "luminaires": lum, "entities": entities,
        "constraints": constraints, "objective": {"lighting_weight": 0.5},
        "optimizer": optimizer(3000)})
    write(f"fig9-apartment-{variant}.json", scene)


# ---------------------------------------------------------------------------
# Figure 6: hierarchical vs flat, on the apartment's living room alone.

def fig6_hierarchy():
    W, D, H = 6.0, 5.0, 2.7
    whole = [{"min": [1.2, 1.2], "max": [W - 1.2, D - 1.2], "rotations": [0, 90, 180, 270]}]
    living = living_group([3.0, 2.6], whole, 80, movable_children=True)
    dining = dining_group([1.5, 1.2], [{"min": [1.0, 1.0], "max": [W - 1.0, D - 1.0],
                                        "rotations": [0, 90, 180, 270]}], [200, 400])
    # let the dining chairs move too (near their places), so that a flat search has to
    # keep them at the table through the constraints
    for c in dining["children"]:
        x, y = c["position"]
        c["placement"] = {"regions": [{"min": [x - 0.15, y - 0.15], "max": [x + 0.15, y + 0.15],
                                       "rotations": [c["rotation"]]}]}
    scene = {
        "luxplan": 1, "name": "fig6-hierarchy", "site": ATHENS,
        "materials": materials(),
        "geometry": [room([W, D, H], [window("south", 1.5, 2.5, sill=0.8, height=1.5),
                                      door("north", 4.6, 1.0)]),
                     box("entrance_free", [4.4, D - 1.3, 0], [5.8, D, 2.0])],
        "luminaires": [{"name": "ceiling", "shape": "disk", "center": [3.0, 2.5, H - 0.01],
                        "normal": [0, 0, -1], "radius": 0.2, "flux_lm": 2500, "cct_k": 3000},
                       panel("kitchen", [1.2, 4.2, H - 0.01], 2500)],
        "entities": [living, dining],
        "constraints": [
            {"type": "focus", "a": "living.tv", "b": "living.sofa", "tolerance_deg": 15},
            {"type": "conversation", "a": "living.sofa", "b": "living.armchair", "min": 1.2,
             "max": 3.0, "tolerance_deg": 60},
            {"type": "alignment", "a": "dining", "b": "room", "tolerance_deg": 10},
            clearance("dining", "living", 2.2),
            {"type": "overlap", "tolerance": 0.05},
        ],
        "objective": {"lighting_weight": 0.5},
        "optimizer": optimizer(1000, paths=16, report=256),
    }
    write("fig6-hierarchy.json", scene)


# ---------------------------------------------------------------------------
# Figure 10: event hall.

HALL = (24.0, 16.0, 4.5)


def round_table(name, position, target):
    """A round-ish table with 8 chairs as one entity (several box parts)."""
    parts = [
        {"box": {"size": [1.5, 0.62, 0.04], "center": [0, 0, 0.73]}, "material": "linen"},
        {"box": {"size": [0.62, 1.5, 0.04], "center": [0, 0, 0.73]}, "material": "linen"},
        {"box": {"size": [1.1, 1.1, 0.04], "center": [0, 0, 0.73]}, "material": "linen"},
        {"box": {"size": [0.16, 0.16, 0.71], "center": [0, 0, 0.355]}, "material": "wood"},
    ]
    r = 1.05
    for k in range(8):
        a = math.radians(45 * k)
        cx, cy = round(r * math.cos(a), 3), round(r * math.sin(a), 3)
        parts.append({"box": {"size": [0.42, 0.42, 0.45], "center": [cx, cy, 0.225]},
                      "material": "wood"})
        bx, by = round((r + 0.2) * math.cos(a), 3), round((r + 0.2) * math.sin(a), 3)
        parts.append({"box": {"size": [0.12, 0.12, 0.45], "center": [bx, by, 0.675]},
                      "material": "wood"})
    return {"name": name, "position": list(position), "rotation": 0,
            "placement": {"regions": [{"min": [1.7, 1.7], "max": [HALL[0] - 1.7, HALL[1] - 1.7]}]},
            "parts": parts,
            "samplers": [planar("top", [0, 0, 0.76], [1.0, 1.0], target, grid=(3, 3))]}


def event_hall(variant):
    W, D, H = HALL
    day = variant == "day"
    # the glazed side: three 3.6 m x 2.2 m panes of solar-control glass
    openings = [window("south", 2.4 + 8 * k, 3.6, sill=0.4, height=2.2, material="tinted")
                for k in range(3)]
    openings += [door("west", 7.0, 2.0, 2.4), door("east", 7.0, 2.0, 2.4),
                 door("north", 11.0, 2.0, 2.4)]
    geometry = [
        room([W, D, H], openings),
        box("west_door_free", [0, 6.5, 0], [1.8, 9.5, 2.4]),
        box("east_door_free", [W - 1.8, 6.5, 0], [W, 9.5, 2.4]),
        box("north_door_free", [10.5, D - 1.8, 0], [13.5, D, 2.4]),
        # the main walkway from the north entrance to the dance floor
        box("main_walkway", [11.0, 11.0, 0], [13.0, D - 1.8, 2.0]),
    ]
    lum = []
    # 6 composite (L-shaped) ceiling panels for ambient light, on at night only
    for k, (x, y) in enumerate(((4, 3.5), (12, 2.5), (20, 3.5), (4, 12.5), (12, 13.5), (20, 12.5))):
        if day:
            continue
        lum.append(panel(f"panel{k + 1}a", [x, y, H - 0.01], 5000, size=(2.4, 0.6)))
        lum.append(panel(f"panel{k + 1}b", [x - 0.9, y + 0.9, H - 0.01], 2500, size=(0.6, 1.2)))
    # 5 bright spotlights over the dance floor (x 9..15, y 5..11)
    for k, (x, y) in enumerate(((10, 6), (14, 6), (12, 8), (10, 10), (14, 10))):
        lum.append({"name": f"spot{k + 1}", "shape": "disk", "center": [x, y, H - 0.01],
                    "normal": [0, 0, -1], "radius": 0.15, "flux_lm": 20000, "cct_k": 3200})
    starts = [(3 + 3 * (k % 7), 2.5 + 11 * (k // 7)) for k in range(10)]
    names = [f"t{k + 1}" for k in range(10)]
    entities = [round_table(n, p, [150, 350]) for n, p in zip(names, starts)]
    constraints = []
    for i in range(len(names)):
        for j in range(i + 1, len(names)):
            constraints.append(clearance(names[i], names[j], 3.2))
    constraints.append({"type": "overlap", "tolerance": 0.05})
    scene = {"luxplan": 1, "name": f"fig10-event-hall-{variant}", "site": ATHENS}
    if day:
        # a clear winter noon: the sun is low (about 30 deg) and lights deep into the hall
        scene["daylight"] = preetham("2026-12-15", "12:00", "13:30", "+02:00")
    scene.update({
        "materials": materials(linen={"type": "diffuse", "reflectance": 0.8}),
        "geometry": geometry, "luminaires": lum, "entities": entities,
        "constraints": constraints, "objective": {"lighting_weight": 0.5},
        "optimizer": optimizer(3000, paths=16, report=256)})
    write(f"fig10-event-hall-{variant}.json", scene)


if __name__ == "__main__":
    fig4_sun_patch()
    fig4_glare()
    fig4_presenter()
    for v in ("morning", "afternoon", "evening"):
        office(v)
    fig8_lab()
    for v in ("day", "night"):
        apartment(v)
    fig6_hierarchy()
    for v in ("day", "night"):
        event_hall(v)
