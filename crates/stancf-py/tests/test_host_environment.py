"""A host's sea from Python (docs/interface.md, "Coupling"):
``stancf.Simulation(deck, water_depth=..., water_density=..., gravity=...)``
fills what a MoorDyn deck leaves out, as OpenFAST gives MoorDyn-F its
WtrDepth, rhoW and g; the deck's own values win."""

from pathlib import Path

import numpy as np
import pytest

import stancf

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "oc4-deepcwind-moordyn.txt"


def without(tmp_path, option):
    lines = EXAMPLE.read_text().splitlines(keepends=True)
    kept = [l for l in lines if l.split()[1:2] != [option]]
    deck = tmp_path / "glue.txt"
    deck.write_text("".join(kept))
    return deck


def fairlead_forces(deck, **host):
    sim = stancf.Simulation(deck, **host)
    return np.array(sim.initialize(sim.initial_positions()))


def test_a_hosts_depth_fills_a_deck_without_wtrdpth_and_the_decks_own_wins(tmp_path):
    glue = without(tmp_path, "WtrDpth")
    rule = fairlead_forces(glue)
    assert np.array_equal(rule, fairlead_forces(glue, water_depth=200.0))
    deeper = fairlead_forces(glue, water_depth=210.0)
    assert np.max(np.abs(deeper - rule)) > 1e-3 * np.max(np.abs(rule))
    own = fairlead_forces(EXAMPLE)
    hosted = fairlead_forces(EXAMPLE, water_depth=210.0, water_density=1100.0, gravity=9.7)
    assert np.array_equal(own, hosted)


def test_a_hosts_bad_value_is_refused_naming_it(tmp_path):
    with pytest.raises(stancf.ScenarioError, match="the host's water depth is -3 m"):
        stancf.Simulation(without(tmp_path, "WtrDpth"), water_depth=-3.0)
