"""Static equilibria of MoorDyn's own body and rod decks against MoorDyn 2.7
(issue 30's check; CI does not run it). Writes out/bodies_check.csv and
out/bodies_check.md; its scratch (the deck copies, both codes' runs) is
out/bodies_check/.

Run through ./run.sh --bodies-check (it builds stancf and makes the
virtual environment with MoorDyn 2.7 or later from PyPI); `--deck=<part>`
runs only the decks whose name contains it. About 20 minutes on the
2-core machine (1179 s on 2026-11-27): MoorDyn's initial-condition
solvers on BodiesAndRods.dat, which settle neither, spend their budgets
(400 s of wall time each), RodHanging.txt takes a minute, the refinement
of example/body.txt four; stancf's runs take seconds.

The decks: those of MoorDyn's repository that have bodies or rods
(tests/Mooring/BodiesAndRods.dat, RodHanging.txt, RodPinnedFloating.txt,
body_tests/, rod_tests/, riser/, rotations/,
local_euler/complex_system.txt, bench/Mooring/floating_rods.txt,
example/body.txt), read from $MOORDYN_DECKS (an extracted tree, default
/tmp/decks/md) or from the MoorDyn git repository $MOORDYN_REPO (a
checkout or a bare mirror, `git show HEAD:<path>`). Each is copied into
the scratch; the originals are never edited. For each deck:

1. `stancf check <deck>`; a refusal (exit 2) is recorded with its reason
   (and, when it names a time-integration option, tScheme or cfl, which
   cannot change an equilibrium, the reason a copy without that option
   is refused for), and whether MoorDyn reads the deck (MoorDyn_Create).
2. stancf's equilibrium: `stancf run <deck> --out <dir> -q` (a deck alone
   runs its static equilibrium); tensions.csv, bodies.csv, points.csv,
   stiffness.csv and summary.json are read.
3. MoorDyn's equilibrium: its initial-condition solver, the one the deck
   names (MoorDyn-C 2.7's default is the stationary solver, ICgenDynamic
   0), on a copy of the deck with TmaxIC set and threshIC 0 (every other
   option the deck's: dtM, dtIC, CdScaleIC), through the Python API, the
   coupled degrees of freedom held where the deck puts them. threshIC 0
   because the solver's own test stops it where its error does not change
   between two checks, which a body falling at a constant acceleration
   satisfies (bodyDrag.txt stopped there at 2.55 s, the body 10 m from its
   equilibrium). The solver is run in chunks of pseudo-time (500 s; 100 s
   of the dynamic relaxation), each from the state the last one saved
   (fileIC), until it settles: the change of every compared number over a
   chunk, extrapolated geometrically, below 1e-6 of the tension, 1e-4 m
   and 1e-3 degrees, and the largest net force left on a line's inner
   node, a free point, body or rod below 1e-4 of the largest line end
   tension. Where it stalls (the change below those limits, the force
   not) or spends its budget (40000 s of pseudo-time, 400 s of wall time)
   the other solver runs too (the legacy dynamic relaxation,
   ICgenDynamic 1, with the deck's CdScaleIC); what each reached is
   recorded, and the comparison takes the one that settled (or the one
   with the smaller force left, marked as not settled). Read after Init:
   each line's end forces (the end nodes' net force, GetLineNodeForce,
   what MoorDyn's L<n>TA/TB channels write and what a point receives; not
   GetLineFairTen, the tension of the segment next to the end), bodies
   (GetBodyPos, GetBodyAngle, GetBodyForce), rods (GetRodNodePos of their
   end nodes), free points (GetPointPos).
4. The comparison: each line end's tension (relative difference to the
   larger of the two), each free body's reference point (m) and
   orientation (the angle of the rotation between the two, degrees), each
   free or pinned rod's end A (m) and direction (degrees), each free
   point (m), each coupled body's net force (relative to its magnitude).
5. The studies that explain a difference above 1 % or a deck that does
   not run (study_body_drag, study_bodies_and_rods) and the refinement of
   both codes' lines on example/body.txt (study_refinement).
"""
import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import race  # noqa: E402  (Quiet, STANCF, OUT)

OUT = race.OUT
WORK = os.path.join(OUT, "bodies_check")
STANCF = race.STANCF
DECKS_DIR = os.environ.get("MOORDYN_DECKS", "/tmp/decks/md")
MOORDYN_REPO = os.environ.get("MOORDYN_REPO", "/work/.mirror/FloatingArrayDesign+MoorDyn/repo")

# (name in the tables, path in MoorDyn's repository)
DECKS = [
    ("BodiesAndRods.dat", "tests/Mooring/BodiesAndRods.dat"),
    ("RodHanging.txt", "tests/Mooring/RodHanging.txt"),
    ("RodPinnedFloating.txt", "tests/Mooring/RodPinnedFloating.txt"),
    ("body_tests/bodyDrag.txt", "tests/Mooring/body_tests/bodyDrag.txt"),
    ("body_tests/orbitalBody.txt", "tests/Mooring/body_tests/orbitalBody.txt"),
    ("body_tests/pinnedBody.txt", "tests/Mooring/body_tests/pinnedBody.txt"),
    ("body_tests/rotatingBody.txt", "tests/Mooring/body_tests/rotatingBody.txt"),
    ("rod_tests/AddedMass.txt", "tests/Mooring/rod_tests/AddedMass.txt"),
    ("riser/riser.txt", "tests/Mooring/riser/riser.txt"),
    ("riser/riser_ic1.txt", "tests/Mooring/riser/riser_ic1.txt"),
    ("riser/riser_ic2.txt", "tests/Mooring/riser/riser_ic2.txt"),
    ("rotations/nwu.txt", "tests/Mooring/rotations/nwu.txt"),
    ("local_euler/complex_system.txt", "tests/Mooring/local_euler/complex_system.txt"),
    ("bench/Mooring/floating_rods.txt", "bench/Mooring/floating_rods.txt"),
    ("example/body.txt", "example/body.txt"),
]

# MoorDyn's initial-condition solver: chunk of pseudo-time (s), largest
# pseudo-time, wall budget (s) per deck. The stationary solver's step is
# bounded by the deck's dtM (kept), so a deck with a small dtM and a heavy
# body (BodiesAndRods: dtM 5e-4, 1e6 kg) moves slowly.
MD_CHUNK, MD_MAX_TIME, MD_WALL = 500.0, 40000.0, 400.0
# Settled: the change over a chunk, extrapolated, below these.
SETTLE_TENSION, SETTLE_POSITION, SETTLE_ANGLE = 1e-6, 1e-4, 1e-3
# A difference worth explaining.
LIMIT = 0.01


# --------------------------------------------------------------------------
# Decks


