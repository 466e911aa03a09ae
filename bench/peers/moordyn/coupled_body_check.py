"""The coupled OC4 platform body through stancf's C library against MoorDyn
2.7 (issue 30's check; CI does not run it).

The deck: examples/oc4-deepcwind-moordyn.txt with a BODIES section holding
one `Coupled` body at the origin (angles 0) and its three fairleads as
`Body1` points (their coordinates as they are: the body sits at the origin
unrotated). At each pose below the body is held still (velocities 0) and
the lines settle:

- stancf: through libstancf_c (ctypes, target/release/libstancf_c.so):
  `stancf_create` on a TOML scenario that takes the deck
  (`[system] moordyn = ...`) with `[[mesh]] elements = N` on the three
  lines, `stancf_init(x = the pose, xd = 0)` (the static equilibrium with
  the body there), then one `stancf_step` of 1e-6 s at the same pose, whose
  f is the lines' force on the body and their moment about its reference
  point (global axes). The step is there because stancf_init writes no
  forces; 1e-6 s from an equilibrium moves nothing measurable (the
  script checks the force against a second step of 1e-5 s).
- MoorDyn 2.7 (the Python package): a copy of the deck with NumSegs N,
  TmaxIC 1000 s and threshIC 1e-5 (the deck's 60 s and 0.01 are loose),
  `moordyn.Init(x, 0)` (its initial-condition solver, the body held at x),
  then GetBodyForce (equal to what `moordyn.Step` returns for the body).
- A closed form: each line's elastic catenary on a flat frictionless bed
  (its wet weight, EA, unstretched length), solved for the fairlead where
  the pose puts it: the N -> infinity limit of both codes, but for the
  seabed's penetration (a few mm at kBot 3e6 Pa/m), which it leaves out.

x is the body's six numbers as MoorDyn takes them: the reference point (m)
and roll, pitch, yaw in radians, R = R_x R_y R_z (the script checks both
codes' fairlead positions against that matrix). The refinement: N = 20
(the deck's), 40, 80, 160 in both codes (stancf also 320). Results:
out/coupled_body/coupled_body_check.{md,csv}; scratch (the deck copies,
MoorDyn's .out files) in out/coupled_body/scratch/.

    ./run.sh --coupled-body-check            (or .venv/bin/python coupled_body_check.py)
    ./run.sh --coupled-body-check --quick    (N = 20 and 40 only)
    ./run.sh --coupled-body-check --tables-only  (rewrites the .md from the
        .csv and out/coupled_body/coupled_body_checks.json)
    ./run.sh --coupled-body-check --one "surge -10 m" 320  (both codes at one
        pose and one N; MoorDyn takes about 5 minutes there)
    ./run.sh --coupled-body-check --ic-check (MoorDyn's threshIC 1e-5 against
        1e-7 at N = 80 on two poses, about 5 minutes; stancf's forces from
        stancf_point_state after stancf_init against the step's)

About 18 minutes on the 2-core machine (shared with another run), nearly
all of it MoorDyn's initial-condition solver: 15 to 40 s a pose at N = 80,
80 to 120 s at N = 160; stancf's solves take under 2 s each.
"""
import csv
import ctypes
import json
import math
import os
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
DECK = os.path.join(ROOT, "examples", "oc4-deepcwind-moordyn.txt")
OUT = os.path.join(HERE, "out", "coupled_body")
SCRATCH = os.path.join(OUT, "scratch")
LIB = os.path.join(ROOT, "target", "release", "libstancf_c.so")

# name, (x, y, z, roll, pitch, yaw) with the angles in degrees
POSES = [
    ("rest", (0, 0, 0, 0, 0, 0)),
    ("surge +10 m", (10, 0, 0, 0, 0, 0)),
    ("surge -10 m", (-10, 0, 0, 0, 0, 0)),
    ("sway 8 m", (0, 8, 0, 0, 0, 0)),
    ("heave -3 m", (0, 0, -3, 0, 0, 0)),
    ("pitch 5 deg", (0, 0, 0, 0, 5, 0)),
    ("yaw 10 deg", (0, 0, 0, 0, 0, 10)),
    ("surge 6 m, roll 3 deg, yaw -8 deg", (6, 0, 0, 3, 0, -8)),
]
THRESH_IC, TMAX_IC = 1e-5, 1000.0
FAIR_RADIUS = 40.868  # m: the fairleads' distance from the body's axis

