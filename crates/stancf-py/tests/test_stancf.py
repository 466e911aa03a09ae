"""The Python package against the command line and on executors.

Run by scripts/test-python (from .ci/run): it builds the package into a
virtual environment with maturin and runs this file with pytest.
"""

import os
import signal
import subprocess
import threading
import time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import stancf

ROOT = Path(__file__).resolve().parents[3]
CLI = Path(os.environ.get("STANCF_BIN", ROOT / "target" / "release" / "stancf"))

IMPACT = """
title = "python test"
[cable]
length = 4.0
elements = 8
element = "SAC-2"
origin = [-2.0, 0.0, 0.0]
[material]
youngs_modulus = 3.4e9
density = 1380.0
area = 3.0e-6
second_moment = 1.25e-13
[[loads]]
type = "gravity"
acceleration = [0.0, -9.81, 0.0]
[[initial_velocity]]
node = "A"
velocity = [0.0, 10.0, 0.0]
[[initial_velocity]]
node = "B"
velocity = [0.0, -10.0, 0.0]
[analysis]
time_step = 5.0e-5
duration = 0.01
[output]
every = 10
"""

PENDULUM = """
title = "pendulum"
[cable]
length = 0.5
elements = 4
[material]
youngs_modulus = 0.91e6
density = 1202.0
area = 1.075e-5
second_moment = 9.15e-12
[[constraints]]
type = "pinned"
node = "A"
[[loads]]
type = "gravity"
acceleration = [0.0, -9.81, 0.0]
[[loads]]
type = "air-drag"
drag_coefficient = 1.5
fluid_density = 1.225
[analysis]
time_step = 1e-4
duration = 0.3
[output]
every = 100
"""


def cli(*args):
    assert CLI.exists(), "build the CLI first: cargo build --release -p stancf-cli"
    return subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True)


def test_same_numbers_as_the_cli_bit_for_bit(tmp_path):
    path = tmp_path / "impact.toml"
    path.write_text(IMPACT)
    p = cli("run", path, "--out", tmp_path / "cli")
    assert p.returncode == 0, p.stderr
    res = stancf.run(stancf.Scenario.from_file(path), out=tmp_path / "py")
    for name in ["history.csv", "nodes.csv", "stress.csv", "solver.csv"]:
        a = (tmp_path / "cli" / name).read_text()
        b = (tmp_path / "py" / name).read_text()
        if name == "solver.csv":  # its last two columns are wall times
            a = [",".join(l.split(",")[:-2]) for l in a.splitlines()]
            b = [",".join(l.split(",")[:-2]) for l in b.splitlines()]
        assert a == b, name
    cli_res = stancf.Result.read(tmp_path / "cli")
    assert np.array_equal(res.nodes, cli_res.nodes)
    assert np.array_equal(res.stress, cli_res.stress)
    assert np.array_equal(res.energy["total"], cli_res.energy["total"])
    assert res.nodes.shape == (21, 9, 3)
    assert res.t[0] == 0.0 and abs(res.t[-1] - 0.01) < 1e-15
    assert res.summary["tip"] == cli_res.summary["tip"]
    # The arrays are the files' numbers.
    last = np.loadtxt(tmp_path / "py" / "nodes.csv", delimiter=",", skiprows=1)[-9:]
    assert np.array_equal(res.nodes[-1], last[:, 2:5])
    # write() gives the interface files.
    res.write(tmp_path / "copy")
    assert (tmp_path / "copy" / "summary.json").read_text() == (tmp_path / "py" / "summary.json").read_text()


def test_from_dict_with_values_and_errors_name_the_key():
    sc = stancf.Scenario(IMPACT)
    d = {
        "cable": {"length": 4.0, "elements": 8, "origin": [-2.0, 0.0, 0.0]},
        "material": {"youngs_modulus": 3.4e9, "density": 1380.0, "area": 3.0e-6,
                     "second_moment": 1.25e-13},
        "initial_velocity": [{"node": "A", "velocity": [0.0, 10.0, 0.0]}],
        "analysis": {"time_step": 5e-5, "duration": 1e-3},
    }
    r = stancf.run(stancf.Scenario.from_dict(d))
    assert r.summary["steps"] == 20
    with pytest.raises(stancf.ScenarioError, match="unknown field `lenght`"):
        stancf.Scenario.from_dict({**d, "cable": {**d["cable"], "lenght": 1.0}})
    with pytest.raises(stancf.ScenarioError, match="time_stepp"):
        sc.with_values({"analysis.time_stepp": 1e-4})
    with pytest.raises(stancf.ScenarioError, match="analysis.time_step"):
        sc.with_values({"analysis.time_step": -1.0})
    s2 = sc.with_values({"analysis.time_step": 2.5e-5, "loads.0.acceleration": [0, -1.62, 0]})
    r2 = stancf.run(s2.with_values({"analysis.duration": 1e-4}))
    assert r2.summary["time_step"] == 2.5e-5 and r2.summary["steps"] == 4
    assert "acceleration = [0, -1.62, 0]" in s2.text


