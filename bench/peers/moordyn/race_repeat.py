"""The race's cheapest runs at 1 % again, each repeated (`./run.sh
--repeat-cheapest [N]`, N = 5 by default, a few minutes): the race times
every run once, on a shared machine whose load moves a run's time by
tens of percent (MoorDyn's 60 OC4 segments took 0.79 to 1.18 s in four
races), so a ratio from one pair of runs carries that noise. Here each
problem's cheapest run of each code within 1 % (read from
out/moordyn_race.csv, the last race; stancf's fixed steps, not its
force-tolerance series) runs N times, the two codes in alternation,
timed as the race times them (MoorDyn's simulation without its initial
conditions and its Python driver, stancf's steps and their writing), and
out/race_repeat.md gives each code's least and median time and their
ratios. The riser is left out: MoorDyn's cheapest run at 1 % takes two
minutes and the ratio was above 50.
"""
import os
import sys

import race
sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
from repeat_runs import repeat_alternating, table_row, write_table  # noqa: E402
from race_problems import OC4, STEEP, segments
from race_tables import cheapest, read_rows, run_text

LEVEL = 0.01


def cheapest_runs(rows, pb):
    """(MoorDyn's, stancf's) cheapest rows within 1 % on `pb`."""
    mine = [r for r in rows if r["problem"] == pb.name and "force tolerance" not in r["mesh"]]
    return cheapest(mine, "moordyn", LEVEL), cheapest(mine, "stancf", LEVEL)


def rerun(pb, row):
    """A callable that runs `row` of `pb` again and returns the time the
    race takes for it."""
    dt = float(row["dt"])
    if row["code"] == "moordyn":
        refine = row["segments"] / segments(pb, 1)

        def moordyn():
            out = race.run_moordyn(pb, refine, dt)
            if out is None:
                sys.exit("MoorDyn failed on %r" % row)
            return out[1]
        return moordyn
    mesh = row["mesh"]
    sections = None
    if mesh.startswith("sections "):
        sections = tuple(int(k) for k in mesh.split()[1].rstrip(",").split("/"))
    refine = 1 if sections else row["segments"] / segments(pb, 1)

    def stancf():
        out = race.run_stancf(pb, refine, dt, race.RACE_TOLERANCE, sections,
                              between="between steps" in mesh)
        if out is None:
            sys.exit("stancf failed on %r" % row)
        return out[3]["stepping_wall_time_s"]
    return stancf


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    rows = read_rows(os.path.join(race.OUT, "moordyn_race.csv"))
    lines = ["The race's cheapest runs within 1 %% (out/moordyn_race.csv), each run %d times, "
             "the codes in alternation, on this machine:" % n, "",
             "| problem | MoorDyn run | stancf run | MoorDyn least / median (s) | "
             "stancf least / median (s) | MoorDyn / stancf, least | of medians |",
             "|---|---|---|---|---|---|---|"]
    for pb in (OC4, STEEP):
        md, st = cheapest_runs(rows, pb)
        if md is None or st is None:
            lines.append("| %s | none within 1 %% | | | | | |" % pb.name)
            continue
        runs = (rerun(pb, md), rerun(pb, st))
        least, median = repeat_alternating(pb.name, runs, n)
        lines.append(table_row(pb.name, (run_text(md), run_text(st)), least, median))
    write_table(os.path.join(race.OUT, "race_repeat.md"), lines)


if __name__ == "__main__":
    main()
