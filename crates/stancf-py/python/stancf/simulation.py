"""stancf.Simulation: a system stepped by a coupling code that moves its
coupled points (docs/method.md §13; MoorDyn's create/init/step in memory),
over the Rust handle `stancf::coupling::CoupledSystem`."""

from pathlib import Path

import numpy as np

from . import _stancf
from . import Scenario, SolverError


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
        f = sim.initialize(x0)                  # static equilibrium, t = 0
        for k in range(1, 101):
            f = sim.step_to(0.1 * k, x(0.1 * k), xd(0.1 * k))

    `scenario_or_deck`: a path (TOML system scenario or MoorDyn v2 deck)
    or a :class:`Scenario`. The coupling arrays have ``coupled_dof``
    values: x, y, z of each coupled point, in the order of their ids
    (``coupled_ids``). ``initialize(x, xd=None)`` solves the static
    equilibrium with the coupled points at x and starts at t = 0;
    ``step_to(t, x, xd=None)`` moves them to x at t (cubically when this
    call and the last gave velocities, else linearly), taking the fewest
    equal steps no longer than the scenario's time step. Both return the
    forces of the lines on the coupled points (N; after ``step_to`` the
    mean over its last step, what ``stancf run`` writes for that step);
    ``interval_mean_force`` is the interval's impulse over its length.
    ``save()`` returns a state that ``restore(state)`` brings back
    exactly. ``line(line_id)`` gives a :class:`LineState`, ``point(point_id)``
    a :class:`PointState` (any point: fixed, coupled or free; ``point_ids``).

    Nothing is written to disk. Bad input raises :class:`ScenarioError`;
    a failed step raises :class:`SolverError` (``result`` is None) and
    leaves the simulation at its last converged step. The solver runs
    without the GIL.
    """

    def __init__(self, scenario_or_deck):
        if isinstance(scenario_or_deck, Scenario):
            text, name = scenario_or_deck.text, scenario_or_deck.name
        else:
            path = Path(scenario_or_deck)
            text, name = path.read_text(), str(path)
        self._sim = _stancf.Simulation(text, name)

    @property
    def coupled_dof(self):
        return self._sim.coupled_dof

    @property
    def coupled_ids(self):
        return list(self._sim.coupled_ids)

    @property
    def line_ids(self):
        return list(self._sim.line_ids)

    @property
    def point_ids(self):
        return list(self._sim.point_ids)

    @property
    def time(self):
        return self._sim.time

    @property
    def interval_mean_force(self):
        f = self._sim.interval_mean_force
        return None if f is None else np.asarray(f, dtype=float)

    @property
    def last_steps(self):
        return self._sim.last_steps

    def initialize(self, x, xd=None):
        return self._call(self._sim.initialize, x, xd)

    def step_to(self, t, x, xd=None):
        return self._call(self._sim.step_to, float(t), x, xd)

    def save(self):
        return self._sim.save()

    def restore(self, state):
        self._sim.restore(state)

    def line(self, line_id):
        ids = self.line_ids
        if line_id not in ids:
            raise KeyError("no line %r (lines: %s)" % (line_id, ids))
        return LineState(*self._sim.line_arrays(ids.index(line_id)))

    def point(self, point_id):
        ids = self.point_ids
        if point_id not in ids:
            raise KeyError("no point %r (points: %s)" % (point_id, ids))
        return PointState(*self._sim.point_arrays(ids.index(point_id)))

    @staticmethod
    def _call(method, *args):
        *head, x, xd = args
        x = [float(v) for v in np.ravel(x)]
        xd = None if xd is None else [float(v) for v in np.ravel(xd)]
        try:
            return np.asarray(method(*head, x, xd), dtype=float)
        except _stancf.RunFailed as e:
            message, time, step, residual = e.args
            raise SolverError(message, time, step, residual, None) from None

    def __repr__(self):
        return "Simulation(%d coupled points, %d lines, t = %g s)" % (
            len(self.coupled_ids), len(self.line_ids), self.time)
