"""Why the race drives MoorDyn at its own step (run_moordyn in race.py), and
a third reference for the lazy wave's dynamics.

One line in air (no water forces, no seabed): 240 m, 45 kg/m, EA 5e8 N,
BA 5e5 N s, from a fairlead at (0, 0, -10) to an anchor at (200, 0, -100),
48 segments; the fairlead moved x(t) = f(t) 5 sin(2 pi t / 20) (the race's
motion, ramp over one period). Four solutions of the fairlead force |f|:

- stancf, 48 SAC-2 elements, Galerkin, dt 0.025 s;
- MoorDyn (dtM 2e-4) coupled every 0.1 s (x at the coupling step's start,
  the secant rate: its linear motion model holds the velocity constant
  over the coupling step);
- MoorDyn coupled every dtM;
- an independent lumped-mass integration written here: the same 48
  segments, the tension EA (l - l0) / l0 + BA (dl/dt) / l0 along each
  segment, gravity, the fairlead node moved by the exact motion, scipy's
  DOP853 at rtol = atol = 1e-9, from the static equilibrium (Newton).

It prints each solution's range after the ramp and its largest difference
from stancf. Needs scipy (`pip install scipy` in the race's venv); about
a minute.
"""
import math
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import race  # noqa: E402

DECK = """--------------------- MoorDyn v2 input file ------------------------------------
one line in air: the coupling check of the race against MoorDyn
------------------------------ LINE TYPES --------------------------------------
TypeName  Diam    Mass/m   EA        BA/-zeta  EI       Cd    Ca    CdAx  CaAx
(name)    (m)     (kg/m)   (N)       (N-s/-)   (N-m^2)  (-)   (-)   (-)   (-)
cable     0.15    45.0     5.0E8     5.0E5     0.0      0.0   0.0   0.0   0.0
-------------------------------- POINTS ----------------------------------------
ID  Attachment  X        Y        Z        Mass    Volume  CdA    Ca
(#) (-)         (m)      (m)      (m)      (kg)    (m^3)   (m^2)  (-)
1   Coupled     0.0      0.0      -10.0    0       0       0      0
2   Fixed       200.0    0.0      -100.0   0       0       0      0
-------------------------------- LINES -----------------------------------------
ID  LineType  AttachA  AttachB  UnstrLen  NumSegs  Outputs
(#) (name)    (#)      (#)      (m)       (-)      (-)
1   cable     1        2        240.0     48       -
------------------------------- OPTIONS ----------------------------------------
0.0002    dtM        time step (s)
9.81      g          gravitational acceleration (m/s^2)
300       WtrDpth    water depth (m)
0.001     WtrDnsty   water density (kg/m^3)
------------------------------- OUTPUTS ----------------------------------------
END
------------------------- need this line ---------------------------------------
"""
SEGMENTS, LENGTH, EA, BA, MASS, G = 48, 240.0, 5e8, 5e5, 45.0, 9.81
FAIRLEAD, ANCHOR = np.array([0.0, 0.0, -10.0]), np.array([200.0, 0.0, -100.0])


def moordyn_coupled_every(pb, coupling):
    """MoorDyn's fairlead force at the 0.1 s outputs, coupled every
    `coupling` seconds (x at the step's start, the secant rate)."""
    import moordyn
    path = os.path.join(race.OUT, "coupling_check_deck.txt")
    with open(path, "w") as f:
        f.write(race.deck_text(pb, 1, 2e-4))
    per_output = int(round(race.OUTPUT_DT / coupling))
    out = []
    with race.Quiet():
        s = moordyn.Create(path)
        moordyn.SetVerbosity(s, moordyn.LEVEL_NONE)
        moordyn.Init(s, list(FAIRLEAD), [0.0] * 3)
        for k in range(int(round(pb.duration / race.OUTPUT_DT)) * per_output):
            ta, tb = k * coupling, (k + 1) * coupling
            xa, xb = race.surge(ta, pb)[0], race.surge(tb, pb)[0]
            f = moordyn.Step(s, [xa, 0.0, -10.0], [(xb - xa) / coupling, 0.0, 0.0], ta, coupling)
            if (k + 1) % per_output == 0:
                out.append(np.linalg.norm(f))
        moordyn.Close(s)
    return np.array(out)


