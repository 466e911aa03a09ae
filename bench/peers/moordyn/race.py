"""The race against MoorDyn (issue 15): both codes on the same MoorDyn v2
deck, the fairleads moved by the same function of time, on this machine in
one run. Writes out/moordyn_race.{csv,md,png}.

Run through ./run.sh (it makes the virtual environment and builds stancf).

Problem (OC4 DeepCwind, the public three-line chain deck shipped as
examples/oc4-deepcwind-moordyn.txt, EI = 0): the three fairleads moved
together in surge, x(t) = f(t) A sin(2 pi t / T), A = 8 m, T = 100 s, with
stancf's ramp f = s^3 (6 s^2 - 15 s + 10), s = min(t / T, 1) (a
`[[motions]]` entry with `ramp = T`), 300 s simulated. Both codes read the
deck with:

- NumSegs = the resolution under test (MoorDyn's segments, stancf's SAC-2
  elements);
- BA fixed at the value the deck's -1 (critical damping of the axial
  segment mode) gives at 20 segments, 1.224e7 N s, for every resolution:
  with BA = -zeta the damping shrinks with the segments and the refined
  runs would converge to another line;
- dtM = MoorDyn's step (stancf takes its own step from its scenario).

The second problem is a bending-stiff cable (EI > 0 in both codes):
examples/steep-wave-moordyn.txt, a power cable over a buoyant section to
a riser base, its top moved 5 m at 20 s after a one-period ramp, 120 s,
raced without added mass (Ca = CaAx = 0 in both codes: the two codes'
added masses are different laws, see STEEP).
(The lazy wave, the same cable lying on the bed, is raced only with
--problem=lazy_wave: see LAZY below.)

Accuracy: the fairlead tension is |f|, the force of the line on its
fairlead (what a coupled platform code receives: MoorDyn_Step's forces,
stancf's points.csv, written as the force at t: `[output] end_forces =
"at_time"`, docs/method.md (M23a); the default, the step's mean, trails
it by half a step); the error of a run is the largest difference from
the reference over the time after the ramp, at the 0.1 s output times,
relative to the reference tension's range over that time, the largest
of the fairleads. The reference is stancf's finest run (on OC4 with the
chains in sections, fine where they touch down); a second run with about
half its elements and twice its step bounds its own error (the table
gives their difference). MoorDyn's runs are shown converging to it too.
stancf runs on the deck's uniform mesh and, on OC4, with the chains in
three sections (`[[mesh]]`): the stretch of about 280 m where they touch
down in short elements, the grounded and suspended parts in long ones;
MoorDyn's lines have one segment length.
MoorDyn's own `FairTen` (the top segment's tension, half a segment below
the fairlead) is not used: at 20 segments it is 22 kN (3 % of the range)
below |f|.

stancf runs the Galerkin step with modified Newton and `step_halvings = 4`
(a step Newton cannot finish at a touchdown is taken in halves,
docs/method.md §11.13).

Cost: wall time of the whole simulation. MoorDyn: MoorDyn_Init (its
initial-condition generation, reported separately) and one MoorDyn_Step
per dtM (the coupled points must move as the motion does inside MoorDyn's
steps: see run_moordyn), less the Python driver's own time, measured by
the same loop without stepping and reported apart. stancf: its steps and
their writing of points.csv, the one table the race reads (`[output]
files`; MoorDyn writes none), after its static solve: summary.json's
`stepping_wall_time_s`; the rest of its process (start, parsing, the
static equilibrium) stands beside MoorDyn's initial conditions, and the
two add up to the time to the answer.

The problems and their decks are in race_problems.py, the runs of each
code in race_grids.py, the tables and figure in race_tables.py.
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

import numpy as np

from race_tables import read_rows, write

from race_grids import GRIDS, RACE_TOLERANCE
from race_problems import (HERE, LAZY, OC4, OUTPUT_DT, PROBLEMS, RISER, ROOT, STEEP,  # noqa: F401
                           Problem, deck_rows, deck_text, mesh_entry, mesh_name, positions0,
                           segments, surge)

STANCF = os.path.join(ROOT, "target", "release", "stancf")
OUT = os.path.join(HERE, "out")
QUICK = "--quick" in sys.argv


class Quiet:
    """Sends the process's stdout to /dev/null (MoorDyn prints every step)."""

    def __enter__(self):
        sys.stdout.flush()
        self.saved = os.dup(1)
        self.null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(self.null, 1)

    def __exit__(self, *exc):
        os.dup2(self.saved, 1)
        os.close(self.null)
        os.close(self.saved)


