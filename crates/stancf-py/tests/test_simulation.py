"""stancf.Simulation: a system stepped by a coupling code (docs/method.md
§13) against `stancf.run` with the same motion prescribed, save and
restore, errors, no files, and the OC4 coupling example (also against the
C example through the C library)."""

import _thread
import math
import os
import shutil
import stat
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

import stancf

ROOT = Path(__file__).resolve().parents[3]
EXAMPLES = ROOT / "examples"
AMPLITUDE, PERIOD, RAMP, DT = [0.2, 0.1, 0.05], 1.0, 0.5, 2e-4
START = [6.0, 0.0, 1.0]


def bridle(steps):
    """examples/bridle.toml with its fairlead (point 2) swinging along all
    three axes, Galerkin steps of DT, every step written."""
    head = (EXAMPLES / "bridle.toml").read_text().split("[[motions]]")[0]
    text = head + f"""[[motions]]
point = 2
amplitude = {AMPLITUDE}
period = {PERIOD}
ramp = {RAMP}

[analysis]
type = "dynamic"
initial = "static"
time_step = {DT}
duration = {steps * DT}
time_scheme = "galerkin"
planar_reduction = false

[output]
every = 1
"""
    return stancf.Scenario(text, "bridle.toml")


def swing(t):
    """The fairlead's position and velocity at t: r0 + f(t) a sin(2 pi t/T)
    with the ramp f = s^3 (6 s^2 - 15 s + 10), s = min(t / ramp, 1)."""
    s = min(t / RAMP, 1.0)
    f = s * s * s * (s * (6.0 * s - 15.0) + 10.0)
    df = 30.0 * s * s * (s - 1.0) ** 2 / RAMP if t < RAMP else 0.0
    w = 2.0 * math.pi / PERIOD
    x = [r + f * a * math.sin(w * t) for r, a in zip(START, AMPLITUDE)]
    v = [df * a * math.sin(w * t) + f * a * w * math.cos(w * t) for a in AMPLITUDE]
    return x, v


def test_stepping_once_per_step_reproduces_the_prescribed_run():
    steps = 200
    sc = bridle(steps)
    res = stancf.run(sc)
    run_force = res.points[2]["force"]
    sim = stancf.Simulation(sc)
    assert sim.coupled_ids == [2] and sim.coupled_dof == 3
    f0 = sim.initialize(START, [0.0, 0.0, 0.0])
    scale = np.abs(run_force).max()
    # Python's sin and the motion's rounding may differ from Rust's in the
    # last bit; the forces then differ at round-off (measured below).
    worst = np.abs(f0 - run_force[0]).max()
    for k in range(1, steps + 1):
        t = sim.time + DT  # the run's own accumulated time
        x, v = swing(t)
        f = sim.step_to(t, x, v)
        assert sim.last_steps == 1
        worst = max(worst, np.abs(f - run_force[k]).max())
    print("worst difference", worst, "of", scale)
    assert worst <= 1e-10 * scale


def test_save_step_restore_step_is_identical_to_the_bit():
    sim = stancf.Simulation(bridle(10))
    # Started where the swing has the fairlead, as a host does.
    sim.initialize(*swing(0.6))
    t = 0.0

    def advance(n):
        nonlocal t
        out = []
        for _ in range(n):
            t += 3.7 * DT
            x, v = swing(t + 0.6)
            out.append(sim.step_to(t, x, v))
        return np.array(out), sim.line(1).nodes.copy(), sim.interval_mean_force

    advance(10)
    state, t_saved = sim.save(), t
    first = advance(5)
    sim.restore(state)
    t = t_saved
    second = advance(5)
    for a, b in zip(first, second):
        assert np.array_equal(a, b)


