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


def top_from_rest(t):
    """The jumper's top as a host moves it: 10 m along x over its 27 s
    period from rest, x = x0 + 5 (1 - cos(2 pi t / 27))."""
    w = 2.0 * np.pi / 27.0
    return [5.0 * (1.0 - np.cos(w * t)), 0.0, -5.0], [5.0 * w * np.sin(w * t), 0.0, 0.0]


def coupled_top_forces(scenario, tolerance, every, duration):
    """The interval means of the force on the top over a host's calls every
    `every` s, and the internal steps of each call (the scenario's
    force_tolerance is `tolerance`)."""
    sim = stancf.Simulation(scenario)
    assert sim.force_tolerance == tolerance
    sim.initialize(*top_from_rest(0.0))
    means, steps = [], []
    for k in range(1, round(duration / every) + 1):
        sim.step_to(k * every, *top_from_rest(k * every))
        means.append(sim.interval_mean_force)
        steps.append(sim.last_steps)
    return np.array(means), np.array(steps)


def test_a_coupled_system_takes_the_steps_its_force_tolerance_needs():
    """A host couples the jumper every 1 s for one period; the scenario's
    force_tolerance (its time_step of 2 s the longest step) chooses the
    handle's internal steps, as `stancf.run` chooses them. Against fixed
    Galerkin steps of 0.05 s: each interval's steps are kept halves (an
    even count), the interval means are within the kept steps times the
    tolerance of the top's largest force (the bound of the Rust test,
    coupled_tolerance.rs), and 100 times tighter takes more steps and
    lands closer."""
    jumper = stancf.Scenario.from_file(ROOT / "examples" / "jumper-tolerance.toml")
    fixed = jumper.text.replace("force_tolerance = 1e-3", 'time_scheme = "galerkin"').replace(
        "time_step = 2.0", "time_step = 0.05")
    fine, fine_steps = coupled_top_forces(stancf.Scenario(fixed, jumper.name), None, 1.0, 27.0)
    assert (fine_steps == 20).all()
    scale = np.abs(fine).max()
    runs = []
    for tol in (1e-2, 1e-4):
        sc = jumper.with_values({"analysis.force_tolerance": tol})
        means, steps = coupled_top_forces(sc, tol, 1.0, 27.0)
        assert (steps >= 2).all() and (steps % 2 == 0).all()
        error = np.abs(means - fine).max() / scale
        kept = steps.sum() // 2
        print(f"tol {tol}: {kept} kept steps, interval means off by {error:.3e}")
        assert error <= kept * tol
        runs.append((error, kept))
    assert runs[1][1] > runs[0][1] and runs[1][0] < runs[0][0], runs
