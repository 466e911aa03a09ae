"""A rod pinned to a coupled body from Python (docs/method.md §15.17):
the host lifts the body at 2 m/s^2 and the rod pulls it down by its
weight less its buoyancy plus its mass times the lift,
-(m (g + a) - rho V g) (B35)."""

import math
from pathlib import Path

import numpy as np
import pytest

from stancf import ScenarioError
from stancf.simulation import Simulation

ROOT = Path(__file__).resolve().parents[3]

SCENARIO = """title = "rod on a coupled body"
[water]
depth = 50.0
density = 1025.0
[[bodies]]
id = 1
type = "coupled"
position = [0.0, 0.0, -10.0]
[[rod_types]]
name = "pipe"
diameter = 0.2
mass_per_length = 60.0
[[rods]]
id = 1
type = "pinned"
body = 1
rod_type = "pipe"
end_a = [0.0, 0.0, -0.6]
end_b = [0.0, 0.0, -4.6]
segments = 4
[analysis]
type = "dynamic"
initial = "static"
time_step = 0.05
duration = 0.05
"""


def test_a_lifted_body_is_pulled_by_the_rod_pinned_under_it(tmp_path):
    path = tmp_path / "rod.toml"
    path.write_text(SCENARIO)
    sim = Simulation(str(path))
    assert sim.coupled_dof == 6
    g, mass = 9.81, 240.0
    lift = 1025.0 * math.pi * 0.01 * 4.0 * g
    f0 = sim.initialize(np.array([0.0, 0.0, -10.0, 0.0, 0.0, 0.0]), np.zeros(6))
    assert abs(f0[2] + (mass * g - lift)) < 1e-9 * mass * g
    for k in range(1, 11):
        t = 0.05 * k
        x = np.array([0.0, 0.0, -10.0 + t * t, 0.0, 0.0, 0.0])
        xd = np.array([0.0, 0.0, 2.0 * t, 0.0, 0.0, 0.0])
        f = sim.step_to(t, x, xd)
    assert abs(f[2] + (mass * (g + 2.0) - lift)) < 1e-9 * mass * g


# A CoupledPinned body carrying a can (the Rust test's deck).
DECK = (
    ROOT / "crates" / "stancf-cli" / "tests" / "fixtures" / "coupled-pinned-can-moordyn.txt"
).read_text()


def test_a_coupled_pinned_body_takes_three_numbers_and_pulls_by_its_wet_weight(tmp_path):
    """MoorDyn's CoupledPinned body: its reference point the host's, 3
    numbers in the coupling arrays, its pull at rest -(m - rho V) g."""
    path = tmp_path / "pinned.txt"
    path.write_text(DECK)
    sim = Simulation(str(path))
    assert sim.coupled_dof == 3
    f = sim.initialize(np.array([0.0, 0.0, -5.0]))
    wet_weight = (50_000.0 - 1025.0 * math.pi * 10.0) * 9.80665
    assert abs(f[2] + wet_weight) < 1e-9 * wet_weight
    assert abs(f[0]) < 1e-9 * wet_weight and abs(f[1]) < 1e-9 * wet_weight


def test_moordyns_count_for_a_coupled_pinned_body_is_refused_naming_why(tmp_path):
    """MoorDyn-C 2.7's NCoupledDOF counts 6 per CoupledPinned body, but it
    reads 3 per such body: an array of its count (here 6 for 3) is refused
    with both counts named, nothing started."""
    path = tmp_path / "pinned.txt"
    path.write_text(DECK)
    sim = Simulation(str(path))
    with pytest.raises(ScenarioError) as e:
        sim.initialize(np.array([0.0, 0.0, -5.0, 0.0, 0.0, 0.0]))
    message = str(e.value)
    assert "NCoupledDOF counts 6 per CoupledPinned body" in message
    assert "give the 3 values" in message
    with pytest.raises(ScenarioError) as e:
        sim.initialize(np.array([0.0, 0.0, -5.0, 0.0]))
    assert "NCoupledDOF" not in str(e.value) and "expected 3 values" in str(e.value)
    f = sim.initialize(np.array([0.0, 0.0, -5.0]))
    assert len(f) == 3


ROD_DECK = DECK[: DECK.index("---------------------- BODIES")] + DECK[
    DECK.index("---------------------- RODS") :
].replace(
    "1    Can      Body1       0     0     -5    0     0     -15   3        -",
    "1    Can      CoupledPinned  0  0     -5    0     0     -15   3        -",
)


def test_a_coupled_pinned_rod_takes_three_numbers_and_pulls_by_its_wet_weight(tmp_path):
    """MoorDyn's CoupledPinned rod: its end A the host's, 3 numbers in the
    coupling arrays, its pull at rest -(m - rho V) g; lifted at 2 m/s^2,
    -((m + m_a) a + (m - rho V) g) with its caps' added mass m_a."""
    assert "CoupledPinned" in ROD_DECK and "BODIES" not in ROD_DECK
    path = tmp_path / "rod.txt"
    path.write_text(ROD_DECK)
    sim = Simulation(str(path))
    assert sim.coupled_dof == 3
    f = sim.initialize(np.array([0.0, 0.0, -5.0]), np.zeros(3))
    mass, displaced = 50_000.0, 1025.0 * math.pi * 10.0
    wet_weight = (mass - displaced) * 9.80665
    assert abs(f[2] + wet_weight) < 1e-9 * wet_weight
    added = 2.0 * 1025.0 * math.pi * 8.0 / 12.0
    lifted = (mass + added) * 2.0 + wet_weight
    for k in range(1, 6):
        t = 0.1 * k
        f = sim.step_to(t, np.array([0.0, 0.0, -5.0 + t * t]), np.array([0.0, 0.0, 2.0 * t]))
        assert abs(f[2] + lifted) < 1e-9 * lifted, (t, f)


COUPLED_ROD_DECK = ROD_DECK.replace("CoupledPinned  0  0", "Coupled        0  0")


def test_a_coupled_rod_takes_six_numbers_and_pushes_by_its_wet_weight_and_inertia(tmp_path):
    """MoorDyn's coupled rod: end A and its angles, 6 numbers; the host
    carries its wet weight at rest and, lifting it at 2 m/s^2, its mass
    and its caps' added mass times the lift (docs/method.md §15.18)."""
    assert "Coupled        0" in COUPLED_ROD_DECK
    path = tmp_path / "rod.txt"
    path.write_text(COUPLED_ROD_DECK)
    sim = Simulation(str(path))
    assert sim.coupled_dof == 6
    f = sim.initialize(np.array([0.0, 0.0, -5.0, 0.0, 0.0, 0.0]), np.zeros(6))
    mass, displaced = 50_000.0, 1025.0 * math.pi * 10.0
    wet_weight = (mass - displaced) * 9.80665
    assert abs(f[2] + wet_weight) < 1e-9 * wet_weight
    assert np.all(np.abs(f[3:]) < 1e-9 * wet_weight)
    added = 2.0 * 1025.0 * math.pi * 8.0 / 12.0
    lifted = (mass + added) * 2.0 + wet_weight
    for k in range(1, 6):
        t = 0.1 * k
        x = np.array([0.0, 0.0, -5.0 + t * t, 0.0, 0.0, 0.0])
        xd = np.array([0.0, 0.0, 2.0 * t, 0.0, 0.0, 0.0])
        f = sim.step_to(t, x, xd)
        assert abs(f[2] + lifted) < 1e-9 * lifted, (t, f)
