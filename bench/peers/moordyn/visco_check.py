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
range.

Then Syrope's working curves (docs/method.md §2.12): OpenFAST's
md_syrope deck and MoorDyn's three test decks (tests/Mooring/syrope:
linear, quadratic and exponential working curves), one segment of
polyester 1 m long, its coupled end driven 2 mm at 20 s for 300 s;
MoorDyn at the decks' dtM (0.01 s), stancf with the Galerkin step of
0.05 s, both from the segment at rest (the decks' Tmean0 set to its tension:
MoorDyn starts its slow strain from Tmean0 and the stretch relaxes over
five minutes); compared after 100 s. MoorDyn's test decks are taken
from its repository's mirror (/work/.mirror, `fetch`). About 15 seconds.
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


def drive_moordyn(deck, x0, amplitude, period, duration, dtm):
    """MoorDyn 2.7 on `deck` (opened from its folder, as its files are
    named), its coupled point at `x0` moved along x by amplitude
    sin(2 pi t / period), one MoorDyn_Step per dtm with the secant rate (as
    race.py drives it): the times and the coupled point's force every
    OUTPUT s."""
    import moordyn

    def x(t):
        return x0[0] + amplitude * math.sin(2.0 * math.pi * t / period)

    per_output = int(round(OUTPUT / dtm))
    times, tensions = [], []
    cwd = os.getcwd()
    os.chdir(os.path.dirname(deck))
    try:
        with race.Quiet():
            s = moordyn.Create(os.path.basename(deck))
            moordyn.SetVerbosity(s, moordyn.LEVEL_NONE)
            moordyn.Init(s, list(x0), [0.0, 0.0, 0.0])
            for k in range(int(round(duration / OUTPUT))):
                for j in range(per_output):
                    ta = (k * per_output + j) * dtm
                    xa, xb = x(ta), x(ta + dtm)
                    f = moordyn.Step(s, [xa, x0[1], x0[2]], [(xb - xa) / dtm, 0.0, 0.0], ta, dtm)
                times.append((k + 1) * OUTPUT)
                tensions.append(float(np.linalg.norm(f)))
            moordyn.Close(s)
    finally:
        os.chdir(cwd)
    return np.array(times), np.array(tensions)


def stancf_tensions(scenario, end):
    """stancf on the scenario file `scenario` (results beside it): the
    times and tensions of line 1's end `end` ("A" or "B")."""
    out = os.path.join(os.path.dirname(scenario), "out-" + os.path.basename(scenario))
    p = subprocess.run([race.STANCF, "run", scenario, "--out", out, "--quiet"],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("stancf failed: " + p.stderr)
    rows = np.genfromtxt(os.path.join(out, "tensions.csv"), delimiter=",", names=True,
                         dtype=None, encoding=None)
    at = rows[rows["end"] == end]
    return np.array(at["t"], dtype=float), np.array(at["tension"], dtype=float)


def run_moordyn(form):
    ea, ba = FORMS[form]
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "deck.txt")
        with open(path, "w") as f:
            f.write(DECK.format(form=form, ea=ea, ba=ba, dtm=DTM))
        return drive_moordyn(path, [2.0, 0.0, 0.0], AMPLITUDE, PERIOD, DURATION, DTM)


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
        return stancf_tensions(sc, "B")


SYROPE_DECKS = {
    # name: the suite it comes from (OpenFAST's r-test beside the
    # repository, or MoorDyn's tests from its mirror)
    "md_syrope": "openfast",
    "linear_wc": "moordyn",
    "quadratic_wc": "moordyn",
    "exp_wc": "moordyn",
}
SYROPE_AMPLITUDE, SYROPE_PERIOD, SYROPE_DURATION, SYROPE_FROM = 0.002, 20.0, 300.0, 100.0
SYROPE_DT = 0.05


