"""luxplan.batch on a LocalCluster of 2 worker processes: results in job order and
identical to the CLI's, scenes whose files (a weather file two folders up, a photometric
file) reach the workers as data, failing jobs in their places, and a worker process
killed mid-job costing a rerun, not a result."""
import json
import os
import signal
import threading
import time

import distributed
import pytest

import luxplan
from conftest import cli, cli_json, without_times

PRESENTER = "scenes/paper/fig4-presenter.json"


def optimize_jobs(iterations):
    return [{"command": "optimize", "scene": PRESENTER, "iterations": iterations, "paths": 4, "seed": seed}
            for seed in range(1, 7)]


def cli_optimize(job, tmp_path):
    out = tmp_path / f"cli-{job['seed']}-{job['iterations']}"
    cli("optimize", job["scene"], "-o", str(out), "--iterations", str(job["iterations"]), "--paths", "4", "--seed",
        str(job["seed"]), "--threads", "1", "-q", "--no-pictures")
    with open(out / "report.json", encoding="utf-8") as f:
        report = json.load(f)
    with open(out / "layout.json", encoding="utf-8") as f:
        report["layout"] = json.load(f)
    return without_times(report)


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as c:
        yield c


def test_six_jobs_give_the_clis_results_in_order(client, tmp_path):
    jobs = optimize_jobs(150)
    results = luxplan.batch(jobs, client)
    assert len(results) == 6
    for job, result in zip(jobs, results):
        assert not isinstance(result, luxplan.JobError), result
        assert without_times(result) == cli_optimize(job, tmp_path), job["seed"]


def test_files_travel_and_outputs_come_back(client, tmp_path):
    at = "2026-06-19T12:00-06:00"
    out = tmp_path / "out"
    jobs = [
        {"command": "measure", "scene": "scenes/annual/fig7-office-year.json", "at": at, "paths": 8, "seed": 2},
        {"command": "measure", "scene": "scenes/photometry/downlights.json", "paths": 8, "seed": 2},
        {"command": "optimize", "scene": PRESENTER, "iterations": 100, "paths": 4, "seed": 9, "out": str(out)},
    ]
    layout = luxplan.Scene(PRESENTER).initial_layout()
    name = next(iter(layout["entities"]))
    layout["entities"][name]["position"][0] += 0.4
    layout_file = tmp_path / "moved.json"
    luxplan.write_layout(layout, layout_file)
    jobs.append({"command": "measure", "scene": PRESENTER, "layout": str(layout_file), "paths": 4, "seed": 5})
    year, downlights, optimized, moved = luxplan.batch(jobs, client)
    assert without_times(moved) == cli_json("measure", PRESENTER, "--layout", str(layout_file), "--paths", "4", "--seed", "5",
                                            "--json")
    assert without_times(year) == cli_json("measure", jobs[0]["scene"], "--at", at, "--paths", "8", "--seed", "2", "--json")
    assert without_times(downlights) == cli_json("measure", jobs[1]["scene"], "--paths", "8", "--seed", "2", "--json")
    assert optimized["file"] == PRESENTER  # the client's path, not the worker's
    with open(out / "layout.json", encoding="utf-8") as f:
        assert json.load(f) == optimized["layout"]
    assert (out / "trace.csv").is_file()


def test_a_failing_job_keeps_its_place(client, tmp_path):
    broken = tmp_path / "broken.json"
    broken.write_text('{"luxplan": 1, "name": "x", "materials": {}, "geometry": [], "no_such_key": 1}')
    jobs = [
        {"command": "measure", "scene": PRESENTER, "paths": 4, "seed": 1},
        {"command": "measure", "scene": str(broken)},
        {"command": "render", "scene": PRESENTER},
        {"command": "measure", "scene": PRESENTER, "paths": 4, "iterations": 3},
        {"command": "measure", "scene": "no-such-scene.json"},
        {"command": "measure", "scene": PRESENTER, "paths": 4, "seed": 2},
    ]
    results = luxplan.batch(jobs, client)
    assert [isinstance(r, luxplan.JobError) for r in results] == [False, True, True, True, True, False]
    assert results[1].kind == "SceneError" and str(broken) in results[1].message
    code, _, stderr = cli("measure", str(broken), check=False)
    assert code == 1 and results[1].message == stderr.strip()
    assert "no_such_key" in results[1].message and results[1].diagnostics
    assert "measure takes no 'iterations'" in str(results[3])
    assert without_times(results[5]) == cli_json("measure", PRESENTER, "--paths", "4", "--seed", "2", "--json")


def test_a_worker_killed_mid_job_costs_a_rerun(tmp_path):
    jobs = optimize_jobs(3000)  # about 2 s each on one thread
    killed = []
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0") as cluster, \
            distributed.Client(cluster) as c:
        pids = c.run(os.getpid)

        def kill_one():
            # The first worker seen running a job, a second into it.
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline:
                busy = [w for w, keys in c.processing().items() if keys]
                if busy:
                    time.sleep(1.0)
                    os.kill(pids[busy[0]], signal.SIGKILL)
                    killed.append(busy[0])
                    return
                time.sleep(0.05)

        killer = threading.Thread(target=kill_one)
        killer.start()
        results = luxplan.batch(jobs, c)
        killer.join()
    assert killed, "no worker was seen busy"
    for job, result in zip(jobs, results):
        assert not isinstance(result, luxplan.JobError), result
        assert without_times(result) == cli_optimize(job, tmp_path), job["seed"]