# The deck's lines (for the closed form): chain, and the points.
L_UNSTR, EA, DIAM, MASS, G, RHO = 835.35, 7.536e8, 0.0766, 113.35, 9.81, 1025.0
ANCHORS = np.array([[-837.6, 0.0, -200.0], [418.8, 725.383, -200.0], [418.8, -725.383, -200.0]])
FAIRLEADS = np.array([[-40.868, 0.0, -14.0], [20.434, 35.393, -14.0], [20.434, -35.393, -14.0]])

BODIES = """-------------------------------- BODIES ----------------------------------------
ID  Attachment  X0   Y0   Z0   r0     p0     y0     Mass  CG   I         Volume  CdA    Ca
(#) (-)         (m)  (m)  (m)  (deg)  (deg)  (deg)  (kg)  (m)  (kg-m^2)  (m^3)   (m^2)  (-)
1   Coupled     0.0  0.0  0.0  0.0    0.0    0.0    0     0    0         0       0      0
"""


def rotation(roll, pitch, yaw):
    """MoorDyn's R = R_x(roll) R_y(pitch) R_z(yaw) (radians)."""
    cr, sr, cp, sp, cy, sy = (math.cos(roll), math.sin(roll), math.cos(pitch), math.sin(pitch),
                              math.cos(yaw), math.sin(yaw))
    rx = np.array([[1, 0, 0], [0, cr, -sr], [0, sr, cr]])
    ry = np.array([[cp, 0, sp], [0, 1, 0], [-sp, 0, cp]])
    rz = np.array([[cy, -sy, 0], [sy, cy, 0], [0, 0, 1]])
    return rx @ ry @ rz


def pose_x(pose):
    """The body's six numbers as both codes take them (angles in radians)."""
    return [float(pose[0]), float(pose[1]), float(pose[2])] + [math.radians(a) for a in pose[3:]]


def fairleads_at(x):
    return np.array(x[:3]) + FAIRLEADS @ rotation(*x[3:]).T


def body_deck(segments, tmax_ic=None, thresh_ic=None):
    """The OC4 deck with the coupled body, NumSegs `segments`; TmaxIC and
    threshIC replaced where given."""
    out = []
    for line in open(DECK).read().splitlines():
        w = line.split()
        if line.startswith("---") and "POINTS" in line:
            out.append(BODIES.rstrip("\n"))
        if len(w) >= 2 and w[1] == "Coupled":
            w[1] = "Body1"
            line = "  ".join(w)
        if len(w) == 7 and w[1] == "chain" and w[0] in ("1", "2", "3"):
            w[5] = str(segments)
            line = "  ".join(w)
        if len(w) >= 2 and w[1] == "TmaxIC" and tmax_ic is not None:
            line = "%g  TmaxIC" % tmax_ic
        if len(w) >= 2 and w[1] == "threshIC" and thresh_ic is not None:
            line = "%g  threshIC" % thresh_ic
        out.append(line)
    return "\n".join(out) + "\n"


