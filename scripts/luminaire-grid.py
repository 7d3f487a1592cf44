#!/usr/bin/env python3
"""Writes an open-plan hall lit by a grid of ceiling panels, for timing how the path
tracer scales with the number of luminaires (every vertex weighs each of them).

    scripts/luminaire-grid.py NX NY OUT.json

The hall is 2.4 NX x 2.25 NY x 3 m, with NX x NY panels of 0.6 x 0.6 m and 5000 lm at
the centres of equal cells of the ceiling, and an 11 x 8 grid of work-plane points at
0.8 m; no daylight. e.g. scripts/luminaire-grid.py 10 8 /tmp/hall80.json, then

    build/luxplan measure /tmp/hall80.json --paths 12000 --threads 1
"""
import json
import sys


def hall(nx, ny):
    width, depth = 2.4 * nx, 2.25 * ny
    panels = [{"name": f"panel_{i}_{j}", "shape": "rect", "center": [2.4 * (i + 0.5), 2.25 * (j + 0.5), 2.99],
               "normal": [0, 0, -1], "size": [0.6, 0.6], "flux_lm": 5000}
              for i in range(nx) for j in range(ny)]
    return {
        "luxplan": 1,
        "name": f"hall with {nx} x {ny} panels",
        "materials": {"floor": {"type": "diffuse", "reflectance": 0.2},
                      "walls": {"type": "diffuse", "reflectance": 0.5},
                      "ceiling": {"type": "diffuse", "reflectance": 0.7}},
        "geometry": [{"name": "room", "room": {"min": [0, 0, 0], "max": [width, depth, 3]},
                      "materials": {"floor": "floor", "walls": "walls", "ceiling": "ceiling"}}],
        "luminaires": panels,
        "samplers": [{"name": "work plane", "type": "planar", "center": [width / 2, depth / 2, 0.8],
                      "size": [width - 2, depth - 2], "grid": [11, 8], "target": [500, 1e6], "tolerance": 100}],
    }


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    nx, ny = int(sys.argv[1]), int(sys.argv[2])
    if nx < 1 or ny < 1:
        sys.exit("luminaire-grid.py: NX and NY must be at least 1")
    with open(sys.argv[3], "w") as f:
        json.dump(hall(nx, ny), f, indent=1)


if __name__ == "__main__":
    main()
