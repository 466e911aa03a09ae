"""The Python package against the command line and on executors.

Run by scripts/test-python (from .ci/run): it builds the package into a
virtual environment with maturin and runs this file with pytest.
"""

import os
import signal
import subprocess
import threading
import time
from concurrent.futures import Future, ProcessPoolExecutor
from pathlib import Path

import numpy as np
import pytest

import stancf
from sweep_executors import KillsTheWorkerOfRun0 as _KillsTheWorkerOfRun0, cluster as _cluster

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


def test_a_system_result_has_the_clis_lines_points_and_tensions(tmp_path):
    """A MoorDyn deck run from Python: the same files as the command
    line's, read into lines, points, tensions and channels; the clump
    weight's wet weight is held by its lines."""
    deck = ROOT / "examples" / "midwater-bridle-moordyn.txt"
    res = stancf.run(stancf.Scenario.from_file(deck), out=tmp_path / "py")
    r = cli("run", deck, "--out", tmp_path / "cli", "--quiet")
    assert r.returncode == 0, r.stderr
    for name in ["points.csv", "tensions.csv", "channels.csv", "lines/1/nodes.csv",
                 "lines/2/stress.csv", "lines/2/node_loads.csv"]:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()
    assert res.is_system and sorted(res.lines) == [1, 2] and sorted(res.points) == [1, 2, 3]
    assert res.lines[1].nodes.shape == (1, 21, 3)
    assert res.lines[1].bending_moment.shape == (1, 21)
    assert res.lines[1].seabed_force.shape == (1, 21, 3)
    assert res.lines[1].node_s[-1] == pytest.approx(res.lines[1].stress_s[-1], rel=1e-15)
    wet = (2000.0 - 1025.0 * 0.5) * 9.81
    assert abs(res.points[3]["force"][-1][2] - wet) <= 1e-9 * wet
    a = res.tensions[(1, "A")]
    assert a["tension"][-1] == pytest.approx(np.linalg.norm(a["force"][-1]), rel=1e-15)
    assert res.channels["AnchTen1"][-1] == a["tension"][-1]


def assert_same_result(a, b):
    """Every array and value of two Results equal to the bit (NaN equal
    to NaN)."""
    def same(x, y, where):
        if isinstance(x, dict):
            assert sorted(x, key=str) == sorted(y, key=str), where
            for k in x:
                same(x[k], y[k], "%s[%r]" % (where, k))
        elif isinstance(x, np.ndarray) or isinstance(y, np.ndarray):
            assert np.array_equal(x, y, equal_nan=True), where
            assert np.asarray(x).dtype == np.asarray(y).dtype, where
        elif hasattr(x, "__dict__") and not isinstance(x, type):
            same(vars(x), vars(y), where)
        else:
            assert x == y, where
    keep = ("t", "energy", "nodes", "slopes", "stress", "stress_s", "curvature",
            "reactions", "reactions_t", "summary", "is_system", "lines", "points",
            "tensions", "channels", "channels_t")
    for name in keep:
        same(getattr(a, name), getattr(b, name), name)


def test_run_from_memory_equals_the_files_to_the_bit(tmp_path):
    """stancf.run takes its arrays from the bytes the run wrote, kept in
    memory: a single cable with reactions, a system with its tensions and
    a MoorDyn deck with OUTPUTS channels give the Result that reading the
    folder back gives, bit for bit."""
    pendulum = stancf.Scenario(PENDULUM).with_values({"cable.elements": 12, "output.every": 1,
                                                      "analysis.duration": 0.05})
    bridle = stancf.Scenario.from_file(ROOT / "examples" / "bridle.toml").with_values(
        {"analysis.duration": 0.03, "output.every": 1})
    deck = stancf.Scenario.from_file(ROOT / "examples" / "midwater-bridle-moordyn.txt")
    for k, sc in enumerate([pendulum, bridle, deck]):
        res = stancf.run(sc, out=tmp_path / str(k))
        assert res._keep is None
        assert_same_result(res, stancf.Result.read(tmp_path / str(k)))
    assert res.channels and res.tensions and pendulum and len(res.lines) == 2