def deck_text(path):
    """The text of a deck of MoorDyn's repository (path in it): from
    $MOORDYN_DECKS, a checkout at $MOORDYN_REPO, or its git objects."""
    for base in (DECKS_DIR, MOORDYN_REPO):
        p = os.path.join(base, path)
        if os.path.isfile(p):
            with open(p) as f:
                return f.read()
    p = subprocess.run(["git", "-C", MOORDYN_REPO, "show", "HEAD:" + path],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("deck %s: not in %s nor in the repository %s" % (path, DECKS_DIR, MOORDYN_REPO))
    return p.stdout


SECTION_KEYS = [("LINE TYPES", "LINE TYPES"), ("LINE DICTIONARY", "LINE TYPES"),
                ("ROD TYPES", "ROD TYPES"), ("ROD DICTIONARY", "ROD TYPES"),
                ("BODIES", "BODIES"), ("BODY LIST", "BODIES"), ("BODY PROPERTIES", "BODIES"),
                ("RODS", "RODS"), ("ROD LIST", "RODS"), ("ROD PROPERTIES", "RODS"),
                ("POINTS", "POINTS"), ("POINT LIST", "POINTS"), ("POINT PROPERTIES", "POINTS"),
                ("CONNECTION PROPERTIES", "POINTS"), ("NODE PROPERTIES", "POINTS"),
                ("LINES", "LINES"), ("LINE LIST", "LINES"), ("LINE PROPERTIES", "LINES"),
                ("OPTIONS", "OPTIONS"), ("OUTPUTS", "OUTPUTS")]


def section_of(line):
    """The section a header line opens (MoorDyn's rule: a line with
    "---" and a keyword), "" for another dashed line, None for a line
    that is no header."""
    if "---" not in line:
        return None
    up = line.upper()
    for key, name in SECTION_KEYS:
        if key in up:
            return name
    return ""


def table_rows(text, section):
    """(line index, fields) of a table's data rows: MoorDyn's rows start
    two lines (names, units) after the header, OPTIONS and OUTPUTS right
    after it; a table ends at the next dashed line."""
    lines = text.splitlines()
    out, current, skip = [], None, 0
    for i, line in enumerate(lines):
        s = section_of(line)
        if s is not None:
            current, skip = s, (0 if s in ("OPTIONS", "OUTPUTS") else 2)
            continue
        if current != section:
            continue
        if skip:
            skip -= 1
            continue
        f = line.split()
        if f:
            out.append((i, f))
    return out


def options(text):
    """The deck's OPTIONS as {name: value string}."""
    return {f[1]: f[0] for _, f in table_rows(text, "OPTIONS") if len(f) >= 2}


def with_options(text, drop, add):
    """The deck with the OPTIONS rows named in `drop` removed and the
    rows `add` ("value name") put first in the section."""
    lines = text.splitlines()
    dropped = {i for i, f in table_rows(text, "OPTIONS") if len(f) >= 2 and f[1] in drop}
    out = []
    for i, line in enumerate(lines):
        if i in dropped:
            continue
        out.append(line)
        if section_of(line) == "OPTIONS":
            out += add
    return "\n".join(out) + "\n"


def with_rows_replaced(text, section, change):
    """The deck with each data row of `section` replaced by change(fields)
    (a list of fields, or None to drop the row)."""
    lines = text.splitlines()
    rows = dict(table_rows(text, section))
    out = []
    for i, line in enumerate(lines):
        if i in rows:
            f = change(list(rows[i]))
            if f is None:
                continue
            line = "  ".join(f)
        out.append(line)
    return "\n".join(out) + "\n"


def refined(text, factor):
    """The deck with every line's NumSegs times `factor`."""
    def times(f):
        """A LINES row with its NumSegs times `factor`."""
        f[5] = str(int(f[5]) * factor)
        return f
    return with_rows_replaced(text, "LINES", times)


def word(attachment):
    """The first run of letters of an attachment word, upper case
    (MoorDyn's decomposeString)."""
    m = re.match(r"[A-Za-z]*", attachment)
    return m.group(0).upper()


def body_kind(f):
    """A BODIES row's kind as MoorDyn reads it."""
    w = word(f[1])
    if w in ("FIXED", "FIX", "ANCHOR"):
        return "fixed"
    if w in ("COUPLED", "VESSEL", "VES", "CPLD"):
        return "coupled"
    if w in ("COUPLEDPINNED", "VESSELPINNED", "VESPIN", "CPLDPIN"):
        return "coupled pinned"
    return "free"


def rod_kind(f):
    """A RODS row's kind: fixed, pinned, body, body-pinned, free,
    coupled."""
    a = f[2].upper()
    m = re.match(r"(BODY)(\d+)(PIN|PINNED)?$", a)
    if m:
        return "pinned to a body" if m.group(3) else "fixed in a body"
    w = word(f[2])
    if w in ("FIXED", "FIX", "ANCHOR"):
        return "fixed"
    if w in ("PINNED", "PIN"):
        return "pinned"
    if w in ("FREE", "POINT", "CON"):
        return "free"
    return "coupled"


def point_kind(f):
    """A POINTS row's kind: fixed, body, coupled, free."""
    w = word(f[1])
    if w in ("FIXED", "FIX", "ANCHOR"):
        return "fixed"
    if w == "BODY":
        return "body"
    if w in ("FAIRLEAD", "VESSEL", "VES", "COUPLED", "CPLD"):
        return "coupled"
    return "free"


def count(kinds):
    """ "2 free, 1 fixed" from a list of kinds."""
    names = []
    for k in dict.fromkeys(kinds):
        names.append("%d %s" % (kinds.count(k), k))
    return ", ".join(names)


def contents(text):
    """What a deck has, in words: its bodies, rods (NumSegs), lines,
    free and coupled points, g."""
    bodies = [body_kind(f) for _, f in table_rows(text, "BODIES") if len(f) >= 14]
    rods = [(rod_kind(f), f[9]) for _, f in table_rows(text, "RODS") if len(f) >= 10]
    lines = [f for _, f in table_rows(text, "LINES") if len(f) >= 6]
    points = [point_kind(f) for _, f in table_rows(text, "POINTS") if len(f) >= 5]
    parts = []
    if bodies:
        parts.append("bodies: " + count(bodies))
    if rods:
        parts.append("rods: " + count(["%s (N %s)" % r for r in rods]))
    parts.append("%d line%s" % (len(lines), "" if len(lines) == 1 else "s"))
    free = points.count("free")
    cpl = points.count("coupled")
    if free:
        parts.append("%d free point%s" % (free, "" if free == 1 else "s"))
    if cpl:
        parts.append("%d coupled point%s" % (cpl, "" if cpl == 1 else "s"))
    return "; ".join(parts)


def coupled_dofs(text):
    """The coupled positions MoorDyn's Init takes, in its order (coupled
    bodies: x, y, z and the angles in radians; coupled rods; coupled
    points: x, y, z), where the deck puts them."""
    x = []
    for _, f in table_rows(text, "BODIES"):
        if len(f) >= 14 and body_kind(f) == "coupled":
            x += [float(v) for v in f[2:5]] + [math.radians(float(v)) for v in f[5:8]]
        elif len(f) >= 14 and body_kind(f) == "coupled pinned":
            x += [float(v) for v in f[2:5]]
    for _, f in table_rows(text, "RODS"):
        if len(f) >= 10 and rod_kind(f) == "coupled":
            x += [float(v) for v in f[3:6]] + [0.0, 0.0, 0.0]
    for _, f in table_rows(text, "POINTS"):
        if len(f) >= 5 and point_kind(f) == "coupled":
            x += [float(v) for v in f[2:5]]
    return x


# --------------------------------------------------------------------------
# Rotations (MoorDyn's angles: R = R_x(roll) R_y(pitch) R_z(yaw))


def rotation(angles_deg):
    """The rotation matrix of MoorDyn's roll, pitch, yaw (degrees)."""
    a, b, c = (math.radians(v) for v in angles_deg)
    rx = np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])
    ry = np.array([[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]])
    rz = np.array([[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]])
    return rx @ ry @ rz


def rotation_angle(r1, r2):
    """The angle (degrees) of the rotation taking r1 to r2."""
    c = (np.trace(r1.T @ r2) - 1.0) / 2.0
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def angle_between(u, v):
    """The angle (degrees) between two directions."""
    c = np.dot(u, v) / (np.linalg.norm(u) * np.linalg.norm(v))
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


# --------------------------------------------------------------------------
# stancf


def stancf_check(path):
    """(exit code, the refusal's first line without "error: <path>: ")."""
    p = subprocess.run([STANCF, "check", path], capture_output=True, text=True)
    first = next((l for l in p.stderr.splitlines() if l.startswith("error:")), "")
    reason = first[len("error: "):]
    if reason.startswith(path + ": "):
        reason = reason[len(path) + 2:]
    return p.returncode, reason