def test_bad_calls_raise_and_the_simulation_goes_on():
    sim = stancf.Simulation(bridle(10))
    with pytest.raises(stancf.ScenarioError, match="initialize"):
        sim.step_to(DT, START)
    with pytest.raises(stancf.ScenarioError, match="expected 3 values"):
        sim.initialize([0.0] * 4)
    with pytest.raises(stancf.ScenarioError, match=r"x\[1\]"):
        sim.initialize([6.0, float("nan"), 1.0])
    sim.initialize(START)
    with pytest.raises(stancf.ScenarioError, match="must come after"):
        sim.step_to(0.0, START)
    assert np.isfinite(sim.step_to(DT, START)).all()
    line = sim.line(2)
    assert line.nodes.shape == (21, 3) and line.tensions.shape == (21,)
    assert line.velocities.shape == (21, 3) and line.curvatures.shape == (21,)
    with pytest.raises(KeyError):
        sim.line(7)
    # Every point: the fairlead where it was put, with the forces the
    # step returned; the shackle (free) and the anchor from the solve.
    assert sim.point_ids == [1, 2, 3]
    f = sim.step_to(2 * DT, START)
    fairlead = sim.point(2)
    assert np.array_equal(fairlead.position, START)
    assert np.array_equal(fairlead.force, f)
    assert np.array_equal(sim.point(3).position, sim.line(2).nodes[-1])
    assert np.array_equal(sim.point(1).position, [0.0, 0.0, 0.0])
    with pytest.raises(KeyError):
        sim.point(4)
    with pytest.raises(stancf.ScenarioError, match="single cable"):
        stancf.Simulation(EXAMPLES / "pendulum.toml")


def test_a_failed_step_raises_solver_error_and_keeps_the_last_step():
    # The bridle at steps of 1 s without halvings, its fairlead moved 4 m
    # toward the anchors in one step: its ropes swing through their whole
    # motion in it, which Newton does not follow (held where it is, the
    # step converges at its residual's floor, docs/method.md §7.2).
    text = bridle(10).text.replace("time_step = %r" % DT, "time_step = 1.0\nstep_halvings = 0")
    text = text.replace("duration = %r" % (10 * DT), "duration = 10.0")
    sim = stancf.Simulation(stancf.Scenario(text, "bridle.toml"))
    sim.initialize(START)
    # A jump of the fairlead by 1000 km is no motion: refused, nothing moves.
    with pytest.raises(ValueError, match="above the 100 m/s"):
        sim.step_to(1.0, [1e6, 1e6, 1e6])
    assert sim.time == 0.0
    with pytest.raises(stancf.SolverError) as e:
        sim.step_to(1.0, [START[0] - 4.0, START[1], START[2]])
    assert e.value.time == 0.0 and e.value.step == 1
    assert "residual" in str(e.value)
    assert sim.time == 0.0
    assert np.isfinite(sim.line(1).nodes).all()


def test_a_simulation_writes_no_file(tmp_path):
    folder = tmp_path / "ro"
    folder.mkdir()
    shutil.copy(EXAMPLES / "bridle.toml", folder / "bridle.toml")
    before = sorted((p.name, p.stat().st_mtime_ns) for p in folder.iterdir())
    cwd = os.getcwd()
    folder.chmod(stat.S_IRUSR | stat.S_IXUSR)
    try:
        os.chdir(folder)
        sim = stancf.Simulation("bridle.toml")
        sim.initialize(START)
        state = sim.save()
        for k in range(1, 4):
            sim.step_to(k * 1e-3, swing(k * 1e-3)[0])
        sim.restore(state)
    finally:
        os.chdir(cwd)
        folder.chmod(stat.S_IRWXU)
    assert sorted((p.name, p.stat().st_mtime_ns) for p in folder.iterdir()) == before


def oc4_example():
    sys.path.insert(0, str(EXAMPLES / "coupling"))
    try:
        import oc4_surge
    finally:
        sys.path.pop(0)
    return oc4_surge


def test_the_oc4_example_holds_the_decks_pretension_and_follows_the_surge():
    example = oc4_example()
    sim = stancf.Simulation(example.DECK)
    x0 = sim.initial_positions()
    f0 = np.linalg.norm(sim.initialize(x0).reshape(-1, 3), axis=1)
    # The deck's pretension, as `stancf run` prints it (1.106e6 N).
    assert np.allclose(f0, 1.106e6, rtol=2e-3), f0
    t, tensions = example.surge(example.DECK, duration=0.5)
    assert t.shape == (5,) and tensions.shape == (5, 3)
    assert np.isfinite(tensions).all()
    # Surging towards +x pulls on fairlead 4 (its anchor is at -x) and
    # slackens the other two, which stay equal by symmetry.
    assert (np.diff(tensions[:, 0]) > 0).all()
    assert (np.diff(tensions[:, 1]) < 0).all()
    assert np.allclose(tensions[:, 1], tensions[:, 2], rtol=1e-12)


