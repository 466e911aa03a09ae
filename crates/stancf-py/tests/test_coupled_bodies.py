"""A coupled body through stancf.Simulation (docs/method.md §13.6,
docs/interface.md "Coupling"): the coupling arrays hold the body's 6
numbers first, and the force and moment returned for it are the sums of
its points' forces and of their moments about its reference point."""

from pathlib import Path

import numpy as np

import stancf

ROOT = Path(__file__).resolve().parents[3]
# MoorDyn's example/body.txt (OC3-Hywind): a coupled body at z = -70 m
# carrying three 902.2 m chains to anchors on the seabed at 320 m.
DECK = ROOT / "crates" / "stancf-cli" / "tests" / "fixtures" / "oc3-coupled-body-moordyn.txt"
BODY_POINTS = {4: [5.2, 0.0, 0.0], 5: [-2.6, 4.5, 0.0], 6: [-2.6, -4.5, 0.0]}


def lines_on_body(sim, reference):
    """The lines' force on the body and their moment about `reference`,
    summed over its points as the simulation reads them."""
    force, moment = np.zeros(3), np.zeros(3)
    for p in BODY_POINTS:
        state = sim.point(p)
        force += state.force
        moment += np.cross(state.position - reference, state.force)
    return force, moment


def assert_sums(sim, f, reference):
    """f[:6] is the lines' force and moment on the body to round-off: a
    few ulps of the largest fairlead force (9e5 N), 1e-12 of it, and of
    its moment on the 5.2 m arms."""
    force, moment = lines_on_body(sim, np.asarray(reference, dtype=float))
    scale = max(np.abs(sim.point(p).force).max() for p in BODY_POINTS)
    assert np.abs(f[:3] - force).max() <= 1e-12 * scale, (f[:3], force)
    assert np.abs(f[3:6] - moment).max() <= 1e-12 * scale * 5.2, (f[3:6], moment)


def test_a_coupled_body_from_a_deck_moves_by_its_six_numbers():
    sim = stancf.Simulation(DECK)
    assert sim.coupled_body_ids == [1]
    assert sim.coupled_ids == []
    assert sim.coupled_dof == 6
    x0 = sim.initial_positions()
    assert np.array_equal(x0, [0.0, 0.0, -70.0, 0.0, 0.0, 0.0])
    f0 = sim.initialize(x0)
    assert f0.shape == (6,)
    # Three chains hang from the body: their pull is down, about 1.6 MN.
    # The anchors are symmetric about the x axis: no sway force and no
    # roll or yaw moment, to round-off of the pull. (The points' readings
    # hold forces from the first step on: the sums are checked there.)
    assert 1.0e6 < -f0[2] < 2.5e6, f0
    assert max(abs(f0[1]), abs(f0[3]), abs(f0[5])) <= 1e-12 * abs(f0[2]), f0
    # A surge of 0.5 m over 0.3 s (a cubic ramp, velocities given), in
    # three intervals of 50 steps of the deck's dtM.
    length, surge = 0.3, 0.5
    f = f0
    for k in range(1, 4):
        t = 0.1 * k
        s = t / length
        x = x0.copy()
        x[0] = surge * (3 * s**2 - 2 * s**3)
        xd = np.zeros(6)
        xd[0] = surge * (6 * s - 6 * s**2) / length
        f = sim.step_to(t, x, xd)
        assert abs(sim.time - t) <= 1e-12
        assert_sums(sim, f, x[:3])
        for p, local in BODY_POINTS.items():
            where = np.add(local, x[:3])
            assert np.abs(sim.point(p).position - where).max() <= 1e-12, p
    # The surge reaches the lines (their drag and inertia answer the
    # ramp: tens of kN), and along the anchors' axis of symmetry it keeps
    # the sway force and the roll and yaw moments zero (the mirrored
    # chains' values are negated exactly; 1e-9 of the pull allows for a
    # Newton solve's last bits).
    assert abs(f[0] - f0[0]) > 1e3, (f0, f)
    assert max(abs(f[1]), abs(f[3]), abs(f[5])) <= 1e-9 * abs(f[2]), f