def test_a_system_run_returns_the_tables_it_was_asked_to_write(tmp_path):
    """[output] files: the tables written are the full run's to the bit,
    the times come from them, the tables left out are empty or None."""
    bridle = stancf.Scenario.from_file(ROOT / "examples" / "bridle.toml").with_values(
        {"analysis.duration": 0.03, "output.every": 1})
    full = stancf.run(bridle)
    some = stancf.run(bridle.with_values({"output.files": ["points.csv", "tensions.csv"]}))
    assert np.array_equal(some.t, full.t) and some.energy == {}
    for p in full.points:
        for k in ("t", "position", "velocity", "force"):
            assert np.array_equal(some.points[p][k], full.points[p][k]), (p, k)
    for end in full.tensions:
        assert np.array_equal(some.tensions[end]["tension"], full.tensions[end]["tension"])
    assert all(line.nodes is None and line.stress is None for line in some.lines.values())
    nodes = stancf.run(bridle.with_values({"output.files": ["nodes.csv"]}), out=tmp_path / "n")
    assert np.array_equal(nodes.t, full.t) and nodes.points == {} and nodes.tensions == {}
    for k, line in full.lines.items():
        assert np.array_equal(nodes.lines[k].nodes, line.nodes)
    assert_same_result(nodes, stancf.Result.read(tmp_path / "n"))
    # From the straight start tensions.csv has no row at t = 0; the times
    # come from nodes.csv, which has.
    straight = bridle.with_values({"analysis.initial": "reference", "analysis.duration": 0.005})
    full = stancf.run(straight)
    some = stancf.run(straight.with_values({"output.files": ["tensions.csv", "nodes.csv"]}))
    assert np.array_equal(some.t, full.t) and some.t[0] == 0.0
    assert np.array_equal(some.lines[1].nodes, full.lines[1].nodes)
    assert np.array_equal(some.tensions[(1, "A")]["tension"], full.tensions[(1, "A")]["tension"])
    assert len(full.tensions[(1, "A")]["t"]) == len(full.t) - 1  # none at t = 0


def test_a_line_in_sections_has_its_nodes_where_the_sections_put_them():
    """grading = {sections = [...]} from Python: line 1 of the bridle
    (4 m) as 1 m in 4 elements then 3 m in 4 has its nodes 0.25 m apart,
    then 0.75 m; the summary records the sections; sections that do not
    add up to the line are refused naming the key."""
    sections = [{"length": 1.0, "elements": 4}, {"length": 3.0, "elements": 4}]
    bridle = stancf.Scenario.from_file(ROOT / "examples" / "bridle.toml").with_values(
        {"analysis.type": "static", "lines.0.elements": 8,
         "lines.0.grading": {"sections": sections}})
    res = stancf.run(bridle)
    want = [0.0, 0.25, 0.5, 0.75, 1.0, 1.75, 2.5, 3.25, 4.0]
    assert np.allclose(res.lines[1].node_s, want, rtol=0, atol=4e-16 * 4), res.lines[1].node_s
    assert res.summary["lines"][0]["grading"]["sections"][1] == {"length": 3.0, "elements": 4}
    with pytest.raises(stancf.ScenarioError, match=r"lines\[0\]\.grading\.sections.*add up to 5"):
        bridle.with_values({"lines.0.grading": {"sections": [sections[0], {**sections[1], "length": 4.0}]}})


def test_end_forces_at_time_follow_the_step_means():
    """[output] end_forces = "at_time" from Python: the bridle's point
    forces are R_k + w (R_k - R_(k-1)) of the step means R, w = h_k /
    (h_k + h_(k-1)) (docs/method.md (M23a)): 1.5 R_k - 0.5 R_(k-1) for
    equal steps, and the 0.01 s run's last step is shortened to land on
    its duration (67 steps of 0.15 ms, the last 0.1 ms); the first step's
    is the mean itself; the states are the same."""
    bridle = stancf.Scenario.from_file(ROOT / "examples" / "bridle.toml").with_values(
        {"analysis.duration": 0.01, "output.every": 1})
    mean = stancf.run(bridle)
    at_t = stancf.run(bridle.with_values({"output.end_forces": "at_time"}))
    for p in mean.points:
        m, a = mean.points[p]["force"][1:], at_t.points[p]["force"][1:]
        assert np.array_equal(mean.points[p]["position"], at_t.points[p]["position"])
        t = mean.points[p]["t"]
        assert len(t) == 68 and t[-1] == 0.01 and t[-2] == 0.0099, t[-3:]
        dt = 1.5e-4
        h = np.array([dt] * 66 + [0.01 - 66 * dt])
        w = (h[1:] / (h[1:] + h[:-1]))[:, None]
        want = np.vstack([m[:1], m[1:] + w * (m[1:] - m[:-1])])
        assert np.allclose(a, want, rtol=0, atol=8 * np.finfo(float).eps * np.abs(m).max()), p


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
    # The partial result from memory is the partial files'.
    assert_same_result(part, stancf.Result.read(part.directory))