# ---------------------------------------------------------------- stancf (C)
class Stancf:
    def __init__(self):
        lib = ctypes.CDLL(LIB)
        vp, dp = ctypes.c_void_p, ctypes.POINTER(ctypes.c_double)
        lib.stancf_create.restype = vp
        lib.stancf_create.argtypes = [ctypes.c_char_p]
        lib.stancf_error_message.restype = ctypes.c_char_p
        lib.stancf_ncoupled_dof.argtypes = [vp, ctypes.POINTER(ctypes.c_uint)]
        lib.stancf_coupled_body_ids.argtypes = [vp, ctypes.POINTER(ctypes.c_int64)]
        lib.stancf_init.argtypes = [vp, dp, dp]
        lib.stancf_step.argtypes = [vp, dp, dp, dp, dp, dp]
        lib.stancf_npoints.argtypes = [vp, ctypes.POINTER(ctypes.c_uint)]
        lib.stancf_point_id.argtypes = [vp, ctypes.c_uint, ctypes.POINTER(ctypes.c_int64)]
        lib.stancf_point_state.argtypes = [vp, ctypes.c_uint, dp, dp, dp]
        lib.stancf_close.argtypes = [vp]
        self.lib = lib

    def check(self, rc, what):
        if rc != 0:
            raise RuntimeError("%s: %d %s" % (what, rc, self.lib.stancf_error_message().decode()))

    def forces(self, path, x, dts=(1e-6,)):
        """Opens path, stancf_init at pose x (velocities 0), then for each dt
        in dts a fresh stancf_init and one stancf_step of dt at the same
        pose: the six numbers f of each, the fairleads' positions (ids 4, 5,
        6) and the wall time of the first init and step."""
        lib, c_d = self.lib, ctypes.c_double
        s = lib.stancf_create(path.encode())
        if not s:
            raise RuntimeError("stancf_create: " + lib.stancf_error_message().decode())
        try:
            n = ctypes.c_uint()
            self.check(lib.stancf_ncoupled_dof(s, ctypes.byref(n)), "ncoupled_dof")
            assert n.value == 6, n.value
            ids = (ctypes.c_int64 * 1)()
            self.check(lib.stancf_coupled_body_ids(s, ids), "coupled_body_ids")
            assert ids[0] == 1
            X, V = (c_d * 6)(*x), (c_d * 6)()
            res, wall = [], None
            for dt in dts:
                t0 = time.time()
                self.check(lib.stancf_init(s, X, V), "stancf_init")
                F, t, d = (c_d * 6)(), c_d(0.0), c_d(dt)
                self.check(lib.stancf_step(s, X, V, F, ctypes.byref(t), ctypes.byref(d)), "stancf_step")
                if wall is None:
                    wall = time.time() - t0
                    npts = ctypes.c_uint()
                    self.check(lib.stancf_npoints(s, ctypes.byref(npts)), "npoints")
                    pos = {}
                    for k in range(npts.value):
                        pid, p = ctypes.c_int64(), (c_d * 3)()
                        self.check(lib.stancf_point_id(s, k, ctypes.byref(pid)), "point_id")
                        self.check(lib.stancf_point_state(s, k, p, None, None), "point_state")
                        pos[pid.value] = np.array(p[:])
                res.append(np.array(F[:]))
            return res, np.array([pos[i] for i in (4, 5, 6)]), wall
        finally:
            lib.stancf_close(s)


def stancf_scenario(deck_name, segments):
    return ("# the coupled OC4 body deck at %d elements a line (coupled_body_check.py)\n"
            "[system]\nmoordyn = \"%s\"\n\n"
            "[analysis]\ntype = \"dynamic\"\ninitial = \"static\"\ntime_step = 0.001\nduration = 1.0\n\n"
            "[[mesh]]\nlines = [1, 2, 3]\nelements = %d\n"
            % (segments, deck_name, segments))


# ------------------------------------------------------------------ MoorDyn
def quiet(fn, *args):
    """fn(*args) with the process's stdout sent to /dev/null (MoorDyn's
    banner is printed by Create and Init from C)."""
    sys.stdout.flush()
    saved = os.dup(1)
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, 1)
    try:
        return fn(*args)
    finally:
        os.dup2(saved, 1)
        os.close(null)
        os.close(saved)


def moordyn_forces(path, x):
    """MoorDyn's initial-condition solve with the body held at x; the body's
    force and moment (GetBodyForce, and what a Step of 1e-6 s returns for
    it), the fairleads' positions and the wall time of Init."""
    import moordyn
    s = quiet(moordyn.Create, path)
    moordyn.SetVerbosity(s, moordyn.LEVEL_NONE)
    t0 = time.time()
    err = quiet(moordyn.Init, s, list(x), [0.0] * 6)
    wall = time.time() - t0
    if err:
        raise RuntimeError("MoorDyn Init: %s" % err)
    b = moordyn.GetBody(s, 1)
    f = np.array(moordyn.GetBodyForce(b))
    pts = np.array([moordyn.GetPointPos(moordyn.GetPoint(s, i)) for i in (4, 5, 6)])
    f_step = np.array(quiet(moordyn.Step, s, list(x), [0.0] * 6, 0.0, 1e-6))
    moordyn.Close(s)
    return f, f_step, pts, wall


