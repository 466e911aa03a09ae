"""stancf.Simulation: a system stepped by a coupling code that moves its
coupled points (docs/method.md §13; MoorDyn's create/init/step in memory),
over the Rust handle `stancf::coupling::CoupledSystem`."""

import math
import numbers
import sys
from pathlib import Path

import numpy as np

from . import _stancf
from . import Scenario, ScenarioError, SolverError


def _seconds(name, t):
    """A time argument as a float: a real number (not a bool, a string or
    None; a numpy scalar is fine)."""
    if isinstance(t, numbers.Real) and not isinstance(t, bool):
        return float(t)
    if isinstance(t, np.ndarray) and t.ndim == 0 and t.dtype.kind in "iuf":
        return float(t)
    raise TypeError("%s: expected a real number of seconds, got %s %r"
                    % (name, type(t).__name__, t))


def _coupling_array(name, values, n):
    """A coupling array argument as a list of floats: a flat list, tuple or
    numpy array of real numbers (ints or floats). Complex values (even with
    a zero imaginary part), other types and arrays of another shape are
    refused, naming the argument; the count is the handle's to check."""
    try:
        a = np.asarray(values)
    except (ValueError, TypeError) as e:
        raise ValueError("%s: expected %d real numbers (coupled_dof: 6 per coupled body, "
                         "3 per CoupledPinned body, 3 per coupled point): %s"
                         % (name, n, e)) from None
    if a.dtype.kind == "c":
        raise TypeError("%s: complex values are refused (even with a zero imaginary part); "
                        "give the %d real coordinates" % (name, n))
    if a.dtype.kind not in "iuf":
        raise TypeError("%s: expected %d real numbers (coupled_dof: 6 per coupled body, "
                        "3 per CoupledPinned body, 3 per coupled point), "
                        "got values of type %s" % (name, n, a.dtype))
    if a.ndim != 1:
        raise ValueError("%s: expected a flat sequence of %d values (coupled_dof: 6 per "
                         "coupled body, then x, y, z of each coupled point), got an array of "
                         "shape %s" % (name, n, a.shape))
    return a.astype(float).tolist()


def _host_array(name, values, n):
    """A host's water kinematics at `n` points as a flat list of 3 n floats:
    an (n, 3) or flat array of real numbers. Complex values (even with a
    zero imaginary part) and other types raise TypeError, another count
    ScenarioError, naming the argument; non-finite values are the
    handle's to refuse."""
    try:
        a = np.asarray(values)
    except (ValueError, TypeError) as e:
        raise ValueError("%s: expected %d points of 3 real numbers: %s" % (name, n, e)) from None
    if a.dtype.kind == "c":
        raise TypeError("%s: complex values are refused (even with a zero imaginary part); "
                        "give the %d points' real components" % (name, n))
    if a.dtype.kind not in "iuf":
        raise TypeError("%s: expected %d points of 3 real numbers, got values of type %s"
                        % (name, n, a.dtype))
    if a.shape not in ((n, 3), (3 * n,)):
        raise ScenarioError("%s: an array of shape %s given, the host's waves are asked at %d "
                            "points: give (%d, 3) values (or %d flat)"
                            % (name, a.shape, n, n, 3 * n))
    return a.astype(float).reshape(-1).tolist()


class LineState:
    """One line of a :class:`Simulation` at its current time: ``nodes``
    (n x 3, m), ``velocities`` (n x 3, m/s), ``tensions`` (n, N: the axial
    force EA eps at each node) and ``curvatures`` (n, 1/m)."""

    def __init__(self, nodes, velocities, tensions, curvatures):
        self.nodes = np.asarray(nodes, dtype=float).reshape(-1, 3)
        self.velocities = np.asarray(velocities, dtype=float).reshape(-1, 3)
        self.tensions = np.asarray(tensions, dtype=float)
        self.curvatures = np.asarray(curvatures, dtype=float)

    def __repr__(self):
        return "LineState(%d nodes)" % len(self.tensions)


