"""Line failures from Python (docs/interface.md, "Line failures";
docs/method.md §11.16): a scenario's failures reach a run through
``stancf.run`` and a coupled ``stancf.Simulation``, which lets go of a
fairlead's line in its own steps and says so in ``releases``."""

import math

import numpy as np
import pytest

import stancf

# Two 80 m chains from anchors 100 m apart to a fairlead (point 3)
# between them, 10 m under the surface; chain 2 lets go of the fairlead
# at t = 1 s.
DECK = """Two chains to a fairlead, one let go of
--- LINE TYPES ---
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
chain 0.05 50 1e8 -0.8 0 1.2 1 0.4 0.5
--- POINTS ---
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed 0 0 -50 0 0 0 0
2 Fixed 100 0 -50 0 0 0 0
3 Coupled 50 0 -10 0 0 0 0
--- LINES ---
ID LineType AttachA AttachB UnstrLen NumSegs Outputs
(#) (name) (#) (#) (m) (-) (-)
1 chain 1 3 80 8 -
2 chain 2 3 80 8 -
--- FAILURE ---
FailureID Point Line(s) FailTime FailTen
() () (,) (s) (N)
1 3 2 1.0 0
--- OPTIONS ---
0.002 dtM
60 WtrDpth
--- need this line ---
"""


def test_a_fairlead_let_go_of_by_one_chain_is_pulled_by_the_other_alone(tmp_path):
    # Held at its place, the fairlead is pulled down between two equal
    # chains (fx = 0 by symmetry, to the static solve's tolerance). After
    # chain 2 lets go at t = 1 s, chain 1, at rest in its equilibrium at a
    # fairlead that does not move, goes on as it was: its pull alone,
    # toward anchor 1 (fx < 0), down by half of the two chains' (to the
    # static solve's and Newton's tolerances).
    (tmp_path / "deck.txt").write_text(DECK)
    sim = stancf.Simulation(tmp_path / "deck.txt")
    x = sim.initial_positions()
    before = sim.initialize(x)
    size = np.linalg.norm(before)
    assert abs(before[0]) < 1e-6 * size
    assert sim.releases == []
    forces = {}
    for k in range(1, 11):
        forces[0.5 * k] = sim.step_to(0.5 * k, x)
    assert len(sim.releases) == 1
    r = sim.releases[0]
    assert r["failure"] == 1 and r["trigger"] == "time" and r["tension"] is None
    assert r["lines"] == [2] and r["new_point"] == 4
    assert r["t"] == pytest.approx(1.0, abs=1e-9)
    assert abs(forces[0.5][0]) < 1e-6 * size
    after = forces[5.0]
    assert after[0] < -0.05 * size, after
    assert abs(after[2] - 0.5 * before[2]) < 1e-6 * size, (after, before)


def test_a_run_reports_its_failures_in_the_summary(tmp_path):
    (tmp_path / "deck.txt").write_text(DECK)
    scenario = tmp_path / "run.toml"
    scenario.write_text(
        '[system]\nmoordyn = "deck.txt"\n[analysis]\ntype = "dynamic"\n'
        'time_step = 0.05\nduration = 1.5\ntime_scheme = "galerkin"\n'
    )
    res = stancf.run(stancf.Scenario.from_file(scenario), out=tmp_path / "out")
    (failure,) = res.summary["failures"]
    assert failure["point"] == "point 3" and failure["lines"] == [2]
    assert failure["released"]["t"] == pytest.approx(1.0)
    assert failure["released"]["new_point"] == 4
    assert failure["dropped"] is None
    points = np.genfromtxt(res.directory / "points.csv", delimiter=",", names=True)
    new = points[points["point"] == 4]
    assert new["t"][0] == pytest.approx(1.0)
    assert math.isfinite(new["z"][-1])


def test_a_failure_of_a_line_elsewhere_is_refused_naming_the_row(tmp_path):
    (tmp_path / "deck.txt").write_text(DECK.replace("1 3 2 1.0 0", "1 1 2 1.0 0"))
    with pytest.raises(stancf.ScenarioError, match=r"line 20: failure 1: line 2 is not attached to 1"):
        stancf.Scenario.from_file(tmp_path / "deck.txt")


def test_a_coupled_step_above_p2s_stable_step_fails_the_call(tmp_path):
    # The deck's chains at dtM 0.05 s, twenty times P2's stable step
    # (0.00234 s, `stancf check`): the energy watchdog stops the call at
    # the step that grew, where the held fairlead's forces went wild
    # unreported before.
    (tmp_path / "deck.txt").write_text(DECK.replace("0.002 dtM", "0.05 dtM"))
    sim = stancf.Simulation(tmp_path / "deck.txt")
    x = sim.initial_positions()
    sim.initialize(x)
    with pytest.raises(stancf.SolverError, match="energy"):
        for k in range(1, 11):
            sim.step_to(0.5 * k, x)
    assert sim.time < 5.0
