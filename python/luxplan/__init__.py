"""luxplan from Python: load a scene, measure it as `luxplan measure --json` does and
optimize it as `luxplan optimize` does.

    import luxplan
    scene = luxplan.Scene("scenes/paper/fig4-presenter.json")
    m = scene.measure(paths=256, seed=3)
    m["C"], m["samplers"][0]["value"], m.point_values["presenter"]
    r = scene.optimize(iterations=500, seed=1)
    r["C"], r["layout"]

Results are the CLI's JSON objects as dicts (the same keys and numbers, bit for bit);
errors are SceneError (every problem: file, JSON path, message), IoError and
UsageError. docs/python.md.
"""
import json
import os
import warnings

import numpy as np

from ._batch import JobError, batch
from ._core import IoError, SceneError, UsageError
from ._core import Scene as _CoreScene

__all__ = ["Scene", "Measurement", "batch", "JobError", "SceneError", "IoError", "UsageError", "SceneWarning", "read_layout", "write_layout"]


class SceneWarning(UserWarning):
    """Valid input that may not be what was meant (what the CLI says as "warning:")."""


def _settings(settings):
    """--set's KEY=VALUE texts from a dict (values as JSON) or a list of texts."""
    if settings is None:
        return []
    if isinstance(settings, dict):
        return [f"{k}={v if isinstance(v, str) else json.dumps(v)}" for k, v in settings.items()]
    return [str(s) for s in settings]


def _whole(name, value, least, most=None):
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int):
        raise TypeError(f"{name} must be a whole number, not {type(value).__name__}")
    if value < least or (most is not None and value > most):
        raise ValueError(f"{name}: {value} is not in [{least}, {most if most is not None else 'inf'}]")
    return value


class Measurement(dict):
    """`luxplan measure --json`'s object, and each sampler's point values as numpy arrays
    (NaN where the JSON holds null: a point furniture covers)."""

    @property
    def point_values(self):
        return {s["name"]: np.array([np.nan if v is None else v for v in s["points"]], dtype=float) for s in self["samplers"]}

    @property
    def point_std_errors(self):
        return {s["name"]: np.array([np.nan if v is None else v for v in s["point_std_errors"]], dtype=float)
                for s in self["samplers"]}


class Scene:
    """A scene file loaded and checked as the CLI loads it. `settings`: the scene's
    "optimizer" settings to override, as `--set KEY=VALUE` does (a dict or KEY=VALUE texts)."""

    def __init__(self, path, settings=None):
        self._path = os.fspath(path)
        self._scene = _CoreScene(self._path, _settings(settings))
        for line in self._scene.warnings:
            warnings.warn(line, SceneWarning, stacklevel=2)

    @property
    def path(self):
        return self._path

    def initial_layout(self):
        """The scene's own placement as a layout dict (layout.json's content)."""
        return json.loads(self._scene.initial_layout())

    def measure(self, layout=None, paths=None, seed=None, threads=None, at=None, annual=False):
        """What `luxplan measure SCENE --json` prints with --layout, --paths, --seed,
        --threads, --at and --annual, as a Measurement (a dict). `layout`: a layout file's
        path, or a layout dict."""
        layout_file = layout_text = None
        if isinstance(layout, dict):
            layout_text = json.dumps(layout)
        elif layout is not None:
            layout_file = os.fspath(layout)
        _whole("paths", paths, 1)
        _whole("seed", seed, 0, 2**64 - 1)
        _whole("threads", threads, 0)
        if annual and at is not None:
            raise ValueError("annual and at exclude each other, as --annual and --at do")
        text, said = self._scene.measure(layout_file, layout_text, paths or 0, seed, threads or 0, at or "", bool(annual))
        for line in said:
            warnings.warn(line, SceneWarning, stacklevel=2)
        return Measurement(json.loads(text))

    def optimize(self, out=None, iterations=None, seed=None, threads=None, paths=None, pictures=False, progress=None,
                 suggestions=None, start=None, pdf=True):
        """What `luxplan optimize SCENE -o OUT` writes, with --iterations, --seed, --threads,
        --paths, --suggestions and --start: report.json's content as a dict, its
        ["layout"] the result (layout.json's content). With `out`, the files are written
        there too (`pictures`: the pictures, scene.glb, report.html and, with `pdf`,
        report.pdf). `progress(dict)` is called at each progress step (iteration,
        iterations, current, best, temperature, feasible, seconds, eta_seconds, line); an
        exception it raises stops the search and is raised. Ctrl-C stops the search and
        returns the best layout so far (its "stop_reason" is "cancelled")."""
        _whole("iterations", iterations, 0)
        _whole("seed", seed, 0, 2**64 - 1)
        _whole("threads", threads, 0)
        _whole("paths", paths, 1)
        _whole("suggestions", suggestions, 1, 50)
        if pictures and out is None:
            raise ValueError("pictures need an output folder (out)")
        if progress is not None and not callable(progress):
            raise TypeError("progress must be callable")
        start_file = start_text = None
        if isinstance(start, dict):
            start_text = json.dumps(start)
        elif start is not None:
            start_file = os.fspath(start)
        report, layout, said = self._scene.optimize(
            None if out is None else os.fspath(out), -1 if iterations is None else iterations, seed, threads or 0,
            paths or 0, suggestions or 0, start_file, start_text, bool(pictures), bool(pdf), progress)
        for line in said:
            warnings.warn(line, SceneWarning, stacklevel=2)
        result = json.loads(report)
        result["layout"] = json.loads(layout)
        return result


def read_layout(path):
    """A layout.json file as a dict."""
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def write_layout(layout, path):
    """Writes a layout dict as a layout.json file (atomically: a temporary file renamed)."""
    tmp = f"{os.fspath(path)}.tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        json.dump(layout, f, indent=2)
        f.write("\n")
    os.replace(tmp, path)
