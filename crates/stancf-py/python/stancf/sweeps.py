"""Sweeps of a scenario over a grid of values, run in parallel on any
executor (``concurrent.futures`` or ``dask.distributed``), written as one
transaction: :func:`sweep` and its summary figures :data:`FIGURES`."""

import csv
import itertools
import json
import os
import tempfile
import time as _time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from . import _stancf, Scenario

#: The summary figures a sweep gathers, with their place in summary.json
#: (the command line's list: `stancf sweep` writes the same columns).
FIGURES = [(name, tuple(int(p) if p.isdigit() else p for p in path))
           for name, path in _stancf.sweep_figures()]


def _figures(summary):
    out = {}
    for name, path in FIGURES:
        v = summary
        try:
            for p in path:
                v = v[p]
        except (KeyError, IndexError, TypeError):
            v = None
        out[name] = v
    return out


def _run_point(text, name, folder):
    """One point of a sweep, on a worker: runs into `folder` and returns
    the summary figures (only these cross the wire)."""
    t0 = _time.perf_counter()
    try:
        _stancf.run(text, name, folder, False, collect=False)
        error = ""
    except _stancf.RunFailed as e:
        error = e.args[0]
    with open(os.path.join(folder, "summary.json")) as f:
        summary = json.load(f)
    row = _figures(summary)
    row["error"] = error
    row["worker_s"] = _time.perf_counter() - t0
    return row


#: The most points a sweep may have (the command line's bound, from Rust).
SWEEP_LIMIT = _stancf.SWEEP_LIMIT


def _points(grid):
    """A grid (dict key -> list of values: the Cartesian product, first key
    slowest) or a list of dicts of dotted overrides: (the varied keys, the
    number of points, an iterator over the points). The size is checked
    (at most :data:`SWEEP_LIMIT`) before any point is built, and so are
    the keys (each once, none inside another), as on the command line."""
    if isinstance(grid, dict):
        keys = list(grid)
        values = [list(grid[k]) for k in keys]
        n = _stancf.sweep_points(keys, [len(v) for v in values])
        return keys, n, (dict(zip(keys, combo)) for combo in itertools.product(*values))
    grid = list(grid)
    n = _stancf.sweep_points([], [len(grid)])
    keys = []
    for p in grid:
        _stancf.sweep_points(list(p), [1] * len(p))
        keys.extend(k for k in p if k not in keys)
    return keys, n, (dict(p) for p in grid)


def _row(k, point, keys, status, figures=None, error="", worker_s=None):
    """One row of sweep.csv: every column, always (None where unknown)."""
    row = {"run": k}
    row.update({key: point.get(key) for key in keys})
    row["status"] = status
    row.update({name: (figures or {}).get(name) for name, _ in FIGURES})
    row["worker_s"] = worker_s
    row["error"] = error
    return row


def sweep(scenario, grid, executor=None, out=None, timeout=None):
    """Runs `scenario` at every point of `grid` in parallel; returns one row
    per point (a pandas DataFrame if pandas is installed, else a list of
    dicts) with the varied values, ``status`` ("ok" or "failed"), the
    summary figures of :data:`FIGURES`, ``worker_s`` (the run's time on its
    worker) and ``error``. The same columns, in this order, head
    ``out/sweep.csv``, whatever failed.

    `grid`: ``{"analysis.time_step": [1e-4, 5e-5], ...}`` (Cartesian
    product) or a list of dicts of dotted overrides; at most
    :data:`SWEEP_LIMIT` points. Every point is validated before anything
    runs (:class:`ScenarioError`, also for a grid above the limit).

    `executor`: anything with ``submit`` and futures with ``result`` --
    a ``concurrent.futures`` executor or a ``dask.distributed.Client``;
    default: a local process pool with one process per core. Only scenario
    text and summary figures cross the wire; each worker writes the full
    results to ``out/run_<k>/`` (`out` must be a folder every worker sees;
    default: a new temporary folder). A run whose worker dies or fails, or
    that is not done within `timeout` seconds of waiting for it, is
    reported as failed, with the reason, and does not stop the others.

    `out` is written as one transaction, as by ``stancf sweep``: the runs
    write into a private folder beside it, which replaces `out` whole at
    the end (also after Ctrl-C, with the unfinished runs failed), so
    nothing of an earlier sweep (its ``run_<k>`` folders, its sweep.csv)
    remains. A folder another sweep or run is writing into, or one of a
    user's files, is refused (:class:`ScenarioError`).
    """
    if not isinstance(scenario, Scenario):
        scenario = Scenario.from_file(scenario)
    keys, n, points = _points(grid)
    points = list(points)
    # Validated one by one (the text is what a worker needs).
    texts = [_stancf.with_values(scenario.text, scenario.name, p) for p in points]
    out = Path(out) if out is not None else Path(tempfile.mkdtemp(prefix="stancf-sweep-"))
    folder = _stancf.ResultFolder(str(out))
    try:
        staging = Path(folder.staging)
        rows, stopped = _run_points(scenario.name, texts, points, keys, executor, staging,
                                    timeout)
        for row in rows:
            if row["status"] == "failed" and row["worker_s"] is None:
                _tidy(staging / ("run_%04d" % row["run"]))
        columns = _write_sweep_csv(staging / "sweep.csv", keys, rows)
        folder.commit()
    except BaseException:
        folder.abort()
        raise
    if stopped is not None:
        raise stopped
    try:
        import pandas as pd
        return pd.DataFrame(rows, columns=columns)
    except ImportError:
        return rows


def _run_points(name, texts, points, keys, executor, folder, timeout):
    """Runs every point into `folder`/run_<k>: (one row per point, the
    exception that stopped the waiting, e.g. Ctrl-C, or None)."""
    own = executor is None
    if own:
        executor = ProcessPoolExecutor(max_workers=os.cpu_count() or 1)
    rows = []
    try:
        futures = []
        for k, text in enumerate(texts):
            try:
                futures.append(executor.submit(_run_point, text, name,
                                               str(folder / ("run_%04d" % k))))
            except Exception as e:  # a closed client, a broken pool
                futures.append(e)
        for k, (point, fut) in enumerate(zip(points, futures)):
            try:
                if isinstance(fut, Exception):
                    raise fut
                figures = fut.result(timeout=timeout)
            except Exception as e:  # a dead worker, a timeout, a crash
                rows.append(_row(k, point, keys, "failed",
                                 error="%s: %s" % (type(e).__name__, e)))
                continue
            rows.append(_row(k, point, keys, "ok" if not figures["error"] else "failed",
                             figures, figures["error"], figures["worker_s"]))
        return rows, None
    except BaseException as e:  # Ctrl-C while waiting: keep what finished
        for k in range(len(rows), len(points)):
            rows.append(_row(k, points[k], keys, "failed",
                             error="not finished: %s" % (type(e).__name__,)))
        return rows, e
    finally:
        if own:
            executor.shutdown(wait=True, cancel_futures=True)


def _tidy(run_folder):
    """Deletes what a run whose worker died left beside `run_folder` (its
    lock and private folder), as the next run into it would."""
    try:
        _stancf.ResultFolder(str(run_folder)).abort()
    except Exception:
        pass  # still being written (a run past its timeout): leave it


def _write_sweep_csv(path, keys, rows):
    """sweep.csv with its fixed header; returns the columns."""
    columns = ["run", *keys, "status", *(name for name, _ in FIGURES), "worker_s", "error"]
    tmp = path.with_name(path.name + ".partial")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, path)
    return columns
