"""MoorDyn's VIV lift from Python (docs/method.md §12.7, docs/interface.md
"Line types"): a TOML line type's ``viv`` table reaches the stepping API,
and a riser in a current starts vibrating across it; without the table
it stays in its plane."""

import numpy as np
import pytest

import stancf

RISER = """title = "catenary riser in a uniform current"
[system]
gravity = [0.0, 0.0, -9.80665]
[water]
depth = 10.0
density = 1000.0
[water.current]
profile = [[-10.0, 0.2, 0.0, 0.0], [0.0, 0.2, 0.0, 0.0]]
[[line_types]]
name = "riser"
diameter = 0.024
mass_per_length = 0.69
ea = 6.66e5
ei = 10.5
ba = 160.729
cd = 1.2
ca = 2.0
cdax = 0.08
caax = 0.08
compression = false
{viv}
[[points]]
id = 1
type = "fixed"
position = [-21.0425, 0.0, -10.0]
[[points]]
id = 2
type = "coupled"
position = [0.0, 0.0, -1.0]
[[lines]]
id = 1
type = "riser"
length = 23.71
elements = 30
a = 1
b = 2
[analysis]
type = "dynamic"
initial = "static"
time_scheme = "galerkin"
time_step = 0.02
duration = 4.0
"""


def cross_flow_swing(tmp_path, viv):
    """The largest cross-flow (y) displacement of the riser's nodes over
    4 s with its top held by the host, in diameters."""
    path = tmp_path / ("riser-%d.toml" % len(viv))
    path.write_text(RISER.format(viv=viv))
    sim = stancf.Simulation(path)
    top = sim.initial_positions()
    sim.initialize(top)
    swing = 0.0
    for k in range(1, 21):
        sim.step_to(0.2 * k, top)
        swing = max(swing, np.abs(sim.line(1).nodes[:, 1]).max())
    return swing / 0.024


def test_the_viv_lift_sets_a_riser_in_a_current_vibrating_across_it(tmp_path):
    # The static riser lies in the plane of the current and its ends;
    # the lift (1/2 rho d Cl U^2 = 0.34 N/m) pushes it across within a
    # shedding period (0.67 s); the riser (MoorDyn's VIV validation case)
    # locks in at about 0.2 D RMS after a start that swings it up to 0.7 D
    # (docs/method.md §12.7), so by 4 s it has swung by more than 0.05 D
    # and, as flexible cylinders in lock-in do, by less than one diameter.
    # Without VIV, nothing leaves the plane.
    with_lift = cross_flow_swing(
        tmp_path, "viv = { cl = 0.7, df = 0.08, cf = 0.18, averaging_time = 0.05 }"
    )
    assert 0.05 < with_lift < 1.0, with_lift
    assert cross_flow_swing(tmp_path, "") == 0.0


def test_a_viv_table_without_its_averaging_time_is_refused_naming_it(tmp_path):
    path = tmp_path / "bad.toml"
    path.write_text(RISER.format(viv="viv = { cl = 0.7 }"))
    with pytest.raises(stancf.ScenarioError, match=r"line_types\[0\]\.viv\.averaging_time"):
        stancf.Scenario.from_file(path)
