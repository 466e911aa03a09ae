#!/usr/bin/env python3
"""Lowe and Langley (OMAE 2006)'s flexible jumper in regular waves that a
host sets at the nodes (MoorDyn's WaveKin 1; docs/method.md §12.1,
(W2f)-(W2g)), cases 4 to 6 of MoorDyn's tests/lowe_and_langley_2006.cpp,
run by MoorDyn 2.7 (PyPI's `moordyn`) and by stancf (its Python package),
each driven as that test drives MoorDyn: the top held at (0, 0, -5) m, the
test's linear waves (amplitude 5 m, period 10 s) evaluated at the points
each code names, at mid-interval, from t = 0; the top tension compared
with the paper's from t = 20 s on.

usage: lowe_langley_waves.py [stancf_dt ...]   (default 0.05 0.025)

Needs `moordyn` and `numpy` and stancf's package in the same Python
(`pip install "moordyn>=2.7" numpy ./crates/stancf-py`). Prints, per
case, the largest difference (kN) of each code from the paper and of
stancf from MoorDyn (the table of docs/method.md §12.1, "Waves a host sets
at the nodes").
"""

import math
import shutil
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[3]
FIXTURES = ROOT / "crates" / "stancf-cli" / "tests" / "fixtures"
DECK = FIXTURES / "lowe-langley-2006-jumper-moordyn.txt"
CASES = {4: (230.0, 0.0), 5: (165.0, 45.0), 6: (0.0, 90.0)}
TOP = [0.0, 0.0, -5.0]
RAMP = 20.0


def wave(points, t, heading, phase):
    """MoorDyn's test's `wave`: deep-water wave number, profile over 100 m."""
    w = 2.0 * math.pi / 10.0
    k = w * w / 9.81
    p = np.asarray(points, dtype=float).reshape(-1, 3)
    x = p[:, 0] * math.cos(heading) + p[:, 1] * math.sin(heading)
    c, s = np.cos(k * x - w * t + phase), np.sin(k * x - w * t + phase)
    ch = np.cosh(k * (p[:, 2] + 100.0)) / math.cosh(k * 100.0)
    sh = np.sinh(k * (p[:, 2] + 100.0)) / math.cosh(k * 100.0)
    u = 5.0 * w * np.stack([c * ch * math.cos(heading), c * ch * math.sin(heading), s * sh], 1)
    a = 5.0 * w * w * np.stack([s * ch * math.cos(heading), s * ch * math.sin(heading),
                                -c * sh], 1)
    return u, a


def reference(case):
    return np.loadtxt(FIXTURES / ("lowe-langley-2006-case-%d.csv" % case), delimiter=",")


def moordyn_series(case, folder):
    """MoorDyn's top tension (kN) at the paper's times, at the test's 5 ms."""
    import moordyn
    phase, heading = (math.radians(v) for v in CASES[case])
    deck = folder / "line.txt"
    deck.write_text(DECK.read_text().replace("\r", ""))
    dt, t, out = 0.005, 0.0, []
    s = moordyn.Create(str(deck))
    moordyn.Init(s, TOP, [0.0, 0.0, 0.0])
    moordyn.ExternalWaveKinInit(s)
    line = moordyn.GetLine(s, 1)
    top_node = moordyn.GetLineN(line)
    ref = reference(case)
    while len(out) < len(ref):
        u, a = wave(moordyn.ExternalWaveKinGetCoordinates(s), t + 0.5 * dt, heading, phase)
        moordyn.ExternalWaveKinSet(s, u.tolist(), a.tolist(), t + 0.5 * dt)
        moordyn.Step(s, TOP, [0.0, 0.0, 0.0], t, dt)
        t += dt
        if t - RAMP >= ref[len(out), 0] - 1e-9:
            out.append(np.linalg.norm(moordyn.GetLineNodeForce(line, top_node)) / 1e3)
    moordyn.Close(s)
    return np.array(out)


def stancf_series(case, dt, folder):
    """stancf's top tension (kN) at the paper's times, Galerkin step dt."""
    import stancf
    phase, heading = (math.radians(v) for v in CASES[case])
    shutil.copy(DECK, folder / "line.txt")
    scenario = folder / "jumper.toml"
    scenario.write_text('[system]\nmoordyn = "line.txt"\n[analysis]\ntype = "dynamic"\n'
                        'time_step = %r\ntime_scheme = "galerkin"\nduration = 60.0\n' % dt)
    sim = stancf.Simulation(scenario)
    sim.initialize(TOP, [0.0, 0.0, 0.0])
    ref = reference(case)
    t, out = 0.0, []
    while len(out) < len(ref):
        u, a = wave(sim.wave_kinematics_points(), t + 0.5 * dt, heading, phase)
        sim.set_wave_kinematics(u, a, t + 0.5 * dt)
        t = round(t + dt, 9)
        f = sim.step_to(t, TOP, [0.0, 0.0, 0.0])
        if t - RAMP >= ref[len(out), 0] - 1e-9:
            out.append(np.linalg.norm(f) / 1e3)
    return np.array(out)


def main():
    steps = [float(a) for a in sys.argv[1:]] or [0.05, 0.025]
    print("| case | MoorDyn 2.7 vs paper | " +
          " | ".join("stancf %g s vs paper | stancf %g s vs MoorDyn" % (d, d) for d in steps) +
          " |")
    print("|---|---|" + "---|---|" * len(steps))
    for case in CASES:
        with tempfile.TemporaryDirectory() as tmp:
            folder = Path(tmp)
            paper = reference(case)[:, 1]
            md = moordyn_series(case, folder)
            row = ["%d" % case, "%.3f" % np.max(np.abs(md - paper))]
            for dt in steps:
                st = stancf_series(case, dt, folder)
                row += ["%.3f" % np.max(np.abs(st - paper)), "%.3f" % np.max(np.abs(st - md))]
            print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()
