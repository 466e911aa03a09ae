"""A rod pinned to a free body (a joint, docs/method.md §15.14) from
Python: OpenFAST's md_BodiesAndRods deck (a float with a flap pinned to
it, three nylon lines to one point under the float) runs its static
equilibrium through ``stancf.run``."""

from pathlib import Path

import stancf

ROOT = Path(__file__).resolve().parents[3]
DECK = ROOT / "crates" / "stancf-cli" / "tests" / "fixtures" / "md-bodies-and-rods-moordyn.txt"


def test_a_float_with_a_flap_at_a_joint_finds_its_equilibrium(tmp_path):
    res = stancf.run(stancf.Scenario.from_file(DECK), out=tmp_path / "out")
    ch = res.channels
    # The flap's lift aside of the float's axis pitches it nose down (the
    # flap leans to +x): a negative pitch, well short of a capsize.
    assert -45.0 < ch["Body1RY"][-1] < -1.0
    # The float sinks until its can and the flap carry it (the cans start
    # 2 m above the surface).
    assert ch["Body1PZ"][-1] < -2.0
    # The flap stays in the plane of lines 1 and the float's axis: lines 2
    # and 3, mirror images about it, pull alike (the heading is held,
    # §15.14), to the static tolerance.
    t1, t2, t3 = (ch["FairTen%d" % k][-1] for k in (1, 2, 3))
    assert abs(t2 - t3) < 1e-8 * t2
    assert t1 > 0.0
