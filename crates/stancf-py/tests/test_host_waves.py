"""A host that sets the water's kinematics from Python (docs/method.md §12.1,
(W2f)-(W2g); MoorDyn's ExternalWaveKin*): ``Simulation.wave_kinematics_points``
and ``set_wave_kinematics`` on Lowe and Langley's jumper (MoorDyn's test
deck, ``WaveKin 1``), against the paper's top tension; the places it is asked
at with rods and bodies, against MoorDyn's; the refusals."""

import math
import shutil
from pathlib import Path

import numpy as np
import pytest

import stancf

ROOT = Path(__file__).resolve().parents[3]
FIXTURES = ROOT / "crates" / "stancf-cli" / "tests" / "fixtures"


def jumper(tmp_path, dt, sea_row=None):
    """Lowe and Langley's jumper (MoorDyn's deck, `WaveKin 1`), stepped at
    `dt`; `sea_row`, if given, in place of the deck's WaveKin row."""
    deck = (FIXTURES / "lowe-langley-2006-jumper-moordyn.txt").read_text()
    if sea_row is not None:
        row = next(r for r in deck.splitlines() if r.split()[1:2] == ["WaveKin"])
        deck = deck.replace(row, sea_row)
    (tmp_path / "line.txt").write_text(deck)
    scenario = tmp_path / "jumper.toml"
    scenario.write_text(
        '[system]\nmoordyn = "line.txt"\n[analysis]\ntype = "dynamic"\n'
        'time_step = %r\ntime_scheme = "galerkin"\nduration = 50.0\n' % dt)
    return stancf.Simulation(scenario)


def wave(points, t, heading, phase):
    """MoorDyn's test's linear wave (amplitude 5 m, period 10 s, deep-water
    wave number, profile over 100 m) at `points` ((n, 3)): velocity and
    local acceleration, (n, 3) each."""
    w = 2.0 * math.pi / 10.0
    k = w * w / 9.81
    x = points[:, 0] * math.cos(heading) + points[:, 1] * math.sin(heading)
    c, s = np.cos(k * x - w * t + phase), np.sin(k * x - w * t + phase)
    ch = np.cosh(k * (points[:, 2] + 100.0)) / math.cosh(k * 100.0)
    sh = np.sinh(k * (points[:, 2] + 100.0)) / math.cosh(k * 100.0)
    u = 5.0 * w * np.stack([c * ch * math.cos(heading), c * ch * math.sin(heading), s * sh], 1)
    a = 5.0 * w * w * np.stack([s * ch * math.cos(heading), s * ch * math.sin(heading),
                                -c * sh], 1)
    return u, a


def test_lowe_langley_2006_case_6_with_waves_set_from_python(tmp_path):
    """Case 6 (waves along y, phase 0) as MoorDyn's test runs it, at a step
    of 0.1 s: the top tension within 1.2 kN of the paper's over its first
    10 s (the bound of the C library's test of cases 4 to 6, measured
    there: MoorDyn 2.7 is 0.46 kN off at worst in this case, stancf over
    the whole 30 s 0.55 kN at this step and 0.43 kN at 0.025 s, the
    difference mostly the step-mean force's half-step lag, docs/method.md
    §12.1)."""
    dt = 0.1
    sim = jumper(tmp_path, dt)
    top = [0.0, 0.0, -5.0]
    sim.initialize(top, [0.0, 0.0, 0.0])
    reference = np.loadtxt(FIXTURES / "lowe-langley-2006-case-6.csv", delimiter=",")
    reference = reference[reference[:, 0] <= 10.0]
    worst, k, t = 0.0, 0, 0.0
    while k < len(reference):
        u, a = wave(sim.wave_kinematics_points(), t + 0.5 * dt, math.pi / 2.0, 0.0)
        sim.set_wave_kinematics(u, a, t + 0.5 * dt)
        t = round(t + dt, 9)
        f = sim.step_to(t, top, [0.0, 0.0, 0.0])
        if t - 20.0 >= reference[k, 0] - 1e-9:
            worst = max(worst, abs(np.linalg.norm(f) / 1e3 - reference[k, 1]))
            k += 1
    assert worst < 1.2, worst


def test_a_moordyn_f_deck_whose_sea_is_seastates_takes_it_from_the_host(tmp_path):
    """MoorDyn-F's `SEASTATE WaterKin` (the glue code's SeaState sea) is a
    host's sea as `WaveKin 1` is: asked at the same places, and 2 s of case
    6's wave give the same top forces to the last bit."""
    forces = []
    for name, row in (("wavekin1", None), ("seastate", "SEASTATE  WaterKin")):
        folder = tmp_path / name
        folder.mkdir()
        sim = jumper(folder, 0.1, row)
        sim.initialize([0.0, 0.0, -5.0])
        points = sim.wave_kinematics_points()
        run, t = [], 0.0
        while t < 2.0 - 1e-9:
            u, a = wave(points, t + 0.05, math.pi / 2.0, 0.0)
            sim.set_wave_kinematics(u, a, t + 0.05)
            t = round(t + 0.1, 9)
            run.append(sim.step_to(t, [0.0, 0.0, -5.0], [0.0, 0.0, 0.0]))
        forces.append((points, np.array(run)))
    (p1, f1), (p2, f2) = forces
    assert np.array_equal(p1, p2)
    assert np.array_equal(f1, f2)
    # The wave moved the top's force: the host's flow was taken.
    assert np.ptp(np.linalg.norm(f1, axis=1)) > 1e3


