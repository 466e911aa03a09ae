"""A deck whose TmaxIC is 0 starts in ``stancf.Simulation`` as MoorDyn
starts without initial conditions (docs/method.md §13.7): its lines in
their closed-form shapes, no static solve; no mooring stiffness."""

from pathlib import Path

import numpy as np
import pytest

import stancf

OC4 = Path(__file__).resolve().parents[3] / "examples" / "oc4-deepcwind-moordyn.txt"


def oc4_with_tmax_ic(tmp_path, tmax):
    deck = tmp_path / ("oc4-%s.txt" % tmax)
    deck.write_text(OC4.read_text().replace("60.0      TmaxIC", "%s      TmaxIC" % tmax, 1))
    return stancf.Simulation(deck)


def test_a_deck_with_tmaxic_0_starts_from_its_chains_closed_forms(tmp_path):
    """The fairlead forces of the chains' closed form resting on the bed,
    within 1e-3 of the equilibrium's (2.3e-4 measured, the C library's
    test), not the equilibrium's; the mooring stiffness is refused."""
    start = oc4_with_tmax_ic(tmp_path, "0")
    solved = oc4_with_tmax_ic(tmp_path, "60.0")
    x = start.initial_positions()
    shapes = start.initialize(x).reshape(3, 3)
    equilibrium = solved.initialize(x).reshape(3, 3)
    apart = np.max(np.abs(shapes - equilibrium), axis=1)
    size = np.linalg.norm(equilibrium, axis=1)
    assert np.all(apart < 1e-3 * size), apart / size
    assert np.all(apart > 1e-9 * size), apart / size
    start.step_to(0.005, x)
    with pytest.raises(stancf.ScenarioError, match="TmaxIC 0"):
        start.point_stiffness(4)
    assert solved.point_stiffness(4)[0, 0] > 0.0