def lumped(pb):
    """The independent lumped-mass solution's fairlead force at the 0.1 s
    outputs: the first segment's tension plus the weight of the fairlead
    node's half segment (its inertia, under 60 N here, left out)."""
    from scipy.integrate import solve_ivp
    n, l0 = SEGMENTS, LENGTH / SEGMENTS
    mass = np.full(n + 1, MASS * l0)
    mass[0] = mass[-1] = MASS * l0 / 2

    def forces(r, v, ea=EA):
        d = r[1:] - r[:-1]
        l = np.linalg.norm(d, axis=1)
        q = d / l[:, None]
        rate = np.einsum("ij,ij->i", v[1:] - v[:-1], q)
        tension = (ea * (l - l0) + BA * rate) / l0
        f = np.zeros_like(r)
        f[:-1] += tension[:, None] * q
        f[1:] -= tension[:, None] * q
        f[:, 2] -= mass * G
        return f

    def static_residual(x, ea):
        r = np.vstack([FAIRLEAD, x.reshape(-1, 3), ANCHOR])
        return forces(r, np.zeros_like(r), ea)[1:-1].ravel()

    # Static equilibrium: Newton with a finite-difference Jacobian and a
    # backtracking line search, continued in EA from a soft line.
    s = np.linspace(0.0, 1.0, n + 1)[1:-1]
    x = (FAIRLEAD + np.outer(s, ANCHOR - FAIRLEAD)
         - np.outer(40.0 * np.sin(np.pi * s), [0.0, 0.0, 1.0])).ravel()
    for ea in (1e6, 1e7, 1e8, EA):
        for _ in range(200):
            res = static_residual(x, ea)
            norm = np.linalg.norm(res)
            if norm < 1e-6:
                break
            jac = np.empty((x.size, x.size))
            for k in range(x.size):
                xp = x.copy()
                xp[k] += 1e-6
                jac[:, k] = (static_residual(xp, ea) - res) / 1e-6
            dx = np.linalg.solve(jac, -res)
            step = 1.0
            while step > 1e-4 and np.linalg.norm(static_residual(x + step * dx, ea)) > norm:
                step /= 2
            x = x + step * dx

    def pinned(t, r, v):
        dx, vx = race.surge(t, pb)
        r[0], v[0] = FAIRLEAD + [dx, 0.0, 0.0], [vx, 0.0, 0.0]
        r[-1], v[-1] = ANCHOR, 0.0

    def rhs(t, y):
        r = y[: 3 * (n + 1)].reshape(-1, 3).copy()
        v = y[3 * (n + 1):].reshape(-1, 3).copy()
        pinned(t, r, v)
        a = forces(r, v) / mass[:, None]
        a[0] = a[-1] = 0.0
        return np.concatenate([v.ravel(), a.ravel()])

    r0 = np.vstack([FAIRLEAD, x.reshape(-1, 3), ANCHOR])
    times = np.arange(1, int(round(pb.duration / race.OUTPUT_DT)) + 1) * race.OUTPUT_DT
    sol = solve_ivp(rhs, (0.0, times[-1]), np.concatenate([r0.ravel(), np.zeros(r0.size)]),
                    t_eval=times, method="DOP853", rtol=1e-9, atol=1e-9)
    out = []
    for k, t in enumerate(sol.t):
        r = sol.y[: 3 * (n + 1), k].reshape(-1, 3).copy()
        v = sol.y[3 * (n + 1):, k].reshape(-1, 3).copy()
        pinned(t, r, v)
        d = r[1] - r[0]
        l = np.linalg.norm(d)
        q = d / l
        tension = (EA * (l - l0) + BA * np.dot(v[1] - v[0], q)) / l0
        out.append(np.linalg.norm(tension * q - [0.0, 0.0, mass[0] * G]))
    return np.array(out)


def main():
    os.makedirs(race.OUT, exist_ok=True)
    deck = os.path.join(race.OUT, "coupling_check_source.txt")
    with open(deck, "w") as f:
        f.write(DECK)
    pb = race.Problem("coupling_check", deck, [1], 5.0, 20.0, 60.0, None, "one line in air")
    stancf = race.run_stancf(pb, 1, 0.025)
    times, reference = stancf[1], stancf[2][:, 0]
    after = times >= pb.period
    solutions = [("stancf, 48 elements, dt 0.025", reference),
                 ("MoorDyn coupled every 0.1 s", moordyn_coupled_every(pb, 0.1)),
                 ("MoorDyn coupled every dtM", moordyn_coupled_every(pb, 2e-4)),
                 ("lumped mass, DOP853", lumped(pb))]
    span = reference[after].max() - reference[after].min()
    for name, series in solutions:
        print("%-32s |f| %8.0f to %8.0f N, largest difference from stancf %6.0f N (%5.1f %% of "
              "its range)" % (name, series[after].min(), series[after].max(),
                              np.abs(series - reference)[after].max(),
                              100 * np.abs(series - reference)[after].max() / span))


if __name__ == "__main__":
    main()
