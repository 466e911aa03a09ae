"""The Exudyn race's cheapest runs at 0.1 mm again, each repeated
(`./run.sh --repeat-cheapest [N]`, N = 5 by default, about a minute): the
race times every run once, on a shared machine whose load moves a run's
time by tens of percent (Exudyn's pendulum winner took 0.35 to 0.54 s in
the runs of 2026-11-29 and 2026-11-30), so a ratio from one pair of runs
carries that noise. Here the pendulum's and the 16-element impact's
cheapest run of each code within 0.1 mm (read from out/work_precision.csv,
the last race) run N times, the two codes in alternation, timed as the
race times them (Exudyn's SolveDynamic, stancf's time loop with its
writing), and out/race_repeat.md gives each code's least and median time
and their ratios.
"""
import os
import sys

import exudyn_models as em
import race
from repeat_runs import repeat_alternating, table_row, write_table

LEVEL = 0.1


def rerun(problem, row):
    """A callable that runs `row` again and returns its time as the race
    takes it."""
    n, dt = row["elements"], row["dt"]
    if row["code"] == "exudyn":
        solve = em.pendulum if problem == "pendulum" else em.impact
        return lambda: solve(n, dt)[0]
    template = race.PENDULUM if problem == "pendulum" else race.IMPACT
    scheme, _, solver = row["scheme"].partition("/")

    def stancf():
        out = race.run_stancf(template, n, row["element"], dt, scheme,
                              solver=solver or race.SOLVER)
        if out is None:
            sys.exit("stancf failed on %r" % row)
        return out[2]["wall_time_s"]
    return stancf


def text_of(r):
    return "%s %s %d el, dt %.4g (%.3g mm)" % (r["scheme"], r["element"], r["elements"], r["dt"],
                                              r["error_mm"])


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    all_rows = race.read_rows()
    lines = ["The Exudyn race's cheapest runs within 0.1 mm (out/work_precision.csv), each run "
             "%d times, the codes in alternation, on this machine:" % n, "",
             "| problem | Exudyn run | stancf run | Exudyn least / median (s) | "
             "stancf least / median (s) | Exudyn / stancf, least | of medians |",
             "|---|---|---|---|---|---|---|"]
    for problem, elements in (("pendulum", None), ("impact", 16)):
        ex = race.cheapest(all_rows, problem, "exudyn", LEVEL, elements)
        st = race.cheapest(all_rows, problem, "stancf", LEVEL, elements)
        if ex is None or st is None:
            lines.append("| %s | none within 0.1 mm | | | | | |" % problem)
            continue
        name = problem if elements is None else "%s, %d elements" % (problem, elements)
        runs = (rerun(problem, ex), rerun(problem, st))
        least, median = repeat_alternating(name, runs, n)
        lines.append(table_row(name, (text_of(ex), text_of(st)), least, median))
    write_table(os.path.join(race.OUT, "race_repeat.md"), lines)


if __name__ == "__main__":
    main()
