"""VIV against MoorDyn 2.7 and the published frequency (issue 32;
docs/method.md §12.7).

MoorDyn's VIV test deck (tests/Mooring/viv/viv.txt with its current
profile, taken from MoorDyn's repository mirror, /work/.mirror, `fetch`):
Thorsen's catenary riser, 23.71 m of 0.024 m cable in 100 segments
between the bed and 1 m below the surface in a 0.2 m/s uniform current,
Cl 0.7, dF 0.08, cF 0.18. Its test asserts that the top tension swings at
2.08 Hz, twice the published cross-flow response frequency of 1.04 Hz.

MoorDyn (RK4, the deck's dtM = 1e-4 s, from its dynamic relaxation) and
stancf (the deck as written, the Galerkin step at dt = 2.5 to 40 ms, from
its static solve), each 15 s; over 8 to 15 s (locked in): the top
tension's mean-crossing frequency, its standard deviation, and the
cross-flow (y) RMS of the riser's quarter, middle and three-quarter
nodes in diameters, with each run's wall time. Written to
out/viv_check.md. About 4 minutes.
"""
import importlib.metadata
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import race  # noqa: E402

MIRROR = "/work/.mirror/FloatingArrayDesign+MoorDyn/repo"
D = 0.024
DURATION, FROM = 15.0, 8.0
STEPS = [0.0025, 0.005, 0.01, 0.02, 0.04]
NODES = [25, 50, 75]


def write_deck(d):
    """MoorDyn's viv.txt and its current profile, where the deck expects
    them (Mooring/viv/ below the working folder d)."""
    folder = os.path.join(d, "Mooring", "viv")
    os.makedirs(folder)
    for f in ("viv.txt", "current_profile.txt"):
        text = subprocess.run(["git", "-C", MIRROR, "show", "HEAD:tests/Mooring/viv/" + f],
                              capture_output=True, text=True, check=True).stdout
        with open(os.path.join(folder, f), "w") as out:
            out.write(text)
    return os.path.join("Mooring", "viv", "viv.txt")


def crossing_frequency(t, x):
    """The mean frequency of x's upward crossings of its mean."""
    x = x - x.mean()
    ups = [t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
           for i in range(len(x) - 1) if x[i] < 0 <= x[i + 1]]
    return (len(ups) - 1) / (ups[-1] - ups[0])


def figures(t, tension, ys, wall):
    m = (t >= FROM - 1e-9) & (t <= DURATION + 1e-9)
    return {
        "frequency": crossing_frequency(t[m], tension[m]),
        "std": tension[m].std(),
        "rms": [ys[m, j].std() / D for j in range(len(NODES))],
        "wall": wall,
    }


def run_moordyn(deck):
    import moordyn
    start = time.time()
    s = moordyn.Create(deck)
    moordyn.Init(s, [], [])
    line = moordyn.GetLine(s, 1)
    dt, t, k = 1e-4, 0.0, 0
    rows = []
    while t < DURATION - 1e-9:
        moordyn.Step(s, [], [], t, dt)
        k += 1
        t = k * dt
        if k % 10 == 0:
            ys = [moordyn.GetLineNodePos(line, n)[1] for n in NODES]
            rows.append([t, moordyn.GetLineFairTen(line)] + ys)
    moordyn.Close(s)
    a = np.array(rows)
    return figures(a[:, 0], a[:, 1], a[:, 2:], time.time() - start)


def run_stancf(deck, dt):
    scenario = "run-%g.toml" % dt
    with open(scenario, "w") as f:
        f.write('[system]\nmoordyn = "%s"\n[analysis]\ntype = "dynamic"\nduration = %r\n'
                'time_step = %r\ntime_scheme = "galerkin"\n' % (deck, DURATION, dt))
    out = "out-%g" % dt
    start = time.time()
    p = subprocess.run([race.STANCF, "run", scenario, "--out", out, "--quiet"],
                       capture_output=True, text=True)
    wall = time.time() - start
    if p.returncode != 0:
        sys.exit("stancf failed: " + p.stderr)
    ten = np.genfromtxt(os.path.join(out, "tensions.csv"), delimiter=",", names=True,
                        dtype=None, encoding=None)
    top = ten[ten["end"] == "B"]
    t = np.array(top["t"], dtype=float)
    nodes = np.genfromtxt(os.path.join(out, "lines", "1", "nodes.csv"), delimiter=",",
                          names=True)
    ys = np.column_stack([nodes[nodes["node"] == n]["y"] for n in NODES])
    return figures(t, np.array(top["tension"], dtype=float), ys, wall)


def row(name, f):
    rms = " / ".join("%.3f" % r for r in f["rms"])
    return "| %s | %.4f | %.3f | %s | %.0f |" % (name, f["frequency"], f["std"], rms, f["wall"])


def main():
    cwd = os.getcwd()
    lines = [
        "| Code, step | Top tension frequency (Hz) | Its std (N) | Cross-flow RMS / D "
        "at nodes 25 / 50 / 75 | Wall (s) |",
        "|---|---|---|---|---|",
    ]
    with tempfile.TemporaryDirectory() as d:
        deck = write_deck(d)
        os.chdir(d)
        try:
            version = importlib.metadata.version("moordyn")
            lines.append(row("MoorDyn %s, RK4 dtM 1e-4 s" % version, run_moordyn(deck)))
            print(lines[-1], flush=True)
            for dt in STEPS:
                lines.append(row("stancf, Galerkin dt %g s" % dt, run_stancf(deck, dt)))
                print(lines[-1], flush=True)
        finally:
            os.chdir(cwd)
    lines.append("| published (Thorsen's riser, MoorDyn's test) | 2.08 | | | |")
    os.makedirs(os.path.join(HERE, "out"), exist_ok=True)
    with open(os.path.join(HERE, "out", "viv_check.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
