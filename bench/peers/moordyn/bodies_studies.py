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
