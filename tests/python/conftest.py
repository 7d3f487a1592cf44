"""What the tests of the Python module share: the CLI to compare with (LUXPLAN_CLI,
set by ctest) run from the repository's root, as the tests run."""
import json
import os
import subprocess

import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TIMES = {"seconds", "start_seconds", "annual_seconds", "samplers_seconds"}


def cli(*args, check=True):
    """The CLI's run: (exit code, stdout, stderr)."""
    exe = os.environ.get("LUXPLAN_CLI", os.path.join(ROOT, "build", "luxplan"))
    r = subprocess.run([exe, *args], cwd=ROOT, capture_output=True, text=True)
    if check and r.returncode != 0:
        raise AssertionError(f"luxplan {' '.join(args)}: exit {r.returncode}\n{r.stderr}")
    return r.returncode, r.stdout, r.stderr


def cli_json(*args):
    """The CLI's JSON output, its wall-clock times left out."""
    return without_times(json.loads(cli(*args)[1]))


def without_times(d):
    return {k: v for k, v in d.items() if k not in TIMES}


@pytest.fixture(autouse=True)
def at_root(monkeypatch):
    """Relative scene paths read as the CLI's do (both from the repository's root)."""
    monkeypatch.chdir(ROOT)
