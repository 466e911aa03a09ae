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


VISCO_ROPE = """title = "viscoelastic rope"
[[line_types]]
name = "rope"
diameter = 0.0356825
mass_per_length = 0.01
ea = 1.0e6
{law}
[[points]]
id = 1
type = "fixed"
position = [0.0, 0.0, 0.0]
[[points]]
id = 2
type = "coupled"
position = [1.01, 0.0, 0.0]
[[lines]]
id = 1
type = "rope"
length = 1.0
elements = 4
a = 1
b = 2
[system]
gravity = [0.0, 0.0, 0.0]
[[motions]]
point = 2
amplitude = [0.005, 0.0, 0.0]
period = 0.5
[analysis]
type = "dynamic"
initial = "static"
time_scheme = "galerkin"
time_step = 0.0025
duration = 1.0
"""


def standard_solid(t):
    """N(t) of the law (V1)-(V2) with k2 = 3e6, c1 = 2e5, c2 = 1e4 under
    eps = 0.01 + 0.005 sin(4 pi t) from rest (docs/method.md §2.11)."""
    ea, k2, c1, c2 = 1e6, 3e6, 2e5, 1e4
    k1 = k2 * ea / (k2 - ea)
    k, c, w, a, e0 = k1 + k2, c1 + c2, 4.0 * np.pi, 0.005, 0.01
    h = (k2 + 1j * w * c2) / (k + 1j * w * c)
    decay = np.exp(-k / c * t)
    eps1 = e0 * k2 / k + a * np.imag(h * np.exp(1j * w * t)) - a * h.imag * decay
    rate = a * w * np.real(h * np.exp(1j * w * t)) + a * h.imag * k / c * decay
    return k1 * eps1 + c1 * rate


def test_a_driven_viscoelastic_rope_pulls_as_the_standard_solid(tmp_path):
    # The fairlead's step-mean tension against the closed form's mean over
    # each step after its start has died out (0.25 s): the CLI's claim
    # (tests/cli/viscoelastic.rs), 1e-4 of the 8.4 kN swing.
    law = "ea_dynamic = 3.0e6\nba = 2.0e5\nba_dynamic = 1.0e4\ncompression = true"
    res = stancf.run(stancf.Scenario(VISCO_ROPE.format(law=law)), out=tmp_path / "out")
    rows = np.genfromtxt(res.directory / "tensions.csv", delimiter=",", names=True, dtype=None,
                         encoding=None)
    b = rows[rows["end"] == "B"]
    x, w = np.polynomial.legendre.leggauss(4)
    dt = 0.0025
    t = np.asarray(b["t"], dtype=float)
    exact = np.array([0.5 * np.sum(w * standard_solid(tk - 0.5 * dt + 0.5 * dt * x)) for tk in t])
    swing = np.max(np.abs(exact - 1e4))
    late = t >= 0.25
    assert swing > 8e3
    assert np.max(np.abs(np.asarray(b["tension"], dtype=float)[late] - exact[late])) < 1e-4 * swing


def test_a_dynamic_stiffness_below_the_static_one_is_refused_naming_its_key():
    law = "ea_dynamic = 5.0e5\nba = 1.0e3"
    with pytest.raises(stancf.ScenarioError, match=r"line_types\[0\]\.ea_dynamic.*not above the static EA"):
        stancf.Scenario(VISCO_ROPE.format(law=law))


SYROPE_ROPE = """title = "Syrope rope"
[[line_types]]
name = "poly"
diameter = 0.203
mass_per_length = 40.0
ba = 5.0e10
ba_dynamic = 1.0e5
syrope = {{ curve = [[2.06897e-3, 1.71768e5], [1.03448e-2, 7.45355e5], [2.06897e-2, 1.29953e6], [2.27586e-2, 1.40061e6]], working_curve = "linear", k1 = 1.25e8, k2 = 0.0, alpha = 1.53e8, beta = 23.12 }}
[[points]]
id = 1
type = "fixed"
position = [0.0, 0.0, 0.0]
[[points]]
id = 2
type = "fixed"
position = [{x!r}, 0.0, 0.0]
[[lines]]
id = 1
type = "poly"
length = 1.0
elements = 2
a = 1
b = 2
tmax0 = 1.302e6
[system]
gravity = [0.0, 0.0, 0.0]
[analysis]
type = "dynamic"
initial = "reference"
time_scheme = "galerkin"
time_step = 0.05
duration = 0.5
"""


def test_a_syrope_rope_at_rest_pulls_with_its_working_curve(tmp_path):
    # docs/method.md §2.12: held straight at rest below Tmax0 it pulls
    # with the linear working curve of slope k1 through the original
    # curve's point at Tmax0 (eps_max, Tmax0).
    x = 1.0137912
    res = stancf.run(stancf.Scenario(SYROPE_ROPE.format(x=x)), out=tmp_path / "out")
    rows = np.genfromtxt(res.directory / "tensions.csv", delimiter=",", names=True, dtype=None,
                         encoding=None)
    # Tmax0 lies on the curve's last segment.
    eps_max = 2.06897e-2 + (1.302e6 - 1.29953e6) * (2.27586e-2 - 2.06897e-2) / (1.40061e6 - 1.29953e6)
    expected = 1.302e6 + 1.25e8 * (x - 1.0 - eps_max)
    assert np.max(np.abs(np.asarray(rows["tension"], dtype=float) - expected)) < 1e-9 * expected


def test_a_syrope_line_without_its_history_is_refused_naming_the_key():
    text = SYROPE_ROPE.format(x=1.0137912).replace("tmax0 = 1.302e6\n", "")
    with pytest.raises(stancf.ScenarioError, match=r"lines\[0\]\.tmax0"):
        stancf.Scenario(text)
