"""A MoorDyn deck of a rod alone, no line (MoorDyn's
rod_tests/AddedMass.txt) from Python: its static equilibrium floats the
rod on the surface, its axis where Archimedes puts it (docs/method.md
§15.10, (B22))."""

import math

import numpy as np

import stancf

DECK = """--------------------- MoorDyn Input File ---------------------------------------
A buoyant rod 10 m down, no line
---------------------- ROD TYPES -----------------------------------------------
TypeName  Diam   Mass/m    Cd     Ca    CdEnd      CaEnd
(name)    (m)    (kg/m)    (-)    (-)   (-)        (-)
floatRod  0.5    100.0     0.0    1.0   0.0        1.0
---------------------- RODS ----------------------------------------------------
ID     RodType   Attachment  Xa    Ya    Za    Xb    Yb    Zb   NumSegs   RodOutputs
(#)    (name)    (#/key)     (m)   (m)   (m)   (m)   (m)   (m)  (-)       (-)
1      floatRod  free        0     -1    -10   0   1.0   -10    4       -
---------------------- OPTIONS -------------------------------------------------
0.0005    dtM          - time step
16.0      WtrDpth      - water depth
------------------------- need this line ---------------------------------------
"""


def test_a_rod_alone_floats_where_archimedes_puts_it(tmp_path):
    deck = tmp_path / "rod.txt"
    deck.write_text(DECK)
    res = stancf.run(stancf.Scenario.from_file(deck), out=tmp_path / "out")
    rows = np.genfromtxt(res.directory / "bodies.csv", delimiter=",", names=True)
    fraction = 100.0 / (1025.0 * math.pi * 0.0625)
    lo, hi = -1.0, 1.0
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        phi = 0.5 + (mid * math.sqrt(1.0 - mid * mid) + math.asin(mid)) / math.pi
        lo, hi = (mid, hi) if phi < fraction else (lo, mid)
    assert abs(float(rows["z"]) + 0.25 * 0.5 * (lo + hi)) < 1e-9


def test_a_sinking_rod_without_initial_conditions_writes_moordyns_start(tmp_path):
    """The same rod three times heavier sinks: it has no static
    equilibrium. Its deck's TmaxIC 0 (MoorDyn's md_vertical) asks for no
    initial conditions, so, as MoorDyn's Init leaves it, the run writes
    its start at t = 0, the rod where the deck puts it, and the summary
    says why there is no equilibrium (docs/method.md §13.7). Asked for
    initial conditions (TmaxIC 60), the deck is refused naming the rod."""
    heavy = DECK.replace("floatRod  0.5    100.0", "floatRod  0.5    300.0")
    deck = tmp_path / "rod.txt"
    deck.write_text(heavy.replace("16.0      WtrDpth", "0         TmaxIC\n16.0      WtrDpth"))
    res = stancf.run(stancf.Scenario.from_file(deck), out=tmp_path / "out")
    assert "rod 1: floats on no line and sinks" in res.summary["no_static_equilibrium"]
    assert res.summary["initial"] == "catenary"
    rows = np.genfromtxt(res.directory / "bodies.csv", delimiter=",", names=True)
    assert float(rows["t"]) == 0.0 and float(rows["z"]) == -10.0
    deck.write_text(heavy.replace("16.0      WtrDpth", "60        TmaxIC\n16.0      WtrDpth"))
    try:
        stancf.run(stancf.Scenario.from_file(deck), out=tmp_path / "never")
    except stancf.ScenarioError as e:
        assert "rod 1: floats on no line and sinks" in str(e)
    else:
        raise AssertionError("a sinking rod's static run was not refused")