class PointState:
    """One point of a :class:`Simulation` at its current time:
    ``position`` (3,, m), ``velocity`` (3,, m/s) and ``force`` (3,, N: the
    net force of its lines on it, the mean over the last step)."""

    def __init__(self, position, velocity, force):
        self.position = np.asarray(position, dtype=float)
        self.velocity = np.asarray(velocity, dtype=float)
        self.force = np.asarray(force, dtype=float)

    def __repr__(self):
        return "PointState(position=%s)" % (self.position,)


class Simulation:
    """A system stepped by a coupling code that moves its coupled points
    (docs/method.md §13; MoorDyn's create/init/step in memory)::

        sim = stancf.Simulation("examples/oc4-deepcwind-moordyn.txt")
        x0 = sim.initial_positions()            # the deck's fairleads (coupled_ids)
        f = sim.initialize(x0)                  # static equilibrium, t = 0
        for k in range(1, 101):
            f = sim.step_to(0.1 * k, x(0.1 * k), xd(0.1 * k))

    `scenario_or_deck`: a path (TOML system scenario or MoorDyn v2 deck)
    or a :class:`Scenario`. The coupling arrays have ``coupled_dof``
    values: first 6 per coupled body (``coupled_body_ids``, in the order
    of the bodies: x holds its reference point's x, y, z and MoorDyn's
    roll, pitch, yaw in radians, xd the reference point's velocity and
    the angular velocity in rad/s, global; the forces returned, the
    lines' force on the body and their moment about the reference point,
    global), then x, y, z of each coupled point not on a body, in the
    order of their ids (``coupled_ids``). A point on a coupled body
    moves with it (docs/method.md §13.6). ``initialize(x, xd=None)`` solves the static
    equilibrium with the coupled points at x and starts at t = 0;
    ``step_to(t, x, xd=None)`` moves them to x at t (cubically, with the
    velocities given or, without them, estimated from this call's and the
    two last calls' positions, docs/method.md (K2a)), taking the fewest
    equal steps no longer than the scenario's time step. Both return the
    forces of the lines on the coupled points (N; after ``step_to`` the
    mean over its last step, what ``stancf run`` writes for that step);
    ``interval_mean_force`` is the interval's impulse over its length.
    ``save()`` returns a state that ``restore(state)`` brings back
    exactly, into this Simulation or one of the same scenario (a restart);
    a state of another system raises ValueError and changes nothing.
    ``initial_positions()`` gives the coupled points' positions from the
    scenario or deck, before ``initialize``. After ``initialize``,
    ``line(line_id)`` gives a :class:`LineState`, ``point(point_id)``
    a :class:`PointState` (any point: fixed, coupled or free; ``point_ids``),
    ``body_stiffness(body_id)`` a free or coupled body's 6 x 6 mooring stiffness at
    the equilibrium (``body_ids``); before it they raise :class:`ScenarioError` naming the id, and an
    unknown id raises KeyError naming it.

    ``water_depth`` (m), ``water_density`` (kg/m^3) and ``gravity``
    (m/s^2) are what a host gives a MoorDyn deck before init, as OpenFAST
    gives MoorDyn-F its depth, density and g: used where the deck leaves
    them out (a glue code's deck has no WtrDpth), the deck's own where it
    gives them (``check`` notes which). ``turbines``, a sequence of
    [x, y, z] (m), places a FAST.Farm deck's turbines (turbine n at index
    n - 1), as FAST.Farm gives them; without it, the FAST.Farm input
    beside the deck that names it does.

    One ``step_to`` takes at most ``max_interval_steps`` internal steps
    (100 000 unless set, here or as ``Simulation(..., max_interval_steps=n)``);
    a longer interval is refused before anything moves. A scenario with
    ``analysis.force_tolerance`` (``force_tolerance``) crosses each
    interval in the steps that tolerance chooses, at most its
    ``time_step`` each, as ``stancf.run`` does (``last_steps`` counts
    them).

    Nothing is written to disk. The arguments are checked: ``t`` a real
    number, ``x`` and ``xd`` flat sequences or arrays of ``coupled_dof``
    real numbers (TypeError or ValueError naming the argument). Bad input
    raises :class:`ScenarioError` (a ValueError); a failed step raises
    :class:`SolverError` (``result`` is None) and leaves the simulation at
    its last converged step. The solver runs without the GIL; Ctrl-C
    stops ``step_to`` (and ``initialize``) between two internal steps with
    KeyboardInterrupt, the simulation at its last converged step (``time``),
    from where the next ``step_to`` continues. A Simulation is used by one
    thread at a time: a call while another thread is inside one raises
    RuntimeError.
    """

    def __init__(
        self,
        scenario_or_deck,
        max_interval_steps=None,
        allow_large=False,
        water_depth=None,
        water_density=None,
        gravity=None,
        turbines=None,
    ):
        if isinstance(scenario_or_deck, Scenario):
            text, name = scenario_or_deck.text, scenario_or_deck.name
        else:
            path = Path(scenario_or_deck)
            text, name = _stancf.read_input(str(path)), str(path)
        if turbines is not None:
            turbines = [[float(c) for c in p] for p in turbines]
            if any(len(p) != 3 for p in turbines):
                raise ValueError("turbines: each turbine's position is [x, y, z]")
        self._sim = _stancf.Simulation(
            text, name, bool(allow_large), water_depth, water_density, gravity, turbines
        )
        if max_interval_steps is not None:
            self.max_interval_steps = max_interval_steps

    @property
    def coupled_dof(self):
        return self._sim.coupled_dof

    @property
    def coupled_ids(self):
        """The coupled points' ids (not those on coupled bodies), in the
        order of the coupling arrays after the bodies."""
        return list(self._sim.coupled_ids)

    @property
    def coupled_body_ids(self):
        """The coupled bodies' ids, in the order of the coupling arrays
        (first, 6 numbers each)."""
        return list(self._sim.coupled_body_ids)

    @property
    def line_ids(self):
        return list(self._sim.line_ids)

    @property
    def point_ids(self):
        return list(self._sim.point_ids)

    @property
    def body_ids(self):
        """The bodies' ids (fixed, coupled and free; a free rod is a body)."""
        return list(self._sim.body_ids)

    @property
    def releases(self):
        """The line failures that happened so far (docs/method.md §11.16),
        in order: each a dict of ``failure`` (its id), ``t`` (s),
        ``trigger`` ("time" or "tension"), ``tension`` (N, or None),
        ``lines`` (the released lines' ids) and ``new_point`` (the id of
        the free point the released ends go on at)."""
        keys = ("failure", "t", "trigger", "tension", "lines", "new_point")
        return [dict(zip(keys, r)) for r in self._sim.releases]

    @property
    def time(self):
        return self._sim.time

    @property
    def interval_mean_force(self):
        f = self._sim.interval_mean_force
        return None if f is None else np.asarray(f, dtype=float)

    @property
    def last_steps(self):
        """The internal steps the last ``step_to`` took: its interval's
        equal steps, or its kept half steps where ``force_tolerance``
        chooses them (0 before the first)."""
        return self._sim.last_steps

    @property
    def force_tolerance(self):
        """The scenario's ``analysis.force_tolerance``, the tolerance on the
        end forces that chooses the internal steps (docs/method.md
        §11.17), or None: each interval in equal steps of at most the
        scenario's ``time_step``."""
        return self._sim.force_tolerance

    @property
    def max_interval_steps(self):
        """The most internal steps one ``step_to`` takes (at least 1)."""
        return self._sim.max_interval_steps

    @max_interval_steps.setter
    def max_interval_steps(self, n):
        if isinstance(n, bool) or not isinstance(n, numbers.Integral):
            raise TypeError("max_interval_steps: expected a whole number of steps, got %r" % (n,))
        if n < 1:
            raise ValueError("max_interval_steps: must be at least 1, got %d" % n)
        self._sim.max_interval_steps = min(int(n), sys.maxsize)

    def initialize(self, x, xd=None):
        return self._call(self._sim.initialize, x, xd)

    def step_to(self, t, x, xd=None):
        return self._call(self._sim.step_to, _seconds("t", t), x, xd)

    def save(self):
        return self._sim.save()

    def restore(self, state):
        self._sim.restore(state)

    def initial_positions(self):
        """The coupled bodies' poses and the coupled points' positions
        where the scenario or deck puts them (``coupled_dof`` values: per
        body in the order of ``coupled_body_ids`` its reference point (m)
        and MoorDyn's roll, pitch, yaw (radians), then x, y, z of each
        point in the order of ``coupled_ids``), known before
        :meth:`initialize`: the start to give it."""
        return np.asarray(self._sim.initial_positions, dtype=float)

    def line(self, line_id):
        ids = self.line_ids
        if line_id not in ids:
            raise KeyError("no line %r (lines: %s)" % (line_id, ids))
        self._require_initialized("line %r" % (line_id,))
        return LineState(*self._sim.line_arrays(ids.index(line_id)))

    def point(self, point_id):
        ids = self.point_ids
        if point_id not in ids:
            raise KeyError("no point %r (points: %s)" % (point_id, ids))
        self._require_initialized("point %r" % (point_id,))
        return PointState(*self._sim.point_arrays(ids.index(point_id)))

    def body_stiffness(self, body_id):
        """Free or coupled body `body_id`'s mooring stiffness at the static
        equilibrium of the last :meth:`initialize` (docs/method.md §15.9):
        a 6 x 6 array K = -d[F; M]/d[dr; dphi], rows the lines' force F_x,
        F_y, F_z and moment M_x, M_y, M_z about the body's reference point
        (global axes), columns the reference point's displacement dx, dy,
        dz and a small rotation about global x, y, z through it (N/m,
        N/rad, N m/m, N m/rad); a positive diagonal restores. The lines'
        stiffness only (not the body's own hydrostatics); not symmetric in
        general. An unknown id raises KeyError; before :meth:`initialize`,
        for a fixed body, or where the rest of the system is singular with
        the body held, ScenarioError naming the id."""
        ids = self.body_ids
        if body_id not in ids:
            raise KeyError("no body %r (bodies: %s)" % (body_id, ids))
        index = ids.index(body_id)
        moving = [ids[b] for b in self._sim.free_bodies] + list(self.coupled_body_ids)
        if body_id not in moving:
            raise ScenarioError(
                "body %r is fixed: only a free or coupled body has a mooring stiffness "
                "(free and coupled bodies: %s)" % (body_id, moving))
        self._require_initialized("body %r" % (body_id,))
        self._require_equilibrium("body %r" % (body_id,))
        k = self._sim.body_stiffness(index)
        if k is None:
            raise ScenarioError(
                "body %r: no mooring stiffness: the rest of the system is singular with the "
                "body held" % (body_id,))
        return np.asarray(k, dtype=float)

    def point_stiffness(self, point_id):
        """Coupled point `point_id`'s (a coupled point not on a body)
        mooring stiffness at the static equilibrium of the last
        :meth:`initialize` (docs/method.md §15.9): a 3 x 3 array
        K = -df/dx of its lines' force (N/m, global axes), the rest of the
        system in equilibrium. An unknown id raises KeyError; before
        :meth:`initialize`, for a point that is not coupled, or where the
        rest is singular with the point held, ScenarioError naming the id."""
        ids = self.point_ids
        if point_id not in ids:
            raise KeyError("no point %r (points: %s)" % (point_id, ids))
        self._require_initialized("point %r" % (point_id,))
        self._require_equilibrium("point %r" % (point_id,))
        k = self._sim.point_stiffness(ids.index(point_id))
        if k is None:
            raise ScenarioError(
                "point %r: no mooring stiffness: it is not a coupled point of its own (fixed, "
                "free or on a body), or the rest of the system is singular with it held"
                % (point_id,))
        return np.asarray(k, dtype=float)

    def wave_kinematics_points(self):
        """Where a host that sets the waves (a deck's ``WaveKin 1``, a
        scenario's ``water.host_waves``) evaluates them now: an (n, 3)
        array of positions (m) in MoorDyn's order (its
        ``ExternalWaveKinGetCoordinates``): every line's nodes, line by
        line, then every rod's nodes, every point, then MoorDyn's ground
        body at the origin and every body.
        ScenarioError before :meth:`initialize` or where the waves are not
        a host's."""
        self._require_host_waves()
        return np.asarray(self._sim.wave_kinematics_points(), dtype=float).reshape(-1, 3)

    def set_wave_kinematics(self, u, a, t=None):
        """Sets the water's velocity `u` (m/s) and local acceleration `a`
        (m/s^2) at the points of :meth:`wave_kinematics_points`, each an
        (n, 3) array (or flat, 3 n values), MoorDyn's
        ``ExternalWaveKinSet``: added to the sea's current and held for the
        steps from now until set again (docs/method.md §12.1,
        (W2f)-(W2h)); still water until first set. `t`, the time they are
        for, is checked to be a real number and, as in MoorDyn, does not
        move them in time. A count other than the points', or a value that
        is not finite, raises ScenarioError and sets nothing."""
        self._require_host_waves()
        if t is not None and not math.isfinite(_seconds("t", t)):
            raise ValueError("t: the time the values are for must be finite, got %r" % (t,))
        n = self._sim.wave_kinematics_count()
        self._sim.set_wave_kinematics(*(_host_array(name, v, n) for name, v in (("u", u), ("a", a))))

    def _require_equilibrium(self, what):
        """A mooring stiffness is taken at the equilibrium of initialize();
        a system that starts as MoorDyn starts without initial conditions
        (a deck's TmaxIC 0) has none: ScenarioError naming the id."""
        if self._sim.starts_from_catenaries:
            raise ScenarioError(
                "%s: no mooring stiffness: the system started from MoorDyn's start without "
                "initial conditions (TmaxIC 0), not from an equilibrium" % (what,))

    def _require_host_waves(self):
        if not self._sim.takes_host_waves:
            raise ScenarioError(
                "the system's waves are not a host's (a deck's WaveKin 1, a scenario's "
                "water.host_waves): there are no water kinematics to set")
        self._require_initialized("the host's water kinematics")

    def _require_initialized(self, what):
        """Point and line values exist from :meth:`initialize` on; before,
        ScenarioError naming the user's id (and where the coupled points'
        positions are)."""
        if not self._sim.initialized:
            raise ScenarioError(
                "%s: no values before initialize(); initial_positions() gives the coupled "
                "points' positions from the scenario (in the order of coupled_ids %s)"
                % (what, self.coupled_ids))

    def _call(self, method, *args):
        *head, x, xd = args
        n = self.coupled_dof
        x = _coupling_array("x", x, n)
        xd = None if xd is None else _coupling_array("xd", xd, n)
        try:
            return np.asarray(method(*head, x, xd), dtype=float)
        except _stancf.RunFailed as e:
            message, time, step, residual = e.args
            raise SolverError(message, time, step, residual, None) from None

    def __repr__(self):
        return "Simulation(%d coupled bodies, %d coupled points, %d lines, t = %g s)" % (
            len(self.coupled_body_ids), len(self.coupled_ids), len(self.line_ids), self.time)
