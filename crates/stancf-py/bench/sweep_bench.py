"""Benchmarks of the Python layer (numbers for the issue note).

    target/py-venv/bin/python crates/stancf-py/bench/sweep_bench.py

1. The 12-point pendulum sweep (6 drag coefficients x 2 steps, 0.8 s each)
   on a Dask LocalCluster with 1 worker and with 2 workers, alternated
   three times; the ratio of the medians.
2. The per-run overhead of the Python layer against the bare CLI on the
   same scenarios (a 1-step run: fixed costs; the 0.8 s pendulum: reading
   its files into numpy included), medians of 15 runs each, alternated.
"""
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import stancf
from dask.distributed import Client, LocalCluster

ROOT = Path(__file__).resolve().parents[3]
CLI = ROOT / "target" / "release" / "stancf"
SC = stancf.Scenario.from_file(ROOT / "examples" / "pendulum-drag.toml")
GRID = {"loads.1.drag_coefficient": [0.0, 0.5, 1.0, 1.5, 2.0, 2.5], "analysis.time_step": [1e-4, 2e-4]}


def sweep_time(workers):
    with LocalCluster(n_workers=workers, threads_per_worker=1, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        client.submit(sum, [1]).result()  # workers up
        with tempfile.TemporaryDirectory() as d:
            t0 = time.perf_counter()
            rows = stancf.sweep(SC, GRID, executor=client, out=d)
            dt = time.perf_counter() - t0
    rows = rows.to_dict("records") if hasattr(rows, "to_dict") else rows
    assert len(rows) == 12 and all(r["status"] == "ok" for r in rows)
    return dt


def per_run(scenario):
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "s.toml"
        path.write_text(scenario.text)
        cli, py = [], []
        for _ in range(15):
            t0 = time.perf_counter()
            subprocess.run([str(CLI), "run", str(path), "--out", str(Path(d) / "cli"), "-q"], check=True)
            cli.append(time.perf_counter() - t0)
            t0 = time.perf_counter()
            stancf.run(scenario, out=Path(d) / "py")
            py.append(time.perf_counter() - t0)
    return statistics.median(cli), statistics.median(py)


def main():
    one, two = [], []
    for _ in range(3):
        one.append(sweep_time(1))
        two.append(sweep_time(2))
    m1, m2 = statistics.median(one), statistics.median(two)
    print("12-point sweep: 1 worker %.2f s, 2 workers %.2f s (medians of 3): speed-up %.2f" % (m1, m2, m1 / m2))
    tiny = SC.with_values({"analysis.duration": 1e-4})
    c, p = per_run(tiny)
    print("1-step run: CLI process %.1f ms, stancf.run %.1f ms: Python layer %+.1f ms (%.2fx)" % (
        1e3 * c, 1e3 * p, 1e3 * (p - c), p / c))
    c, p = per_run(SC)
    print("0.8 s pendulum (8000 steps, 801 written): CLI %.3f s, stancf.run %.3f s: ratio %.3f" % (c, p, p / c))


if __name__ == "__main__":
    sys.exit(main())
