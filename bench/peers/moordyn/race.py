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

Accuracy: the fairlead tension is |f|, the force of the line on its
fairlead (what a coupled platform code receives: MoorDyn_Step's forces,
stancf's points.csv); the error of a run is the largest difference from
the reference over 100 s <= t <= 300 s (after the ramp), at the 0.1 s
output times, relative to the reference tension's range over that time,
the largest of the three fairleads. The reference is stancf's finest run;
MoorDyn's runs are shown converging to it too (the table's last rows).
MoorDyn's own `FairTen` (the top segment's tension, half a segment below
the fairlead) is not used: at 20 segments it is 22 kN (3 % of the range)
below |f|.

Cost: wall time of the whole simulation. MoorDyn: MoorDyn_Init (its
initial-condition generation, reported separately) and the MoorDyn_Step
calls, one per 0.1 s output (it sub-steps at dtM inside). stancf: the
whole `stancf run` process (parsing, static equilibrium, writing every
result file).
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

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
STANCF = os.path.join(ROOT, "target", "release", "stancf")
OUT = os.path.join(HERE, "out")
QUICK = "--quick" in sys.argv
DECK = os.path.join(ROOT, "examples", "oc4-deepcwind-moordyn.txt")
COUPLED = [4, 5, 6]
AMPLITUDE, PERIOD, DURATION = 8.0, 100.0, 300.0
OUTPUT_DT = 0.1
# BA = zeta l sqrt(EA m) at zeta = 1, l = 835.35 / 20 m (docs/method.md (M36)).
BA = 1.0 * 835.35 / 20 * math.sqrt(7.536e8 * 113.35)


def surge(t):
    """x offset and rate of every fairlead at t (stancf's [[motions]])."""
    s = min(t / PERIOD, 1.0)
    f = s * s * s * (s * (6.0 * s - 15.0) + 10.0)
    df = 30.0 * s * s * (s - 1.0) ** 2 / PERIOD if t < PERIOD else 0.0
    w = 2.0 * math.pi / PERIOD
    return (f * AMPLITUDE * math.sin(w * t),
            df * AMPLITUDE * math.sin(w * t) + f * AMPLITUDE * w * math.cos(w * t))


def deck_text(segments, dtm):
    """The race's deck: NumSegs, BA and dtM set, no OUTPUTS channels, a
    tight initial-condition threshold for MoorDyn."""
    out, section = [], None
    with open(DECK) as f:
        for line in f:
            if line.startswith("---"):
                section = line.strip("- \n").upper()
                out.append(line)
                continue
            fields = line.split()
            if section and fields and fields[0][0].isdigit() or (
                    section == "LINE TYPES" and fields and fields[0] == "chain"):
                if section == "LINE TYPES":
                    fields[4] = "%.6e" % BA
                    line = "  ".join(fields) + "\n"
                elif section == "LINES":
                    fields[5] = str(segments)
                    line = "  ".join(fields) + "\n"
                elif section == "OPTIONS" and fields[1] == "dtM":
                    line = "%r  dtM\n" % dtm
                elif section == "OPTIONS" and fields[1] == "threshIC":
                    line = "0.0001  threshIC\n"
                elif section == "OPTIONS" and fields[1] == "TmaxIC":
                    line = "200.0  TmaxIC\n"
            if section == "OUTPUTS" and fields and fields[0] != "END":
                continue
            out.append(line)
    return "".join(out)


def positions0():
    """The coupled points' positions in the deck."""
    rows, section = {}, None
    with open(DECK) as f:
        for line in f:
            if line.startswith("---"):
                section = line.strip("- \n").upper()
                continue
            fields = line.split()
            if section == "POINTS" and fields and fields[0].isdigit():
                rows[int(fields[0])] = [float(v) for v in fields[2:5]]
    return np.array([rows[i] for i in COUPLED])


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


def run_moordyn(segments, dtm):
    """(IC seconds, simulation seconds, times, tensions k x 3) or None."""
    import moordyn
    x0 = positions0()
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "deck.txt")
        with open(path, "w") as f:
            f.write(deck_text(segments, dtm))
        with Quiet():
            t0 = time.perf_counter()
            s = moordyn.Create(path)
            moordyn.SetVerbosity(s, moordyn.LEVEL_NONE)
            moordyn.Init(s, list(x0.ravel()), [0.0] * x0.size)
            t1 = time.perf_counter()
            times, tensions = [], []
            t = 0.0
            ok = True
            for k in range(1, int(round(DURATION / OUTPUT_DT)) + 1):
                tn = k * OUTPUT_DT
                dx, vx = surge(tn)
                x = x0.copy()
                x[:, 0] += dx
                xd = np.zeros_like(x0)
                xd[:, 0] = vx
                f = np.asarray(moordyn.Step(s, list(x.ravel()), list(xd.ravel()), t, tn - t))
                t = tn
                ten = np.linalg.norm(f.reshape(-1, 3), axis=1)
                if not np.all(np.isfinite(ten)):
                    ok = False
                    break
                times.append(tn)
                tensions.append(ten)
            t2 = time.perf_counter()
            moordyn.Close(s)
    if not ok:
        return None
    return t1 - t0, t2 - t1, np.array(times), np.array(tensions)


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

