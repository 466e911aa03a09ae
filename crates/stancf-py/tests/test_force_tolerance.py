"""Steps chosen by a tolerance on the end forces from Python
(`analysis.force_tolerance`, docs/method.md §11.17): the jumper example
over its first 40 s, against fixed steps of 0.05 s (forces at t)."""

from pathlib import Path

import numpy as np

import stancf

ROOT = Path(__file__).resolve().parents[3]


def top_tension(res):
    return res.tensions[(1, "B")]["tension"]


def test_a_tighter_force_tolerance_lands_closer_to_fine_fixed_steps():
    jumper = stancf.Scenario.from_file(ROOT / "examples" / "jumper-tolerance.toml").with_values(
        {"analysis.duration": 40.0})
    # The same jumper in fixed Galerkin steps of 0.05 s, written every 2 s.
    fixed = (jumper.text.replace("force_tolerance = 1e-3", 'time_scheme = "galerkin"')
             .replace("time_step = 2.0", "time_step = 0.05")
             + '\n[output]\nend_forces = "at_time"\nevery = 40\n')
    fine = stancf.run(stancf.Scenario(fixed, jumper.name))
    assert np.allclose(fine.t, np.arange(0.0, 40.0 + 1e-9, 2.0))
    errors = []
    for tol in (1e-2, 1e-4):
        res = stancf.run(jumper.with_values({"analysis.force_tolerance": tol}))
        control = res.summary["step_control"]
        assert control["force_tolerance"] == tol and control["longest_step"] <= 2.0
        assert np.allclose(res.t, fine.t, rtol=0, atol=1e-9)
        errors.append((np.max(np.abs(top_tension(res) - top_tension(fine))), control["steps"]))
    # 100 times tighter: more steps, each with a smaller local error, and
    # closer (measured: 167 N in 20 steps, 25 N in 63; the top tension is
    # about 45 kN: 0.37 and 5.5 times the tolerance, docs/method.md §11.17).
    assert errors[1][1] > errors[0][1], errors
    assert errors[1][0] < errors[0][0], errors
