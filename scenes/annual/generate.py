#!/usr/bin/env python3
"""The paper's six-workstation office (scenes/paper/fig7-office-morning.json) under
Chicago's typical year: its daylight from the weather file's hours (the Perez sky),
occupied on weekdays 8-18, and each desk with an annual goal besides its mean. Run from
this folder: python3 generate.py"""
import json
from pathlib import Path

here = Path(__file__).resolve().parent
scene = json.loads((here / "../paper/fig7-office-morning.json").read_text())
scene["name"] = "fig7-office-year"
del scene["site"]  # the weather file's
scene["daylight"] = {
    "weather": "../../tests/data/weather/chicago.epw",
    "sky": {"model": "perez"},
    "ground_reflectance": 0.2,
    "occupied": {"hours": [8, 18], "weekdays": [1, 2, 3, 4, 5]},
}


def desks(entity):
    for child in entity.get("children", []):
        if child["name"] == "desk":
            yield child
        yield from desks(child)


for ws in scene["entities"]:
    for desk in desks(ws):
        for s in desk.get("samplers", []):
            if s["name"] == "task":
                # Useful daylight (100-3000 lx in UDI's terms, from 300 lx for a desk) in at
                # least 60% of the occupied hours.
                s["target"] = [300, 3000]
                s["annual"] = {"in_range": {"target": [0.6, 1], "tolerance": 0.2}}
(here / "fig7-office-year.json").write_text(json.dumps(scene, indent=1) + "\n")