# --------------------------------------------------------------- closed form
def catenary(xf, zf):
    """Horizontal and vertical fairlead force (H, V) of the chain anchored on
    a flat frictionless bed, span xf, height zf: the elastic catenary
    resting on the bed where V < w L, else hanging whole (MoorPy's and
    MAP's equations with CB = 0)."""
    from scipy.optimize import fsolve
    w = (MASS - RHO * math.pi / 4 * DIAM ** 2) * G
    L = L_UNSTR

    def eq(p):
        h, v = math.exp(p[0]), math.exp(p[1])
        if v < w * L:
            x = L - v / w + h / w * math.asinh(v / h) + h * L / EA
            z = h / w * (math.sqrt(1 + (v / h) ** 2) - 1) + v * v / (2 * EA * w)
        else:
            va = v - w * L
            x = h / w * (math.asinh(v / h) - math.asinh(va / h)) + h * L / EA
            z = (h / w * (math.sqrt(1 + (v / h) ** 2) - math.sqrt(1 + (va / h) ** 2))
                 + (v * L - w * L * L / 2) / EA)
        return [x / xf - 1.0, z / zf - 1.0]

    sol = fsolve(eq, [math.log(1e6), math.log(1.2e6)], xtol=1e-13)
    res = np.abs(eq(sol)).max()
    assert res < 1e-10, res
    return math.exp(sol[0]), math.exp(sol[1])


def closed_form(x):
    ref = np.array(x[:3])
    F, M = np.zeros(3), np.zeros(3)
    for a, f in zip(ANCHORS, fairleads_at(x)):
        dxy = a[:2] - f[:2]
        xf = float(np.linalg.norm(dxy))
        h, v = catenary(xf, f[2] - a[2])
        fi = np.array([h * dxy[0] / xf, h * dxy[1] / xf, -v])
        F += fi
        M += np.cross(f - ref, fi)
    return np.concatenate([F, M])


# ------------------------------------------------------------------- report
def rel(a, b, scale=None):
    """|a - b| over |b| of the force (first 3) and of the moment (last 3);
    the moment over `scale` where given."""
    rf = np.linalg.norm(a[:3] - b[:3]) / np.linalg.norm(b[:3])
    rm = np.linalg.norm(a[3:] - b[3:]) / (scale if scale else np.linalg.norm(b[3:]))
    return rf, rm


def moment_scale(ref):
    """|M| of the reference, or |F| times the fairlead radius where the
    moment is zero by symmetry (below 0.1 % of that: the rest and heave
    poses, where it is below 1e-6 of it)."""
    m, f = np.linalg.norm(ref[3:]), np.linalg.norm(ref[:3]) * FAIR_RADIUS
    return (m, False) if m > 1e-3 * f else (f, True)


def fmt6(v):
    return "(%s)" % ", ".join("%.1f" % (e / 1e3) for e in v)


def ic_check(segments=80, poses=(1, 7), thresholds=(1e-5, 1e-7)):
    """MoorDyn's equilibrium against its initial-condition threshold: the
    body's force and moment at threshIC 1e-5 (the check's) and 1e-7, N =
    80, two poses; and stancf's equilibrium read without a step (the sum
    of stancf_point_state's forces of the fairleads after stancf_init,
    their moment about the reference point) against the step's f."""
    os.makedirs(SCRATCH, exist_ok=True)
    stancf = Stancf()
    for k in poses:
        pname, pose = POSES[k]
        x = pose_x(pose)
        got = []
        for th in thresholds:
            path = os.path.join(SCRATCH, "oc4_body_%d_ic%g.txt" % (segments, th))
            with open(path, "w") as fh:
                fh.write(body_deck(segments, TMAX_IC, th))
            f, _, _, wall = moordyn_forces(path, x)
            got.append(f)
            print("MoorDyn N=%d threshIC %g %-34s F=%s (%.1f s)" % (segments, th, pname, fmt6(f), wall),
                  flush=True)
        rf, rm = rel(got[-1], got[0])
        print("  threshIC %g against %g: dF/F %.2e, dM/M %.2e" % (thresholds[-1], thresholds[0], rf, rm))
        path = os.path.join(SCRATCH, "oc4_body_%d_ic%g.txt" % (segments, thresholds[0]))
        (f_step,), _, _ = stancf.forces(path, x)
        f_pts = stancf_point_sum(stancf, path, x)
        print("  stancf N=%d: the sum of stancf_point_state after stancf_init against the step's f: "
              "dF/F %.1e, dM/M %.1e" % ((segments,) + rel(f_pts, f_step)))


