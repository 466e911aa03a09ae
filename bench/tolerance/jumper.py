#!/usr/bin/env python3
"""Steps chosen by a force tolerance against fixed steps on the jumper of
examples/jumper-tolerance.toml (docs/method.md §11.17): the largest error
of the top tension after the 27 s ramp against fixed Galerkin steps of
0.025 s, for tolerances 1e-2, 1e-3, 3e-4, 1e-4 (time_step 2 s) and fixed
steps of 0.25, 0.5 and 1 s, each with its steps, Newton iterations and
wall time (the whole `stancf run`). About a minute.

    cargo build --release -p stancf-cli && bench/tolerance/jumper.py
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
STANCF = os.environ.get("STANCF", os.path.join(ROOT, "target", "release", "stancf"))
EXAMPLE = os.path.join(ROOT, "examples", "jumper-tolerance.toml")
STEPPING = "time_step = 2.0\nforce_tolerance = 1e-3\n"
RAMP = 27.0


def scenario(dt, tolerance):
    """The example with its step `dt` and `tolerance` (None: fixed Galerkin
    steps writing the force at t, as the tolerance's runs do)."""
    text = open(EXAMPLE).read()
    if STEPPING not in text:
        sys.exit("examples/jumper-tolerance.toml no longer has %r" % STEPPING)
    if tolerance is not None:
        return text.replace(STEPPING, "time_step = %r\nforce_tolerance = %r\n" % (dt, tolerance))
    return (text.replace(STEPPING, "time_step = %r\ntime_scheme = \"galerkin\"\n" % dt)
            + "\n[output]\nend_forces = \"at_time\"\n")


def run(folder, name, dt, tolerance=None):
    """(top tension by time, summary, wall seconds)."""
    path = os.path.join(folder, name + ".toml")
    with open(path, "w") as f:
        f.write(scenario(dt, tolerance))
    out = os.path.join(folder, "out-" + name)
    t0 = time.perf_counter()
    p = subprocess.run([STANCF, "run", path, "--out", out, "--quiet"], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        sys.exit("%s failed: %s" % (name, p.stderr[-500:]))
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    top = {}
    with open(os.path.join(out, "points.csv")) as f:
        for r in csv.DictReader(f):
            if r["point"] == "2":
                top[round(float(r["t"]), 6)] = math.sqrt(sum(float(r[k]) ** 2 for k in ("fx", "fy", "fz")))
    return top, summary, wall


def main():
    with tempfile.TemporaryDirectory() as folder:
        reference, _, _ = run(folder, "reference", 0.025)
        after = [t for t in reference if t >= RAMP]
        largest = max(reference[t] for t in after)
        print("reference: fixed 0.025 s; top tension after the ramp %.1f kN, its range %.1f kN"
              % (largest / 1e3, (largest - min(reference[t] for t in after)) / 1e3))
        print("| run | largest error of the top tension | of the tension | steps kept (rejected) "
              "| Newton iterations | wall |")
        print("|---|---|---|---|---|---|")
        runs = [("tol %g" % tol, 2.0, tol) for tol in (1e-2, 1e-3, 3e-4, 1e-4)]
        runs += [("fixed %g s" % dt, dt, None) for dt in (0.25, 0.5, 1.0)]
        for label, dt, tol in runs:
            top, summary, wall = run(folder, label.replace(" ", "-"), dt, tol)
            error = max(abs(top[t] - reference[t]) for t in after if t in top)
            control = summary.get("step_control")
            steps = ("%d (%d)" % (control["steps"], control["rejected"]) if control
                     else str(summary["steps"]))
            print("| jumper, %s | %.0f N | %.3f %% | %s | %d | %.2f s |"
                  % (label, error, 100 * error / largest, steps, summary["iterations"], wall))


if __name__ == "__main__":
    main()
