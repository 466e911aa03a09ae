#!/usr/bin/env python3
"""The farm at scale (issue 33, "Scale"): 30 OC4 DeepCwind platforms in a
5 x 6 grid 1600 m apart in 200 m of water, each on its three catenary
chains (the OC4 deck's chain and anchors), and 10 shared chains between
neighbours in a row: 100 lines of 50 SAC-2 elements, 5 000 elements.
Every platform surges 2 m and heaves 1 m at a 20 s period, ramped in
over one period, its phase that of a deep-water wave of that period
passing along x (wavelength 624.5 m). Solved for 60 s in Galerkin steps
of 0.5 s from the static equilibrium, with the race's solver (modified
Newton), through `stancf run`.

The claim it measures: the cost per element per step of the farm within
1.2 times that of a single 50-element chain of the same type under the
same motion and steps, and what the two cores give (the farm's lines end
at coupled points, so they are solved apart, on rayon's threads:
`system/apart.rs`). Each configuration is run `--repeat` times,
alternating, and the medians of summary.json's `stepping_wall_time_s`
(the steps alone, after the static solve) are compared; one run, this
machine, as the races are reported.

    bench/farm/farm.py [--stancf target/release/stancf] [--repeat 3] [--out docs/race/farm.md]
"""

import argparse
import datetime
import json
import math
import os
import statistics
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

DEPTH = 200.0
FAIRLEAD_RADIUS, FAIRLEAD_Z = 40.868, -14.0
ANCHOR_RADIUS = 837.6
ANCHOR_ANGLES = (180.0, 60.0, -60.0)
LENGTH = 835.35
SPACING = 1600.0
ROWS, COLUMNS, SHARED = 5, 6, 10
SHARED_LENGTH = 1560.0
ELEMENTS = 50
PERIOD, SURGE, HEAVE = 20.0, 2.0, 1.0
WAVELENGTH = 9.81 * PERIOD ** 2 / (2.0 * math.pi)
DT, DURATION = 0.5, 60.0

HEAD = """title = "{title}"

[system]
gravity = [0.0, 0.0, -9.81]

[[line_types]]
name = "chain"              # the OC4 DeepCwind deck's
diameter = 0.0766
mass_per_length = 113.35
ea = 7.536e8
ba = -1.0
ei = 0.0
cd = 2.0
ca = 0.8
cdax = 0.4
caax = 0.25

[water]
depth = {depth}
density = 1025.0

[water.seabed]
stiffness = 3.0e6
damping = 3.0e5
"""

TAIL = """
[analysis]
type = "dynamic"
initial = "static"
time_step = {dt}
duration = {duration}
time_scheme = "galerkin"
solver = "modified-newton"

[output]
every = 20
files = ["tensions.csv"]
"""


def on_circle(centre, radius, angle, z):
    a = math.radians(angle)
    return [centre[0] + radius * math.cos(a), centre[1] + radius * math.sin(a), z]


class Writer:
    """Points, lines and motions of a scenario, numbered as they come."""

    def __init__(self):
        self.points, self.lines, self.motions = [], [], []

    def point(self, kind, position):
        self.points.append((kind, position))
        return len(self.points)

    def line(self, a, b, length):
        self.lines.append((a, b, length))

    def move(self, point, phase):
        self.motions.append((point, phase))

    def text(self, title):
        out = [HEAD.format(title=title, depth=DEPTH)]
        for i, (kind, r) in enumerate(self.points, 1):
            out.append('[[points]]\nid = %d\ntype = "%s"\nposition = [%r, %r, %r]\n'
                       % (i, kind, r[0], r[1], r[2]))
        for i, (a, b, length) in enumerate(self.lines, 1):
            out.append('[[lines]]\nid = %d\ntype = "chain"\nlength = %r\nelements = %d\n'
                       'a = %d\nb = %d\n' % (i, length, ELEMENTS, a, b))
        for point, phase in self.motions:
            out.append("[[motions]]\npoint = %d\namplitude = [%r, 0.0, %r]\nperiod = %r\n"
                       "phase = %r\nramp = %r\n" % (point, SURGE, HEAVE, PERIOD, phase, PERIOD))
        out.append(TAIL.format(dt=DT, duration=DURATION))
        return "\n".join(out)


def platform(w, centre):
    """A platform's three chains; its fairleads (coupled points) move with
    the wave's phase at its centre. Returns the fairleads by angle."""
    phase = -360.0 * (centre[0] / WAVELENGTH % 1.0)
    fairleads = {}
    for angle in ANCHOR_ANGLES:
        anchor = w.point("fixed", on_circle(centre, ANCHOR_RADIUS, angle, -DEPTH))
        fairlead = w.point("coupled", on_circle(centre, FAIRLEAD_RADIUS, angle, FAIRLEAD_Z))
        w.move(fairlead, phase)
        w.line(anchor, fairlead, LENGTH)
        fairleads[angle] = fairlead
    return fairleads, phase


