"""Errors arrive as the CLI says them: SceneError with every problem (its file, JSON
path and message, one line each as on the CLI's stderr), UsageError for a setting,
SceneError naming the scene for a problem found after loading."""
import json

import pytest

import luxplan
from conftest import cli

BROKEN = {
    "luxplan": 1,
    "name": "two problems",
    "materials": {"m": {"type": "diffuse", "reflectance": 1.5}},
    "geometry": [{"name": "room", "room": {"min": [0, 0, 0], "max": [4, 4, 3]},
                  "materials": {"floor": "m", "walls": "m", "ceiling": "nope"}}],
}


def test_a_broken_scene_lists_every_problem(tmp_path):
    path = tmp_path / "broken.json"
    path.write_text(json.dumps(BROKEN))
    with pytest.raises(luxplan.SceneError) as caught:
        luxplan.Scene(path)
    code, _, stderr = cli("validate", str(path), check=False)
    assert code == 1
    assert str(caught.value).splitlines() == stderr.strip().splitlines()
    assert len(caught.value.diagnostics) == len(stderr.strip().splitlines()) >= 2
    first = caught.value.diagnostics[0]
    assert first["file"] == str(path) and first["path"].startswith("/") and first["message"]
    assert isinstance(caught.value, ValueError)


def test_a_missing_file_and_a_bad_setting():
    with pytest.raises(luxplan.SceneError, match="no-such.json: /: cannot open the file"):
        luxplan.Scene("no-such.json")
    with pytest.raises(luxplan.UsageError, match="no_such_key"):
        luxplan.Scene("scenes/paper/fig4-presenter.json", settings={"no_such_key": 1})
    scene = luxplan.Scene("scenes/paper/fig4-presenter.json", settings={"seed": 5})
    assert scene.measure(paths=4)["seed"] == 5


def test_a_problem_after_loading_names_the_scene():
    # The presenter scene has no daylight: --at is refused, naming the file.
    with pytest.raises(luxplan.SceneError) as caught:
        luxplan.Scene("scenes/paper/fig4-presenter.json").measure(at="2026-03-20T12:00+02:00", paths=4)
    code, _, stderr = cli("measure", "scenes/paper/fig4-presenter.json", "--at", "2026-03-20T12:00+02:00", "--paths", "4",
                          check=False)
    assert code == 1
    assert str(caught.value) == stderr.strip()