def refusal_chain(text, folder, reason):
    """Where a deck is refused for a time-integration option (tScheme,
    cfl: MoorDyn's integrator and its step, which no equilibrium depends
    on), the reason a copy without it is refused for ("" where the copy
    is accepted or the reason names another option)."""
    m = re.search(r"option (tScheme|cfl)\b", reason)
    if not m:
        return ""
    drop = {"tScheme", "cfl"}
    path = os.path.join(folder, "without_integrator.txt")
    with open(path, "w") as f:
        f.write(with_options(text, drop, []))
    rc, again = stancf_check(path)
    if rc == 0:
        return "a copy without tScheme and cfl is accepted"
    return "without tScheme and cfl: " + again


def moordyn_reads(deck):
    """Whether MoorDyn reads a deck (MoorDyn_Create, in a process of its
    own): "" where it does, else its error line."""
    p = subprocess.run([sys.executable, "-c", "import moordyn, sys; moordyn.Create(sys.argv[1])",
                        os.path.basename(deck)], capture_output=True, text=True,
                       cwd=os.path.dirname(deck))
    if p.returncode == 0:
        return ""
    lines = [l.strip() for l in (p.stdout + p.stderr).splitlines() if l.strip()]
    for k, line in enumerate(lines):
        if line.startswith("ERR"):
            # "ERR <source>: Error in <deck> at line <n>:", the row quoted,
            # the reason.
            at = re.search(r"at line (\d+)", line)
            why = next((l for l in lines[k + 1:] if not l.startswith("'")), "")
            return ("line %s: " % at.group(1) if at else "") + why
    return "MoorDyn_Create failed"


def read_csv(path):
    """The rows of a CSV as dicts (numbers as floats where they parse)."""
    if not os.path.exists(path):
        return []
    rows = []
    with open(path, newline="") as f:
        for r in csv.DictReader(f):
            for k, v in r.items():
                try:
                    r[k] = float(v)
                except (TypeError, ValueError):
                    pass
            rows.append(r)
    return rows


