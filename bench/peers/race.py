"""The race: stancf (P2 and Galerkin, SAC-2 and SAC-3) against Exudyn's
ANCFCable2D on the paper's pendulum and transverse impact, all on this
machine in one run. Writes out/work_precision.{csv,md,png}.

Run through ./run.sh (it makes the virtual environment and builds stancf);
`./run.sh --table` redoes the table and plot from out/work_precision.csv.
A run reaches an accuracy when it and every run of its series at a smaller
step are within it (a lucky hit of a non-monotone error does not count).

Errors:
- pendulum (no drag, 0.8 s): the largest distance of the tip from the
  Exudyn reference that stancf ships (data/reference/, 64 elements,
  dt = 1e-5, converged to ~0.005 mm) at the six report times;
- transverse impact (PVC, 10 m/s at both end nodes, 0.3 s): on fixed
  meshes of 16 and 32 elements, where stancf SAC-2 with 5 axial and 3
  bending Gauss points is the same spatial model as Exudyn's ANCFCable2D
  (the problem itself depends on the mesh: the initial velocity is given
  at the end nodes only), the distance of the tip at t = 0.02 s from a
  stancf Galerkin run at dt = 2.5e-6, Newton to 1e-13 (checked against
  dt = 5e-6); the
  energy drift over the whole 0.3 s. Only at 0.02 s because the motion is
  chaotic: two runs that differ by the Newton variant (both converged to
  1e-10) differ by 1.4e-9 m at 10 ms, 1.4e-6 m at 50 ms and 4.6e-3 m at
  80 ms (16 elements, dt = 1e-5), so a tip error of 0.01 mm means nothing
  later than a few hundredths of a second, for any code.
Wall times: Exudyn's SolveDynamic (not the Python model building), the
whole stancf process (parsing, set-up and writing results included); both
write the tip every 10 ms. Engineering strain for
both (Exudyn's only axial strain).
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

import exudyn_models as em

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
STANCF = os.path.join(ROOT, "target", "release", "stancf")
OUT = os.path.join(HERE, "out")
REPORT_TIMES = [0.19, 0.30, 0.42, 0.53, 0.67, 0.79]
# Impact: the tip is compared at 0.02 s (see the module documentation).
IMPACT_TIME = 0.02
# stancf's solver in the race: the factorized Jacobian kept across steps.
SOLVER = "modified-newton"
QUICK = "--quick" in sys.argv
# Only redo the table and plot from out/work_precision.csv.
TABLE_ONLY = "--table" in sys.argv


def reference_pendulum():
    ref = {}
    with open(os.path.join(ROOT, "data", "reference", "pendulum", "exudyn_nodrag_tip.csv")) as f:
        for row in csv.reader(f):
            if row[0].startswith("t"):
                continue
            ref[round(float(row[0]), 6)] = (float(row[1]), float(row[2]))
    return ref


PENDULUM = """
[cable]
length = 0.5
elements = {n}
element = "{element}"
[material]
youngs_modulus = 0.91e6
density = 1202.0
area = 1.075e-5
second_moment = 9.15e-12
[[constraints]]
type = "pinned"
node = "A"
[[loads]]
type = "gravity"
acceleration = [0.0, -9.81, 0.0]
[analysis]
time_step = {dt}
duration = 0.8
axial_strain = "engineering"
time_scheme = "{scheme}"
solver = "{solver}"
[output]
every = {every}
"""

IMPACT = """
[cable]
length = 4.0
elements = {n}
element = "{element}"
origin = [-2.0, 0.0, 0.0]
[material]
youngs_modulus = 3.4e9
density = 1380.0
area = 3.0e-6
second_moment = 1.25e-13
[[initial_velocity]]
node = "A"
velocity = [0.0, 10.0, 0.0]
[[initial_velocity]]
node = "B"
velocity = [0.0, -10.0, 0.0]
[analysis]
time_step = {dt}
duration = 0.3
quadrature = [5, 3, 3]
axial_strain = "engineering"
time_scheme = "{scheme}"
solver = "{solver}"
[output]
every = {every}
"""


def run_stancf(template, n, element, dt, scheme, solver=SOLVER, duration=None, tolerance=None):
    """(wall time, {t: tip}, summary) of a stancf run, or None if it failed."""
    every = max(1, int(round(0.01 / dt)))
    text = template.format(n=n, element=element, dt=repr(dt), scheme=scheme, solver=solver, every=every)
    if duration is not None:
        text = text.replace("duration = 0.3", "duration = %r" % duration)
    if tolerance is not None:
        text = text.replace("[analysis]", "[analysis]\ntolerance = %r" % tolerance)
    with tempfile.TemporaryDirectory() as d:
        sc = os.path.join(d, "s.toml")
        with open(sc, "w") as f:
            f.write(text)
        out = os.path.join(d, "out")
        t0 = time.perf_counter()
        p = subprocess.run([STANCF, "run", sc, "--out", out], capture_output=True, text=True)
        process_wall = time.perf_counter() - t0
        if p.returncode != 0:
            return None
        with open(os.path.join(out, "summary.json")) as f:
            s = json.load(f)
        tips = {}
        with open(os.path.join(out, "nodes.csv")) as f:
            for row in csv.DictReader(f):
                if int(row["node"]) == n:
                    tips[round(float(row["t"]), 6)] = (float(row["x"]), float(row["y"]))
    # The whole process (parsing, set-up, writing results): the time a
    # user waits, which is more than Exudyn's SolveDynamic alone; the
    # simulation's own time, as Exudyn's is timed, is summary.json's
    # `wall_time_s` (the time loop with its writing).
    return process_wall, tips, s


def max_error(tips, ref, times):
    """Largest tip distance (mm) from the reference at `times`."""
    try:
        return max(math.dist(tips[t], ref[t]) for t in times) * 1e3
    except KeyError:
        return float("nan")


def pendulum_error(tips, ref):
    return max_error(tips, ref, REPORT_TIMES)


def main():
    os.makedirs(OUT, exist_ok=True)
    rows = []
    ref = reference_pendulum()

    def record(problem, code, scheme, element, n, dt, wall, error, extra="", process=""):
        rows.append(dict(problem=problem, code=code, scheme=scheme, element=element, elements=n,
                         dt=dt, wall_s=wall, error_mm=error, note=extra, process_s=process))
        print("%-9s %-7s %-9s %-6s %3d %-8g %8.3f s  error %10.4g mm %s"
              % (problem, code, scheme, element, n, dt, wall, error, extra), flush=True)

    # ---- pendulum ----
    # Steps that divide 10 ms, so that every run hits the report times.
    steps_exu = [2e-3, 1e-3, 6.25e-4, 5e-4, 1e-2 / 30, 2.5e-4, 2e-4, 1.25e-4, 1e-4, 5e-5]
    meshes_exu = [8, 16, 32, 48, 64]
    if QUICK:
        steps_exu, meshes_exu = [5e-4, 1e-4], [16]
    for n in meshes_exu:
        for dt in steps_exu:
            wall, data = em.pendulum(n, dt)
            tips = {round(r[0], 6): (r[1], r[2]) for r in data}
            record("pendulum", "exudyn", "gen-alpha", "cable2d", n, dt, wall, pendulum_error(tips, ref))
    stancf_sets = [
        ("p2", "SAC-2", [4, 8, 16, 32], [1e-3, 5e-4, 2.5e-4, 1.25e-4]),
        ("p2", "SAC-3", [4, 8, 16], [5e-4, 2.5e-4, 1.25e-4, 6.25e-5]),
        ("galerkin", "SAC-2", [8, 16, 32, 48], [1e-2, 5e-3, 1e-2 / 3, 2.5e-3, 2e-3, 1e-3, 5e-4]),
        ("galerkin", "SAC-3", [8, 12, 16], [1e-2, 5e-3, 1e-2 / 3, 2.5e-3, 2e-3, 1e-3, 5e-4]),
    ]
    if QUICK:
        stancf_sets = [("galerkin", "SAC-3", [8], [1e-3])]
    for scheme, element, meshes, steps in stancf_sets:
        # Large Galerkin steps: modified Newton may need many chord steps,
        # so Newton runs too (the table takes the cheaper).
        solvers = [SOLVER, "newton"] if scheme == "galerkin" and not QUICK else [SOLVER]
        for n in meshes:
            for dt in steps:
              for solver in solvers:
                label = scheme if solver == SOLVER else scheme + "/" + solver
                r = run_stancf(PENDULUM, n, element, dt, scheme, solver=solver)
                if r is None:
                    record("pendulum", "stancf", label, element, n, dt, float("nan"), float("nan"), "unstable")
                    continue
                process, tips, s = r
                record("pendulum", "stancf", label, element, n, dt, s["wall_time_s"],
                       pendulum_error(tips, ref),
                       "%.2f it/step, %d tangents" % (s["iterations"]["mean_per_step"],
                                                      s["iterations"]["factorizations"]),
                       process)

    # ---- transverse impact ----
    # The problem is mesh-dependent by definition (10 m/s at the two end
    # nodes only: the struck mass is that of the end elements), so there is
    # no mesh-converged solution; it is compared on fixed meshes where
    # stancf's SAC-2 with 5 axial and 3 bending points is Exudyn's
    # ANCFCable2D (same shape functions, strain, curvature and quadrature):
    # the error is that of the time integration, against a stancf Galerkin
    # run at dt = 2.5e-6 on the same mesh (checked against dt = 5e-6 and
    # against Exudyn's finest step).
    meshes = [16, 32] if not QUICK else [8]
    # Steps that divide 10 ms (the output period).
    steps_exu = [1e-4, 6.25e-5, 5e-5, 4e-5, 3.125e-5, 2.5e-5, 2e-5, 1.25e-5, 1e-5, 6.25e-6, 5e-6, 2e-6] \
        if not QUICK else [5e-5]
    stancf_sets = [
        ("p2", [4e-5, 3.125e-5, 2.5e-5, 2e-5, 1e-5, 5e-6]),
        ("galerkin", [4e-4, 1e-2 / 30, 2.5e-4, 2e-4, 1.25e-4, 1e-4, 6.25e-5, 5e-5, 2.5e-5, 1.25e-5]),
    ] if not QUICK else [("galerkin", [1e-4])]
    for n in meshes:
        # Newton to 1e-13: the chaos amplifies solver round-off too.
        exact = dict(duration=IMPACT_TIME, solver="newton", tolerance=1e-13)
        ref = run_stancf(IMPACT, n, "SAC-2", 2.5e-6, "galerkin", **exact)
        check = run_stancf(IMPACT, n, "SAC-2", 5e-6, "galerkin", **exact)
        ref_tip = ref[1]
        print("impact reference, %d elements: dt 2.5e-6 vs 5e-6: %.3g mm"
              % (n, max_error(check[1], ref_tip, [IMPACT_TIME])), flush=True)
        for dt in steps_exu:
            wall, data = em.impact(n, dt)
            tips = {round(r[0], 6): (r[1], r[2]) for r in data}
            record("impact", "exudyn", "gen-alpha", "cable2d", n, dt, wall,
                   max_error(tips, ref_tip, [IMPACT_TIME]))
        for scheme, steps in stancf_sets:
            for dt in steps:
                r = run_stancf(IMPACT, n, "SAC-2", dt, scheme)
                if r is None:
                    record("impact", "stancf", scheme, "SAC-2", n, dt, float("nan"), float("nan"), "unstable")
                    continue
                process, tips, s = r
                record("impact", "stancf", scheme, "SAC-2", n, dt, s["wall_time_s"],
                       max_error(tips, ref_tip, [IMPACT_TIME]),
                       "energy drift %.1e, %.2f it/step, %d tangents" % (
                           s["energy"]["max_rel_drift"], s["iterations"]["mean_per_step"],
                           s["iterations"]["factorizations"]), process)

    write_outputs(rows)


def series_key(r):
    """A run's series: same problem, code, scheme, element and mesh."""
    return (r["problem"], r["code"], r["scheme"], r["element"], r["elements"])


