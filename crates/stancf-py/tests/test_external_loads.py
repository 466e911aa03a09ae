"""MoorDyn-F's EXTERNAL LOADS from Python (docs/interface.md, "Rigid
bodies"; docs/method.md §15.21 (B42)-(B43)): a deck's external force and
damping on a free body reach a run through ``stancf.run``, and a row
stancf does not build is refused naming it."""

import math

import numpy as np
import pytest

import stancf

DECK = """A body pushed and damped
--- BODIES ---
ID Attachment X0 Y0 Z0 r0 p0 y0 Mass CG* I* Volume CdA* Ca
(#) (-) (m) (m) (m) (deg) (deg) (deg) (kg) (m) (kg-m^2) (m^3) (m^2) (-)
1 free 0 0 -10 0 0 0 1025 0 100 1 0 0
--- EXTERNAL LOADS ---
ID Object Fext Blin Bquad CSys
(#) (name) (N) (Ns/m) (Ns^2/m^2) (-)
1 Body1 1025|0|0 0|0|0 1025|0|0 G
--- OPTIONS ---
0.01 dtM
100 WtrDpth
1025 WtrDnsty
--- need this line ---
"""


def test_a_decks_external_force_and_quadratic_damping_give_the_terminal_velocity_law(tmp_path):
    # A neutrally buoyant 1025 kg body pushed by 1025 N against the
    # quadratic damping 1025 N s^2/m^2: v = tanh(t) (v_t = 1 m/s, tau =
    # 1 s), to the Galerkin step's error at dt = 0.05 s (1e-13 measured).
    (tmp_path / "deck.txt").write_text(DECK)
    scenario = tmp_path / "run.toml"
    scenario.write_text(
        '[system]\nmoordyn = "deck.txt"\n[analysis]\ntype = "dynamic"\n'
        'initial = "reference"\ntime_step = 0.05\nduration = 2.0\n'
    )
    res = stancf.run(stancf.Scenario.from_file(scenario), out=tmp_path / "out")
    rows = np.genfromtxt(res.directory / "bodies.csv", delimiter=",", names=True)
    last = rows[-1]
    assert last["t"] == pytest.approx(2.0)
    assert abs(last["vx"] - math.tanh(2.0)) < 1e-9
    assert abs(last["x"] - math.log(math.cosh(2.0))) < 1e-9


def test_external_loads_on_a_rod_are_refused_naming_the_row(tmp_path):
    (tmp_path / "deck.txt").write_text(DECK.replace("1 Body1 1025", "1 Rod1 1025"))
    with pytest.raises(stancf.ScenarioError, match=r"line 9: .*external loads on a rod"):
        stancf.Scenario.from_file(tmp_path / "deck.txt")
