"""A FAST.Farm farm-level deck from Python (docs/interface.md, "MoorDyn
decks"): its turbines found in the FAST.Farm input beside it, each
turbine's platform six coupled degrees of freedom, as FAST.Farm moves
each turbine's platform."""

import shutil
from pathlib import Path

import numpy as np
import pytest

import stancf

FIXTURES = Path(__file__).resolve().parents[2] / "stancf-cli" / "tests" / "fixtures"

FSTF = """------- FAST.Farm for OpenFAST INPUT FILE -------
Two turbines with shared moorings
"SharedMooring2.dat" SharedMoorFile  - shared mooring input file
2                 NumTurbines        - Number of wind turbines (-)
WT_X     WT_Y  WT_Z     WT_FASTInFile
(m)      (m)   (m)      (string)
   0.000 0     0.000    "T1.fst"
1600.000 0     0.000    "T2.fst"
--- WAKE DYNAMICS ---
"""


def test_each_turbine_of_a_farm_deck_is_six_coupled_degrees_of_freedom(tmp_path):
    deck = tmp_path / "SharedMooring2.dat"
    shutil.copy(FIXTURES / "fast-farm-shared-mooring.dat", deck)
    (tmp_path / "FAST.Farm.fstf").write_text(FSTF)
    sim = stancf.Simulation(deck)
    assert sim.coupled_dof == 12 and len(sim.coupled_body_ids) == 2
    x0 = np.array(sim.initial_positions())
    assert np.array_equal(x0[:3], [0.0, 0.0, 0.0]) and np.array_equal(x0[6:9], [1600.0, 0.0, 0.0])
    f0 = np.array(sim.initialize(x0))
    # The shared line pulls the turbines towards each other: turbine 1
    # towards +x less than its anchors pull it to -x, so the net x forces
    # have the signs of the equilibrium's (bodies.csv of the CLI test).
    assert f0[0] < 0 and f0[6] < 0
    # The equilibrium with turbine 2 surged 5 m away from turbine 1: the
    # shared line pulls it back harder, and turbine 1 towards it.
    x1 = x0.copy()
    x1[6] += 5.0
    f1 = np.array(stancf.Simulation(deck).initialize(list(x1)))
    assert f1[6] < f0[6] - 1e4 and f1[0] > f0[0] + 1e4
    # A step from that equilibrium with both platforms held keeps its
    # forces, to the steps' Newton tolerance (1e-10 of the scaled rows;
    # measured 1e-13).
    sim = stancf.Simulation(deck)
    sim.initialize(list(x1))
    f = np.array(sim.step_to(1e-3, list(x1)))
    assert np.max(np.abs(f - f1)) <= 1e-9 * np.max(np.abs(f1))


def test_a_host_places_the_turbines_of_a_farm_deck_without_its_fast_farm_input(tmp_path):
    deck = tmp_path / "SharedMooring2.dat"
    shutil.copy(FIXTURES / "fast-farm-shared-mooring.dat", deck)
    with pytest.raises(stancf.ScenarioError, match="point 1 is on turbine 1"):
        stancf.Simulation(deck)
    hosted = stancf.Simulation(deck, turbines=[[0.0, 0.0, 0.0], [1600.0, 0.0, 0.0]])
    f_hosted = np.array(hosted.initialize(hosted.initial_positions()))
    (tmp_path / "FAST.Farm.fstf").write_text(FSTF)
    beside = stancf.Simulation(deck)
    f_beside = np.array(beside.initialize(beside.initial_positions()))
    assert np.array_equal(f_hosted, f_beside)
    with pytest.raises(ValueError, match="each turbine's position is"):
        stancf.Simulation(deck, turbines=[[0.0, 0.0]])