def test_a_failed_run_without_out_names_no_deleted_folder(tmp_path):
    # Twenty times P2's stable step: the energy watchdog stops the run.
    sc = stancf.Scenario(IMPACT).with_values({"analysis.time_step": 2e-3, "analysis.duration": 0.2,
                                              "output.every": 1})
    with pytest.raises(stancf.SolverError) as e:
        stancf.run(sc)
    message, folder = str(e.value), str(e.value.result.directory)
    # The run's temporary folder goes with its result: the message names
    # where the results are instead.
    assert folder not in message
    assert "are in the SolverError's result (in memory: with no out folder, stancf.run keeps " \
        "no files)" in message, message
    # Given a folder, the message names it, and the files are there.
    with pytest.raises(stancf.SolverError) as e:
        stancf.run(sc, out=tmp_path / "r")
    assert "are in %s" % (tmp_path / "r") in str(e.value)
    assert (tmp_path / "r" / "summary.json").exists()


def test_an_interrupted_run_without_out_names_no_deleted_folder(tmp_path, monkeypatch):
    # The run's temporary folder (and its staging folder beside it) in
    # tmp_path, so that a second thread sees when the run is writing.
    import _thread
    import tempfile
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    sc = stancf.Scenario(IMPACT).with_values({"analysis.duration": 20.0, "output.every": 200})

    def interrupt_once_running():
        end = time.monotonic() + 120.0
        while time.monotonic() < end and not list(tmp_path.glob(".stancf-*/scenario.toml")):
            time.sleep(1e-3)
        _thread.interrupt_main()

    th = threading.Thread(target=interrupt_once_running)
    th.start()
    try:
        with pytest.raises(KeyboardInterrupt) as e:
            stancf.run(sc)
    finally:
        th.join()
    message = str(e.value)
    assert "interrupted; results up to t = " in message, message
    assert "are in no folder (stancf.run was given no out folder and kept no files)" in message
    assert str(tmp_path) not in message


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


def _columns(keys):
    return ["run", *keys, "status", *(name for name, _ in stancf.FIGURES), "worker_s", "error"]


def test_a_killed_worker_is_reported_not_waited_for(tmp_path):
    import csv
    import dask
    sc = stancf.Scenario(PENDULUM)
    grid = {"loads.1.drag_coefficient": [0.1 * k for k in range(8)]}
    # No retries: the run on the dead worker fails instead of moving on.
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        cluster, client = _cluster()
        try:
            t0 = time.perf_counter()
            rows = stancf.sweep(sc, grid, executor=_KillsTheWorkerOfRun0(client),
                                out=tmp_path / "sw", timeout=120)
            elapsed = time.perf_counter() - t0
        finally:
            client.close()
            cluster.close()
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert elapsed < 120
    assert [r["run"] for r in rows] == list(range(8))
    # Run 0: failed, with the reason, and no figures.
    assert rows[0]["status"] == "failed"
    assert rows[0]["error"].startswith("KilledWorker"), rows[0]
    assert all(rows[0][name] is None or rows[0][name] != rows[0][name]  # None or NaN
               for name, _ in stancf.FIGURES)
    # Every other run: complete, with its figures.
    for r in rows[1:]:
        assert r["status"] == "ok" and r["error"] == "", r
        for name, _ in stancf.FIGURES:
            assert np.isfinite(r[name]), (name, r)
        assert r["steps"] == 3000 and r["worker_s"] > 0
    # sweep.csv: the fixed header, every row, run 0's with its reason.
    with open(tmp_path / "sw" / "sweep.csv", newline="") as f:
        reader = csv.DictReader(f)
        assert reader.fieldnames == _columns(["loads.1.drag_coefficient"])
        table = list(reader)
    assert len(table) == 8
    assert table[0]["status"] == "failed" and table[0]["error"].startswith("KilledWorker")
    assert all(table[0][name] == "" for name, _ in stancf.FIGURES)
    for r, t in zip(rows[1:], table[1:]):
        assert t["status"] == "ok"
        for name, _ in stancf.FIGURES:
            assert float(t[name]) == r[name], name
    # The folder: the complete runs and the table, nothing of the dead run.
    assert sorted(os.listdir(tmp_path / "sw")) == \
        ["run_%04d" % k for k in range(1, 8)] + ["sweep.csv"]
    assert sorted(os.listdir(tmp_path)) == ["sw"]


