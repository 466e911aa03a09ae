"""bodies_check.py's comparison of the two codes' equilibria and the studies
that explain a difference above 1 % or a deck that does not run, with
their paragraphs."""

from bodies_common import *  # noqa: F401,F403
from bodies_decks import *  # noqa: F401,F403
from bodies_codes import *  # noqa: F401,F403

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
            apart = float(np.linalg.norm(sa[:3] - mb[:3]))
            # Both zero (a body holding nothing): no difference, not 0/0.
            rows.append(dict(object=name, quantity="lines' force on it (N)",
                             stancf=fmt_vec(sa[:3], 1), moordyn=fmt_vec(mb[:3], 1),
                             difference=100 * apart / big if big > 0 else 0.0,
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


def study_bodies_and_rods(folder, text, res):
    """BodiesAndRods.dat's buoyant cable (lines 4 to 6 over free points 8
    and 9, from an anchor to the float's reference point) with the float
    held at stancf's equilibrium (`res`), its lines 4 to 6 in 1, 2, 4 and
    8 times the deck's segments, against the closed-form catenaries of
    the three lines (cable_closed_form). Returns a dict of the runs and
    numbers."""
    os.makedirs(folder, exist_ok=True)
    float_row = res["bodies"][1]
    opts = options(text)
    g, rho = float(opts.get("g", 9.80665)), float(opts.get("WtrDnsty", 1025.0))
    depth = float(opts["WtrDpth"])
    types = {f[0]: f for _, f in table_rows(text, "LINE TYPES")}
    lines = {int(f[0]): f for _, f in table_rows(text, "LINES")}
    points = {int(f[0]): f for _, f in table_rows(text, "POINTS")}
    held = with_rows_replaced(text, "BODIES", lambda f: f[:1] + ["Fixed"] + [
        "%r" % float_row[c] for c in ("x", "y", "z", "roll", "pitch", "yaw")] + f[8:])
    held = with_rows_replaced(held, "RODS", lambda f: None if rod_kind(f) == "pinned to a body"
                              else f)
    out = dict(refined=[])
    for factor in (1, 2, 4, 8):
        t = with_rows_replaced(held, "LINES", lambda f: f[:5] + [str(int(f[5]) * factor)] + f[6:]
                               if int(f[0]) >= 4 else f)
        path = os.path.join(folder, "held_x%d.txt" % factor)
        with open(path, "w") as f:
            f.write(t)
        r = stancf_run(path, os.path.join(folder, "stancf_held_x%d" % factor))
        out["refined"].append((factor, r))
    # The closed form: lines 6, 5, 4 from the float's point 10 down to the
    # anchor, point 7.
    def wet(name):
        f = types[name]
        d, m = float(f[1]), float(f[2])
        return (m - rho * math.pi * d * d / 4) * g, float(f[3])
    segs = []
    for n in (6, 5, 4):
        w, ea = wet(lines[n][1])
        segs.append((float(lines[n][4]), w, ea))
    top = np.array([float_row["x"], float_row["z"]])
    anchor = np.array([float(points[7][2]), float(points[7][4])])
    out["closed"] = cable_closed_form(top, anchor, -depth, segs)
    return out


def cable_closed_form(top, anchor, bed, segs, n=20000):
    """The equilibrium of elastic catenaries in series in a vertical plane
    (x, z), hung from `top` down to `anchor` on the bed z = `bed`, the
    last one's end part lying on the frictionless bed: each (length, wet
    weight per length, EA), their joints weightless. Shooting from the
    top on (H, V_top), the horizontal tension (the same in every line)
    and the top's vertical pull, the lines integrated by the midpoint
    rule in n steps each, the touchdown where V reaches 0 on the bed;
    Newton on the miss of the anchor. Returns H, V_top and the joints'
    (x, z)."""
    def shoot(h, v):
        x, z = top
        joints = []
        for k, (length, w, ea) in enumerate(segs):
            ds = length / n
            for i in range(n):
                vm = v - 0.5 * w * ds
                t = math.hypot(h, vm)
                st = ds * (1 + t / ea)
                xn, zn = x - h / t * st, z - vm / t * st
                if k == len(segs) - 1 and zn <= bed and vm <= 0:
                    rest = length - (i + 0.5) * ds
                    return np.array([xn - rest * (1 + h / ea) - anchor[0], zn - anchor[1]]), joints
                x, z, v = xn, zn, v - w * ds
            joints.append((x, z))
        return np.array([x - anchor[0], z - anchor[1]]), joints

    p = np.array([100.0, sum(w * length for length, w, _ in segs[:1])])
    for _ in range(200):
        miss, _ = shoot(*p)
        if np.max(np.abs(miss)) < 1e-7:
            break
        jac = np.zeros((2, 2))
        for j in range(2):
            q = p.copy()
            q[j] += 1e-6 * max(abs(p[j]), 1.0)
            jac[:, j] = (shoot(*q)[0] - miss) / (q[j] - p[j])
        step = np.linalg.solve(jac, miss)
        cut = min(1.0, 0.1 * abs(p[0]) / max(abs(step[0]), 1e-30),
                  0.1 * abs(p[1]) / max(abs(step[1]), 1e-30))
        p = p - cut * step
    miss, joints = shoot(*p)
    return dict(H=p[0], V=p[1], joints=joints, miss=float(np.max(np.abs(miss))))

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
    st = res["stancf"]
    fl = st["bodies"][1]
    s = study_bodies_and_rods(os.path.join(res["folder"], "study"), res["text"], st)
    c = s["closed"]
    lines = ["### BodiesAndRods.dat: stancf solves it, MoorDyn does not settle it", ""]
    text = ("stancf reaches the equilibrium by pseudo-transient continuation (docs/method.md "
            "§6.9, (M26b): summary.json's static_path is \"%s\") in %.1f s: the float at "
            "(%.4f, %.4f, %.4f) m pitched %.3f deg, the flap upright; its balance in force and "
            "moment is checked by hand in `cargo test --release -p stancf-cli --test cli "
            "joints::moordyns_bodies_and_rods`. "
            % (st["summary"].get("static_path"), st["wall"], fl["x"], fl["y"], fl["z"],
               fl["pitch"]))
    text += ("The deck's buoyant cable is too coarse for its shape: with the float held at that "
             "pose, the anchor's horizontal pull H and the free points against the closed-form "
             "catenaries of lines 6, 5 and 4 (H = %.1f N, points 9 and 8 at x, z = %s m):"
             % (c["H"], ", ".join("(%.2f, %.2f)" % j for j in c["joints"][:2])))
    lines += [text, "", "| segments | H (N) | difference | point 9 (m) | point 8 (m) |",
              "|---|---|---|---|---|"]
    for factor, r in s["refined"]:
        if r["rc"] != 0:
            lines.append("| x%d | the static solve fails (exit %d) | | | |" % (factor, r["rc"]))
            continue
        h = r["points"][7]["fx"]
        p9, p8 = r["points"][9], r["points"][8]
        lines.append("| x%d | %.1f | %.2f %% | (%.2f, %.2f) | (%.2f, %.2f) |" % (
            factor, h, 100 * (h - c["H"]) / c["H"], p9["x"], p9["z"], p8["x"], p8["z"]))
    lines += ["", "Line 6 hangs in a U of radius H/w = %.2f m at its bottom, which the deck's "
              "8.3 m segments do not follow; on such meshes the discrete cable has more than one "
              "equilibrium, and which one the static solve reaches depends on its seeds."
              % (c["H"] / segs_weight(res["text"]))]
    return lines


def segs_weight(text):
    """The wet weight per length (N/m) of the deck's line 6's type."""
    types = {f[0]: f for _, f in table_rows(text, "LINE TYPES")}
    lines = {int(f[0]): f for _, f in table_rows(text, "LINES")}
    f = types[lines[6][1]]
    d, m = float(f[1]), float(f[2])
    return (m - 1025.0 * math.pi * d * d / 4) * 9.80665

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