def deck_points(deck):
    """The POINTS table of a MoorDyn deck: id -> [x, y, z]."""
    rows, section = {}, None
    for line in Path(deck).read_text().splitlines():
        if line.startswith("---"):
            section = line.strip("- ").upper()
            continue
        fields = line.split()
        if section and section.startswith("POINTS") and fields and fields[0].isdigit():
            rows[int(fields[0])] = [float(v) for v in fields[2:5]]
    return rows


def test_coupled_point_positions_are_known_before_initialize():
    deck = EXAMPLES / "oc4-deepcwind-moordyn.txt"
    sim = stancf.Simulation(deck)
    assert sim.coupled_ids == [4, 5, 6]
    rows = deck_points(deck)
    x0 = sim.initial_positions()
    assert x0.shape == (sim.coupled_dof,)
    assert np.array_equal(x0, np.ravel([rows[i] for i in sim.coupled_ids]))
    # Before initialize a point or a line is named by the user's id, not
    # by an internal index, and the message says where the positions are.
    with pytest.raises(stancf.ScenarioError, match=r"point 4: .*initialize.*initial_positions"):
        sim.point(4)
    with pytest.raises(stancf.ScenarioError, match=r"line 1: .*initialize"):
        sim.line(1)
    with pytest.raises(KeyError, match="no point 9"):
        sim.point(9)
    # A TOML system: its coupled fairlead (point 2) where the file puts it.
    assert np.array_equal(stancf.Simulation(bridle(10)).initial_positions(), START)


def test_the_oc4_example_checks_for_matplotlib_before_simulating(tmp_path):
    # A matplotlib that cannot be imported, ahead of any installed one.
    fake = tmp_path / "matplotlib"
    fake.mkdir()
    (fake / "__init__.py").write_text("raise ImportError('no matplotlib here')\n")
    env = dict(os.environ, PYTHONPATH=str(tmp_path))
    started = time.monotonic()
    run = subprocess.run([sys.executable, str(EXAMPLES / "coupling" / "oc4_surge.py"), "40",
                          "--plot", str(tmp_path / "tension.png")],
                         capture_output=True, text=True, env=env)
    assert run.returncode == 2, run.stderr
    assert "--plot needs matplotlib" in run.stderr and "pip install matplotlib" in run.stderr
    # Refused before the 40 s of simulation (about 70 s of wall time).
    assert run.stdout == "" and time.monotonic() - started < 20


def test_the_c_example_prints_the_python_examples_tensions():
    source = EXAMPLES / "coupling" / "oc4_surge.c"
    library = ROOT / "target" / "release"
    assert (library / "libstancf_c.so").exists(), \
        "build the C library first: cargo build --release -p stancf-capi"
    exe = Path(os.environ.get("TMPDIR", "/tmp")) / f"oc4_surge_{os.getpid()}"
    subprocess.run(["cc", "-O1", "-I", str(ROOT / "crates" / "stancf-capi" / "include"),
                    str(source), "-L", str(library), "-lstancf_c",
                    f"-Wl,-rpath,{library}", "-lm", "-o", str(exe)], check=True)
    out = subprocess.run([str(exe), str(EXAMPLES / "oc4-deepcwind-moordyn.txt"), "0.5"],
                         capture_output=True, text=True, check=True).stdout
    exe.unlink()
    rows = np.array([[float(v) for v in line.split(",")]
                     for line in out.splitlines()[1:] if line.strip()])
    t, tensions = oc4_example().surge(duration=0.5)
    assert out.splitlines()[0] == "t,tension_4,tension_5,tension_6"
    assert np.array_equal(rows[:, 0], t)
    # The same Rust code runs behind both: the same bits.
    assert np.array_equal(rows[:, 1:], tensions)