def test_the_host_is_asked_at_the_nodes_then_the_points_then_the_ground(tmp_path):
    sim = jumper(tmp_path, 0.05)
    with pytest.raises(stancf.ScenarioError, match="before initialize"):
        sim.wave_kinematics_points()
    sim.initialize([0.0, 0.0, -5.0])
    points = sim.wave_kinematics_points()
    assert points.shape == (69 + 2 + 1, 3)
    assert np.array_equal(points[:69], sim.line(1).nodes.reshape(-1, 3))
    assert np.array_equal(points[69], sim.point(1).position)
    assert np.array_equal(points[70], sim.point(2).position)
    assert np.array_equal(points[71], [0.0, 0.0, 0.0])


# What MoorDyn 2.7 gives (MoorDyn_ExternalWaveKinGetCoordinates) for the
# deck host-waves-rods-bodies-moordyn.txt at the pose below, after its
# first step (at init it has not yet placed the inner nodes of a rod on
# a body): rod 2's 3 nodes (fixed), rod 3's 4 (on the coupled body), then
# the 5 points, the ground and the body (places 107 to 113, 115 to 121).
MOORDYN_RODS = [[0.0, 50.0, -100.0], [0.0, 50.0, -97.5], [0.0, 50.0, -95.0],
                [-0.1736481777, 0.0, -20.9848077530], [-0.0578827259, 0.0, -20.3282692510],
                [0.0578827259, 0.0, -19.6717307490], [0.1736481777, 0.0, -19.0151922470]]
MOORDYN_POINTS_AND_BODIES = [[-450.0, 0.0, 0.0], [450.0, 0.0, 0.0], [200.0, 0.0, -50.0],
                             [0.8528685320, 0.5, -20.1503837332], [30.0, 0.0, -150.0],
                             [0.0, 0.0, 0.0], [0.0, 0.0, -20.0]]


@pytest.mark.parametrize("body", ["Coupled", "Fixed", "CoupledPinned"])
def test_the_host_is_asked_where_moordyn_asks_at_rods_points_and_bodies(tmp_path, body):
    """A deck with every kind of rod (free, fixed, on a body, of zero
    length), points of every kind and a body, coupled, fixed or pinned to
    the host, turned by
    pitch 10 deg and yaw 30 deg (docs/method.md (W2h)): the host is asked
    at MoorDyn 2.7's 122 places (the lines' 46, 46, 5 and 8 nodes; the
    rods' 2, 3, 4 and 1; the 5 points; the ground; the body), the fixed
    rod's, the body's rod's, the points' and the bodies' where MoorDyn
    puts them, to 1e-9 m (the lines' nodes and the free rods' follow each
    code's own start; on the fixed body MoorDyn 2.7 never places its rod's
    two inner nodes, which stay at the rod's body coordinates, 0, 0 and
    +-0.33 m: stancf's are where the coupled body's are, MoorDyn's
    there; a CoupledPinned body's pin, a point stancf adds for the host to
    move, is not asked at: 122 places too, as in MoorDyn 2.7); and a flow
    set there is taken by a step."""
    text = (FIXTURES / "host-waves-rods-bodies-moordyn.txt").read_text()
    if body != "Coupled":
        text = text.replace("1       Coupled   0     0      -20", "1  %s  0  0  -20" % body)
    (tmp_path / "deck.txt").write_text(text)
    sim = stancf.Simulation(tmp_path / "deck.txt")
    pose = [0.0, 0.0, -20.0, 0.0, math.radians(10.0), math.radians(30.0)]
    held = {"Coupled": pose, "Fixed": [], "CoupledPinned": pose[:3]}[body]
    x = held + [
        -450.0, 0.0, 0.0, 450.0, 0.0, 0.0, 200.0, 0.0, -50.0]
    assert sim.coupled_dof == len(x)
    sim.initialize(x)
    r = sim.wave_kinematics_points()
    assert r.shape == (122, 3)
    np.testing.assert_allclose(r[107:114], MOORDYN_RODS, rtol=0, atol=1e-9)
    np.testing.assert_allclose(r[115:], MOORDYN_POINTS_AND_BODIES, rtol=0, atol=1e-9)
    u = np.tile([0.2, 0.1, 0.0], (122, 1))
    sim.set_wave_kinematics(u, np.zeros((122, 3)), 0.0)
    sim.step_to(0.1, x)
    assert sim.time == pytest.approx(0.1)


def test_a_hosts_water_kinematics_are_refused_where_they_cannot_be_taken(tmp_path):
    sim = jumper(tmp_path, 0.05)
    sim.initialize([0.0, 0.0, -5.0])
    n = len(sim.wave_kinematics_points())
    with pytest.raises(stancf.ScenarioError, match="asked at 72 points"):
        sim.set_wave_kinematics(np.zeros((n - 1, 3)), np.zeros((n, 3)))
    with pytest.raises(TypeError, match="complex"):
        sim.set_wave_kinematics(np.zeros((n, 3)) + 0j, np.zeros((n, 3)))
    with pytest.raises(ValueError, match="must be finite"):
        sim.set_wave_kinematics(np.zeros((n, 3)), np.zeros((n, 3)), float("inf"))
    bad = np.zeros((n, 3))
    bad[4, 2] = np.nan
    with pytest.raises(stancf.ScenarioError, match=r"acceleration\[4\]"):
        sim.set_wave_kinematics(np.zeros((n, 3)), bad)
    with pytest.raises(TypeError, match="t:"):
        sim.set_wave_kinematics(np.zeros((n, 3)), np.zeros((n, 3)), "now")
    own = stancf.Simulation(ROOT / "examples" / "bridle.toml")
    own.initialize(own.initial_positions())
    with pytest.raises(stancf.ScenarioError, match="not a host's"):
        own.wave_kinematics_points()
