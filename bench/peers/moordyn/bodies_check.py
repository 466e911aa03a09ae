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
from bodies_common import *  # noqa: F401,F403
from bodies_decks import *  # noqa: F401,F403
from bodies_codes import *  # noqa: F401,F403
from bodies_studies import *  # noqa: F401,F403

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
    st = check_and_solve(res, lambda reason: refusal_chain(text, folder, reason))
    if st is None:
        return res
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
    if bar and bar.get("stancf") and bar["stancf"]["rc"] == 0:
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


if __name__ == "__main__":
    main()