class _InThisProcess:
    """An executor that runs each point here, at once."""

    def submit(self, fn, *args):
        f = Future()
        f.set_result(fn(*args))
        return f


class _LosesRun0(_InThisProcess):
    """An executor in this process whose run 0 is lost (its future raises,
    as for a dead worker)."""

    def submit(self, fn, *args):
        if not args[-1].endswith("run_0000"):
            return super().submit(fn, *args)
        f = Future()
        f.set_exception(RuntimeError("the worker of run 0 died"))
        return f


def test_sweep_csv_has_every_column_when_run_0_is_lost(tmp_path):
    import csv
    sc = stancf.Scenario(PENDULUM).with_values({"analysis.duration": 0.01})
    # A list of points: the columns are the keys of all of them.
    points = [{"analysis.time_step": 1e-4}, {"loads.1.drag_coefficient": 0.5},
              {"analysis.time_step": 2e-4, "loads.1.drag_coefficient": 1.0}]
    rows = stancf.sweep(sc, points, executor=_LosesRun0(), out=tmp_path / "sw")
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    columns = _columns(["analysis.time_step", "loads.1.drag_coefficient"])
    assert all(list(r) == columns for r in rows)
    assert rows[0]["status"] == "failed"
    assert rows[0]["error"] == "RuntimeError: the worker of run 0 died"
    assert [r["status"] for r in rows[1:]] == ["ok", "ok"]
    with open(tmp_path / "sw" / "sweep.csv", newline="") as f:
        reader = csv.DictReader(f)
        assert reader.fieldnames == columns
        table = list(reader)
    assert [t["status"] for t in table] == ["failed", "ok", "ok"]
    assert table[1]["analysis.time_step"] == "" and table[1]["loads.1.drag_coefficient"] == "0.5"
    assert float(table[2]["steps"]) == 50 and float(table[2]["worker_s"]) > 0


def test_a_grid_above_the_limit_is_refused_before_it_is_built(tmp_path):
    sc = stancf.Scenario(PENDULUM)
    assert stancf.SWEEP_LIMIT == 10000
    # The size is checked first: the misspelt key is not reached.
    grid = {"analysis.time_step": [1e-4] * 101, "analysis.time_stepp": [1e-4] * 100}
    with pytest.raises(stancf.ScenarioError,
                       match=r"10100 points \(101 x 100\), more than the limit of 10000"):
        stancf.sweep(sc, grid, out=tmp_path / "sw")
    with pytest.raises(stancf.ScenarioError, match="10001 points"):
        stancf.sweep(sc, [{"analysis.time_step": 1e-4}] * 10001, out=tmp_path / "sw")
    assert not (tmp_path / "sw").exists()


def test_sweep_keys_that_overlap_or_alias_are_refused(tmp_path):
    sc = stancf.Scenario(PENDULUM)
    with pytest.raises(stancf.ScenarioError,
                       match="the keys loads.1 and loads.1.drag_coefficient overlap"):
        stancf.sweep(sc, {"loads.1": [{"type": "air-drag"}],
                          "loads.1.drag_coefficient": [0.5]}, out=tmp_path / "sw")
    with pytest.raises(stancf.ScenarioError, match="is not an index"):
        stancf.sweep(sc, {"loads.01.drag_coefficient": [0.5]}, out=tmp_path / "sw")
    assert not (tmp_path / "sw").exists()


def test_a_new_sweep_replaces_an_earlier_larger_one_whole(tmp_path):
    import csv
    sc = stancf.Scenario(PENDULUM).with_values({"analysis.duration": 0.01})
    out = tmp_path / "sw"
    stancf.sweep(sc, {"loads.1.drag_coefficient": [0.0, 0.5, 1.0, 1.5]},
                 executor=_InThisProcess(), out=out)
    assert sorted(os.listdir(out)) == ["run_0000", "run_0001", "run_0002", "run_0003",
                                       "sweep.csv"]
    stancf.sweep(sc, {"analysis.time_step": [1e-4, 2e-4]}, executor=_InThisProcess(), out=out)
    # No run_0002, run_0003 or old table beside the new ones, nothing beside `out`.
    assert sorted(os.listdir(out)) == ["run_0000", "run_0001", "sweep.csv"]
    assert sorted(os.listdir(tmp_path)) == ["sw"]
    with open(out / "sweep.csv", newline="") as f:
        table = list(csv.DictReader(f))
    assert [t["analysis.time_step"] for t in table] == ["0.0001", "0.0002"]
    assert stancf.Result.read(out / "run_0001").summary["time_step"] == 2e-4


