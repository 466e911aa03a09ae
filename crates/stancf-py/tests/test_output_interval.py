"""`[output] interval` from Python (docs/method.md §6.5a): a system stepped
at 1 s and written every 0.25 s from the steps' cubics, the same scenario
code as the command line's; its times are the interval's multiples and
where a step ends its tension is the run's written at its steps."""

import csv
import shutil
from pathlib import Path

import stancf

ROOT = Path(__file__).resolve().parents[3]


def oc4(tmp_path, output):
    shutil.copy(ROOT / "examples" / "oc4-deepcwind-moordyn.txt", tmp_path / "deck.txt")
    scenario = tmp_path / ("%s.toml" % output.split()[0])
    scenario.write_text(
        '[system]\nmoordyn = "deck.txt"\n[[motions]]\npoint = 4\namplitude = [8.0, 0.0, 0.0]\n'
        'period = 100.0\nramp = 100.0\n[analysis]\ntype = "dynamic"\ninitial = "static"\n'
        'time_step = 1.0\nduration = 5.0\ntime_scheme = "galerkin"\n[output]\n'
        'end_forces = "at_time"\n%s\nfiles = ["tensions.csv"]\n' % output)
    res = stancf.run(scenario, out=tmp_path / output.split()[0])
    with open(res.directory / "tensions.csv") as f:
        return {(float(r["t"]), r["line"], r["end"]): float(r["tension"])
                for r in csv.DictReader(f)}


def test_a_system_is_written_between_its_steps_from_python(tmp_path):
    between = oc4(tmp_path, "interval = 0.25")
    steps = oc4(tmp_path, "every = 1")
    times = sorted({t for t, _, _ in between})
    assert times == [0.25 * k for k in range(21)]
    for key, tension in steps.items():
        assert abs(between[key] - tension) <= 1e-9 * tension, key