def test_solver_failure_raises_with_the_partial_result():
    # Twenty times P2's stable step: the energy watchdog stops the run.
    sc = stancf.Scenario(IMPACT).with_values({"analysis.time_step": 2e-3, "analysis.duration": 0.2,
                                              "output.every": 1})
    with pytest.raises(stancf.SolverError) as e:
        stancf.run(sc)
    err = e.value
    assert err.step >= 1 and err.time >= 0.0
    assert err.residual is None or np.isfinite(err.residual)
    part = err.result
    assert part.summary["converged"] is False
    assert len(part.t) == err.step  # t = 0 and every converged step before it
    assert np.all(np.isfinite(part.nodes))


def test_ctrl_c_stops_a_run_cleanly(tmp_path):
    sc = stancf.Scenario(IMPACT).with_values({"analysis.duration": 20.0, "output.every": 200})
    timer = threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    t0 = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        stancf.run(sc, out=tmp_path / "r")
    assert time.perf_counter() - t0 < 5.0
    part = stancf.Result.read(tmp_path / "r")
    assert part.summary["interrupted"] is True
    assert 0 < part.t[-1] < 20.0


def test_the_gil_is_released_while_the_solver_runs():
    sc = stancf.Scenario(IMPACT).with_values({"analysis.duration": 0.5, "output.every": 1000})
    done = threading.Event()
    th = threading.Thread(target=lambda: (stancf.run(sc), done.set()))
    th.start()
    count = 0
    while not done.is_set():
        count += 1
    th.join()
    assert count > 10000, count


def test_sweep_on_a_process_pool_matches_separate_runs(tmp_path):
    sc = stancf.Scenario(PENDULUM)
    grid = {"loads.1.drag_coefficient": [0.0, 1.5], "analysis.time_step": [1e-4, 2e-4]}
    with ProcessPoolExecutor(2) as ex:
        rows = stancf.sweep(sc, grid, executor=ex, out=tmp_path / "sw")
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert len(rows) == 4
    assert [r["loads.1.drag_coefficient"] for r in rows] == [0.0, 0.0, 1.5, 1.5]
    for r in rows:
        alone = stancf.run(sc.with_values({"loads.1.drag_coefficient": r["loads.1.drag_coefficient"],
                                           "analysis.time_step": r["analysis.time_step"]}))
        assert r["status"] == "ok"
        assert r["tip_x"] == alone.summary["tip"][0] and r["tip_y"] == alone.summary["tip"][1]
    assert (tmp_path / "sw" / "run_0003" / "nodes.csv").exists()
    assert (tmp_path / "sw" / "sweep.csv").exists()




def _cluster(**kw):
    from dask.distributed import Client, LocalCluster
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=None, **kw)
    return cluster, Client(cluster)


def test_twelve_point_sweep_on_a_dask_cluster(tmp_path):
    sc = stancf.Scenario(PENDULUM)
    grid = {"loads.1.drag_coefficient": [0.0, 0.5, 1.0, 1.5, 2.0, 2.5],
            "analysis.time_step": [1e-4, 2e-4]}
    cluster, client = _cluster()
    try:
        rows = stancf.sweep(sc, grid, executor=client, out=tmp_path / "sw")
    finally:
        client.close()
        cluster.close()
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert len(rows) == 12
    for r in rows:
        assert r["status"] == "ok", r
        alone = stancf.run(sc.with_values({"loads.1.drag_coefficient": r["loads.1.drag_coefficient"],
                                           "analysis.time_step": r["analysis.time_step"]}))
        for k, name in enumerate(["tip_x", "tip_y", "tip_z"]):
            assert r[name] == alone.summary["tip"][k]
        assert r["steps"] == alone.summary["steps"]
        assert r["energy_max_rel_drift"] == alone.summary["energy"]["max_rel_drift"]


def test_a_killed_worker_is_reported_not_waited_for(tmp_path):
    import dask
    sc = stancf.Scenario(PENDULUM).with_values({"analysis.duration": 2.0})
    grid = {"loads.1.drag_coefficient": [0.1 * k for k in range(8)]}
    # No retries: a run on a dead worker fails instead of moving on.
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        cluster, client = _cluster()
        try:
            def kill_one():
                time.sleep(1.0)
                workers = list(client.scheduler_info()["workers"])
                try:
                    client.run(os._exit, 1, workers=workers[:1])
                except Exception:
                    pass  # the worker is gone before it can answer
            threading.Thread(target=kill_one, daemon=True).start()
            t0 = time.perf_counter()
            rows = stancf.sweep(sc, grid, executor=client, out=tmp_path / "sw", timeout=120)
            elapsed = time.perf_counter() - t0
        finally:
            client.close()
            cluster.close()
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert len(rows) == 8
    failed = [r for r in rows if r["status"] == "failed"]
    assert failed, rows
    assert all("KilledWorker" in r["error"] or "died" in r["error"].lower() for r in failed), failed
    assert elapsed < 120
