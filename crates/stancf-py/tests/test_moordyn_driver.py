"""A MoorDyn driver file (OpenFAST's md_driver.inp) from Python: the deck
it names runs in its sea for its TMax from MoorDyn's start (docs/method.md
§13.7). OpenFAST's md_horizontal rod, released level at its deck pose
(TmaxIC 0), sinks as the closed form of its net weight, mass with added
mass and quadratic drag."""

import math
from pathlib import Path

import numpy as np

import stancf

# OpenFAST's r-test md_horizontal deck (a free rod 10 m long, 2 m across,
# 3250 kg/m, level 5 m down; a dummy line between two fixed points).
DECK = (Path(__file__).resolve().parents[2] / "stancf-cli" / "tests" / "fixtures"
        / "md-horizontal-moordyn.txt")

DRIVER = """MoorDyn driver input file
another comment line
---------------------- ENVIRONMENTAL CONDITIONS -------------------------------
9.80665            Gravity          - Gravity (m/s^2)
1025.0             rhoW             - Water density (kg/m^3)
75.0               WtrDpth          - Water depth (m)
---------------------- MOORDYN ------------------------------------------------
"horizontal.dat"   MDInputFile      - Primary MoorDyn input file name (quoted string)
"driver"           OutRootName      - The name which prefixes all generated files
3                  TMax             - Total run time (s)
0.01               dtC              - TimeInterval for the simulation (sec)
0                  InputsMode       - MoorDyn coupled object inputs (switch)
""                 InputsFile       - Filename for the MoorDyn inputs file
0                  NumTurbines      - Number of wind turbines (-)
---------------------- Initial Positions --------------------------------------
ref_X    ref_Y    surge_init   sway_init  heave_init  roll_init  pitch_init   yaw_init
(m)      (m)        (m)          (m)        (m)       (rad)       (rad)        (rad)
0        0          0            0          0          0           0            0
END of driver input file
"""


def test_a_driver_file_sinks_md_horizontals_rod_as_its_closed_form(tmp_path):
    (tmp_path / "horizontal.dat").write_text(DECK.read_text())
    driver = tmp_path / "md_driver.inp"
    driver.write_text(DRIVER)
    res = stancf.run(stancf.Scenario.from_file(driver), out=tmp_path / "out")
    rows = np.genfromtxt(res.directory / "channels.csv", delimiter=",", names=True)
    g, rho, length = 9.80665, 1025.0, 10.0
    weight = (3250.0 - rho * math.pi) * g * length
    mass = (3250.0 + rho * math.pi) * length
    drag = 0.5 * rho * 0.6 * 2.0 * length
    t = rows["t"]
    z = -5.0 - mass / drag * np.log(np.cosh(t * math.sqrt(drag * weight) / mass))
    assert t[-1] == 3.0
    assert np.max(np.abs(rows["ROD1PZ"] - z)) < 1e-8