def farm():
    w = Writer()
    grid = {}
    for r in range(ROWS):
        for c in range(COLUMNS):
            grid[(r, c)] = (c * SPACING, r * SPACING)
    fairleads = {rc: platform(w, centre) for rc, centre in grid.items()}
    pairs = [((r, c), (r, c + 1)) for r in range(ROWS) for c in range(COLUMNS - 1)][:SHARED]
    for a, b in pairs:
        # A fourth fairlead on a's side facing b, to b's fairlead at 180 deg.
        shared = w.point("coupled", on_circle(grid[a], FAIRLEAD_RADIUS, 0.0, FAIRLEAD_Z))
        w.move(shared, fairleads[a][1])
        w.line(shared, fairleads[b][0][180.0], SHARED_LENGTH)
    return w.text("a farm: 30 OC4 platforms, 90 chains and 10 shared"), len(w.lines)


def single():
    """The farm's first chain alone (the platform at the origin, its chain
    at 180 deg, along the surge: the most loaded of the three)."""
    w = Writer()
    platform(w, (0.0, 0.0))
    w.lines = w.lines[:1]
    w.points = w.points[:2]
    w.motions = w.motions[:1]
    return w.text("one OC4 chain of the farm"), 1


def one_platform():
    """The farm's first platform alone: its three chains."""
    w = Writer()
    platform(w, (0.0, 0.0))
    return w.text("one OC4 platform of the farm"), 3


def run(stancf, scenario, threads, folder):
    out = os.path.join(folder, "out-%d" % threads)
    env = dict(os.environ, RAYON_NUM_THREADS=str(threads))
    p = subprocess.run([stancf, "run", scenario, "--out", out, "--quiet", "--allow-large"],
                       capture_output=True, text=True, env=env)
    if p.returncode != 0:
        raise SystemExit("%s failed (%d): %s" % (scenario, p.returncode, p.stderr))
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return s["stepping_wall_time_s"], s["steps"], s["wall_time_s"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--stancf", default=os.path.join(ROOT, "target", "release", "stancf"))
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--out", default=os.path.join(ROOT, "docs", "race", "farm.md"))
    args = ap.parse_args()
    with tempfile.TemporaryDirectory() as d:
        runs = {}
        for name, (text, lines) in (("single", single()), ("platform", one_platform()),
                                    ("farm", farm())):
            path = os.path.join(d, name + ".toml")
            with open(path, "w") as f:
                f.write(text)
            runs[name] = (path, lines)
        times = {k: [] for k in ("single 1", "platform 1", "farm 1", "farm 2")}
        whole = {k: [] for k in times}
        steps = {}
        for _ in range(args.repeat):
            for key in times:
                name, threads = key.split()
                stepping, n, wall = run(args.stancf, runs[name][0], int(threads), d)
                times[key].append(stepping)
                whole[key].append(wall)
                steps[key] = n
                print("%-9s %.3f s stepping, %.3f s in all" % (key, stepping, wall), flush=True)
    elements = {k: ELEMENTS * runs[k.split()[0]][1] for k in times}
    median = {k: statistics.median(v) for k, v in times.items()}
    per = {k: 1e6 * median[k] / (elements[k] * steps[k]) for k in times}
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    rows = [
        "| run | threads | elements | steps | stepping (median of %d, s) | whole run (median, s) "
        "| per element and step (us) | against the single chain |" % args.repeat,
        "|---|---|---|---|---|---|---|---|",
    ]
    for key, label in (("single 1", "one chain (along the surge)"),
                       ("platform 1", "one platform (3 chains)"), ("farm 1", "the farm"),
                       ("farm 2", "the farm")):
        rows.append("| %s | %s | %d | %d | %.3f | %.3f | %.2f | %.2f |" % (
            label, key.split()[1], elements[key], steps[key], median[key],
            statistics.median(whole[key]), per[key], per[key] / per["single 1"]))
    speedup = median["farm 1"] / median["farm 2"]
    text = "\n".join([
        "# The farm at scale",
        "",
        "`bench/farm/farm.py --repeat %d`, %s, commit %s, this machine (2 cores, shared)."
        % (args.repeat, datetime.date.today().isoformat(), commit),
        "",
        "30 OC4 DeepCwind platforms (5 x 6, 1600 m apart, 200 m of water), 90 chains "
        "and 10 shared chains between neighbours, 50 SAC-2 elements each; every platform "
        "surging 2 m and heaving 1 m at 20 s with a wave's phase; 60 s in Galerkin steps "
        "of 0.5 s after the static equilibrium, modified Newton. The single chain is the "
        "farm's first, alone, under the same motion: the chain along the surge, the most "
        "loaded of a platform's three; one platform is its three chains.",
        "",
    ] + rows + [
        "",
        "The farm on two threads against one: **%.2fx**." % speedup,
        "",
    ])
    with open(args.out, "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main()
