"""A moored spar in waves from Python (docs/method.md §15.15): the
example examples/spar-in-waves.toml, shortened, runs through
``stancf.run``; the waves move the spar that the static solve left at
rest, and its heave follows them."""

from pathlib import Path

import numpy as np

import stancf

ROOT = Path(__file__).resolve().parents[3]
EXAMPLE = ROOT / "examples" / "spar-in-waves.toml"


def test_a_moored_spar_heaves_in_the_waves(tmp_path):
    sc = stancf.Scenario.from_file(EXAMPLE).with_values({"analysis.duration": 20.0})
    res = stancf.run(sc, out=tmp_path / "out")
    rows = np.genfromtxt(res.directory / "bodies.csv", delimiter=",", names=True)
    t, z = rows["t"], rows["z"]
    assert t[-1] == 20.0
    # At rest at its equilibrium until the waves (ramped over 10 s) arrive,
    # then heaving: a wave 1.5 m high moves it by more than half a metre.
    assert abs(z[1] - z[0]) < 1e-3
    assert np.ptp(z[t >= 10.0]) > 0.5