def stancf_point_sum(stancf, path, x):
    """The fairleads' (ids 4, 5, 6) forces from stancf_point_state right
    after stancf_init, summed, and their moment about the reference point."""
    lib, c_d = stancf.lib, ctypes.c_double
    s = lib.stancf_create(path.encode())
    try:
        X, V = (c_d * 6)(*x), (c_d * 6)()
        stancf.check(lib.stancf_init(s, X, V), "stancf_init")
        npts = ctypes.c_uint()
        stancf.check(lib.stancf_npoints(s, ctypes.byref(npts)), "npoints")
        out = np.zeros(6)
        for k in range(npts.value):
            pid, p, f = ctypes.c_int64(), (c_d * 3)(), (c_d * 3)()
            stancf.check(lib.stancf_point_id(s, k, ctypes.byref(pid)), "point_id")
            stancf.check(lib.stancf_point_state(s, k, p, None, f), "point_state")
            if pid.value in (4, 5, 6):
                out[:3] += f[:]
                out[3:] += np.cross(np.array(p[:]) - np.array(x[:3]), np.array(f[:]))
        return out
    finally:
        lib.stancf_close(s)


def one(pname, segments):
    """Both codes at one pose and one refinement (`--one "surge -10 m" 320`):
    the six numbers and their differences (MoorDyn at 320 segments takes
    about 5 minutes a pose)."""
    os.makedirs(SCRATCH, exist_ok=True)
    pose = dict(POSES)[pname]
    x = pose_x(pose)
    path = os.path.join(SCRATCH, "oc4_body_%d.txt" % segments)
    with open(path, "w") as fh:
        fh.write(body_deck(segments, TMAX_IC, THRESH_IC))
    (fs,), _, ws = Stancf().forces(path, x)
    fm, _, _, wm = moordyn_forces(path, x)
    scale = moment_scale(fm)[0]
    print("%s, N = %d (N, N m)\n  stancf  (%s) (%.2f s)\n  MoorDyn (%s) (%.1f s)\n  dF/F %.4f %%, dM/M %.4f %%" % (
        (pname, segments, ", ".join("%.1f" % v for v in fs), ws, ", ".join("%.1f" % v for v in fm), wm)
        + tuple(100 * v for v in rel(fs, fm, scale))))


