"""Nonlinear axial laws from Python (docs/interface.md, "Line types";
docs/method.md §2.2a (M4b)): a deck whose EA names MoorDyn's curve file
and a TOML line type's ``ea_curve`` reach a run through ``stancf.run``,
and a table stancf cannot use is refused naming it."""

import numpy as np
import pytest

import stancf

CURVE = "Polyester rope\nStrain Tension\n(-) (N)\n0.0 0.0\n0.01 1.0e5\n0.03 5.0e5\n0.06 1.4e6\n"


def deck(ea):
    return f"""A weight on a polyester rope
--- LINE TYPES ---
TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx
(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)
poly 0.111464 30.0 {ea} 0 0 0 0 0 0
--- POINTS ---
ID Attachment X Y Z Mass Volume CdA Ca
(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)
1 Fixed 0 0 0 0 0 0 0
2 Free 0 0 -100 {3.0e5 / 9.81!r} 0 0 0
--- LINES ---
ID LineType AttachA AttachB UnstrLen NumSegs Outputs
(#) (name) (#) (#) (m) (-) (-)
1 poly 1 2 100.0 10 -
--- OPTIONS ---
9.81 g
300 WtrDpth
1025 WtrDnsty
--- need this line ---
"""


def test_a_decks_ea_curve_file_stretches_the_rope_as_its_table(tmp_path):
    # The rope's tension runs from 3e5 N at the weight to 3.196e5 N at
    # the top, inside the table's segment of slope 2e7 N: the strain is
    # 0.01 + (T - 1e5) / 2e7, linear along the rope, so the weight hangs at
    # L (1 + mean strain) to the static solve's tolerance.
    (tmp_path / "poly_ea.txt").write_text(CURVE)
    (tmp_path / "deck.txt").write_text(deck("poly_ea.txt"))
    res = stancf.run(stancf.Scenario.from_file(tmp_path / "deck.txt"), out=tmp_path / "out")
    rows = np.genfromtxt(res.directory / "points.csv", delimiter=",", names=True)
    z = rows[rows["point"] == 2]["z"][0]
    w = (30.0 - 1025.0 * np.pi * 0.111464**2 / 4.0) * 9.81
    mean_tension = 3.0e5 + 0.5 * w * 100.0
    assert abs(z + 100.0 * (1.0 + 0.01 + (mean_tension - 1.0e5) / 2.0e7)) < 1e-8


def test_a_falling_table_is_refused_naming_its_point(tmp_path):
    (tmp_path / "poly_ea.txt").write_text(CURVE.replace("0.06 1.4e6", "0.06 4.0e5"))
    (tmp_path / "deck.txt").write_text(deck("poly_ea.txt"))
    with pytest.raises(stancf.ScenarioError, match=r"line 5: EA of line type \"poly\".*point 4"):
        stancf.Scenario.from_file(tmp_path / "deck.txt")