def run_moordyn(pb, refine, dtm):
    """(IC seconds, simulation seconds, times, tensions k x points, driver
    seconds) or None.

    MoorDyn_Step takes the coupled points' state at the start t of a
    coupling step and moves them by r = x + xd (t' - t) inside it
    (Point::updateFairlead): a constant velocity. The line's axial damping
    turns a velocity error at the fairlead into a tension error at once
    (BA / l per segment: 1e5 N s/m at the lazy wave's 48 segments), so
    coupling steps of 0.1 s (velocity off by up to a dt / 2) put 4 kN
    (65 % of the range) into the lazy wave's fairlead tension and 870 N
    even when the last piece before each output is short. Both codes must
    solve the same problem, so MoorDyn is driven at its own step: one
    MoorDyn_Step per dtM, x = the motion at the step's start, xd = the
    secant rate (the points pass through the motion at every dtM, the
    velocity is off by a dtM / 2 at most: 0.05 mm/s for the lazy wave).
    The driver's own time (the Python loop, the motion, the call: measured
    by the same loop with dt = 0, which MoorDyn answers with the forces
    alone) is subtracted from MoorDyn's wall time and reported apart."""
    import moordyn
    x0 = positions0(pb)
    per_output = int(round(OUTPUT_DT / dtm))
    if abs(per_output * dtm - OUTPUT_DT) > 1e-12:
        sys.exit("MoorDyn step %r does not divide the output interval %r" % (dtm, OUTPUT_DT))
    outputs = int(round(pb.duration / OUTPUT_DT))

    def state(ta, tb):
        """The coupled points' (x, xd) for the coupling step [ta, tb]."""
        xa, xb = surge(ta, pb)[0], surge(tb, pb)[0]
        rate = (xb - xa) / (tb - ta)
        x, xd = [], []
        for p in x0:
            x += [p[0] + xa, p[1], p[2]]
            xd += [rate, 0.0, 0.0]
        return x, xd

    def drive(s, step):
        """Every coupling step; the tensions at the outputs (None on a
        non-finite force)."""
        times, tensions = [], []
        for k in range(outputs):
            for j in range(per_output):
                ta, tb = (k * per_output + j) * dtm, (k * per_output + j + 1) * dtm
                x, xd = state(ta, tb)
                try:
                    f = moordyn.Step(s, x, xd, ta, dtm if step else 0.0)
                except RuntimeError:
                    # MoorDyn stops on a non-finite state (an unstable
                    # step).
                    return None
            ten = np.linalg.norm(np.asarray(f).reshape(-1, 3), axis=1)
            if not np.all(np.isfinite(ten)):
                return None
            times.append((k + 1) * OUTPUT_DT)
            tensions.append(ten)
        return np.array(times), np.array(tensions)

    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "deck.txt")
        with open(path, "w") as f:
            f.write(deck_text(pb, refine, dtm))
        with Quiet():
            t0 = time.perf_counter()
            s = moordyn.Create(path)
            moordyn.SetVerbosity(s, moordyn.LEVEL_NONE)
            moordyn.Init(s, list(x0.ravel()), [0.0] * x0.size)
            t1 = time.perf_counter()
            series = drive(s, True)
            t2 = time.perf_counter()
            if series is not None:
                drive(s, False)
            t3 = time.perf_counter()
            moordyn.Close(s)
    if series is None:
        return None
    return t1 - t0, (t2 - t1) - (t3 - t2), series[0], series[1], t3 - t2


SCENARIO = """title = "MoorDyn race"
[system]
moordyn = "deck.txt"
{motions}
[analysis]
type = "dynamic"
initial = "static"
time_step = {dt!r}
duration = {duration!r}
time_scheme = "{scheme}"
solver = "{solver}"
step_halvings = 4
{tolerance}
[output]
{writing}
files = ["points.csv"]
end_forces = "at_time"
"""


