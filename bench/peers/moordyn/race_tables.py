"""The MoorDyn race's tables and figure (see race.py): the rows of a
run as CSV, per problem the cheapest run of each code within 1, 0.5,
0.25 and 0.1 % and their ratio, every run, and the work-precision
figure."""
import csv
import os


def read_rows(path):
    """The rows of a race's CSV (numbers as numbers, blanks as "")."""
    with open(path, newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k in ("segments", "dt", "ic_s", "wall_s", "error", "driver_s"):
            if r.get(k, "") != "":
                r[k] = int(r[k]) if k == "segments" else float(r[k])
            else:
                r[k] = ""
        r["mesh"] = r.get("mesh") or "uniform"
    return rows


def to_answer(r):
    """The whole time a user waits for a run: MoorDyn's initial-condition
    generation and its simulation; stancf's process (its start and static
    solve, `ic_s`, and its steps, `wall_s`; rows of races before
    2026-11-29's second half have the whole process in `wall_s`)."""
    return r["wall_s"] + (r["ic_s"] if r["ic_s"] != "" else 0.0)


def cheapest(rows, code, level, uniform_only=False, cost=lambda r: r["wall_s"]):
    """The cheapest run of `code` within `level` by `cost` (on the deck's
    uniform mesh only, if asked)."""
    ok = [r for r in rows if r["code"] == code and r["error"] != "" and r["error"] <= level
          and (not uniform_only or r["mesh"].startswith("uniform"))]
    return min(ok, key=cost) if ok else None


def run_text(r):
    """ "60 segments, dt 0.005 (0.889 %)", the mesh named if in sections."""
    mesh = "" if r["mesh"] == "uniform" else " in %s" % r["mesh"]
    mesh = mesh.replace(" in uniform, between steps", ", between steps")
    mesh = mesh.replace(" in uniform, force tolerance", ", force tolerance")
    return "%d segments%s, dt %g (%.3g %%)" % (r["segments"], mesh, r["dt"], 100 * r["error"])


def summary_table(rows, pb):
    """The ratios at 1 % and 0.1 % of problem `pb` (markdown lines)."""
    lines = ["## %s" % pb.title, "",
             "| accuracy | MoorDyn cheapest (s) | run | stancf cheapest (s) | run "
             "| MoorDyn / stancf | stancf, deck's uniform mesh (s) | MoorDyn / stancf uniform "
             "| time to the answer: MoorDyn IC + simulation (s) | MoorDyn / stancf, to the answer |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    # Where MoorDyn reaches neither 1 % nor 0.1 %: also the accuracy of
    # its most accurate run (what stancf needs to match it).
    best = [r["error"] for r in rows if r["code"] == "moordyn" and r["error"] != ""]
    # 0.5 % and 0.25 % between them: how the ratio moves with accuracy.
    levels = [(0.01, "1 %"), (0.005, "0.5 %"), (0.0025, "0.25 %"), (0.001, "0.1 %")]
    if best and min(best) > 0.01:
        levels.append((min(best), "MoorDyn's best, %.3g %%" % (100 * min(best))))
    ratio = lambda a, b: "%.2f" % (a["wall_s"] / b["wall_s"]) if a and b else "-"
    for level, label in levels:
        m, s_ = cheapest(rows, "moordyn", level), cheapest(rows, "stancf", level)
        u = cheapest(rows, "stancf", level, uniform_only=True)
        cells = [("%.2f" % r["wall_s"], run_text(r)) if r else ("-", "not reached")
                 for r in (m, s_)]
        a = cheapest(rows, "moordyn", level, cost=to_answer)
        sa = cheapest(rows, "stancf", level, cost=to_answer)
        answer = ("%.2f (%d segments)" % (to_answer(a), a["segments"]), "%.2f" % (
            to_answer(a) / to_answer(sa)) if sa else "-") if a else ("-", "-")
        lines.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            label, cells[0][0], cells[0][1], cells[1][0], cells[1][1], ratio(m, s_),
            "%.2f" % u["wall_s"] if u else "not reached", ratio(m, u), answer[0], answer[1]))
    ref = [r for r in rows if r["code"] == "stancf reference"]
    check = [r for r in rows if r["code"] == "stancf reference check" and r["error"] != ""]
    if ref:
        lines += ["", "Reference: stancf, %d elements%s, dt %g." % (
            ref[0]["segments"], "" if ref[0]["mesh"] == "uniform" else " in " + ref[0]["mesh"],
            ref[0]["dt"])]
        if check:
            lines[-1] += (" The same with about half the elements and twice the step differs "
                          "from it by %.3g %% (the reference's own error is of that order or "
                          "smaller)." % (100 * check[0]["error"]))
    lines += ["", "| code | segments | mesh | dt (s) | MoorDyn IC / stancf start and statics "
              "(s) | simulation (s) | MoorDyn driver (s, not in wall) | error (% of range) |",
              "|---|---|---|---|---|---|---|---|"]
    for r in rows:
        err = "%.3g" % (100 * r["error"]) if r["error"] != "" else "failed"
        wall = "%.2f" % r["wall_s"] if r["wall_s"] != "" else "-"
        ic = "%.2f" % r["ic_s"] if r["ic_s"] != "" else ""
        driver = "%.2f" % r["driver_s"] if r["driver_s"] != "" else ""
        lines.append("| %s | %d | %s | %g | %s | %s | %s | %s |" % (
            r["code"], r["segments"], r["mesh"], r["dt"], ic, wall, driver, err))
    return lines + [""]


