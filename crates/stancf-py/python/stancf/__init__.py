"""stancf from Python: flexible cables with space-time ANCF elements.

A thin layer over the Rust library and command line (the same scenario
validation, the same solver, the same result files)::

    import stancf
    sc = stancf.Scenario.from_file("examples/pendulum.toml")
    res = stancf.run(sc.with_values({"analysis.time_step": 5e-5}))
    res.t, res.nodes[-1], res.energy["total"], res.summary["energy"]["max_rel_drift"]

    table = stancf.sweep(sc, {"loads.1.drag_coefficient": [0, 0.5, 1.5]}, out="sweep")

Results are numpy arrays read from the files a run writes
(docs/interface.md), so they are the command line's numbers to the bit.
"""

import csv
import io
import json
import shutil
import tempfile
from pathlib import Path

import numpy as np

from . import _stancf
from ._stancf import ScenarioError

__version__ = _stancf.__version__
__all__ = ["Scenario", "Result", "Line", "ScenarioError", "SolverError", "run", "sweep",
           "Simulation", "LineState", "PointState"]


class Scenario:
    """A validated scenario (the TOML contract of docs/interface.md)."""

    def __init__(self, text, name="scenario"):
        _stancf.validate(text, name)
        self._text = text
        self.name = name

    @classmethod
    def from_file(cls, path):
        """Reads and validates a scenario file. Its title defaults to the
        file's stem, as on the command line."""
        path = Path(path)
        text = _stancf.read_input(str(path))
        name = str(path)
        _stancf.validate(text, name)
        if _stancf.is_moordyn(text):
            # A MoorDyn deck or driver file: its title is the file's stem already.
            return cls(text, name)
        if not any(line.split("=")[0].strip() == "title" for line in text.splitlines()
                   if not line.lstrip().startswith("[")):
            text = _stancf.with_values(text, name, {"title": path.stem})
        return cls(text, name)

    @classmethod
    def from_dict(cls, d, name="scenario"):
        """A scenario from a dictionary with the keys of the TOML contract,
        e.g. ``{"cable": {"length": 4.0, ...}, "loads": [{...}], ...}``."""
        return cls(_stancf.dict_to_toml(d), name)

    def with_values(self, values):
        """A copy with dotted keys set: ``{"analysis.time_step": 1e-4,
        "loads.1.drag_coefficient": 0.5}`` (list entries by 0-based index).
        A MoorDyn deck's copy is the scenario that takes the deck
        (``[system] moordyn = "<deck>"``) with the keys set:
        ``water.jonswap.hs``, ``analysis.duration``, ``system.mbl.chain``."""
        return Scenario(_stancf.with_values(self._text, self.name, dict(values)), self.name)

    @property
    def text(self):
        """The scenario as TOML text."""
        return self._text

    def __repr__(self):
        return "Scenario(%r)" % self.name

    def __reduce__(self):
        return (Scenario, (self._text, self.name))


class SolverError(RuntimeError):
    """The solver failed at `time` (the start of step `step`) with scaled
    residual `residual`; `result` holds every converged step before it."""

    def __init__(self, message, time, step, residual, result):
        super().__init__(message)
        self.time = time
        self.step = step
        self.residual = residual
        self.result = result


def _table(path):
    """A numeric CSV result file: (header, 2-D float array)."""
    with open(path) as f:
        return _parse_table(f)


def _parse_table(lines):
    """(header, 2-D float array) of a numeric CSV's lines (an empty field
    is NaN)."""
    lines = iter(lines)
    header = next(lines, "").strip().split(",")
    rows = [[float(x) if x else np.nan for x in line.strip().split(",")]
            for line in lines if line.strip()]
    data = np.array(rows, dtype=float).reshape(len(rows), len(header))
    return header, data


class _Folder:
    """Result files in a folder (docs/interface.md)."""

    def __init__(self, directory):
        self.directory = Path(directory)

    def exists(self, name):
        return (self.directory / name).exists()

    def table(self, name):
        return _table(self.directory / name)

    def text(self, name):
        return (self.directory / name).read_text()