def run_stancf(pb, refine, dt, tolerance=None, sections=None, scheme="galerkin",
               solver="modified-newton", between=False, force_tolerance=None):
    """(wall seconds, times, tensions k x points, summary) or None;
    `tolerance`: the scenario's `analysis.tolerance` (None: stancf's
    default, 1e-10 of the line's length); `sections`: the touchdown
    lines' element counts in their sections (None: the deck's uniform
    NumSegs times `refine`)."""
    motions = "".join(
        "\n[[motions]]\npoint = %d\namplitude = [%r, 0.0, 0.0]\nperiod = %r\nramp = %r\n"
        % (p, pb.amplitude, pb.period, pb.period) for p in pb.coupled)
    # Every run is judged at the same 0.1 s output times: a step that
    # does not divide them (0.2 s wrote every 0.2 s, half the samples) is
    # refused, as MoorDyn's is.
    # With `between`, the steps need not divide it: the tables are
    # written at its multiples from the steps' cubics (`[output]
    # interval`, docs/method.md §6.5a).
    every = int(round(OUTPUT_DT / dt))
    if between:
        writing = "interval = %r" % OUTPUT_DT
    elif every < 1 or abs(every * dt - OUTPUT_DT) > 1e-12:
        sys.exit("stancf step %r does not divide the output interval %r" % (dt, OUTPUT_DT))
    else:
        writing = "every = %d" % every
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "deck.txt"), "w") as f:
            f.write(deck_text(pb, refine, 1e-3))
        sc = os.path.join(d, "race.toml")
        with open(sc, "w") as f:
            f.write(SCENARIO.format(motions=motions, dt=dt, duration=pb.duration, scheme=scheme,
                                    solver=solver, writing=writing,
                                    tolerance=("" if tolerance is None
                                               else "tolerance = %r\n" % tolerance)
                                    + ("" if force_tolerance is None
                                       else "force_tolerance = %r\n" % force_tolerance)))
            if sections:
                f.write(mesh_entry(pb, sections))
        out = os.path.join(d, "out")
        t0 = time.perf_counter()
        p = subprocess.run([STANCF, "run", sc, "--out", out, "--quiet"],
                           capture_output=True, text=True)
        wall = time.perf_counter() - t0
        if p.returncode != 0:
            return None
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
        rows = {}
        with open(os.path.join(out, "points.csv")) as f:
            for r in csv.DictReader(f):
                point = int(float(r["point"]))
                if point in pb.coupled:
                    t = round(float(r["t"]), 6)
                    f3 = [float(r["fx"]), float(r["fy"]), float(r["fz"])]
                    rows.setdefault(t, {})[point] = math.sqrt(sum(c * c for c in f3))
    times = np.array(sorted(t for t in rows if t > 0))
    tensions = np.array([[rows[t][p] for p in pb.coupled] for t in times])
    return wall, times, tensions, summary


def error(times, tensions, ref, pb):
    """Largest |T - T_ref| over t >= one period (after the ramp), over
    the reference's range there, the worst fairlead (None without common
    times)."""
    rt, rv = ref
    index = {round(t, 6): k for k, t in enumerate(rt)}
    pairs = [(k, index[round(t, 6)]) for k, t in enumerate(times)
             if t >= pb.period - 1e-9 and round(t, 6) in index]
    if not pairs:
        return None
    a = tensions[[p[0] for p in pairs]]
    b = rv[[p[1] for p in pairs]]
    span = b.max(axis=0) - b.min(axis=0)
    return float((np.abs(a - b).max(axis=0) / span).max())


def stancf_row(pb, code, refine, dt, sections, out, ref_series, between=False,
               force_tolerance=None):
    """A CSV row of a stancf run (`out` None: failed). Its `wall_s` is the
    simulation's time, summary.json's `stepping_wall_time_s` (the steps
    and their writing), as MoorDyn's is its simulation after its initial
    conditions; its `ic_s` is the rest of the process (start, reading,
    the static solve), as MoorDyn's is its initial-condition generation:
    the two add up to the whole process, the time to the answer."""
    stepping = out[3].get("stepping_wall_time_s") if out else None
    return dict(problem=pb.name, code=code, segments=segments(pb, refine, sections), dt=dt,
                ic_s=max(out[0] - stepping, 0.0) if stepping is not None else "",
                wall_s=(stepping if stepping is not None else out[0]) if out else "",
                error=error(out[1], out[2], ref_series, pb) if out else "", driver_s="",
                mesh=mesh_name(sections, between, force_tolerance))