def test_the_gil_is_released_while_stepping():
    import threading
    sim = stancf.Simulation(bridle(10))
    sim.initialize(START)
    done = threading.Event()
    # One long call: 200 steps inside a single coupling interval (about a
    # second; a loop holding the GIL would count nothing until it ends).
    th = threading.Thread(target=lambda: (sim.step_to(200 * DT, swing(200 * DT)[0]),
                                          done.set()))
    th.start()
    count = 0
    while not done.is_set():
        count += 1
    th.join()
    assert sim.last_steps == 200
    assert count > 10000, count


def test_restoring_a_state_of_another_system_raises_value_error_and_changes_nothing():
    sim = stancf.Simulation(bridle(10))
    sim.initialize(START)
    sim.step_to(DT, START)
    # One line from an anchor to a fairlead at (8, 0, 4).
    other = stancf.Simulation(EXAMPLES / "fairlead-graded.toml")
    other.initialize([8.0, 0.0, 4.0])
    before = (sim.time, sim.line(1).nodes.copy(), sim.line_ids)
    with pytest.raises(ValueError, match=r"another system \(1 line, 2 points\) cannot be "
                                         r"restored into this one \(2 lines, 3 points\)"):
        sim.restore(other.save())
    assert (sim.time, sim.line_ids) == (before[0], before[2])
    assert np.array_equal(sim.line(1).nodes, before[1])
    for not_a_state in ("state", None, 1.5, other):
        with pytest.raises(ValueError, match=r"state: expected a state from Simulation.save\(\)"):
            sim.restore(not_a_state)
    # A second Simulation of the same scenario takes it: a restart.
    again = stancf.Simulation(bridle(10))
    again.restore(sim.save())
    assert np.array_equal(again.step_to(2 * DT, START), sim.step_to(2 * DT, START))


def test_an_interval_of_too_many_steps_is_refused_until_max_interval_steps_is_raised():
    sim = stancf.Simulation(bridle(10))
    assert sim.max_interval_steps == 100_000
    sim.initialize(START)
    sim.step_to(DT, START)
    nodes = sim.line(1).nodes.copy()
    with pytest.raises(ValueError, match="more than the 100000 one call may take") as e:
        sim.step_to(1e6, START)
    assert isinstance(e.value, stancf.ScenarioError)
    assert "max_interval_steps" in str(e.value)
    assert sim.time == DT and np.array_equal(sim.line(1).nodes, nodes)
    few = stancf.Simulation(bridle(10), max_interval_steps=4)
    few.initialize(START)
    with pytest.raises(ValueError, match="takes 5 steps"):
        few.step_to(5 * DT, START)
    few.max_interval_steps = 5
    few.step_to(5 * DT, START)
    assert few.last_steps == 5
    for bad, error in ((0, ValueError), (-3, ValueError), (2.5, TypeError), ("9", TypeError),
                       (True, TypeError)):
        with pytest.raises(error, match="max_interval_steps"):
            few.max_interval_steps = bad
    assert few.max_interval_steps == 5


def test_arguments_that_are_not_real_numbers_or_flat_arrays_are_refused_naming_them():
    sim = stancf.Simulation(bridle(10))
    sim.initialize(START)
    for t in ("1", None, 1j, [DT]):
        with pytest.raises(TypeError, match="t: expected a real number of seconds"):
            sim.step_to(t, START)
    complex_x = np.array(START, dtype=complex)  # a zero imaginary part
    with pytest.raises(TypeError, match="x: complex values are refused"):
        sim.step_to(DT, complex_x)
    with pytest.raises(TypeError, match="xd: complex values are refused"):
        sim.step_to(DT, START, [0.0, 1j, 0.0])
    with pytest.raises(TypeError, match="x: expected 3 real numbers"):
        sim.step_to(DT, ["6", "0", "1"])
    with pytest.raises(ValueError, match=r"x: expected a flat sequence .* shape \(3, 3\)"):
        sim.step_to(DT, np.tile(START, (3, 1)))
    with pytest.raises(ValueError, match=r"x: expected 3 values \(coupled_dof"):
        sim.step_to(DT, START + [0.0])
    with pytest.raises(ValueError, match=r"x: expected 3 real numbers"):
        sim.step_to(DT, [[6.0, 0.0], [1.0]])
    assert sim.time == 0.0
    # Lists, tuples, numpy scalars and real arrays of ints or floats.
    sim.step_to(np.float64(DT), (6, 0, 1))
    sim.step_to(2 * DT, np.array([6, 0, 1]), np.zeros(3, dtype=np.float32))
    sim.step_to(np.array(3 * DT), np.array(START))
    assert sim.time == pytest.approx(3 * DT)


