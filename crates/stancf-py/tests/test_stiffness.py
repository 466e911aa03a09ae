"""A free body's and a coupled point's mooring stiffness from Python (docs/interface.md,
"Systems" and "Coupling"; docs/method.md §15.9): ``Result.stiffness``
of a run (its stiffness.csv) and ``Simulation.body_stiffness`` after
``initialize``, on the moored buoy of examples/moored-buoy.toml."""

from pathlib import Path

import numpy as np
import pytest

import stancf

ROOT = Path(__file__).resolve().parents[3]
BUOY = (ROOT / "examples" / "moored-buoy.toml").read_text()
STATIC = BUOY.replace('type = "dynamic"\ninitial = "static"', 'type = "static"')
# The same buoy with its anchors (points 4, 5, 6) moved by a coupling
# code, which holds them where the scenario fixes them, and without the
# push the example gives it at t = 0 (initialize starts at rest).
COUPLED = (BUOY.replace('type = "fixed"', 'type = "coupled"')
           .replace("velocity = [0.5, 0.0, 0.0]", "")
           .replace("angular_velocity = [0.0, 0.0, 0.2]", ""))


def test_a_runs_result_holds_the_matrix_of_its_stiffness_csv(tmp_path):
    assert STATIC != BUOY
    res = stancf.run(stancf.Scenario(STATIC, "buoy.toml"), out=tmp_path / "out")
    assert list(res.stiffness) == [1]
    k = res.stiffness[1]
    assert k.shape == (6, 6)
    # The file's numbers and summary.json's, to the bit.
    assert (tmp_path / "out" / "stiffness.csv").exists()
    assert np.array_equal(k, np.array(res.summary["bodies"][0]["stiffness"]))
    assert np.array_equal(stancf.Result.read(tmp_path / "out").stiffness[1], k)
    # Conservative lines: the translational block is symmetric (to 1e-8
    # of the matrix, the static solve converging to 1e-10), and resists.
    assert np.abs(k[:3, :3] - k[:3, :3].T).max() < 1e-8 * np.abs(k).max()
    assert (np.diag(k)[:3] > 0).all()


def test_a_system_without_free_bodies_has_no_stiffness():
    res = stancf.run(stancf.Scenario.from_file(ROOT / "examples" / "bridle.toml")
                     .with_values({"analysis.duration": 0.01}))
    assert res.stiffness == {}


def test_a_simulations_matrix_is_the_static_runs_at_the_same_equilibrium():
    # initialize with the anchors where the static run fixes them solves
    # the same equilibrium, to the static solve's tolerance (1e-10 of the
    # lines' scale): the matrices agree to 1e-8 of their size.
    assert "velocity = [" not in COUPLED and COUPLED.count('type = "coupled"') == 3
    run = stancf.run(stancf.Scenario(STATIC, "buoy.toml")).stiffness[1]
    sim = stancf.Simulation(stancf.Scenario(COUPLED, "coupled.toml"))
    assert sim.body_ids == [1] and sim.coupled_ids == [4, 5, 6]
    sim.initialize(sim.initial_positions())
    k = sim.body_stiffness(1)
    assert isinstance(k, np.ndarray) and k.shape == (6, 6)
    assert np.abs(k - run).max() < 1e-8 * np.abs(run).max()


def test_body_stiffness_refuses_before_initialize_an_unknown_id_and_a_fixed_body():
    fixed = COUPLED + '[[bodies]]\nid = 7\ntype = "fixed"\nposition = [5.0, 0.0, -20.0]\n'
    sim = stancf.Simulation(stancf.Scenario(fixed, "fixed.toml"))
    assert sim.body_ids == [1, 7]
    with pytest.raises(stancf.ScenarioError, match="body 1: no values before initialize"):
        sim.body_stiffness(1)
    sim.initialize(sim.initial_positions())
    with pytest.raises(KeyError, match="no body 3"):
        sim.body_stiffness(3)
    with pytest.raises(stancf.ScenarioError, match="body 7 is fixed"):
        sim.body_stiffness(7)
    assert sim.body_stiffness(1).shape == (6, 6)


def test_a_coupled_anchors_stiffness_restores_and_a_body_point_has_none():
    # Anchor 4 holds one taut line: its 3 x 3 is the lines' condensed
    # stiffness there, symmetric (a conservative line, to 1e-8 of it, the
    # static solve converging to 1e-10) and restoring.
    sim = stancf.Simulation(stancf.Scenario(COUPLED, "coupled.toml"))
    with pytest.raises(stancf.ScenarioError, match="point 4: no values before initialize"):
        sim.point_stiffness(4)
    sim.initialize(sim.initial_positions())
    k = sim.point_stiffness(4)
    assert isinstance(k, np.ndarray) and k.shape == (3, 3)
    assert np.abs(k - k.T).max() < 1e-8 * np.abs(k).max()
    assert (np.diag(k) > 0).all()
    with pytest.raises(stancf.ScenarioError, match="point 1: no mooring stiffness"):
        sim.point_stiffness(1)
    with pytest.raises(KeyError, match="no point 9"):
        sim.point_stiffness(9)