def controlled_rows(pb, grid, ref_series):
    """The rows of `pb`'s runs whose steps a force tolerance chose
    (`analysis.force_tolerance`, dt the first and largest step), written
    at the 0.1 s outputs from the steps' cubics."""
    rows = []
    for refine, dt, sections, tol in grid.get("controlled", []):
        out = run_stancf(pb, refine, dt, RACE_TOLERANCE, sections, between=True,
                         force_tolerance=tol)
        rows.append(stancf_row(pb, "stancf", refine, dt, sections, out, ref_series, True, tol))
        print(rows[-1], flush=True)
    return rows


# `--controlled-only`: the reference and the force-tolerance series
# alone, merged into out/moordyn_race.csv in place of that file's
# force-tolerance rows.
CONTROLLED_ONLY = "--controlled-only" in sys.argv


def race(pb):
    """Every run of problem `pb`; the rows of its table."""
    grid = GRIDS[pb.name]["quick" if QUICK else "full"]
    r0, dt0, sections0 = grid["reference"]
    ref = run_stancf(pb, r0, dt0, sections=sections0)
    if ref is None:
        sys.exit("%s: the reference run failed: %r" % (pb.name, grid["reference"]))
    ref_series = (ref[1], ref[2])
    rows = []
    runs = [] if CONTROLLED_ONLY else [(run, False) for run in grid["stancf"]]
    runs += [] if CONTROLLED_ONLY else [(run, True) for run in grid.get("between", [])]
    for run, between in runs:
        refine, dt, sections = run if len(run) == 3 else run + (None,)
        out = run_stancf(pb, refine, dt, RACE_TOLERANCE, sections, between=between)
        rows.append(stancf_row(pb, "stancf", refine, dt, sections, out, ref_series, between))
        print(rows[-1], flush=True)
    rows += controlled_rows(pb, grid, ref_series)
    if CONTROLLED_ONLY:
        return rows
    for r, dtm in grid["moordyn"]:
        out = run_moordyn(pb, r, dtm)
        rows.append(dict(problem=pb.name, code="moordyn", segments=segments(pb, r), dt=dtm,
                         ic_s=out[0] if out else "", wall_s=out[1] if out else "",
                         error=error(out[2], out[3], ref_series, pb) if out else "",
                         driver_s=out[4] if out else "", mesh="uniform"))
        print(rows[-1], flush=True)
    if grid["check"]:
        r1, dt1, sections1 = grid["check"]
        out = run_stancf(pb, r1, dt1, sections=sections1)
        rows.append(stancf_row(pb, "stancf reference check", r1, dt1, sections1, out,
                               ref_series))
    rows.append(dict(stancf_row(pb, "stancf reference", r0, dt0, sections0, ref, ref_series),
                     error=0.0))
    return rows


def main():
    os.makedirs(OUT, exist_ok=True)
    if "--tables-only" in sys.argv:
        # The table and figure again from out/moordyn_race.csv, no runs.
        write(read_rows(os.path.join(OUT, "moordyn_race.csv")), PROBLEMS, OUT)
        return
    only = [a.split("=", 1)[1] for a in sys.argv if a.startswith("--problem=")]
    rows = []
    for pb in PROBLEMS:
        if (not only and pb is not LAZY) or pb.name in only:
            rows += race(pb)
    if CONTROLLED_ONLY:
        kept = [r for r in read_rows(os.path.join(OUT, "moordyn_race.csv"))
                if "force tolerance" not in r["mesh"]]
        rows = kept + rows
    write(rows, PROBLEMS, OUT)
    if "--publish" in sys.argv:
        # The committed copy: docs/race/moordyn_race.{csv,md,png}.
        for ext in ("csv", "md", "png"):
            src = os.path.join(OUT, "moordyn_race." + ext)
            if os.path.exists(src):
                shutil.copy(src, os.path.join(ROOT, "docs", "race"))


if __name__ == "__main__":
    main()
