"""bodies_check.py's runs of the two codes: stancf's check and static run
and what they give; MoorDyn's initial-condition solvers run until they
settle, and what they give."""

from bodies_common import *  # noqa: F401,F403
from bodies_decks import *  # noqa: F401,F403

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


def check_and_solve(res, chain=None):
    """Steps 1 and 2 of a deck `res` (name, deck, folder): `stancf check`,
    its refusal recorded (with `chain(reason)`, where given, the reason
    a copy without the integrator options is refused for) and whether
    MoorDyn reads the deck; else stancf's equilibrium. Returns stancf's
    run (stancf_run), None for a refused deck."""
    name, deck = res["name"], res["deck"]
    rc, reason = stancf_check(deck)
    res["check"] = (rc, reason, chain(reason) if chain and rc == 2 else "")
    print("%-32s check exit %d %s" % (name, rc, reason[:100]), flush=True)
    if rc != 0:
        res["moordyn_reads"] = moordyn_reads(deck)
        return None
    st = stancf_run(deck, os.path.join(res["folder"], "stancf"))
    res["stancf"] = st
    print("%-32s stancf run exit %d in %.2f s %s" % (name, st["rc"], st["wall"], st["error"][:120]),
          flush=True)
    return st


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
