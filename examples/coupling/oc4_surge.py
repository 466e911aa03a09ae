"""Drives the three fairleads of the OC4 DeepCwind mooring with a
platform surge through stancf.Simulation, as a floating platform's solver
would, and prints (or plots) the fairlead tensions against time.

    python examples/coupling/oc4_surge.py [duration_s] [--plot tension.png]

The surge moves every fairlead along x by dx(t) = A/2 (1 - cos(2 pi t/T)),
A = 5 m, T = 20 s, starting from rest; the coupling interval is 0.1 s.
Prints the CSV ``t,tension_4,tension_5,tension_6`` (one row per coupling
step), the same numbers as examples/coupling/oc4_surge.c prints through
the C library.
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
    x0 = np.array(_positions(deck, sim.coupled_ids), dtype=float).ravel()
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


def _positions(deck, ids):
    """The positions of points `ids` in the deck's POINTS table."""
    rows = {}
    section = None
    for line in Path(deck).read_text().splitlines():
        if line.startswith("---"):
            section = line.strip("- ").upper()
            continue
        fields = line.split()
        if section and section.startswith("POINTS") and fields and fields[0].isdigit():
            rows[int(fields[0])] = [float(v) for v in fields[2:5]]
    return [rows[i] for i in ids]


def main(argv):
    plot = None
    if "--plot" in argv:
        i = argv.index("--plot")
        plot = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    duration = float(argv[0]) if argv else 40.0
    sim_ids = stancf.Simulation(DECK).coupled_ids
    t, tensions = surge(DECK, duration)
    print("t," + ",".join("tension_%d" % i for i in sim_ids))
    for tk, row in zip(t, tensions):
        print(",".join(repr(float(v)) for v in (tk, *row)))
    if plot:
        try:
            import matplotlib
            matplotlib.use("Agg")
            import matplotlib.pyplot as plt
        except ImportError:
            sys.exit("--plot needs matplotlib (pip install matplotlib)")
        fig, ax = plt.subplots(figsize=(7, 4))
        for k, i in enumerate(sim_ids):
            ax.plot(t, tensions[:, k] / 1e3, label="fairlead %d" % i)
        ax.set_xlabel("t (s)")
        ax.set_ylabel("tension (kN)")
        ax.set_title("OC4 DeepCwind: 5 m surge at 20 s")
        ax.legend()
        fig.tight_layout()
        fig.savefig(plot, dpi=120)


if __name__ == "__main__":
    main(sys.argv[1:])