def syrope_files(name, d):
    """Writes the deck and its files into d (MoorDyn's test decks name
    ../owc.dat: the deck goes one folder down) and returns the deck's
    path and its coupled point's position."""
    peer = os.path.join(race.ROOT, "..", "shared", "peer-decks", "openfast-r-test", "modules",
                        "moordyn", "md_syrope")
    mirror = "/work/.mirror/FloatingArrayDesign+MoorDyn/repo"
    if SYROPE_DECKS[name] == "openfast":
        folder = os.path.join(d, name)
        os.makedirs(folder)
        for f in ("moordyn.dat", "owc.dat", "syrope.dat"):
            with open(os.path.join(peer, f)) as src, open(os.path.join(folder, f), "w") as dst:
                dst.write(src.read())
        deck = os.path.join(folder, "moordyn.dat")
    else:
        folder = os.path.join(d, "syrope", name)
        os.makedirs(folder)
        def show(path):
            return subprocess.run(["git", "-C", mirror, "show", "HEAD:" + path],
                                  capture_output=True, text=True, check=True).stdout
        with open(os.path.join(d, "syrope", "owc.dat"), "w") as f:
            f.write(show("tests/Mooring/syrope/owc.dat"))
        for f in ("line.txt", "syrope.dat"):
            with open(os.path.join(folder, f), "w") as out:
                out.write(show("tests/Mooring/syrope/%s/%s" % (name, f)))
        deck = os.path.join(folder, "line.txt")
    with open(deck) as f:
        for line in f:
            w = line.split()
            if len(w) > 4 and w[0] == "2" and w[1].lower() == "coupled":
                return deck, [float(w[2]), float(w[3]), float(w[4])]
    sys.exit("no coupled point 2 in " + deck)


def start_at_rest(deck):
    """Sets the deck's SYROPE IC Tmean0 to the tension of its segment held
    straight at rest (stancf, a step from the reference shape): MoorDyn starts
    its slow strain from Tmean0 on the working curve of Tmax0, stancf at
    rest at its equilibrium, and the slow strain relaxes over
    (BA + BA_D) / (alpha + beta T), 5 minutes for these ropes, so both
    start from the same state."""
    sc = os.path.join(os.path.dirname(deck), "rest.toml")
    with open(sc, "w") as f:
        f.write('title = "at rest"\n[system]\nmoordyn = "%s"\n[analysis]\ntype = "dynamic"\n'
                'initial = "reference"\ntime_scheme = "galerkin"\ntime_step = %r\n'
                'duration = %r\n' % (os.path.basename(deck), SYROPE_DT, SYROPE_DT))
    tension = float(stancf_tensions(sc, "A")[1][0])
    with open(deck) as f:
        lines = f.read().split("\n")
    inside = False
    for i, line in enumerate(lines):
        if "SYROPE IC" in line.upper():
            inside, skip = True, 2
            continue
        if inside and line.startswith("---"):
            break
        if inside:
            if skip > 0:
                skip -= 1
                continue
            w = line.split()
            if len(w) >= 3:
                lines[i] = "%s %s %r" % (w[0], w[1], tension)
    with open(deck, "w") as f:
        f.write("\n".join(lines))
    return tension


def syrope_moordyn(deck, x0):
    return drive_moordyn(deck, x0, SYROPE_AMPLITUDE, SYROPE_PERIOD, SYROPE_DURATION, 0.01)


def syrope_stancf(deck):
    sc = os.path.join(os.path.dirname(deck), "run.toml")
    with open(sc, "w") as f:
        f.write(SCENARIO.replace('moordyn = "deck.txt"', 'moordyn = "%s"' % os.path.basename(deck))
                .format(form="syrope", amplitude=SYROPE_AMPLITUDE, period=SYROPE_PERIOD,
                        dt=SYROPE_DT, duration=SYROPE_DURATION,
                        every=int(round(OUTPUT / SYROPE_DT))))
    return stancf_tensions(sc, "A")


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
    print("\nSyrope decks, driven %g m at %g s for %g s (Galerkin dt %g s), after %g s"
          % (SYROPE_AMPLITUDE, SYROPE_PERIOD, SYROPE_DURATION, SYROPE_DT, SYROPE_FROM))
    for name in SYROPE_DECKS:
        with tempfile.TemporaryDirectory() as d:
            deck, x0 = syrope_files(name, d)
            start_at_rest(deck)
            tm, fm = syrope_moordyn(deck, x0)
            ts, fs = syrope_stancf(deck)
        fs_at = np.interp(tm, ts, fs)
        keep = tm >= SYROPE_FROM
        rng = fm[keep].max() - fm[keep].min()
        diff = np.abs(fs_at[keep] - fm[keep]).max()
        print("%-13s MoorDyn %.6e .. %.6e  stancf %.6e .. %.6e  %.4g N = %.3g %% of the range"
              % (name, fm[keep].min(), fm[keep].max(), fs_at[keep].min(), fs_at[keep].max(),
                 diff, 100.0 * diff / rng))


if __name__ == "__main__":
    main()
