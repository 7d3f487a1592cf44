"""Scene.optimize against `luxplan optimize`: the same report and layout for the same
seed (the wall-clock times aside), the same files in `out`; progress, its errors, and
Ctrl-C, which stops the search and returns its best layout so far."""
import json
import os
import signal
import subprocess
import sys
import textwrap

import pytest

import luxplan
from conftest import ROOT, cli, without_times

PRESENTER = "scenes/paper/fig4-presenter.json"
ARGS = dict(iterations=150, paths=4, seed=2, threads=2)


@pytest.fixture(scope="module")
def cli_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("cli")
    cli("optimize", PRESENTER, "-o", str(out), "--iterations", "150", "--paths", "4", "--seed", "2", "--threads", "2",
        "-q", "--no-pictures")
    return out


def read(path):
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def test_the_report_and_the_layout_are_the_clis(cli_run):
    result = luxplan.Scene(PRESENTER).optimize(**ARGS)
    layout = result.pop("layout")
    assert layout == read(cli_run / "layout.json")
    assert without_times(result) == without_times(read(cli_run / "report.json"))


def test_out_holds_the_clis_files(cli_run, tmp_path):
    luxplan.Scene(PRESENTER).optimize(out=tmp_path, **ARGS)
    for name in ("layout.json", "trace.csv"):
        assert (tmp_path / name).read_bytes() == (cli_run / name).read_bytes(), name
    assert without_times(read(tmp_path / "report.json")) == without_times(read(cli_run / "report.json"))
    # A layout the search wrote reads back as the CLI's --layout reads it.
    scene = luxplan.Scene(PRESENTER)
    assert scene.measure(layout=tmp_path / "layout.json", paths=4, seed=1)["C"] == \
        scene.measure(layout=luxplan.read_layout(tmp_path / "layout.json"), paths=4, seed=1)["C"]


def test_progress_is_told_and_its_error_raised():
    seen = []
    luxplan.Scene(PRESENTER).optimize(progress=seen.append, **ARGS)
    assert [p["iteration"] for p in seen] == [100, 150]
    assert seen[-1]["iterations"] == 150 and "line" in seen[-1]

    def fail(p):
        raise RuntimeError("stop here")

    with pytest.raises(RuntimeError, match="stop here"):
        luxplan.Scene(PRESENTER).optimize(progress=fail, **ARGS)


def test_a_start_layout_as_a_dict():
    scene = luxplan.Scene(PRESENTER)
    start = scene.initial_layout()
    result = scene.optimize(iterations=0, paths=4, seed=1, start=start)
    assert result["layout"]["entities"].keys() == start["entities"].keys()
    with pytest.raises(luxplan.SceneError, match="start: "):
        scene.optimize(iterations=0, paths=4, start={"entities": {"no such entity": {"position": [0, 0]}}})


def test_ctrl_c_returns_the_best_layout_so_far():
    # In a process of its own: SIGINT a second into a long search.
    code = textwrap.dedent(f"""
        import json, os, signal, threading
        import luxplan
        threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT)).start()
        r = luxplan.Scene({PRESENTER!r}).optimize(iterations=10**7, paths=4, seed=3, threads=2)
        print(json.dumps({{"stop": r["stop_reason"], "iterations": r["iterations"], "layout": bool(r["layout"]["entities"])}}))
    """)
    env = dict(os.environ)
    r = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, env=env, timeout=120)
    assert r.returncode == 0, r.stderr
    got = json.loads(r.stdout.strip().splitlines()[-1])
    # The signal may come while the start is planned (its tables and look take seconds on
    # a busy machine): the run then stops before its first iteration, with the start.
    assert got["stop"] == "cancelled" and got["layout"] and 0 <= got["iterations"] < 10**7
