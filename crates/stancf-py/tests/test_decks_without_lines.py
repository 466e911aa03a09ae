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
