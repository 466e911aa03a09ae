"""Design load cases from Python: the design statistics of a system run
against numpy on its written time series, a sweep of a system on a
process pool against its runs done one at a time, and extremes.csv's
Gumbel most probable maximum against scipy's maximum-likelihood fit
(docs/interface.md, "Design statistics" and "stancf sweep")."""

import csv
import os
from pathlib import Path
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import scipy.stats

import stancf

# Two chains in 50 m of water under a JONSWAP sea, one fairlead moved
# sideways: 20 s in steps of 0.25 s, the statistics from 5 s on (the
# command line's tests run the same file).
SEA = (Path(__file__).resolve().parents[2] / "stancf-cli" / "tests" / "fixtures"
       / "two-lines-in-a-sea.toml").read_text()


def test_a_system_runs_statistics_are_numpys_on_its_tensions():
    """numpy's mean and standard deviation (ddof 0) of the written
    tensions from 5 s on: equal to round-off (Welford's update against
    numpy's pairwise sum, 1e-12 of the mean); the largest and smallest
    and the largest's time to the bit."""
    result = stancf.run(stancf.Scenario(SEA))
    stats = result.summary["statistics"]
    assert stats["moments"] == 61
    for e in stats["line_ends"]:
        series = result.tensions[(e["line"], e["end"])]
        window = series["t"] >= 5.0
        tension, t = series["tension"][window], series["t"][window]
        assert len(tension) == 61
        assert e["max"] == tension.max() and e["min"] == tension.min()
        assert e["time_of_max"] == t[np.argmax(tension)]
        assert abs(e["mean"] - np.mean(tension)) <= 1e-12 * np.mean(tension)
        assert abs(e["std"] - np.std(tension)) <= 1e-12 * np.mean(tension)
    largest = max(e["max"] for e in stats["line_ends"])
    assert stats["line_types"][0]["safety_factor"] == 2.0e6 / largest


def test_a_system_sweep_on_a_process_pool_and_its_gumbel_extremes(tmp_path):
    """Two sea states x four seeds on two processes: each row's statistics
    are those of the same run alone (to the bit); extremes.csv's mean of
    the maxima is numpy's, and its most probable maximum and scale are
    scipy's maximum-likelihood Gumbel fit of the same maxima (to 1e-9 of
    the maxima's spread, scipy solving its likelihood equation to about
    1e-12 relative)."""
    sc = stancf.Scenario(SEA)
    grid = {"water.jonswap.hs": [1.0, 2.5], "water.jonswap.seed": [0, 1, 2, 3]}
    with ProcessPoolExecutor(2) as ex:
        rows = stancf.sweep(sc, grid, executor=ex, out=tmp_path / "sw")
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert len(rows) == 8 and all(r["status"] == "ok" for r in rows)
    for r in rows[::3]:
        alone = stancf.run(sc.with_values({"water.jonswap.hs": r["water.jonswap.hs"],
                                           "water.jonswap.seed": r["water.jonswap.seed"]}))
        for e in alone.summary["statistics"]["line_ends"]:
            end = "line%d_%s" % (e["line"], e["end"])
            assert r["tension_max_" + end] == e["max"]
            assert r["tension_mean_" + end] == e["mean"]
            assert r["tension_std_" + end] == e["std"]
    with open(tmp_path / "sw" / "extremes.csv", newline="") as f:
        extremes = list(csv.DictReader(f))
    assert [e["water.jonswap.hs"] for e in extremes] == ["1.0", "2.5"]
    for k, state in enumerate(extremes):
        assert state["seeds"] == "4" and state["failed"] == "0"
        for end in ["line1_A", "line1_B", "line2_A", "line2_B"]:
            name = "tension_max_" + end
            maxima = np.array([r[name] for r in rows[4 * k:4 * k + 4]])
            assert float(state[name + "_mean"]) == maxima.sum() / 4
            loc, scale = scipy.stats.gumbel_r.fit(maxima)
            spread = maxima.max() - maxima.min()
            assert abs(float(state[name + "_mpm"]) - loc) <= 1e-9 * spread, (state, loc)
            assert abs(float(state[name + "_gumbel_scale"]) - scale) <= 1e-9 * spread


def _damaged(text):
    """SEA with its second line gone, with its anchor and fairlead."""
    for block in ['[[points]]\nid = 2\ntype = "fixed"\nposition = [120.0, 0.0, -50.0]\n',
                  '[[points]]\nid = 4\ntype = "coupled"\nposition = [5.0, 0.0, -5.0]\n',
                  '[[lines]]\nid = 2\ntype = "chain"\nlength = 130.0\nelements = 8\na = 2\nb = 4\n']:
        assert block in text
        text = text.replace(block, "")
    return text


def test_intact_and_damaged_systems_on_dask_keep_every_row_when_a_worker_dies(tmp_path):
    """The intact and the damaged system (one more axis, ``scenario``) over
    three seeds on a Dask cluster of two workers, the worker of run 0
    killed while it runs: run 0's row is failed with the reason, every
    other row is its run's, and extremes.csv reduces the intact system's
    two remaining seeds (one failed) and the damaged system's three."""
    from sweep_executors import KillsTheWorkerOfRun0, cluster
    import dask
    intact = stancf.Scenario(SEA, "intact")
    damaged = stancf.Scenario(_damaged(SEA), "damaged")
    grid = {"water.jonswap.seed": [0, 1, 2]}
    with dask.config.set({"distributed.scheduler.allowed-failures": 0}):
        cl, client = cluster()
        try:
            # Run 0 lasts 2000 s of 0.25 s steps: still running when killed.
            rows = stancf.sweep([intact, damaged], grid, out=tmp_path / "sw", timeout=120,
                                executor=KillsTheWorkerOfRun0(client, duration=2000.0))
        finally:
            client.close()
            cl.close()
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert [r["scenario"] for r in rows] == ["intact"] * 3 + ["damaged"] * 3
    assert rows[0]["status"] == "failed" and rows[0]["error"].startswith("KilledWorker")
    assert all(r["status"] == "ok" for r in rows[1:])
    for r in rows[1:]:
        sc = intact if r["scenario"] == "intact" else damaged
        alone = stancf.run(sc.with_values({"water.jonswap.seed": r["water.jonswap.seed"]}))
        for e in alone.summary["statistics"]["line_ends"]:
            assert r["tension_max_line%d_%s" % (e["line"], e["end"])] == e["max"]
    # The damaged runs have no second line.
    assert all(r["tension_max_line2_A"] != r["tension_max_line2_A"] or
               r["tension_max_line2_A"] is None for r in rows[3:])
    with open(tmp_path / "sw" / "extremes.csv", newline="") as f:
        extremes = list(csv.DictReader(f))
    assert [(e["scenario"], e["seeds"], e["failed"]) for e in extremes] == \
        [("intact", "2", "1"), ("damaged", "3", "0")]
    maxima = np.array([r["tension_max_line1_B"] for r in rows[1:3]])
    assert float(extremes[0]["tension_max_line1_B_mean"]) == maxima.sum() / 2
    assert sorted(os.listdir(tmp_path / "sw")) == \
        ["extremes.csv"] + ["run_%04d" % k for k in range(1, 6)] + ["sweep.csv"]