def test_a_sweep_into_a_folder_in_use_is_refused(tmp_path):
    sc = stancf.Scenario(PENDULUM).with_values({"analysis.duration": 0.01})
    out = tmp_path / "sw"
    stancf.sweep(sc, {"analysis.time_step": [1e-4, 2e-4]}, executor=_InThisProcess(), out=out)
    before = (out / "sweep.csv").read_text()
    # Another sweep is writing into `out` (it holds the folder's lock).
    other = stancf._stancf.ResultFolder(str(out))
    try:
        with pytest.raises(stancf.ScenarioError, match="another stancf run is writing"):
            stancf.sweep(sc, {"analysis.time_step": [5e-5]}, executor=_InThisProcess(),
                         out=out)
    finally:
        other.abort()
    assert (out / "sweep.csv").read_text() == before
    assert sorted(os.listdir(out)) == ["run_0000", "run_0001", "sweep.csv"]
    assert sorted(os.listdir(tmp_path)) == ["sw"]
    # Once it is done, the folder is free.
    stancf.sweep(sc, {"analysis.time_step": [5e-5]}, executor=_InThisProcess(), out=out)
    assert sorted(os.listdir(out)) == ["run_0000", "sweep.csv"]


WD0050_CHAIN = """--------------------- MoorDyn Input File ---------------------
MoorDyn's tests/Mooring/WD0050_Chain.txt, dtM in place of cfl
----------------------- LINE TYPES ---------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI   Cd    Ca    CdAx   CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (-)  (-)   (-)   (-)    (-)
chain      0.252   390        1.674e9    -1.0        0    1.37  1.0   0.64   0.0
---------------------- POINT PROPERTIES ----------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     400    0.0     -50.0    0      0       0      0
2     Vessel    0.0     0.0     0.0     0      0       0      0
---------------------- LINES ---------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain      1        2         410       41      -
---------------------- OPTIONS -------------------------------
0.001    dtM
1.0e5    kBot
1.0e4    cBot
1025.0   WtrDnsty
50       WtrDpth
0.5      FrictionCoefficient
------------------------- need this line ---------------------
"""


@pytest.mark.parametrize("policy", ["as_laid", "pulled"])
def test_static_friction_holds_what_the_policy_says(tmp_path, policy):
    """MoorDyn's WD0050_Chain deck (mu = 0.5) under `[water.seabed]
    static_friction` from Python (docs/method.md §12.2): as laid the
    anchor's horizontal force is the fairlead's (friction holds nothing,
    MoorDyn's equilibrium); pulled it is lower, by the friction the bed's
    nodal forces hold, at most mu w L_B."""
    (tmp_path / "wd0050.txt").write_text(WD0050_CHAIN)
    sc = tmp_path / "friction.toml"
    sc.write_text('[system]\nmoordyn = "wd0050.txt"\n\n[water.seabed]\n'
                  'static_friction = "%s"\n\n[analysis]\ntype = "static"\n' % policy)
    res = stancf.run(stancf.Scenario.from_file(sc), out=tmp_path / "out")
    h_anchor = abs(res.tensions[(1, "A")]["force"][-1][0])
    h_fairlead = abs(res.tensions[(1, "B")]["force"][-1][0])
    friction = res.lines[1].seabed_force[-1][:, 0].sum()
    assert h_fairlead - h_anchor == pytest.approx(friction, abs=1e-8 * h_fairlead)
    w = (390.0 - 1025.0 * np.pi / 4 * 0.252**2) * 9.80665
    v_fairlead = -res.tensions[(1, "B")]["force"][-1][2]
    resting = 410.0 - v_fairlead / w
    if policy == "as_laid":
        assert abs(friction) < 1e-8 * h_fairlead
    else:
        assert 0.9 * 0.5 * w * resting < friction <= 0.5 * w * resting * (1 + 1e-3)