def write(rows, all_problems, out):
    """moordyn_race.csv, .md (per problem: the ratios, every run) and .png
    (work-precision, one panel per problem) in the folder `out`, for the
    problems of `all_problems` that have rows."""
    with open(os.path.join(out, "moordyn_race.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    problems = [pb for pb in all_problems if any(r["problem"] == pb.name for r in rows)]
    lines = ["# The race against MoorDyn (this machine, one run)", "",
             "The simulation's time: MoorDyn's after its initial conditions (its Python "
             "driver's own time taken out), stancf's steps and their writing after its "
             "static solve (summary.json's `stepping_wall_time_s`). The time to the answer: "
             "MoorDyn's initial conditions and simulation; stancf's whole process.", ""]
    for pb in problems:
        lines += summary_table([r for r in rows if r["problem"] == pb.name], pb)
    with open(os.path.join(out, "moordyn_race.md"), "w") as f:
        f.write("\n".join(lines))
    print("\n".join(lines))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, axes = plt.subplots(1, len(problems), figsize=(6.0 * len(problems), 4.5), squeeze=False)
    for ax, pb in zip(axes[0], problems):
        for code, uniform, between, marker, label in [
                ("moordyn", True, False, "s", "MoorDyn"),
                ("stancf", True, False, "o", "stancf, the deck's uniform mesh"),
                ("stancf", False, False, "^", "stancf, touchdown in sections"),
                ("stancf", True, True, "D", "stancf, uniform, written between steps"),
                ("stancf", False, True, "v", "stancf, sections, written between steps"),
                ("stancf", None, None, "*", "stancf, steps chosen by a force tolerance")]:
            controlled = uniform is None
            pts = [(r["wall_s"], r["error"]) for r in rows if r["problem"] == pb.name
                   and r["code"] == code and r["error"] not in ("", 0.0)
                   and ("force tolerance" in r["mesh"]) == controlled
                   and (controlled or (r["mesh"].startswith("uniform") == uniform
                                       and r["mesh"].endswith("between steps") == between))]
            if pts:
                x, y = zip(*sorted(pts))
                ax.loglog(x, [100 * v for v in y], marker, label=label)
        for level in (1.0, 0.1):
            ax.axhline(level, color="grey", lw=0.8, ls="--")
        ax.set_xlabel("simulation's wall time (s)")
        ax.set_ylabel("fairlead tension error (% of range)")
        ax.set_title(pb.title)
        ax.grid(True, which="both", alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(out, "moordyn_race.png"), dpi=120)
