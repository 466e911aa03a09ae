"""Drives the three fairleads of the OC4 DeepCwind mooring with a
platform surge through stancf.Simulation, as a floating platform's solver
would, and prints (or plots) the fairlead tensions against time.

    .venv/bin/python examples/coupling/oc4_surge.py [duration_s] [--plot out/tension.png]

The surge moves every fairlead along x by dx(t) = A/2 (1 - cos(2 pi t/T)),
A = 5 m, T = 20 s, starting from rest; the coupling interval is 0.1 s.
Prints the CSV ``t,tension_4,tension_5,tension_6`` (one row per coupling
step), the same numbers as examples/coupling/oc4_surge.c prints through
the C library. ``--plot`` needs matplotlib: checked at the start (exit 2
with how to install it), not after the simulation.
"""

import math
import sys
from pathlib import Path

import numpy as np

import stancf

DECK = Path(__file__).resolve().parents[1] / "oc4-deepcwind-moordyn.txt"
AMPLITUDE, PERIOD, INTERVAL = 5.0, 20.0, 0.1


def surge_offset(t):
    """The surge dx(t) and its rate (m, m/s)."""
    w = 2.0 * math.pi / PERIOD
    return 0.5 * AMPLITUDE * (1.0 - math.cos(w * t)), 0.5 * AMPLITUDE * w * math.sin(w * t)


def surge(deck=DECK, duration=40.0, interval=INTERVAL):
    """Steps the deck's coupled fairleads through the surge; returns the
    times (k,) and the fairlead tensions (k x points) after every coupling
    step."""
    sim = stancf.Simulation(deck)
    n = sim.coupled_dof
    x0 = sim.initial_positions()  # the deck's fairleads, in the order of coupled_ids
    sim.initialize(x0, np.zeros(n))
    times, tensions = [], []
    steps = int(round(duration / interval))
    t = 0.0
    for _ in range(steps):
        # t advanced by the interval, as MoorDyn_Step and stancf_step do.
        t = t + interval
        dx, vx = surge_offset(t)
        x, xd = x0.copy(), np.zeros(n)
        x[0::3] += dx
        xd[0::3] = vx
        f = sim.step_to(t, x, xd).reshape(-1, 3)
        times.append(t)
        # |f| in the C example's order of operations (the same bits).
        tensions.append([math.sqrt(fx * fx + fy * fy + fz * fz) for fx, fy, fz in f])
    return np.array(times), np.array(tensions)


def pyplot():
    """matplotlib's pyplot (Agg), or exit 2 saying how to install it: checked
    before the simulation, not after it."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        sys.stderr.write("oc4_surge.py: --plot needs matplotlib, which this Python (%s) does "
                         "not have: %s -m pip install matplotlib\n"
                         % (sys.executable, sys.executable))
        sys.exit(2)
    return plt


def main(argv):
    plot = None
    if "--plot" in argv:
        i = argv.index("--plot")
        if i + 1 >= len(argv):
            sys.stderr.write("oc4_surge.py: --plot needs a file name (--plot tension.png)\n")
            sys.exit(2)
        plot = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    plt = pyplot() if plot else None
    duration = float(argv[0]) if argv else 40.0
    sim_ids = stancf.Simulation(DECK).coupled_ids
    t, tensions = surge(DECK, duration)
    print("t," + ",".join("tension_%d" % i for i in sim_ids))
    for tk, row in zip(t, tensions):
        print(",".join(repr(float(v)) for v in (tk, *row)))
    if plot:
        fig, ax = plt.subplots(figsize=(7, 4))
        for k, i in enumerate(sim_ids):
            ax.plot(t, tensions[:, k] / 1e3, label="fairlead %d" % i)
        ax.set_xlabel("t (s)")
        ax.set_ylabel("tension (kN)")
        ax.set_title("OC4 DeepCwind: 5 m surge at 20 s")
        ax.legend()
        fig.tight_layout()
        Path(plot).parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(plot, dpi=120)

if __name__ == "__main__":
    main(sys.argv[1:])
