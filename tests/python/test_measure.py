"""Scene.measure against `luxplan measure --json`: the same keys and numbers, bit for bit
(the wall-clock times aside), for the scene's placement, a layout given as a file or a
dict, one instant of a weather file and the year; the point values as numpy arrays."""
import json
import math
import os

import numpy as np
import pytest

import luxplan
from conftest import cli_json, without_times

PRESENTER = "scenes/paper/fig4-presenter.json"
OFFICE_YEAR = "tests/data/weather/office.json"


def test_the_scenes_placement_gives_the_clis_numbers():
    m = luxplan.Scene(PRESENTER).measure(paths=16, seed=3, threads=2)
    assert isinstance(m, dict)
    assert without_times(m) == cli_json("measure", PRESENTER, "--json", "--paths", "16", "--seed", "3", "--threads", "2")
    assert m["seconds"] > 0


def test_a_layout_as_a_file_or_a_dict(tmp_path):
    scene = luxplan.Scene(PRESENTER)
    layout = scene.initial_layout()
    name = next(iter(layout["entities"]))
    layout["entities"][name]["position"][0] += 0.5
    path = tmp_path / "layout.json"
    luxplan.write_layout(layout, path)
    want = cli_json("measure", PRESENTER, "--layout", str(path), "--json", "--paths", "8", "--seed", "4")
    assert without_times(scene.measure(layout=path, paths=8, seed=4)) == want
    assert without_times(scene.measure(layout=layout, paths=8, seed=4)) == want
    assert luxplan.read_layout(path) == layout


def test_an_hour_of_a_weather_file_and_the_year(tmp_path):
    # The office over a June week (a whole year's bake takes seconds), its weather file
    # named by its absolute path.
    with open(OFFICE_YEAR, encoding="utf-8") as f:
        office = json.load(f)
    office["daylight"]["weather"] = os.path.abspath(os.path.join(os.path.dirname(OFFICE_YEAR), office["daylight"]["weather"]))
    office["daylight"]["from"], office["daylight"]["to"] = "2026-06-18T00:00-06:00", "2026-06-22T23:00-06:00"
    path = tmp_path / "office.json"
    path.write_text(json.dumps(office))
    scene = luxplan.Scene(path)
    at = "2026-06-19T12:00-06:00"
    m = scene.measure(paths=32, seed=5, at=at)
    assert without_times(m) == cli_json("measure", str(path), "--json", "--paths", "32", "--seed", "5", "--at", at)
    assert m["at"] == "2006-06-19T12:30-06:00"  # the file's hour (its year), at its middle
    year = scene.measure(paths=16, seed=5, annual=True)
    assert without_times(year) == cli_json("measure", str(path), "--json", "--paths", "16", "--seed", "5", "--annual")
    assert len(year["hours"]) == 40  # Monday 19 to Thursday 22 June 2006, 8-18


def test_point_values_as_numpy_arrays():
    m = luxplan.Scene(PRESENTER).measure(paths=8, seed=1)
    for s in m["samplers"]:
        values = m.point_values[s["name"]]
        assert isinstance(values, np.ndarray) and values.dtype == np.float64
        assert len(values) == len(s["points"])
        for v, p in zip(values, s["points"]):
            assert (math.isnan(v) and p is None) or v == p


def test_two_measurements_in_one_process_are_the_same():
    scene = luxplan.Scene(PRESENTER)
    a, b = (without_times(scene.measure(paths=8, seed=9)) for _ in range(2))
    assert a == b


def test_arguments_are_checked_as_the_clis_options():
    scene = luxplan.Scene(PRESENTER)
    with pytest.raises(ValueError):
        scene.measure(paths=0)
    with pytest.raises(ValueError):
        scene.measure(seed=-1)
    with pytest.raises(TypeError):
        scene.measure(paths=2.5)
    with pytest.raises(ValueError):
        luxplan.Scene(OFFICE_YEAR).measure(annual=True, at="2026-06-19T12:00-06:00")