class _Memory:
    """The result files of a run as it wrote them, kept in memory: the same
    bytes, numeric tables parsed in Rust (correctly rounded, as ``float``
    parses them: the same numbers as :class:`_Folder`'s)."""

    def __init__(self, files):
        self.files = {name: (raw, table) for name, raw, table in files}

    def exists(self, name):
        return name in self.files

    def table(self, name):
        raw, table = self.files[name]
        if table is None:
            return _parse_table(raw.decode().splitlines())
        header, rows, values = table
        return header, np.frombuffer(values, dtype="<f8").reshape(rows, len(header))

    def text(self, name):
        return self.files[name][0].decode()


def _by_step(rows, steps, columns):
    """A table of the same number of rows at each of its written times as
    an array times x rows per time x columns (`steps` times where the
    table is empty)."""
    if len(rows):
        steps = len(np.unique(rows[:, 0]))
    return rows.reshape(steps, len(rows) // max(steps, 1), columns)


def _written_times(files, summary):
    """The written times: history.csv's first column; a system run that
    leaves history.csv out (``[output] files``) has them in the other
    tables it writes, each time once per point, node or sample (but for
    tensions.csv, which has no row at t = 0 of a run from the straight
    start: the times of a run that writes tensions.csv alone)."""
    if files.exists("history.csv"):
        return files.table("history.csv")[1][:, 0].copy()
    tables = ["points.csv"] + [
        "lines/%s/%s" % (line["id"], name) for line in summary.get("lines", [])
        for name in ("nodes.csv", "node_loads.csv", "stress.csv")] + [
        "channels.csv", "tensions.csv"]
    for name in tables:
        if files.exists(name):
            if name == "tensions.csv":
                with io.StringIO(files.text(name)) as f:
                    next(f)
                    column = [float(row[0]) for row in csv.reader(f)]
            else:
                column = files.table(name)[1][:, 0]
            return np.unique(np.asarray(column, dtype=float))
    return np.zeros(0)


class Line:
    """One cable's results: ``t`` (steps,), ``nodes``: positions r (steps x
    nodes x 3), ``slopes``: r_x (same), ``stress``: axial stress (steps x
    samples) at material coordinates ``stress_s``, ``curvature`` likewise;
    a system's line also ``node_s`` (nodes,), ``node_curvature`` and
    ``bending_moment`` (steps x nodes) and ``seabed_force`` (steps x nodes
    x 3) from ``node_loads.csv``."""

    def __init__(self, files, prefix, t):
        steps = len(t)
        self.t = t
        # A system run may leave out any of its line's files
        # (``[output] files``): their arrays are then None.
        self.nodes = self.slopes = self.stress_s = self.stress = self.curvature = None
        self.node_s = self.node_curvature = self.bending_moment = None
        self.seabed_force = None
        if files.exists(prefix + "nodes.csv"):
            h, nodes = files.table(prefix + "nodes.csv")
            col = {name: k for k, name in enumerate(h)}
            nodes = _by_step(nodes, steps, len(h))
            self.nodes = nodes[:, :, [col["x"], col["y"], col["z"]]].copy()
            self.slopes = nodes[:, :, [col["dx_ds"], col["dy_ds"], col["dz_ds"]]].copy() \
                if "dx_ds" in col else None
        if files.exists(prefix + "stress.csv"):
            h, stress = files.table(prefix + "stress.csv")
            col = {name: k for k, name in enumerate(h)}
            stress = _by_step(stress, steps, len(h))
            self.stress_s = stress[0, :, col["s"]].copy() if steps else np.zeros(0)
            self.stress = stress[:, :, col["axial_stress"]].copy()
            self.curvature = stress[:, :, col["curvature"]].copy()
        # A system's line: per node curvature, bending moment and the
        # seabed's force (node_loads.csv); None for a single cable.
        if files.exists(prefix + "node_loads.csv"):
            h, loads = files.table(prefix + "node_loads.csv")
            col = {name: k for k, name in enumerate(h)}
            loads = _by_step(loads, steps, len(h))
            self.node_s = loads[0, :, col["s"]].copy() if steps else np.zeros(0)
            self.node_curvature = loads[:, :, col["curvature"]].copy()
            self.bending_moment = loads[:, :, col["bending_moment"]].copy()
            self.seabed_force = loads[:, :, [col["seabed_fx"], col["seabed_fy"],
                                             col["seabed_fz"]]].copy()

    def __repr__(self):
        if self.nodes is None:
            return "Line(%d steps)" % len(self.t)
        return "Line(%d steps, %d nodes)" % self.nodes.shape[:2]


def _stiffness(text):
    """stiffness.csv as a dict body id -> 6 x 6 array (its rows in the
    file's order, fx to mz)."""
    out = {}
    with io.StringIO(text) as f:
        next(f)
        for row in csv.reader(f):
            out.setdefault(int(row[0]), []).append([float(v) for v in row[2:]])
    return {body: np.array(rows, dtype=float) for body, rows in out.items()}


class Result:
    """The results of a run (docs/interface.md), read from its folder or,
    from :func:`run`, taken from memory as the run wrote them (the same
    numbers to the bit):

    - ``t``: the written times (steps,);
    - ``nodes``: positions r (steps x nodes x 3), ``slopes``: r_x (same);
    - ``energy``: dict of arrays over t (kinetic, strain, gravity, total,
      load_potential, constraint_work, drag_work, iterations, residual, ...);
    - ``stress``: axial stress (steps x samples) at material coordinates
      ``stress_s``; ``curvature`` likewise;
    - ``reactions``: dict node -> (steps x 3) forces on the cable (times
      ``reactions_t``), empty without constraints;
    - ``summary``: summary.json as a dict; ``directory``: the folder.

    A system of lines (``is_system``) has instead of nodes, stress and
    reactions:

    - ``lines``: dict line id -> :class:`Line`;
    - ``points``: dict point id -> dict of ``t``, ``position``,
      ``velocity`` and ``force`` (the lines' net force on it), arrays
      (steps x 3);
    - ``tensions``: dict (line id, "A" or "B") -> dict of ``t``, ``force``
      (the force that end exerts on its point, k x 3) and ``tension`` (k,);
    - ``channels``: dict name -> array over ``channels_t`` (a MoorDyn
      deck's OUTPUTS; empty otherwise);
    - ``stiffness``: dict body id -> 6 x 6 array, each free body's mooring
      stiffness at the static equilibrium (stiffness.csv: rows fx, fy, fz,
      mx, my, mz, columns dx, dy, dz, rx, ry, rz; empty without one).
    """

    def __init__(self, directory, _keep=None, _files=None):
        d = Path(directory)
        self.directory = d
        self._keep = _keep
        files = _Memory(_files) if _files else _Folder(d)
        self.summary = json.loads(files.text("summary.json"))
        self.is_system = bool(self.summary.get("system"))
        self.t, self.energy = _written_times(files, self.summary), {}
        if files.exists("history.csv"):
            h, hist = files.table("history.csv")
            self.energy = {name: hist[:, k].copy() for k, name in enumerate(h) if k > 0}
        self.reactions = {}
        self.reactions_t = np.zeros(0)
        self.lines, self.points, self.tensions, self.channels = {}, {}, {}, {}
        self.stiffness = {}
        self.channels_t = np.zeros(0)
        if self.is_system:
            self._read_system(files)
            return
        line = Line(files, "", self.t)
        self.nodes, self.slopes = line.nodes, line.slopes
        self.stress_s, self.stress, self.curvature = line.stress_s, line.stress, line.curvature
        if files.exists("reactions.csv"):
            h, r = files.table("reactions.csv")
            if len(r):
                for node in np.unique(r[:, 1]).astype(int):
                    rows = r[r[:, 1] == node]
                    self.reactions[int(node)] = rows[:, 2:5].copy()
                    self.reactions_t = rows[:, 0].copy()

    def _read_system(self, files):
        self.nodes = self.slopes = self.stress = self.curvature = None
        self.stress_s = None
        self.lines = {int(line["id"]): Line(files, "lines/%s/" % line["id"], self.t)
                      for line in self.summary["lines"]}
        self.points, self.tensions = {}, {}
        h, p = files.table("points.csv") if files.exists("points.csv") else ([], np.zeros((0, 1)))
        col = {name: k for k, name in enumerate(h)}
        for point in (np.unique(p[:, col["point"]]).astype(int) if col else []):
            rows = p[p[:, col["point"]] == point]
            self.points[int(point)] = {
                "t": rows[:, col["t"]].copy(),
                "position": rows[:, [col["x"], col["y"], col["z"]]].copy(),
                "velocity": rows[:, [col["vx"], col["vy"], col["vz"]]].copy(),
                "force": rows[:, [col["fx"], col["fy"], col["fz"]]].copy(),
            }
        tensions = files.text("tensions.csv") if files.exists("tensions.csv") else "t\n"
        with io.StringIO(tensions) as f:
            next(f)
            for row in csv.reader(f):
                t, line, end, fx, fy, fz, tension = row
                entry = self.tensions.setdefault(
                    (int(float(line)), end), {"t": [], "force": [], "tension": []})
                entry["t"].append(float(t))
                entry["force"].append([float(fx), float(fy), float(fz)])
                entry["tension"].append(float(tension))
        for entry in self.tensions.values():
            for k in entry:
                entry[k] = np.array(entry[k], dtype=float)
        if files.exists("stiffness.csv"):
            self.stiffness = _stiffness(files.text("stiffness.csv"))
        if files.exists("channels.csv"):
            h, c = files.table("channels.csv")
            self.channels_t = c[:, 0].copy()
            self.channels = {name: c[:, k].copy() for k, name in enumerate(h) if k > 0}

    def write(self, directory):
        """Writes the result files (docs/interface.md) to `directory`."""
        out = Path(directory)
        out.mkdir(parents=True, exist_ok=True)
        for f in self.directory.iterdir():
            if f.is_file() and not f.name.endswith(".partial"):
                shutil.copy2(f, out / f.name)
        if (self.directory / "lines").is_dir():
            shutil.copytree(self.directory / "lines", out / "lines", dirs_exist_ok=True,
                            ignore=shutil.ignore_patterns("*.partial"))
        if (self.directory / "vtk").is_dir():
            shutil.copytree(self.directory / "vtk", out / "vtk", dirs_exist_ok=True)
        return out

    @classmethod
    def read(cls, directory):
        """The results of a run already on disk (e.g. written by the CLI)."""
        return cls(directory)

    def __repr__(self):
        return "Result(%d steps to t = %g s, %s)" % (
            len(self.t), self.t[-1] if len(self.t) else 0.0, self.directory)


def run(scenario, out=None, progress=False, allow_large=False):
    """Runs a scenario; returns a :class:`Result`.

    `out`: the folder for the result files (default: a temporary folder
    that lives as long as the result). The solver runs without the GIL;
    Ctrl-C stops it after the current step (KeyboardInterrupt). A solver
    failure raises :class:`SolverError` with the partial result. `out` is
    replaced whole when the run ends (the command line's result folders).
    A run above 1e8 steps or about 4 GB of result files is refused
    (:class:`ScenarioError`) unless `allow_large` is true.
    """
    if not isinstance(scenario, Scenario):
        scenario = Scenario.from_file(scenario)
    keep = None
    if out is None:
        keep = tempfile.TemporaryDirectory(prefix="stancf-")
        out = keep.name
    try:
        files = _stancf.run(scenario.text, scenario.name, str(out), progress, allow_large)
    except _stancf.RunFailed as e:
        message, files = e.args
        partial = Result(out, keep, files)
        failure = partial.summary.get("failure") or {}
        if keep is not None:
            message = _unnamed(message, out, "the SolverError's result (in memory: with "
                               "no out folder, stancf.run keeps no files)")
        raise SolverError(message, failure.get("time"), failure.get("step"),
                          failure.get("residual"), partial) from None
    except KeyboardInterrupt as e:
        if keep is None or not e.args:
            raise
        raise KeyboardInterrupt(_unnamed(
            str(e.args[0]), out, "no folder (stancf.run was given no out folder and kept "
            "no files)")) from None
    return Result(out, keep, files)


def _unnamed(message, folder, instead):
    """A run's message without the temporary folder it ran in (deleted with
    the run's result, or at once): "are in <folder>" becomes "are in
    <instead>", and the folder anywhere else "<instead>"."""
    folder = str(folder)
    return message.replace("are in " + folder, "are in " + instead).replace(folder, instead)


# ---- sweeps (stancf/sweeps.py) ----

from .sweeps import FIGURES, SWEEP_LIMIT, sweep  # noqa: E402

# ---- coupling (stancf/simulation.py) ----

from .simulation import LineState, PointState, Simulation  # noqa: E402