def stancf_run(path, out):
    """stancf's static equilibrium of a deck (or a scenario): a dict with
    rc, error (the error line), warnings, wall (s), and where it ran,
    tensions {(line, end): (force vector, tension)}, bodies {id: row of
    bodies.csv}, points {id: row}, stiffness {id: 6 x 6}, summary."""
    if os.path.exists(out):
        shutil.rmtree(out)
    t0 = time.perf_counter()
    p = subprocess.run([STANCF, "run", path, "--out", out, "-q"], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    errs = [l for l in p.stderr.splitlines() if l.startswith("error:")]
    res = dict(rc=p.returncode, wall=wall, error=errs[0] if errs else "",
               warnings=[l for l in p.stderr.splitlines() if l.startswith("warning:")])
    if p.returncode != 0:
        return res
    res["tensions"] = {(int(r["line"]), r["end"]): (np.array([r["fx"], r["fy"], r["fz"]]),
                                                     r["tension"])
                       for r in read_csv(os.path.join(out, "tensions.csv"))}
    res["bodies"] = {int(r["body"]): r for r in read_csv(os.path.join(out, "bodies.csv"))}
    res["points"] = {int(r["point"]): r for r in read_csv(os.path.join(out, "points.csv"))}
    stiff = {}
    for r in read_csv(os.path.join(out, "stiffness.csv")):
        stiff.setdefault(int(r["body"]), []).append([r[k] for k in ("dx", "dy", "dz", "rx",
                                                                      "ry", "rz")])
    res["stiffness"] = {k: np.array(v) for k, v in stiff.items()}
    with open(os.path.join(out, "summary.json")) as f:
        res["summary"] = json.load(f)
    return res


def stancf_objects(res, text):
    """stancf's compared objects: {("body", id): (position, R)} of free
    bodies, {("rod", id): (end A, direction)} of free and pinned rods (and
    a zero-length free rod: ("point", position)), {("point", id): position}
    of free points, {("coupled body", id): force and moment}."""
    objs = {}
    bodies = {f[0]: (body_kind(f), f) for _, f in table_rows(text, "BODIES") if len(f) >= 14}
    rods = {f[0]: f for _, f in table_rows(text, "RODS") if len(f) >= 10}
    for bid, (kind, f) in bodies.items():
        row = res["bodies"].get(int(bid))
        if row is None:
            continue
        pos = np.array([row["x"], row["y"], row["z"]])
        if kind == "free":
            objs[("body", int(bid))] = (pos, rotation([row["roll"], row["pitch"], row["yaw"]]))
        elif kind == "coupled":
            objs[("coupled body", int(bid))] = np.array([row[k] for k in ("fx", "fy", "fz", "mx",
                                                                          "my", "mz")])
    for entry in res["summary"].get("rods", []):
        rid = entry["id"]
        if entry["type"] in ("free", "pinned"):
            row = res["bodies"][entry["body_id"]]
            f = rods[str(rid)]
            a, b = np.array([float(v) for v in f[3:6]]), np.array([float(v) for v in f[6:9]])
            q0 = (b - a) / np.linalg.norm(b - a)
            if rod_kind(f) == "pinned to a body":
                host = bodies[re.match(r"BODY(\d+)", f[2].upper()).group(1)][1]
                q0 = rotation([float(v) for v in host[5:8]]) @ q0
            r = rotation([row["roll"], row["pitch"], row["yaw"]])
            objs[("rod", rid)] = (np.array([row["x"], row["y"], row["z"]]), r @ q0)
        elif entry["type"] == "point":
            pid = entry["points"][0]
            row = res["points"][pid]
            objs[("rod", rid)] = (np.array([row["x"], row["y"], row["z"]]), None)
    for _, f in table_rows(text, "POINTS"):
        if len(f) >= 5 and point_kind(f) == "free":
            row = res["points"][int(f[0])]
            objs[("point", int(f[0]))] = np.array([row["x"], row["y"], row["z"]])
    return objs


# --------------------------------------------------------------------------
# MoorDyn


def md_snapshot(s, text):
    """MoorDyn's numbers after Init: tensions {(line, end): (force,
    magnitude)} (the end nodes' net force), the objects as stancf_objects
    gives them, `residual` (N: the largest net force on a degree of
    freedom MoorDyn moves: a line's inner node, a free point, the
    translation of a free body or rod, as its last evaluation left them)
    and `scale` (N: the largest line end tension)."""
    import moordyn
    tensions, residual = {}, 0.0
    for i in range(1, moordyn.GetNumberLines(s) + 1):
        line = moordyn.GetLine(s, i)
        n = moordyn.GetLineN(line)
        for end, node in (("A", 0), ("B", n)):
            f = np.array(moordyn.GetLineNodeForce(line, node))
            tensions[(i, end)] = (f, float(np.linalg.norm(f)))
        for node in range(1, n):
            residual = max(residual, float(np.linalg.norm(moordyn.GetLineNodeForce(line, node))))
    objs = {}
    bodies = [f for _, f in table_rows(text, "BODIES") if len(f) >= 14]
    for k, f in enumerate(bodies):
        b = moordyn.GetBody(s, k + 1)
        force = np.array(moordyn.GetBodyForce(b))
        if body_kind(f) == "free":
            ang = np.degrees(moordyn.GetBodyAngle(b))
            objs[("body", k + 1)] = (np.array(moordyn.GetBodyPos(b)), rotation(ang))
            residual = max(residual, float(np.linalg.norm(force[:3])))
        elif body_kind(f) == "coupled":
            objs[("coupled body", k + 1)] = force
    rods = [f for _, f in table_rows(text, "RODS") if len(f) >= 10]
    for k, f in enumerate(rods):
        if rod_kind(f) not in ("free", "pinned", "pinned to a body"):
            continue
        r = moordyn.GetRod(s, k + 1)
        n = moordyn.GetRodN(r)
        a = np.array(moordyn.GetRodNodePos(r, 0))
        if n == 0:
            objs[("rod", k + 1)] = (a, None)
        else:
            b = np.array(moordyn.GetRodNodePos(r, n))
            objs[("rod", k + 1)] = (a, (b - a) / np.linalg.norm(b - a))
        if rod_kind(f) == "free":
            residual = max(residual, float(np.linalg.norm(np.array(moordyn.GetRodForce(r))[:3])))
    for _, f in table_rows(text, "POINTS"):
        if len(f) >= 5 and point_kind(f) == "free":
            p = moordyn.GetPoint(s, int(f[0]))
            objs[("point", int(f[0]))] = np.array(moordyn.GetPointPos(p))
            residual = max(residual, float(np.linalg.norm(moordyn.GetPointForce(p))))
    scale = max((v[1] for v in tensions.values()), default=0.0)
    return dict(tensions=tensions, objects=objs, residual=residual, scale=scale)


def change(a, b):
    """The change between two snapshots: (largest relative tension
    change, largest position change m, largest angle change deg)."""
    dt = max((abs(a["tensions"][k][1] - b["tensions"][k][1])
              / max(a["tensions"][k][1], b["tensions"][k][1], 1e-300)
              for k in a["tensions"]), default=0.0)
    dp, da = 0.0, 0.0
    for k, va in a["objects"].items():
        vb = b["objects"][k]
        if k[0] == "body":
            dp = max(dp, float(np.linalg.norm(va[0] - vb[0])))
            da = max(da, rotation_angle(va[1], vb[1]))
        elif k[0] == "rod":
            dp = max(dp, float(np.linalg.norm(va[0] - vb[0])))
            if va[1] is not None:
                da = max(da, angle_between(va[1], vb[1]))
        elif k[0] == "point":
            dp = max(dp, float(np.linalg.norm(va - vb)))
    return dt, dp, da


def ic_error(log):
    """The initial-condition solver's last "Remaining error" from
    MoorDyn's log, as it writes it ("0.0173 m/s2 per state" for the
    stationary solver, "1.2 % on line 3" for the dynamic relaxation)."""
    if not os.path.exists(log):
        return ""
    found = ""
    with open(log, errors="replace") as f:
        for line in f:
            m = re.search(r"Remaining error after [-+.\deE]+ s = ([-+.\deE]+) m/s2", line)
            if m:
                found = "%.3g m/s^2 per state" % float(m.group(1))
            m = re.search(r"Remaining error after [-+.\deE]+ s = ([-+.\deE]+)% on line (\d+)",
                          line)
            if m:
                found = "%.3g %% on line %s" % (float(m.group(1)), m.group(2))
    return found


# Settled: the residual (md_snapshot) below this fraction of the largest
# line end tension, besides the SETTLE_ limits on the change.
SETTLE_RESIDUAL = 1e-4


def moordyn_equilibrium(text, folder, max_time=MD_MAX_TIME, wall_budget=MD_WALL,
                        chunk=MD_CHUNK):
    """MoorDyn's static equilibrium of a deck by its initial-condition
    solver (the one the deck's ICgenDynamic names) in chunks of `chunk` s
    of pseudo-time, each from the state the last one saved (fileIC),
    until it settles (the change over a chunk, extrapolated geometrically,
    below the SETTLE_ limits and the residual below SETTLE_RESIDUAL of
    the largest tension), stalls (the change below its limits, the
    residual not) or spends the budget. Returns a dict: solver, settled,
    stalled, time (pseudo-time s), wall (s), change (the last chunk's:
    tension, m, deg), left (its extrapolation), error (the solver's own,
    from its log), history [(time, change, residual)], snapshot
    (md_snapshot), failed (a message where MoorDyn stopped)."""
    import moordyn
    os.makedirs(folder, exist_ok=True)
    x = coupled_dofs(text)
    drop = {"TmaxIC", "ICTmax", "threshIC", "ICthresh", "fileIC"}
    dynamic = options(text).get("ICgenDynamic", options(text).get("GenDynamicIC", "0")) != "0"
    out = dict(solver="dynamic relaxation" if dynamic else "stationary", settled=False,
               stalled=False, failed="", history=[], time=0.0, wall=0.0, error="")
    prev, prev_change, k = None, None, 0
    while True:
        add = ["%r  TmaxIC" % chunk, "0  threshIC"]
        if k:
            add.append("chunk%d.state  fileIC" % (k - 1))
        deck = os.path.join(folder, "chunk%d.txt" % k)
        with open(deck, "w") as f:
            f.write(with_options(text, drop, add))
        log = os.path.join(folder, "chunk%d.log" % k)
        t0 = time.perf_counter()
        with race.Quiet():
            s = moordyn.Create(deck)
            moordyn.SetVerbosity(s, moordyn.LEVEL_NONE)
            moordyn.SetLogFile(s, log)
            moordyn.SetLogLevel(s, moordyn.LEVEL_MSG)
            try:
                err = moordyn.Init(s, x, [0.0] * len(x))
            except RuntimeError as e:
                err = str(e)
        out["wall"] += time.perf_counter() - t0
        if err:
            out["failed"] = "Init failed after %g s of pseudo-time (%s)" % (out["time"], err)
            moordyn.Close(s)
            break
        snap = md_snapshot(s, text)
        moordyn.SaveState(s, os.path.join(folder, "chunk%d.state" % k))
        moordyn.Close(s)
        if not all(np.isfinite(v[1]) for v in snap["tensions"].values()):
            out["failed"] = "its state is not finite after %g s of pseudo-time" % (
                out["time"] + chunk)
            break
        out["time"] += chunk
        out.update(snapshot=snap, error=ic_error(log))
        if prev is not None:
            c = change(prev, snap)
            out["history"].append((out["time"], c, snap["residual"]))
            out["change"] = c
            # What is left, extrapolated geometrically: c r / (1 - r), r the
            # ratio of this chunk's change to the last one's.
            left = []
            for j in range(3):
                r = c[j] / prev_change[j] if prev_change and prev_change[j] > 0 else 1.0
                left.append(c[j] * r / (1.0 - r) if r < 0.95 else (math.inf if c[j] > 0
                                                                     else 0.0))
            out["left"] = left
            quiet = max(c[0], left[0]) < SETTLE_TENSION and max(c[1], left[1]) < SETTLE_POSITION \
                and max(c[2], left[2]) < SETTLE_ANGLE
            if quiet and snap["residual"] <= SETTLE_RESIDUAL * snap["scale"]:
                out["settled"] = True
                break
            if quiet:
                out["stalled"] = True
                break
            prev_change = c
        prev = snap
        k += 1
        if out["time"] >= max_time or out["wall"] >= wall_budget:
            break
    return out


def moordyn_settle(text, folder, wall_budget=MD_WALL):
    """MoorDyn's equilibrium: the deck's initial-condition solver
    (moordyn_equilibrium); where it does not settle, the other one too
    (the dynamic relaxation, ICgenDynamic 1, with the deck's CdScaleIC,
    after the stationary solver, or the reverse). Returns (the run
    compared: the one that settled, else the one with the smaller
    residual, [every run])."""
    first = moordyn_equilibrium(text, os.path.join(folder, "first"), wall_budget=wall_budget)
    runs = [first]
    if not first["settled"]:
        flip = "0" if first["solver"] == "dynamic relaxation" else "1"
        other = with_options(text, {"ICgenDynamic", "GenDynamicIC"}, [flip + "  ICgenDynamic"])
        runs.append(moordyn_equilibrium(other, os.path.join(folder, "second"),
                                        wall_budget=wall_budget,
                                        chunk=MD_CHUNK if flip == "0" else MD_CHUNK / 5))
    done = [r for r in runs if r["settled"]]
    if done:
        return done[0], runs
    have = [r for r in runs if "snapshot" in r]
    if not have:
        return runs[0], runs
    return min(have, key=lambda r: r["snapshot"]["residual"] / max(r["snapshot"]["scale"],
                                                                     1e-300)), runs


# --------------------------------------------------------------------------
# Comparison


def compare(st, md):
    """The comparison rows of one deck: every line end's tension, every
    free body's position and orientation, free or pinned rod's end A and
    direction, free point's position, coupled body's net force. Each row:
    object, quantity, stancf, moordyn, difference, unit ("%": relative to
    the larger; "m"; "deg")."""
    rows = []
    for key in sorted(st["tensions"]):
        a, b = st["tensions"][key][1], md["tensions"][key][1]
        rows.append(dict(object="line %d end %s" % key, quantity="tension (N)", stancf=a,
                         moordyn=b, difference=100 * abs(a - b) / max(a, b), unit="%"))
    for key in sorted(st["objects"], key=str):
        sa, mb = st["objects"][key], md["objects"].get(key)
        if mb is None:
            continue
        name = "%s %d" % key
        if key[0] == "body":
            rows.append(dict(object=name, quantity="reference point (m)", stancf=fmt_vec(sa[0]),
                             moordyn=fmt_vec(mb[0]),
                             difference=float(np.linalg.norm(sa[0] - mb[0])), unit="m"))
            rows.append(dict(object=name, quantity="roll, pitch, yaw (deg)",
                             stancf=fmt_vec(angles(sa[1])), moordyn=fmt_vec(angles(mb[1])),
                             difference=rotation_angle(sa[1], mb[1]), unit="deg"))
        elif key[0] == "rod":
            rows.append(dict(object=name, quantity="end A (m)", stancf=fmt_vec(sa[0]),
                             moordyn=fmt_vec(mb[0]),
                             difference=float(np.linalg.norm(sa[0] - mb[0])), unit="m"))
            if sa[1] is not None and mb[1] is not None:
                rows.append(dict(object=name, quantity="direction A to B",
                                 stancf=fmt_vec(sa[1], 6), moordyn=fmt_vec(mb[1], 6),
                                 difference=angle_between(sa[1], mb[1]), unit="deg"))
        elif key[0] == "point":
            rows.append(dict(object=name, quantity="position (m)", stancf=fmt_vec(sa),
                             moordyn=fmt_vec(mb), difference=float(np.linalg.norm(sa - mb)),
                             unit="m"))
        elif key[0] == "coupled body":
            big = max(np.linalg.norm(sa[:3]), np.linalg.norm(mb[:3]))
            rows.append(dict(object=name, quantity="lines' force on it (N)",
                             stancf=fmt_vec(sa[:3], 1), moordyn=fmt_vec(mb[:3], 1),
                             difference=100 * float(np.linalg.norm(sa[:3] - mb[:3])) / big,
                             unit="%"))
    return rows


def angles(r):
    """MoorDyn's roll, pitch, yaw (degrees) of a rotation matrix (pitch
    within [-90, 90])."""
    pitch = math.asin(max(-1.0, min(1.0, r[0, 2])))
    if abs(r[0, 2]) < 1 - 1e-12:
        roll = math.atan2(-r[1, 2], r[2, 2])
        yaw = math.atan2(-r[0, 1], r[0, 0])
    else:
        roll, yaw = math.atan2(r[2, 1], r[1, 1]), 0.0
    return np.degrees([roll, pitch, yaw])


def fmt_vec(v, digits=4):
    """A vector as "(a, b, c)" rounded to `digits` decimals."""
    return "(" + ", ".join("%.*f" % (digits, 0.0 if abs(x) < 0.5 * 10 ** -digits else x)
                           for x in v) + ")"


# --------------------------------------------------------------------------
# Studies: where the codes differ by more than 1 %, or a deck does not run


def study_body_drag(folder, text, st, md):
    """bodyDrag.txt: a 10 kg body (no volume) on a 4.5 m line of 500 N
    (one segment, no compression) to a fixed point 5 m below it. The
    closed form of the body hanging below the point (the line's tension
    W_b + w s from the body, its stretch integrated), stancf from a copy
    with the body started 10 m down (below the point) and the stability
    of both stancf equilibria (stiffness.csv's horizontal entry).
    Returns the lines of its paragraph and the numbers."""
    opts = options(text)
    g = float(opts.get("g", 9.80665))
    rho = float(opts.get("WtrDnsty", 1025.0))
    lt = [f for _, f in table_rows(text, "LINE TYPES")][0]
    d, m, ea = float(lt[1]), float(lt[2]), float(lt[3])
    line = [f for _, f in table_rows(text, "LINES")][0]
    length = float(line[4])
    body = [f for _, f in table_rows(text, "BODIES")][0]
    wb = float(body[8]) * g - rho * float(body[11]) * g
    w = (m - rho * math.pi * d * d / 4) * g
    anchor = [f for _, f in table_rows(text, "POINTS") if point_kind(f) == "fixed"][0]
    za = float(anchor[4])
    z_closed = za - length - (wb * length + w * length * length / 2) / ea
    below = with_rows_replaced(text, "BODIES",
                               lambda f: f[:4] + ["%r" % (za - 5.0)] + f[5:])
    os.makedirs(folder, exist_ok=True)
    path = os.path.join(folder, "bodyDrag_below.txt")
    with open(path, "w") as f:
        f.write(below)
    again = stancf_run(path, os.path.join(folder, "stancf_below"))
    z_st = st["bodies"][1]["z"]
    z_md = md["objects"][("body", 1)][0][2] if md else float("nan")
    z_again = again["bodies"][1]["z"] if again["rc"] == 0 else float("nan")
    k_st = st["stiffness"].get(1, np.zeros((6, 6)))[0, 0]
    k_again = again["stiffness"].get(1, np.zeros((6, 6)))[0, 0] if again["rc"] == 0 else 0.0
    short = next((l for l in st["warnings"] if "shortens" in l), "")
    m_short = re.search(r"shortens it by up to ([\d.eE+-]+) \(a compression of ([\d.eE+-]+) N",
                        short)
    return dict(z_closed=z_closed, z_stancf=z_st, z_moordyn=z_md, z_stancf_below=z_again,
                k_stancf=k_st, k_stancf_below=k_again,
                shortening=float(m_short.group(1)) if m_short else None,
                compression=float(m_short.group(2)) if m_short else None,
                top=za - 5.0, w=w, gap=float(body[4]) - za)


def study_bodies_and_rods(folder, text):
    """BodiesAndRods.dat, which stancf does not solve, taken apart:
    (1) a copy without rod 2 (pinned to the body, no line on it: the
    limitation docs/interface.md documents); (2) without rod 2 and the
    buoyant cable (lines 4 to 6, points 7 to 10): the body floating on
    rod 1, against the closed form of its heave (rod 1's wet length h
    from rho g A h = (body + rod) g - the lines' vertical force on the
    body); (3) the buoyant cable alone, the body fixed where (2) floats
    it, line 4 (the deck's 200 m) shortened, and (4) at 200 m in 96
    elements instead of 12. Returns a dict of the runs and numbers."""
    os.makedirs(folder, exist_ok=True)

    def run(name, t):
        """stancf's equilibrium of the copy `t`, written as <name>.txt."""
        path = os.path.join(folder, name + ".txt")
        with open(path, "w") as f:
            f.write(t)
        return stancf_run(path, os.path.join(folder, "stancf_" + name))

    out = {}
    no_pin = with_rows_replaced(text, "RODS",
                                lambda f: None if rod_kind(f) == "pinned to a body" else f)
    out["no_rod2"] = run("without_rod2", no_pin)
    spar = with_rows_replaced(no_pin, "LINES", lambda f: None if int(f[0]) >= 4 else f)
    spar = with_rows_replaced(spar, "POINTS", lambda f: None if int(f[0]) >= 7 else f)
    out["spar"] = sp = run("without_rod2_and_lines_4_to_6", spar)
    opts = options(text)
    g, rho = float(opts.get("g", 9.80665)), float(opts.get("WtrDnsty", 1025.0))
    body = [f for _, f in table_rows(text, "BODIES")][0]
    rod = [f for _, f in table_rows(no_pin, "RODS")][0]
    rtype = {f[0]: f for _, f in table_rows(text, "ROD TYPES")}[rod[1]]
    d, w = float(rtype[1]), float(rtype[2])
    length = abs(float(rod[8]) - float(rod[5]))
    area = math.pi * d * d / 4
    if sp["rc"] == 0:
        fz = sp["bodies"][1]["fz"]
        h = ((float(body[8]) + w * length) * g - fz) / (rho * g * area)
        out["spar_closed"] = -float(rod[5]) - h
        out["spar_z"] = sp["bodies"][1]["z"]
        out["spar_fz"] = fz
    z_body = out.get("spar_z", -14.586)

    def cable(length4):
        """The buoyant cable alone: the body fixed at z_body, lines 4-6
        renumbered 1-3, line 4 `length4` m."""
        t = with_rows_replaced(no_pin, "BODIES", lambda f: f[:1] + ["Fixed"] + f[2:4]
                               + ["%r" % z_body] + f[5:])
        t = with_rows_replaced(t, "LINES", lambda f: None if int(f[0]) <= 3 else
                               [str(int(f[0]) - 3)] + f[1:4]
                               + ([repr(length4)] if int(f[0]) == 4 else [f[4]]) + f[5:])
        return t

    out["cable"] = []
    for length4 in (150.0, 170.0, 180.0, 190.0, 195.0, 200.0):
        r = run("cable_%g" % length4, cable(length4))
        h = r["points"][7]["fx"] if r["rc"] == 0 else None
        out["cable"].append((length4, r, h))
    path = os.path.join(folder, "cable_200.txt")
    sc = os.path.join(folder, "cable_200_96.toml")
    with open(sc, "w") as f:
        f.write('title = "the cable, line 4 in 96 elements"\n[system]\nmoordyn = "%s"\n'
                '[analysis]\ntype = "static"\n[[mesh]]\nlines = [1]\nelements = 96\n'
                % os.path.basename(path))
    out["cable_96"] = c96 = stancf_run(sc, os.path.join(folder, "stancf_cable_200_96"))
    if c96["rc"] == 0:
        # Line 1's stretch |r_x| - 1 at its nodes: where it goes negative
        # (the compression the warning names) and the touchdown (the first
        # node from the anchor more than 1 cm above the bed).
        nodes = read_csv(os.path.join(folder, "stancf_cable_200_96", "lines", "1", "nodes.csv"))
        bed = -float(opts["WtrDpth"])
        stretch = [(math.sqrt(n["dx_ds"] ** 2 + n["dy_ds"] ** 2 + n["dz_ds"] ** 2) - 1.0,
                    n["x"], n["z"]) for n in nodes]
        lo = min(stretch)
        hi = max(stretch)
        touch = next(n for n in nodes if n["z"] > bed + 0.01)
        out["cable_96_stretch"] = dict(low=lo[0], low_x=lo[1], high=hi[0], high_x=hi[1],
                                       touchdown_x=touch["x"])
    cab = [f for _, f in table_rows(text, "LINE TYPES") if f[0] == "cable"][0]
    out["cable_w"] = (float(cab[2]) - rho * math.pi * float(cab[1]) ** 2 / 4) * g
    return out


def study_refinement(folder, text, factors=(1, 2, 4, 8)):
    """Both codes' line end tensions as their lines are refined: stancf
    with a scenario taking the deck and a [[mesh]] of NumSegs x factor
    SAC-2 elements per line, MoorDyn on a copy with NumSegs x factor.
    Returns [(factor, stancf result, MoorDyn result)]."""
    os.makedirs(folder, exist_ok=True)
    segs = {}
    for _, f in table_rows(text, "LINES"):
        segs.setdefault(int(f[5]), []).append(int(f[0]))
    deck = os.path.join(folder, "deck.txt")
    with open(deck, "w") as f:
        f.write(text)
    rows = []
    for k in factors:
        sc = os.path.join(folder, "refined_%d.toml" % k)
        with open(sc, "w") as f:
            f.write('title = "refined x%d"\n[system]\nmoordyn = "deck.txt"\n'
                    '[analysis]\ntype = "static"\n' % k)
            for n, ids in sorted(segs.items()):
                f.write("[[mesh]]\nlines = %r\nelements = %d\n" % (ids, n * k))
        st = stancf_run(sc, os.path.join(folder, "stancf_x%d" % k))
        md = moordyn_equilibrium(refined(text, k), os.path.join(folder, "moordyn_x%d" % k),
                                 wall_budget=300.0)
        rows.append((k, st, md))
    return rows


# --------------------------------------------------------------------------
# The run


def check_deck(name, path):
    """One deck through steps 1 to 4: a dict with name, path, contents,
    check (exit code, reason, the reason without the integrator options),
    stancf (stancf_run), moordyn (moordyn_equilibrium) and rows (compare),
    the deck's text and scratch folder."""
    folder = os.path.join(WORK, re.sub(r"[^A-Za-z0-9_.-]+", "_", name))
    if os.path.exists(folder):
        shutil.rmtree(folder)
    os.makedirs(folder)
    text = deck_text(path)
    deck = os.path.join(folder, os.path.basename(path))
    with open(deck, "w") as f:
        f.write(text)
    res = dict(name=name, path=path, text=text, folder=folder, deck=deck,
               contents=contents(text), rows=[])
    rc, reason = stancf_check(deck)
    res["check"] = (rc, reason, refusal_chain(text, folder, reason) if rc == 2 else "")
    print("%-32s check exit %d %s" % (name, rc, reason[:100]), flush=True)
    if rc != 0:
        res["moordyn_reads"] = moordyn_reads(deck)
        return res
    st = stancf_run(deck, os.path.join(folder, "stancf"))
    res["stancf"] = st
    print("%-32s stancf run exit %d in %.2f s %s" % (name, st["rc"], st["wall"], st["error"][:120]),
          flush=True)
    md, runs = moordyn_settle(text, os.path.join(folder, "moordyn"))
    res["moordyn"], res["moordyn_runs"] = md, runs
    for r in runs:
        print("%-32s MoorDyn %s: %s after %g s (%.0f s wall), last change %s, residual %.3g of "
              "%.3g N %s" % (name, r["solver"], "settled" if r["settled"] else "stalled"
                             if r["stalled"] else "NOT settled", r["time"], r["wall"],
                             r.get("change"), r.get("snapshot", {}).get("residual", math.nan),
                             r.get("snapshot", {}).get("scale", math.nan), r["failed"]),
              flush=True)
    if st["rc"] == 0 and "snapshot" in md:
        st["objects"] = stancf_objects(st, text)
        res["rows"] = compare(st, dict(tensions=md["snapshot"]["tensions"],
                                       objects=md["snapshot"]["objects"]))
    return res


def largest(rows, unit, quantity=None):
    """The row with the largest difference in `unit` (and quantity
    containing `quantity`), or None."""
    pick = [r for r in rows
            if r["unit"] == unit and (quantity is None or quantity in r["quantity"])]
    return max(pick, key=lambda r: r["difference"]) if pick else None


def run_text(r):
    """One MoorDyn initial-condition run in words."""
    if r["failed"] and "snapshot" not in r:
        return "%s: %s" % (r["solver"], r["failed"])
    snap = r["snapshot"]
    chunk = MD_CHUNK if r["solver"] == "stationary" else MD_CHUNK / 5
    c = r.get("change", (math.nan,) * 3)
    if r["settled"]:
        return "%s: settled after %g s (%.0f s wall; residual %.2g N)" % (
            r["solver"], r["time"], r["wall"], snap["residual"])
    how = "stalled" if r["stalled"] else "not settled"
    text = ("%s: %s after %g s (%.0f s wall): residual %.3g N (largest tension %.4g N), over "
            "its last %g s the tensions changed by %.2g, positions by %.2g m, angles by %.2g "
            "deg" % (r["solver"], how, r["time"], r["wall"], snap["residual"], snap["scale"],
                     chunk, c[0], c[1], c[2]))
    for key, v in sorted(snap["objects"].items(), key=str):
        if key[0] == "body":
            text += "; body %d at %s m, roll, pitch, yaw %s deg" % (
                key[1], fmt_vec(v[0], 3), fmt_vec(angles(v[1]), 3))
    if r["error"]:
        text += "; its own error %s" % r["error"]
    if r["failed"]:
        text += "; then %s" % r["failed"]
    return text


def status_text(res):
    """The deck's stancf and MoorDyn columns of the summary table."""
    rc, reason, then = res["check"]
    if rc == 2:
        m = res.get("moordyn_reads", "")
        return ("refused: " + reason + (" (%s)" % then if then else ""),
                "not run (MoorDyn refuses it too: %s)" % m if m else "not run (MoorDyn reads it)")
    st = res["stancf"]
    s = ("equilibrium in %.2f s" % st["wall"]) if st["rc"] == 0 else \
        "exit %d: %s" % (st["rc"], st["error"].split(": ", 2)[-1].split(";")[0])
    if st["rc"] == 0:
        for w in st["warnings"]:
            m = re.search(r"\(id (\d+)\): its static equilibrium shortens it by up to ([\d.eE+-]+) "
                          r"\(a compression of ([\d.eE+-]+) N", w)
            if m:
                s += " (warning: line %s left shortened by up to %.3g, a compression of %.4g N)" \
                    % (m.group(1), float(m.group(2)), float(m.group(3)))
    return s, "; ".join(run_text(r) for r in res["moordyn_runs"])


def tension_text(res):
    """ "stancf / MoorDyn" of the largest line end tension."""
    rows = [r for r in res["rows"] if r["quantity"] == "tension (N)"]
    if not rows:
        return ""
    r = max(rows, key=lambda r: r["stancf"])
    return "%s: %.6g / %.6g N" % (r["object"], r["stancf"], r["moordyn"])


def bodies_text(res):
    """stancf / MoorDyn of the bodies' and rods' positions."""
    out = []
    for r in res["rows"]:
        if r["quantity"] in ("reference point (m)", "end A (m)", "position (m)"):
            if r["object"].startswith("point"):
                continue
            out.append("%s %s / %s" % (r["object"], r["stancf"], r["moordyn"]))
        elif r["quantity"] == "lines' force on it (N)":
            out.append("%s (coupled): force %s / %s N" % (r["object"], r["stancf"], r["moordyn"]))
    return "; ".join(out)


def differences_text(res):
    """The largest differences of a compared deck."""
    parts = []
    for unit, what, fmt in (("%", "tension (N)", "tension %.3g %% (%s)"),
                            ("%", "force", "coupled body's force %.3g %% (%s)"),
                            ("m", None, "%.3g m (%s)"), ("deg", None, "%.3g deg (%s)")):
        r = largest(res["rows"], unit, what)
        if r is not None:
            parts.append(fmt % (r["difference"], r["object"] + ", " + r["quantity"].split(" (")[0]))
    return "; ".join(parts)


def write_csv(results, path):
    """out/bodies_check.csv: one row per compared number (and one per
    deck not compared, its status in `object`)."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["deck", "object", "quantity", "stancf", "moordyn", "difference", "unit"])
        for res in results:
            if not res["rows"]:
                s, m = status_text(res)
                w.writerow([res["name"], "stancf: " + s, "MoorDyn: " + m, "", "", "", ""])
            for r in res["rows"]:
                a, b = r["stancf"], r["moordyn"]
                w.writerow([res["name"], r["object"], r["quantity"],
                            "%.10g" % a if isinstance(a, float) else a,
                            "%.10g" % b if isinstance(b, float) else b,
                            "%.4g" % r["difference"], r["unit"]])


def summary_table(results):
    """The markdown summary table, one row per deck."""
    lines = ["| deck | what it has | stancf | MoorDyn 2.7 (initial-condition solvers) | largest "
             "line end tension, stancf / MoorDyn | bodies and rods, stancf / MoorDyn | largest "
             "differences |", "|---|---|---|---|---|---|---|"]
    for res in results:
        s, m = status_text(res)
        lines.append("| %s | %s | %s | %s | %s | %s | %s |" % (
            res["name"], res["contents"], s, m, tension_text(res), bodies_text(res),
            differences_text(res)))
    return lines


def detail_table(res):
    """Every compared number of one deck (markdown)."""
    lines = ["| object | quantity | stancf | MoorDyn | difference |", "|---|---|---|---|---|"]
    for r in res["rows"]:
        a = "%.7g" % r["stancf"] if isinstance(r["stancf"], float) else r["stancf"]
        b = "%.7g" % r["moordyn"] if isinstance(r["moordyn"], float) else r["moordyn"]
        d = ("%.3g %%" if r["unit"] == "%" else "%.3g " + r["unit"]) % r["difference"]
        flag = " **> 1 %**" if (r["unit"] == "%" and r["difference"] > 100 * LIMIT) else ""
        lines.append("| %s | %s | %s | %s | %s%s |" % (r["object"], r["quantity"], a, b, d, flag))
    return lines


def main():
    """Every deck (or those whose name contains a --deck=<part>), compared
    and explained; out/bodies_check.csv and out/bodies_check.md."""
    os.makedirs(WORK, exist_ok=True)
    t_start = time.perf_counter()
    only = [a.split("=", 1)[1] for a in sys.argv if a.startswith("--deck=")]
    results = [check_deck(n, p) for n, p in DECKS if not only or any(o in n for o in only)]
    by_name = {r["name"]: r for r in results}
    md = ["# Static equilibria of MoorDyn's body and rod decks against MoorDyn 2.7", "",
          "stancf `%s`; MoorDyn %s (Python package). Written by bodies_check.py." % (
              git_describe(), moordyn_version()), ""]
    md += summary_table(results)
    for res in results:
        if res["rows"]:
            md += ["", "## %s" % res["name"], ""] + detail_table(res)
    # Studies.
    studies = []
    bd = by_name.get("body_tests/bodyDrag.txt")
    if bd and bd["rows"]:
        studies += [""] + body_drag_text(bd)
    bar = by_name.get("BodiesAndRods.dat")
    if bar and bar.get("stancf"):
        studies += [""] + bodies_and_rods_text(bar)
    body = by_name.get("example/body.txt")
    if body and body["rows"]:
        studies += [""] + refinement_text(body)
    md += [""] + studies
    md += ["", "Total time %.0f s." % (time.perf_counter() - t_start)]
    write_csv(results, os.path.join(OUT, "bodies_check.csv"))
    with open(os.path.join(OUT, "bodies_check.md"), "w") as f:
        f.write("\n".join(md) + "\n")
    print("\n".join(md))


def git_describe():
    """The stancf commit (and "+ changes" when the tree has some)."""
    p = subprocess.run(["git", "-C", race.ROOT, "rev-parse", "--short", "HEAD"],
                       capture_output=True, text=True)
    d = subprocess.run(["git", "-C", race.ROOT, "status", "--porcelain", "--untracked-files=no"],
                       capture_output=True, text=True)
    return p.stdout.strip() + (" with uncommitted changes" if d.stdout.strip() else "")


def moordyn_version():
    """The installed moordyn package's version."""
    try:
        from importlib.metadata import version
        return version("moordyn")
    except Exception:  # noqa: BLE001
        return "?"


# --------------------------------------------------------------------------
# The studies' paragraphs


def body_drag_text(res):
    """The paragraph of bodyDrag.txt's difference (study_body_drag)."""
    st = res["stancf"]
    md = res["moordyn"]["snapshot"]
    b = study_body_drag(os.path.join(res["folder"], "study"), res["text"], st, md)
    dz = abs(b["z_stancf"] - b["z_moordyn"])
    return [
        "### bodyDrag.txt: the body %.2f m apart (the tensions equal)" % dz, "",
        "The deck holds a 10 kg body (no volume) by a 4.5 m line (EA 500 N, one segment, "
        "no compression, as every deck line) to a fixed point %.4g m below it. A line "
        "without compression cannot hold the body above its point: MoorDyn's body falls past "
        "it and hangs below, at z = %.7f m; the closed form of a body hanging on the line "
        "(its tension W_b + w s from the body, w = %.4g N/m wet, its stretch the integral of "
        "T/EA) is %.7f m. stancf's static solve keeps the line's compressive stiffness on its "
        "first path (docs/method.md §11.6) and ends with the body resting on the line pushed "
        "together, z = %.7f m (the line shortened by up to %s, a compression of %s N); its "
        "second path, with the line's own law, has no equilibrium near it (the body would "
        "fall through), so the first stays, with a warning, and `stancf run` exits 0. That "
        "equilibrium is unstable: its horizontal stiffness (stiffness.csv, fx by dx) is "
        "%.4g N/m. The end tensions are the same at both (98.1 N at the body, 184.17 N at "
        "the point: the same weights hang on the line, pushing in one, pulling in the "
        "other). Started from a copy with the body at z = %.4g m (below the point), stancf "
        "finds z = %.7f m (%.2g m from the closed form, stiffness %+.4g N/m)." % (
            b["gap"], b["z_moordyn"], b["w"], b["z_closed"], b["z_stancf"],
            "%.3g" % b["shortening"] if b["shortening"] is not None else "?",
            "%.4g" % b["compression"] if b["compression"] is not None else "?",
            b["k_stancf"], b["top"], b["z_stancf_below"],
            abs(b["z_stancf_below"] - b["z_closed"]), b["k_stancf_below"])]


def bodies_and_rods_text(res):
    """The paragraph of BodiesAndRods.dat (study_bodies_and_rods)."""
    s = study_bodies_and_rods(os.path.join(res["folder"], "study"), res["text"])
    nr = s["no_rod2"]
    m = re.search(r"load factor ([\d.]+) \(increment \d+, \d+ iterations, scaled residual "
                  r"([\d.eE+-]+)\)", nr["error"])
    first = re.search(r"load factor ([\d.]+) \(increment \d+, \d+ iterations, scaled residual "
                      r"([\d.eE+-]+)\)", res["stancf"]["error"])
    lines = ["### BodiesAndRods.dat: stancf does not solve it, MoorDyn does not settle it", ""]
    text = ("stancf exits 3 (Newton does not converge at load factor %s, scaled residual %s). "
            "The deck's rod 2 is pinned to the free body (Body1Pinned) with no line on it: the "
            "static solve of such a rod does not converge in this version (docs/interface.md, "
            "\"Known limitation\"). " % (first.group(1) if first else "?",
                                         first.group(2) if first else "?"))
    if nr["rc"] == 0:
        text += "A copy without rod 2 is solved. "
    else:
        text += ("A copy without rod 2 gets to load factor %s and stops there (scaled residual "
                 "%s against the tolerance 1e-10). " % (m.group(1) if m else "?",
                                                        m.group(2) if m else "?"))
    if s["spar"]["rc"] == 0:
        text += ("Without rod 2 and the buoyant cable (lines 4 to 6, points 7 to 10) it is: the "
                 "body floats on rod 1 at z = %.6f m, the closed form of its heave (rod 1's wet "
                 "length from rho g A h = (body + rod) g + the lines' pull %.1f N) %.6f m. "
                 % (s["spar_z"], -s["spar_fz"], s["spar_closed"]))
    ok = [(L, h) for L, r, h in s["cable"] if r["rc"] == 0]
    bad = [L for L, r, h in s["cable"] if r["rc"] != 0]
    text += ("The cable alone (the body fixed where it floats) fails as the whole does, and "
             "converges when its line 4 is shorter: the anchor's horizontal pull H falls as "
             "line 4 lengthens, %s, and the solve stops at %s m (the deck's is 200 m). " % (
                 ", ".join("%.0f N at %g m" % (h, L) for L, h in ok),
                 " and ".join("%g" % L for L in bad)))
    c96 = s["cable_96"]
    if c96["rc"] == 0:
        comp = [re.search(r"shortens it by up to ([\d.eE+-]+) \(a compression of ([\d.eE+-]+) N",
                          w) for w in c96["warnings"]]
        comp = [(float(x.group(1)), float(x.group(2))) for x in comp if x]
        h96 = c96["points"][7]["fx"]
        text += ("With line 4 at 200 m in 96 elements instead of 12 stancf solves it: H = %.0f "
                 "N, H/w = %.2f m (w = %.1f N/m wet), a touchdown the elements (%.2f m) hardly "
                 "follow, and the solve keeps compressions of up to %.4g N (line 4 shortened by "
                 "%.3g) where the anchor pulls %.0f N. They are at the touchdown (it leaves the "
                 "bed at x = %.1f m), where line 4's stretch at its nodes, |r_x| - 1, alternates "
                 "in sign (%.2g at x = %.1f m, %.2g at x = %.1f m): the locking docs/method.md "
                 "§11.6 describes at a touchdown the elements do not follow."
                 % (h96, h96 / s["cable_w"], s["cable_w"], 200.0 / 96,
                    max(c[1] for c in comp) if comp else float("nan"),
                    max(c[0] for c in comp) if comp else float("nan"),
                    math.hypot(h96, c96["points"][7]["fz"]),
                    s["cable_96_stretch"]["touchdown_x"], s["cable_96_stretch"]["low"],
                    s["cable_96_stretch"]["low_x"], s["cable_96_stretch"]["high"],
                    s["cable_96_stretch"]["high_x"]))
    else:
        text += "At 200 m in 96 elements it still fails (%s)." % c96["error"][:120]
    lines.append(text)
    lines += ["", "MoorDyn: " + "; ".join(run_text(r) for r in res["moordyn_runs"]) + "."]
    return lines


def refinement_text(res):
    """The table of both codes refined on example/body.txt
    (study_refinement)."""
    rows = study_refinement(os.path.join(res["folder"], "refinement"), res["text"])
    out = ["### example/body.txt refined: both codes converge to one line", "",
           "Line 1's end tensions (its anchor A on the bed, its fairlead B on the coupled "
           "body) and its anchor's vertical force, the deck's NumSegs (20) times the factor: "
           "stancf's SAC-2 elements ([[mesh]]), MoorDyn's segments.", "",
           "| factor | stancf A (N) | MoorDyn A (N) | stancf B (N) | MoorDyn B (N) | B: "
           "difference | anchor's vertical force, stancf / MoorDyn (N) | MoorDyn settled |",
           "|---|---|---|---|---|---|---|---|"]
    for k, st, md in rows:
        if st["rc"] != 0 or "snapshot" not in md:
            out.append("| %d | %s | | | | | | %s |" % (k, st["error"][:60], md["failed"]))
            continue
        ta, tb = st["tensions"][(1, "A")], st["tensions"][(1, "B")]
        ma, mb = md["snapshot"]["tensions"][(1, "A")], md["snapshot"]["tensions"][(1, "B")]
        diff = 100 * abs(tb[1] - mb[1]) / max(tb[1], mb[1])
        out.append("| %d | %.1f | %.1f | %.1f | %.1f | %.3g %% | %.0f / %.0f | %s after %g s "
                   "|" % (k, ta[1], ma[1], tb[1], mb[1], diff, ta[0][2], ma[0][2],
                          "yes" if md["settled"] else "no", md["time"]))
    return out


if __name__ == "__main__":
    main()
