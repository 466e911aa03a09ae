"""Sweeps of a scenario over a grid of values, run in parallel on any
executor (``concurrent.futures`` or ``dask.distributed``), written as one
transaction: :func:`sweep` and its summary figures (:data:`FIGURES` for a
single cable; a system's design statistics, docs/interface.md "Design
statistics")."""

import csv
import itertools
import json
import os
import tempfile
import time as _time
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from . import _stancf, Scenario, ScenarioError

#: The summary figures a sweep of a single cable gathers, with their place
#: in summary.json (the command line's list: `stancf sweep` writes the same
#: columns). A system's rows have their own (steps, time, wall_time_s,
#: iterations and the design statistics), computed by the same code as
#: the command line's.
FIGURES = [(name, tuple(int(p) if p.isdigit() else p for p in path))
           for name, path in _stancf.sweep_figures()]


def _run_point(text, name, folder):
    """One point of a sweep, on a worker: runs into `folder` and returns
    the summary figures as (column, value) pairs (only these cross the
    wire)."""
    t0 = _time.perf_counter()
    try:
        _stancf.run(text, name, folder, False, collect=False)
        error = ""
    except _stancf.RunFailed as e:
        error = e.args[0]
    with open(os.path.join(folder, "summary.json")) as f:
        figures = _stancf.summary_figures(f.read())
    return {"figures": figures, "error": error, "worker_s": _time.perf_counter() - t0}


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


def _row(k, point, keys, status, figures=(), error="", worker_s=None):
    """One row of sweep.csv, its figures (column, value) pairs in
    ``_figures`` until the columns are known (:func:`_complete`)."""
    row = {"run": k}
    row.update({key: point.get(key) for key in keys})
    row["status"] = status
    row["_figures"] = list(figures)
    row["worker_s"] = worker_s
    row["error"] = error
    return row


def _complete(rows, keys, system):
    """The figure columns of the rows (the kind's fixed ones, then those
    the runs add) and each row with every column (None where unknown)."""
    names = _stancf.sweep_columns(system, [r["_figures"] for r in rows])
    done = []
    for r in rows:
        values = dict(r["_figures"])
        row = {"run": r["run"], **{key: r[key] for key in keys}, "status": r["status"]}
        row.update({name: values.get(name) for name in names})
        row["worker_s"] = r["worker_s"]
        row["error"] = r["error"]
        done.append((row, r["_figures"]))
    return names, done


def sweep(scenario, grid, executor=None, out=None, timeout=None):
    """Runs `scenario` at every point of `grid` in parallel; returns one row
    per point (a pandas DataFrame if pandas is installed, else a list of
    dicts) with the varied values, ``status`` ("ok" or "failed"), the
    summary figures (a single cable's :data:`FIGURES`; a system's steps,
    time, wall_time_s, iterations and its design statistics: each line
    end's ``tension_max_line<id>_<end>``, ``tension_max_time_...``,
    ``tension_min_...``, ``tension_mean_...``, ``tension_std_...``, each
    line type's ``safety_factor_<type>``, each free or coupled point's and
    body's ``offset_max_point<id>``, ``offset_max_body<id>``),
    ``worker_s`` (the run's time on its worker) and ``error``. The same
    columns, in this order, head ``out/sweep.csv``, whatever failed.

    `scenario`: a single cable, a system of lines, or a MoorDyn deck
    (varied as the scenario ``[system] moordyn = "<deck>"``, so that keys
    such as ``water.jonswap.hs`` and ``analysis.duration`` reach it), as a
    :class:`Scenario` or a path; or a list of them, all of one kind, which
    is one more axis, ``scenario`` (the slowest; each row names its
    scenario: intact and damaged variants of a mooring). With
    a seed axis (a key ending ``.seed``, such as ``water.jonswap.seed``),
    ``out/extremes.csv`` reduces each sea state's runs over their seeds:
    the mean of the maxima and a Gumbel fit's most probable maximum
    (docs/interface.md, "stancf sweep").

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
    several = isinstance(scenario, (list, tuple))
    scenarios = [s if isinstance(s, Scenario) else Scenario.from_file(s)
                 for s in (scenario if several else [scenario])]
    keys, n, grid_points = _points(grid)
    grid_points = list(grid_points)
    # The limit counts every scenario's points.
    _stancf.sweep_points([], [len(scenarios), n])
    # What the grid varies (a bare MoorDyn deck: the scenario taking it).
    bases = [_stancf.sweep_base(s.text, s.name) for s in scenarios]
    system = bases[0][1]
    if any(b[1] != system for b in bases):
        raise ScenarioError(
            "sweep: the scenarios are systems of lines and single cables; a sweep's "
            "scenarios are all of one kind, their rows of one table")
    if several and "scenario" in keys:
        raise ScenarioError("sweep: the key scenario names the axis of the scenarios")
    # Validated one by one (the text is what a worker needs).
    texts, points = [], []
    for sc, (base, _) in zip(scenarios, bases):
        for p in grid_points:
            texts.append((_stancf.with_values(base, sc.name, p), sc.name))
            points.append({"scenario": sc.name, **p} if several else p)
    if several:
        keys = ["scenario", *keys]
    out = Path(out) if out is not None else Path(tempfile.mkdtemp(prefix="stancf-sweep-"))
    folder = _stancf.ResultFolder(str(out))
    try:
        staging = Path(folder.staging)
        rows, stopped = _run_points(texts, points, keys, executor, staging, timeout)
        for row in rows:
            if row["status"] == "failed" and row["worker_s"] is None:
                _tidy(staging / ("run_%04d" % row["run"]))
        names, rows = _complete(rows, keys, system)
        columns = _write_sweep_csv(staging / "sweep.csv", keys, names, [r for r, _ in rows])
        extremes = _stancf.sweep_extremes(
            keys, names,
            [([_cell(r[k]) for k in keys], r["status"] == "ok", f) for r, f in rows])
        if extremes is not None:
            _write_text(staging / "extremes.csv", extremes)
        rows = [r for r, _ in rows]
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


def _run_points(texts, points, keys, executor, folder, timeout):
    """Runs every point, its (text, name) of `texts`, into
    `folder`/run_<k>: (one row per point, the exception that stopped the
    waiting, e.g. Ctrl-C, or None)."""
    own = executor is None
    if own:
        executor = ProcessPoolExecutor(max_workers=os.cpu_count() or 1)
    rows = []
    try:
        futures = []
        for k, (text, name) in enumerate(texts):
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
                             figures["figures"], figures["error"], figures["worker_s"]))
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


def _cell(v):
    """An axis value as extremes.csv groups and writes it."""
    return v if isinstance(v, str) else json.dumps(v)


def _write_sweep_csv(path, keys, names, rows):
    """sweep.csv: run, the keys, status, the figures `names`, worker_s and
    error; returns the columns."""
    columns = ["run", *keys, "status", *names, "worker_s", "error"]
    tmp = path.with_name(path.name + ".partial")
    with open(tmp, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns)
        w.writeheader()
        w.writerows(rows)
    os.replace(tmp, path)
    return columns


def _write_text(path, text):
    """A file written whole (through a partial file and a rename)."""
    tmp = path.with_name(path.name + ".partial")
    with open(tmp, "w", newline="") as f:
        f.write(text)
    os.replace(tmp, path)