def main(argv):
    if "--ic-check" in argv:
        return ic_check()
    if "--one" in argv:
        k = argv.index("--one")
        return one(argv[k + 1], int(argv[k + 2]))
    if "--tables-only" in argv:
        return tables_only()
    quick = "--quick" in argv
    md_levels = [20, 40] if quick else [20, 40, 80, 160]
    st_levels = [20, 40] if quick else [20, 40, 80, 160, 320]
    os.makedirs(SCRATCH, exist_ok=True)
    stancf = Stancf()
    rows = []  # (pose, code, segments, 6 forces, wall)
    checks = []
    t_start = time.time()
    for segments in sorted(set(md_levels) | set(st_levels)):
        name = "oc4_body_%d.txt" % segments
        path = os.path.join(SCRATCH, name)
        with open(path, "w") as fh:
            fh.write(body_deck(segments, TMAX_IC, THRESH_IC))
        toml = os.path.join(SCRATCH, "oc4_body_mesh_%d.toml" % segments)
        with open(toml, "w") as fh:
            # stancf takes the deck's NumSegs 20 and refines through [[mesh]]
            fh.write(stancf_scenario("oc4_body_20.txt", segments))
        for pname, pose in POSES:
            x = pose_x(pose)
            expect = fairleads_at(x)
            if segments in st_levels:
                (f, f2), pos, wall = stancf.forces(toml, x, dts=(1e-6, 1e-5))
                rows.append((pname, "stancf", segments, f, wall))
                checks.append(("stancf", pname, segments, float(np.abs(pos - expect).max()),
                               rel(f2, f, np.linalg.norm(f[:3]) * FAIR_RADIUS)))
                print("stancf  N=%-3d %-34s F=%s kN, kN m  (%.2f s)" % (segments, pname, fmt6(f), wall),
                      flush=True)
            if segments in md_levels:
                f, f_step, pos, wall = moordyn_forces(path, x)
                rows.append((pname, "MoorDyn", segments, f, wall))
                checks.append(("MoorDyn", pname, segments, float(np.abs(pos - expect).max()),
                               rel(f_step, f, np.linalg.norm(f[:3]) * FAIR_RADIUS)))
                print("MoorDyn N=%-3d %-34s F=%s kN, kN m  (%.1f s)" % (segments, pname, fmt6(f), wall),
                      flush=True)
    # the check's own stancf input at the deck's NumSegs without [[mesh]]: the same numbers
    (f_deck,), _, _ = stancf.forces(os.path.join(SCRATCH, "oc4_body_20.txt"), pose_x(POSES[-1][1]))
    f_mesh = [r[3] for r in rows if r[:3] == (POSES[-1][0], "stancf", 20)][0]
    deck_vs_mesh = float(np.abs(f_deck - f_mesh).max())
    closed = {pname: closed_form(pose_x(pose)) for pname, pose in POSES}
    with open(os.path.join(OUT, "coupled_body_check.csv"), "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["pose", "code", "segments", "fx", "fy", "fz", "mx", "my", "mz", "wall_s"])
        for r in rows:
            w.writerow([r[0], r[1], r[2]] + ["%.6f" % v for v in r[3]] + ["%.3f" % r[4]])
        for pname, _ in POSES:
            w.writerow([pname, "closed form", "inf"] + ["%.6f" % v for v in closed[pname]] + [""])
    lines = check_lines(checks, deck_vs_mesh)
    with open(os.path.join(OUT, "coupled_body_checks.json"), "w") as fh:
        json.dump({"checks": lines, "wall_s": time.time() - t_start}, fh, indent=1)
    write(rows, closed, md_levels, st_levels, lines, time.time() - t_start)


def check_lines(checks, deck_vs_mesh):
    return [
        "- Fairlead positions against x + R_x R_y R_z p (p the body-relative point): largest "
        "deviation stancf %.2e m, MoorDyn %.2e m (over every pose and level)." % (
            max(c[3] for c in checks if c[0] == "stancf"),
            max(c[3] for c in checks if c[0] == "MoorDyn")),
        "- stancf's force after a 1e-5 s step against the 1e-6 s step's: largest difference "
        "%.1e of |F| (force), %.1e of |F| x %.3f m (moment). MoorDyn's Step(1e-6 s) against "
        "GetBodyForce: %.1e, %.1e." % (
            max(c[4][0] for c in checks if c[0] == "stancf"),
            max(c[4][1] for c in checks if c[0] == "stancf"), FAIR_RADIUS,
            max(c[4][0] for c in checks if c[0] == "MoorDyn"),
            max(c[4][1] for c in checks if c[0] == "MoorDyn")),
        "- stancf on the deck itself (NumSegs 20, no TOML) against the TOML with [[mesh]] "
        "elements = 20, the combined pose: largest difference %.2e N (N m)." % deck_vs_mesh]


def tables_only():
    """Rewrites coupled_body_check.md from the CSV and the checks' JSON."""
    rows, closed = [], {}
    with open(os.path.join(OUT, "coupled_body_check.csv")) as fh:
        for r in csv.DictReader(fh):
            v = np.array([float(r[k]) for k in ("fx", "fy", "fz", "mx", "my", "mz")])
            if r["code"] == "closed form":
                closed[r["pose"]] = v
            else:
                rows.append((r["pose"], r["code"], int(r["segments"]), v, float(r["wall_s"])))
    with open(os.path.join(OUT, "coupled_body_checks.json")) as fh:
        saved = json.load(fh)
    levels = lambda code: sorted({r[2] for r in rows if r[1] == code})
    write(rows, closed, levels("MoorDyn"), levels("stancf"), saved["checks"], saved["wall_s"])


def write(rows, closed, md_levels, st_levels, checks, wall):
    get = {(r[0], r[1], r[2]): r[3] for r in rows}
    nm, ns = md_levels[-1], st_levels[-1]
    L = []
    L.append("# The coupled OC4 body through the C library against MoorDyn 2.7\n")
    L.append("Written by `coupled_body_check.py` (`./run.sh --coupled-body-check`), %.0f s of wall "
             "time. Force F (kN) on the body and moment M (kN m) about its reference point, "
             "global axes, the body held at each pose (x, y, z, roll, pitch, yaw; MoorDyn's "
             "angles, R = R_x R_y R_z). stancf: libstancf_c, stancf_init then one 1e-6 s "
             "stancf_step at the pose; MoorDyn 2.7: its initial-condition solver (TmaxIC %g s, "
             "threshIC %g), GetBodyForce. Differences |dF|/|F| and |dM|/|M| of MoorDyn's.\n"
             % (wall, TMAX_IC, THRESH_IC))
    L.append("## Each pose at the finest discretisation (stancf %d, MoorDyn %d segments a line)\n" % (ns, nm))
    L.append("| pose | stancf F (kN) | stancf M (kN m) | MoorDyn F (kN) | MoorDyn M (kN m) | dF/F | dM/M |")
    L.append("|---|---|---|---|---|---|---|")
    footnote = False
    for pname, _ in POSES:
        s, m = get[(pname, "stancf", ns)], get[(pname, "MoorDyn", nm)]
        scale, sym = moment_scale(m)
        footnote |= sym
        rf, rm = rel(s, m, scale)
        L.append("| %s | %s | %s | %s | %s | %.3f %% | %.3f %%%s |" % (
            pname, fmt6(s[:3]), fmt6(s[3:]), fmt6(m[:3]), fmt6(m[3:]), 100 * rf, 100 * rm,
            " *" if sym else ""))
    if footnote:
        L.append("\n\\* The moment is nearly zero by symmetry there (|M| below 0.1 %% of |F| times "
                 "the fairlead radius %.3f m): the difference is given over |F| x %.3f m.\n"
                 % (FAIR_RADIUS, FAIR_RADIUS))
    L.append("\n## The same at the deck's 20 segments and against the closed form\n")
    L.append("Closed form: each line's elastic catenary on a flat frictionless bed (no seabed "
             "penetration), the limit of both codes' refinement.\n")
    L.append("| pose | stancf 20 vs MoorDyn 20: dF/F, dM/M | stancf %d vs closed form | MoorDyn %d vs closed form |" % (ns, nm))
    L.append("|---|---|---|---|")
    for pname, _ in POSES:
        c = closed[pname]
        scale, sym = moment_scale(c)
        a = rel(get[(pname, "stancf", 20)], get[(pname, "MoorDyn", 20)], moment_scale(get[(pname, "MoorDyn", 20)])[0])
        b = rel(get[(pname, "stancf", ns)], c, scale)
        d = rel(get[(pname, "MoorDyn", nm)], c, scale)
        L.append("| %s | %.3f %%, %.3f %% | %.3f %%, %.3f %% | %.3f %%, %.3f %% |" % (
            pname, 100 * a[0], 100 * a[1], 100 * b[0], 100 * b[1], 100 * d[0], 100 * d[1]))
    L.append("\n## Convergence: the change from the last refinement (largest over the poses)\n")
    L.append("| code | segments | max dF/F | max dM/M | its difference from the closed form, max dF/F, dM/M |")
    L.append("|---|---|---|---|---|")
    for code, levels in (("stancf", st_levels), ("MoorDyn", md_levels)):
        for k, n in enumerate(levels):
            dfs, dms, cfs, cms = [], [], [], []
            for pname, _ in POSES:
                v = get[(pname, code, n)]
                c = closed[pname]
                cf, cm = rel(v, c, moment_scale(c)[0])
                cfs.append(cf)
                cms.append(cm)
                if k:
                    p = get[(pname, code, levels[k - 1])]
                    df, dm = rel(v, p, moment_scale(p)[0])
                    dfs.append(df)
                    dms.append(dm)
            L.append("| %s | %d | %s | %s | %.3f %%, %.3f %% |" % (
                code, n, "%.3f %%" % (100 * max(dfs)) if dfs else "-",
                "%.3f %%" % (100 * max(dms)) if dms else "-", 100 * max(cfs), 100 * max(cms)))
    L.append("\n## Checks\n")
    L.extend(checks)
    L.append("\nWall time per pose: stancf %.2f s at %d segments; MoorDyn %.1f s at %d (mean)." % (
        np.mean([r[4] for r in rows if r[1] == "stancf" and r[2] == ns]), ns,
        np.mean([r[4] for r in rows if r[1] == "MoorDyn" and r[2] == nm]), nm))
    text = "\n".join(L) + "\n"
    with open(os.path.join(OUT, "coupled_body_check.md"), "w") as fh:
        fh.write(text)
    print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
