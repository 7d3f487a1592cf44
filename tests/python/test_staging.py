"""What luxplan.batch sends to a worker: the scene and every file it names (an OBJ mesh,
a glTF with an external buffer, a photometric file, in folders of their own), enough to
run the job where none of the client's files exist; the worker's paths turned back into
the client's in the result and in errors."""
import base64
import json
import os
import shutil

import pytest

import luxplan
from luxplan import _batch
from conftest import ROOT, without_times


def write_scene(folder):
    """A room with a mesh bar, a glTF block (its buffer a file beside it) and a downlight
    of an IES file, each in a folder of its own."""
    os.makedirs(folder / "models")
    os.makedirs(folder / "ies")
    shutil.copy(os.path.join(ROOT, "tests/data/cube.obj"), folder / "models" / "bar.obj")
    gltf = json.load(open(os.path.join(ROOT, "tests/data/cube.gltf"), encoding="utf-8"))
    buffer = gltf["buffers"][0]
    (folder / "models" / "block.bin").write_bytes(base64.b64decode(buffer["uri"].split(",", 1)[1]))
    buffer["uri"] = "block.bin"
    (folder / "models" / "block.gltf").write_text(json.dumps(gltf))
    shutil.copy(os.path.join(ROOT, "scenes/photometry/downlight.ies"), folder / "ies" / "downlight.ies")
    scene = {
        "luxplan": 1, "name": "staged",
        "materials": {"m": {"type": "diffuse", "reflectance": 0.5}},
        "geometry": [
            {"name": "room", "room": {"min": [0, 0, 0], "max": [5, 4, 3]}, "materials": {"floor": "m", "walls": "m", "ceiling": "m"}},
            {"name": "bar", "mesh": "models/bar.obj", "transform": {"translate": [1, 3, 0.5], "scale": 0.3}, "material": "m"},
        ],
        "luminaires": [{"name": "dl", "shape": "disk", "center": [2.5, 2, 2.99], "normal": [0, 0, -1], "radius": 0.075,
                        "photometry": "ies/downlight.ies"}],
        "entities": [{"name": "block", "position": [3, 1], "placement": {"regions": [{"min": [1, 1], "max": [4, 3]}]},
                      "parts": [{"mesh": "models/block.gltf", "transform": {"scale": 0.2}, "material": "m"}]}],
        "samplers": [{"name": "desk", "type": "planar", "center": [2.5, 2, 0.8], "size": [1, 1], "grid": [2, 2],
                      "target": [100, 1000]}],
    }
    path = folder / "scene.json"
    path.write_text(json.dumps(scene))
    return path


def test_a_job_runs_where_its_files_are_gone(tmp_path):
    folder = tmp_path / "client"
    path = write_scene(folder)
    want = without_times(luxplan.Scene(path).measure(paths=8, seed=3))
    files, own, kwargs = _batch._bundle(str(path), {"paths": 8, "seed": 3})
    assert own == {}
    assert sorted(os.path.relpath(p, folder) for p in files) == \
        ["ies/downlight.ies", "models/bar.obj", "models/block.bin", "models/block.gltf", "scene.json"]
    shutil.rmtree(folder)  # the worker has only what the job carries
    spec = {"command": "measure", "scene": str(path), "scene_abs": os.path.abspath(path), "settings": None,
            "kwargs": kwargs, "out": None}
    status, result, written = _batch._run_job(spec, files)
    assert status == "ok" and written == {}
    assert without_times(result) == want


def test_an_error_names_the_clients_files(tmp_path):
    folder = tmp_path / "client"
    path = write_scene(folder)
    (folder / "ies" / "downlight.ies").write_text("not an IES file\n")
    with pytest.raises(Exception) as caught:
        luxplan.Scene(path)
    files, _, kwargs = _batch._bundle(str(path), {})
    spec = {"command": "measure", "scene": str(path), "scene_abs": os.path.abspath(path), "settings": None,
            "kwargs": kwargs, "out": None}
    status, kind, message, _ = _batch._run_job(spec, files)
    assert status == "error" and kind == type(caught.value).__name__
    assert message == str(caught.value)
    assert str(folder / "ies" / "downlight.ies") in message
