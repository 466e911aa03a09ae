"""A MoorDyn free rod of zero length joining two lines with bending
stiffness, from Python: the rod is a connector the lines are clamped to
(docs/method.md §15.20), turning to balance their moments, so the pair
hangs as one line of the same length and mesh: the anchors' tensions
agree to the static solve's tolerance. A connector has no mooring
stiffness of its own; a body lines are clamped to has one (§15.9)."""

import csv

import numpy as np

import stancf

HEAD = """--------------------- MoorDyn Input File ---------------------------------------
{title}
----------------------- LINE TYPES ------------------------------------------
TypeName Diam  Mass/m   EA         BA/-zeta EI      Cd  Ca  CdAx CaAx
(name)   (m)   (kg/m)   (N)        (N-s/-)  (N-m^2) (-) (-) (-)  (-)
bent     0.1   20.0     1.0E8      -0.5     2.0E4   1.2 1.0 0.1  0.0
"""

TAIL = """---------------------- OPTIONS -------------------------------------------------
0.01          dtM                  time step (s)
100           WtrDpth              water depth (m)
------------------------- need this line --------------------------------------
"""

POINTS = """---------------------- POINTS --------------------------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     -20     0       -10     0      0       0      0
2     Fixed      20     0       -10     0      0       0      0
"""

JOINED = (
    HEAD.format(title="two 22 m lines joined by a zero-length rod")
    + """---------------------- ROD TYPES -----------------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
conn          0.1      5         1.0    1.0     1.0      1.0
---------------------- RODS ----------------------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)     (-)
1    conn      Free        0     0     -15   0     0     -15  0       -
"""
    + POINTS
    + """---------------------- LINES ---------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     bent       1        R1A       22        8       -
2     bent       R1B      2         22        8       -
"""
    + TAIL
)

ONE = (
    HEAD.format(title="one 44 m line")
    + POINTS
    + """---------------------- LINES ---------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     bent       1        2         44        16      -
"""
    + TAIL
)


def anchor_tensions(tmp_path, name, text):
    deck = tmp_path / f"{name}.txt"
    deck.write_text(text)
    res = stancf.run(stancf.Scenario.from_file(deck), out=tmp_path / name)
    with open(res.directory / "tensions.csv") as f:
        rows = list(csv.DictReader(f))
    last = max(float(r["t"]) for r in rows)
    tension = {
        (int(r["line"]), r["end"]): float(r["tension"]) for r in rows if float(r["t"]) == last
    }
    return res, lambda line, end: tension[(line, end)]


def test_two_lines_joined_by_a_connector_hang_as_one(tmp_path):
    _, joined = anchor_tensions(tmp_path, "joined", JOINED)
    _, one = anchor_tensions(tmp_path, "one", ONE)
    a, b = joined(1, "A"), joined(2, "B")
    assert abs(a - one(1, "A")) < 1e-8 * a, (a, one(1, "A"))
    assert abs(b - one(1, "B")) < 1e-8 * b, (b, one(1, "B"))


def test_a_connector_has_no_mooring_stiffness_and_says_why(tmp_path):
    res, _ = anchor_tensions(tmp_path, "joined", JOINED)
    assert res.stiffness == {}
    entry = res.summary["bodies"][0]
    assert entry["stiffness"] is None
    assert "a connector" in entry["stiffness_note"]


CLAMPED_BODY = """--------------------- MoorDyn Input File ---------------------------------------
a body on a rod between two bent lines clamped to its ends
----------------------- LINE TYPES ------------------------------------------
TypeName Diam  Mass/m   EA         BA/-zeta EI      Cd  Ca  CdAx CaAx
(name)   (m)   (kg/m)   (N)        (N-s/-)  (N-m^2) (-) (-) (-)  (-)
bent     0.1   20.0     1.0E8      -0.5     2.0E4   1.2 1.0 0.1  0.0
---------------------- ROD TYPES -----------------------------------------------
TypeName      Diam     Mass/m    Cd     Ca      CdEnd    CaEnd
(name)        (m)      (kg/m)    (-)    (-)     (-)      (-)
conn          0.1      5         1.0    1.0     1.0      1.0
---------------------------- BODIES -----------------------------------------------
ID   Attachment  X0     Y0    Z0     r0      p0     y0     Mass  CG*   I*      Volume   CdA*   Ca
(#)     (-)      (m)    (m)   (m)   (deg)   (deg)  (deg)   (kg)  (m)  (kg-m^2)  (m^3)   (m^2)  (-)
1       Free      0     0     -15    0       0      0      500    0    50       0.1      0      0
---------------------- RODS ----------------------------------------------------
ID   RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs RodOutputs
(#)  (name)     (#/key)    (m)   (m)   (m)   (m)   (m)   (m)  (-)     (-)
1    conn      Body1       -1    0     0     1     0     0    2       -
---------------------- POINTS --------------------------------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     -20     0       -10     0      0       0      0
2     Coupled    20     0       -10     0      0       0      0
---------------------- LINES ---------------------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     bent       1        R1A       20        8       -
2     bent       R1B      2         20        8       -
---------------------- OPTIONS -------------------------------------------------
0.01          dtM                  time step (s)
100           WtrDpth              water depth (m)
------------------------- need this line --------------------------------------
"""


def test_a_clamped_bodys_stiffness_from_a_simulation_is_the_static_runs(tmp_path):
    # A 500 kg body on a 2 m rod, the two bent lines clamped along it at
    # its ends; point 2 coupled. initialize at the deck's positions solves
    # the static run's equilibrium, so the matrices (the clamps' moments
    # in them) agree to 1e-8 of their size (the solves' tolerance 1e-10).
    deck = tmp_path / "body.txt"
    deck.write_text(CLAMPED_BODY)
    run = stancf.run(stancf.Scenario.from_file(deck), out=tmp_path / "out").stiffness[1]
    assert run.shape == (6, 6)
    # The clamps hold the body's pitch: a restoring moment.
    assert run[4, 4] > 0
    sim = stancf.Simulation(stancf.Scenario.from_file(deck))
    sim.initialize(sim.initial_positions())
    k = sim.body_stiffness(1)
    assert np.abs(k - run).max() < 1e-8 * np.abs(run).max()
