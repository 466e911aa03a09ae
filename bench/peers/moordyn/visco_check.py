"""Viscoelastic lines against MoorDyn 2.7 (issue 32; docs/method.md §2.11).

MoorDyn's own test of its viscoelastic model (tests/Mooring/polyester,
OpenFAST's md_viscoelastic): one segment of rope 1 m long between a
fixed point at the origin and a coupled point 2 m away, in its two
forms:

- `mean`: EA|alphaMBL|vbeta = 1.424e8|1.586e8|0.4, BA|BA_D = 4e9|11e6
  (the dynamic stiffness alpha + beta T1 of the mean load);
- `constant`: EA|EA_D = 1.424e8|1.9e8, BA|BA_D = 4e9|11e6.

The coupled point moves x(t) = 2 + 0.05 sin(2 pi t / 10) (strain 1 +-
0.05) for 300 s. MoorDyn (dtM 1e-3, stepped at its own step with the
secant rate, as race.py drives it) against stancf (1 SAC-2 element,
Galerkin, dt 0.01 s, the force at t), both from the straight line at
rest: MoorDyn sets its static spring's stretch to the whole stretch at
the start (Line.cpp: dl_1 = lstr - l, a state far from rest that relaxes
over the dashpot's time (BA + BA_D) / (k1 + k2), 5 to 6 s here; at 30 s
it still pulls 1 % of the range harder), stancf to its rest value, so the
fairlead tensions are compared after 150 s, 25 of those times later.
Printed: each code's range and the largest difference, in % of the
range. About ten seconds.
"""
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import race  # noqa: E402

FORMS = {
    "mean": ("1.424e+08|1.586e+08|0.4", "4E9|11E6"),
    "constant": ("1.424e+08|1.9e+08", "4E9|11E6"),
}
DECK = """viscoelastic segment: {form}
---------------------- LINE TYPES -----------------------------------
TypeName Diam   Mass/m EA   BA/-zeta EI  Cd  Ca  CdAx CaAx
(name)   (m)    (kg/m) (N)  (N-s/-)  (N-m^2) (-) (-) (-) (-)
rope     0.1438 22.42  {ea} {ba}     0   0   0   0   0
---------------------- POINTS ---------------------------------------
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed   0 0 0 0 0 0 0
2 Coupled 2 0 0 0 0 0 0
---------------------- LINES ----------------------------------------
ID LineType AttachA AttachB UnstrLen NumSegs Outputs
(#) (name) (#) (#) (m) (-) (-)
1 rope 1 2 1.0 1 -
---------------------- OPTIONS --------------------------------------
{dtm} dtM
0 g
200 WtrDpth
0 TmaxIC
--------------------- need this line --------------------------------
"""
AMPLITUDE, PERIOD, DURATION, COMPARE_FROM = 0.05, 10.0, 300.0, 150.0
DTM, DT, OUTPUT = 1e-3, 0.01, 0.1


def motion(t):
    return 2.0 + AMPLITUDE * math.sin(2.0 * math.pi * t / PERIOD)


def run_moordyn(form):
    import moordyn
    ea, ba = FORMS[form]
    per_output = int(round(OUTPUT / DTM))
    times, tensions = [], []
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "deck.txt")
        with open(path, "w") as f:
            f.write(DECK.format(form=form, ea=ea, ba=ba, dtm=DTM))
        with race.Quiet():
            s = moordyn.Create(path)
            moordyn.SetVerbosity(s, moordyn.LEVEL_NONE)
            moordyn.Init(s, [2.0, 0.0, 0.0], [0.0, 0.0, 0.0])
            for k in range(int(round(DURATION / OUTPUT))):
                for j in range(per_output):
                    ta = (k * per_output + j) * DTM
                    xa, xb = motion(ta), motion(ta + DTM)
                    f = moordyn.Step(s, [xa, 0.0, 0.0], [(xb - xa) / DTM, 0.0, 0.0], ta, DTM)
                times.append((k + 1) * OUTPUT)
                tensions.append(float(np.linalg.norm(f)))
            moordyn.Close(s)
    return np.array(times), np.array(tensions)


SCENARIO = """title = "viscoelastic segment: {form}"
[system]
moordyn = "deck.txt"
[[motions]]
point = 2
amplitude = [{amplitude!r}, 0.0, 0.0]
period = {period!r}
[analysis]
type = "dynamic"
initial = "reference"
time_scheme = "galerkin"
time_step = {dt!r}
duration = {duration!r}
[output]
every = {every}
files = ["tensions.csv"]
end_forces = "at_time"
"""


def run_stancf(form):
    ea, ba = FORMS[form]
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "deck.txt"), "w") as f:
            f.write(DECK.format(form=form, ea=ea, ba=ba, dtm=DT))
        sc = os.path.join(d, "run.toml")
        with open(sc, "w") as f:
            f.write(SCENARIO.format(form=form, amplitude=AMPLITUDE, period=PERIOD, dt=DT,
                                    duration=DURATION, every=int(round(OUTPUT / DT))))
        out = os.path.join(d, "out")
        p = subprocess.run([race.STANCF, "run", sc, "--out", out, "--quiet"],
                           capture_output=True, text=True)
        if p.returncode != 0:
            sys.exit("stancf failed: " + p.stderr)
        rows = np.genfromtxt(os.path.join(out, "tensions.csv"), delimiter=",", names=True,
                             dtype=None, encoding=None)
        b = rows[rows["end"] == "B"]
        return np.array(b["t"], dtype=float), np.array(b["tension"], dtype=float)


def main():
    print("form      code     range (N)          largest |diff| after %g s" % COMPARE_FROM)
    for form in FORMS:
        tm, fm = run_moordyn(form)
        ts, fs = run_stancf(form)
        fs_at = np.interp(tm, ts, fs)
        keep = tm >= COMPARE_FROM
        rng = fm[keep].max() - fm[keep].min()
        diff = np.abs(fs_at[keep] - fm[keep]).max()
        print("%-9s MoorDyn  %.6e .. %.6e" % (form, fm[keep].min(), fm[keep].max()))
        print("%-9s stancf   %.6e .. %.6e   %.4g N = %.3g %% of the range"
              % (form, fs_at[keep].min(), fs_at[keep].max(), diff, 100.0 * diff / rng))


if __name__ == "__main__":
    main()