def reaches(rows, r, acc):
    """The run is within `acc`, and so is every run of its series at a
    smaller step: a lucky hit of a non-monotone error does not count."""
    def ok(x):
        return x["error_mm"] == x["error_mm"] and x["error_mm"] <= acc
    return ok(r) and all(ok(x) for x in rows if series_key(x) == series_key(r) and x["dt"] < r["dt"])


def cheapest(rows, problem, code, acc, elements=None, key="wall_s"):
    """The cheapest run of `code` on `problem` (on `elements`, if given)
    that reaches `acc`, by `key`; None if none does."""
    ok = [r for r in rows if r["problem"] == problem and r["code"] == code
          and (elements is None or r["elements"] == elements) and reaches(rows, r, acc)]
    return min(ok, key=lambda r: r[key]) if ok else None


def write_outputs(rows):
    with open(os.path.join(OUT, "work_precision.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    lines = ["# The race: work-precision (this machine, one run)", "",
             "The simulation's time: Exudyn's `SolveDynamic`, stancf's time loop with its "
             "writing (summary.json's `wall_time_s`). The whole process: stancf's `run` "
             "from its start to its exit (reading, set-up, the steps, every file).", ""]

    def desc(r):
        if not r:
            return "not reached"
        return "%s %s %d el, dt %.4g (%.3g mm)" % (
            r["scheme"], r["element"], r["elements"], r["dt"], r["error_mm"])

    # The pendulum has a mesh-converged solution: any mesh may win. The
    # impact depends on the mesh: the same mesh for both codes.
    groups = [("pendulum", None)] + [
        ("impact", n) for n in sorted({r["elements"] for r in rows if r["problem"] == "impact"})]
    for problem, elements in groups:
        lines.append("## %s" % (problem if elements is None else "%s, %d elements" % (problem, elements)))
        lines.append("")
        lines.append("| accuracy | Exudyn cheapest (s) | run | stancf cheapest (s) | run "
                     "| Exudyn / stancf | stancf's whole process (s) | Exudyn / stancf's process |")
        lines.append("|---|---|---|---|---|---|---|---|")
        for acc in [0.1, 0.01]:
            e = cheapest(rows, problem, "exudyn", acc, elements)
            st = cheapest(rows, problem, "stancf", acc, elements)
            sp = cheapest(rows, problem, "stancf", acc, elements, key="process_s")
            ratio = "%.2f" % (e["wall_s"] / st["wall_s"]) if e and st else "-"
            ratio_p = "%.2f" % (e["wall_s"] / sp["process_s"]) if e and sp else "-"
            lines.append("| %g mm | %s | %s | %s | %s | %s | %s | %s |" % (
                acc, "%.3f" % e["wall_s"] if e else "-", desc(e), "%.3f" % st["wall_s"] if st else "-",
                desc(st), ratio, "%.3f" % sp["process_s"] if sp else "-", ratio_p))
        lines.append("")
    with open(os.path.join(OUT, "work_precision.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axes = plt.subplots(1, 2, figsize=(13, 8))
        for ax, problem in zip(axes, ["pendulum", "impact"]):
            series = {}
            for r in rows:
                if r["problem"] != problem or not (r["error_mm"] == r["error_mm"]):
                    continue
                key = "Exudyn ANCFCable2D (gen.-alpha), %d el" % r["elements"] if r["code"] == "exudyn" \
                    else "stancf %s %s, %d el" % (r["scheme"], r["element"], r["elements"])
                series.setdefault(key, []).append((r["wall_s"], max(r["error_mm"], 1e-6)))
            for key, pts in sorted(series.items()):
                pts.sort()
                style = "o--" if key.startswith("Exudyn") else ("s-" if "galerkin" in key else "^-")
                ax.loglog([p[0] for p in pts], [p[1] for p in pts], style, ms=4, lw=1, label=key)
            for acc in [0.1, 0.01]:
                ax.axhline(acc, color="grey", lw=0.8, ls=":")
            ax.set_xlabel("simulation's wall time (s)")
            ax.set_ylabel("tip error (mm)")
            ax.set_title({"pendulum": "Pendulum, 0.8 s: largest tip error at the report times",
                          "impact": "Transverse impact, 0.3 s: tip error at 0.02 s (same mesh)"}[problem], fontsize=10)
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize=6, ncol=2, loc="upper center", bbox_to_anchor=(0.5, -0.1))
        fig.tight_layout()
        fig.savefig(os.path.join(OUT, "work_precision.png"), dpi=130)
    except ImportError:
        print("matplotlib not installed: no plot")


def read_rows():
    with open(os.path.join(OUT, "work_precision.csv")) as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in ["elements"]:
            r[k] = int(r[k])
        for k in ["dt", "wall_s", "error_mm"]:
            r[k] = float(r[k])
        r["process_s"] = float(r["process_s"]) if r.get("process_s") else ""
    return rows


if __name__ == "__main__":
    t0 = time.perf_counter()
    if TABLE_ONLY:
        write_outputs(read_rows())
        sys.exit(0)
    main()
    print("race took %.0f s" % (time.perf_counter() - t0))