def _interrupted_while_stepping():
    """A long step_to in this (the main) thread, interrupted by a second
    thread as Ctrl-C would: the second thread calls ``sim.time`` until it
    is refused (the step_to holds the Simulation), then interrupts the
    main thread. Nothing waits on a clock: the interval, 5e7 steps, cannot
    end before the interruption (hours of work), and the second thread
    gives up after 120 s of being let through. Returns the simulation,
    the time reached before, the time asked for, the KeyboardInterrupt
    and the refusal the second thread saw."""
    sim = stancf.Simulation(bridle(10), max_interval_steps=10**8)
    sim.initialize(START)
    sim.step_to(DT, START)
    start, asked = sim.time, 1e4
    refused = []

    def second():
        end = time.monotonic() + 120.0
        while time.monotonic() < end:
            try:
                sim.time
            except RuntimeError as e:
                refused.append(str(e))
                break
            time.sleep(1e-3)
        _thread.interrupt_main()

    th = threading.Thread(target=second)
    th.start()
    try:
        with pytest.raises(KeyboardInterrupt) as e:
            sim.step_to(asked, START)
    finally:
        th.join()
    return sim, start, asked, e.value, refused


def test_ctrl_c_stops_step_to_at_its_last_converged_step_and_the_next_call_goes_on():
    sim, start, asked, _, refused = _interrupted_while_stepping()
    assert refused, "the step_to was never seen running"
    assert start < sim.time < asked
    reached = sim.time
    f = sim.step_to(reached + DT, START)
    assert np.isfinite(f).all() and sim.time == pytest.approx(reached + DT)


def test_a_second_thread_is_told_a_simulation_is_used_by_one_thread_at_a_time():
    sim, _, _, _, refused = _interrupted_while_stepping()
    assert len(refused) == 1
    assert refused[0].startswith("a Simulation is used by one thread at a time;"), refused
    assert "give each thread its own Simulation" in refused[0]
    # Not pyo3's borrow message, and the Simulation answers again after.
    assert "borrowed" not in refused[0]
    assert sim.time > 0.0


def _bridle_deck_with_segments(tmp_path, segs):
    """The bridle deck of the examples, its line 1 of `segs` segments and
    its clump weight a coupled point."""
    text = (ROOT / "examples" / "midwater-bridle-moordyn.txt").read_text()
    row = "1   wire      1        3        46.0      20 "
    assert row in text
    text = text.replace(row, "1   wire      1        3        46.0      %s " % segs)
    text = text.replace("3   Free ", "3   Coupled ")
    deck = tmp_path / "deck.txt"
    deck.write_text(text)
    return deck


def test_a_deck_beyond_the_bounds_is_refused_before_it_is_built(tmp_path):
    # Issue 28, item 4: 1e7 segments used to abort the interpreter.
    deck = _bridle_deck_with_segments(tmp_path, "10000000")
    for allow in (False, True):
        with pytest.raises(stancf.ScenarioError, match="above the 1000000 segments"):
            stancf.Simulation(deck, allow_large=allow)
    deck = _bridle_deck_with_segments(tmp_path, "3000")
    with pytest.raises(stancf.ScenarioError, match="3024 elements in all"):
        stancf.Simulation(deck)
    sim = stancf.Simulation(deck, allow_large=True)
    assert sim.coupled_dof == 3


def test_a_device_or_a_folder_is_refused_naming_it(tmp_path):
    # Issue 28, item 13: the files are read as the command line reads them.
    for path in ("/dev/zero", str(tmp_path)):
        with pytest.raises(stancf.ScenarioError, match="not a regular file"):
            stancf.Simulation(path)
        with pytest.raises(stancf.ScenarioError, match="not a regular file"):
            stancf.Scenario.from_file(path)