[output]
every = {every}
"""


def run_stancf(elements, dt, scheme="galerkin", solver="modified-newton"):
    """(wall seconds, times, tensions k x 3, summary) or None."""
    motions = "".join(
        "\n[[motions]]\npoint = %d\namplitude = [%r, 0.0, 0.0]\nperiod = %r\nramp = %r\n"
        % (p, AMPLITUDE, PERIOD, PERIOD) for p in COUPLED)
    every = max(1, int(round(OUTPUT_DT / dt)))
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, "deck.txt"), "w") as f:
            f.write(deck_text(elements, 1e-3))
        sc = os.path.join(d, "race.toml")
        with open(sc, "w") as f:
            f.write(SCENARIO.format(motions=motions, dt=dt, duration=DURATION, scheme=scheme,
                                    solver=solver, every=every))
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
                if point in COUPLED:
                    t = round(float(r["t"]), 6)
                    f3 = [float(r["fx"]), float(r["fy"]), float(r["fz"])]
                    rows.setdefault(t, {})[point] = math.sqrt(sum(c * c for c in f3))
    times = np.array(sorted(t for t in rows if t > 0))
    tensions = np.array([[rows[t][p] for p in COUPLED] for t in times])
    return wall, times, tensions, summary


def error(times, tensions, ref):
    """Largest |T - T_ref| over t >= one period, over the reference's
    range there, the worst fairlead (None without common times)."""
    rt, rv = ref
    index = {round(t, 6): k for k, t in enumerate(rt)}
    pairs = [(k, index[round(t, 6)]) for k, t in enumerate(times)
             if t >= PERIOD - 1e-9 and round(t, 6) in index]
    if not pairs:
        return None
    a = tensions[[p[0] for p in pairs]]
    b = rv[[p[1] for p in pairs]]
    span = b.max(axis=0) - b.min(axis=0)
    return float((np.abs(a - b).max(axis=0) / span).max())


def main():
    os.makedirs(OUT, exist_ok=True)
    if QUICK:
        stancf_runs = [(10, 0.1), (20, 0.05)]
        reference = (20, 0.025)
        moordyn_runs = [(10, 2e-3), (20, 1e-3)]
    else:
        stancf_runs = [(n, dt) for n in (5, 10, 20, 40) for dt in (0.1, 0.05, 0.025)]
        reference = (80, 0.0125)
        moordyn_runs = [(10, 2e-3), (20, 1e-3), (40, 5e-4), (80, 2.5e-4), (160, 1.25e-4)]
    ref = run_stancf(*reference)
    if ref is None:
        sys.exit("the reference run failed: %r" % (reference,))
    ref_series = (ref[1], ref[2])
    rows = []
    for n, dt in stancf_runs:
        r = run_stancf(n, dt)
        rows.append(dict(code="stancf", resolution=n, dt=dt, ic_s="",
                         wall_s=r[0] if r else "", error=error(r[1], r[2], ref_series) if r else ""))
        print(rows[-1], flush=True)
    for n, dtm in moordyn_runs:
        r = run_moordyn(n, dtm)
        rows.append(dict(code="moordyn", resolution=n, dt=dtm, ic_s=r[0] if r else "",
                         wall_s=r[1] if r else "", error=error(r[2], r[3], ref_series) if r else ""))
        print(rows[-1], flush=True)
    rows.append(dict(code="stancf reference", resolution=reference[0], dt=reference[1], ic_s="",
                     wall_s=ref[0], error=0.0))
    write(rows)


def cheapest(rows, code, level):
    ok = [r for r in rows if r["code"] == code and r["error"] != "" and r["error"] <= level]
    return min(ok, key=lambda r: r["wall_s"]) if ok else None


def write(rows):
    with open(os.path.join(OUT, "moordyn_race.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    lines = ["# The race against MoorDyn: OC4 surge (this machine, one run)", "",
             "| accuracy | MoorDyn cheapest (s) | run | stancf cheapest (s) | run | MoorDyn / stancf |",
             "|---|---|---|---|---|---|"]
    for level, label in [(0.01, "1 %"), (0.001, "0.1 %")]:
        m, s = cheapest(rows, "moordyn", level), cheapest(rows, "stancf", level)
        cell = lambda r, what: ("%.2f" % r["wall_s"], "%d %s, dt %g (%.3g %%)" % (
            r["resolution"], what, r["dt"], 100 * r["error"])) if r else ("-", "not reached")
        mc, sc_ = cell(m, "segments"), cell(s, "elements")
        ratio = "%.2f" % (m["wall_s"] / s["wall_s"]) if m and s else "-"
        lines.append("| %s | %s | %s | %s | %s | %s |" % (label, mc[0], mc[1], sc_[0], sc_[1], ratio))
    lines += ["", "| code | resolution | dt (s) | IC (s) | wall (s) | error (% of range) |",
              "|---|---|---|---|---|---|"]
    for r in rows:
        err = "%.3g" % (100 * r["error"]) if r["error"] != "" else "failed"
        wall = "%.2f" % r["wall_s"] if r["wall_s"] != "" else "-"
        ic = "%.2f" % r["ic_s"] if r["ic_s"] != "" else ""
        lines.append("| %s | %s | %g | %s | %s | %s |" % (r["code"], r["resolution"], r["dt"],
                                                          ic, wall, err))
    with open(os.path.join(OUT, "moordyn_race.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    for code, marker in [("moordyn", "s"), ("stancf", "o")]:
        pts = [(r["wall_s"], r["error"]) for r in rows
               if r["code"] == code and r["error"] not in ("", 0.0)]
        if pts:
            x, y = zip(*sorted(pts))
            ax.loglog(x, [100 * v for v in y], marker, label=code)
    ax.set_xlabel("wall time (s)")
    ax.set_ylabel("fairlead tension error (% of range)")
    ax.set_title("OC4 DeepCwind, 8 m surge at 100 s, 300 s")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(OUT, "moordyn_race.png"), dpi=120)


if __name__ == "__main__":
    main()
