"""A seabed of varying depth from Python (docs/interface.md, "Water";
docs/method.md §12.2 (W40a)-(W40c)): a MoorDyn deck's ``SeafloorFile``
reaches the coupled simulation, and ``[water.seabed] file`` a scenario's
run."""

from pathlib import Path

import numpy as np
import pytest

import stancf

EXAMPLE = Path(__file__).resolve().parents[3] / "examples" / "oc4-deepcwind-moordyn.txt"


def seafloor(height_at):
    """MoorDyn's seafloor format on x, y = -1000, -500, ..., 1000 m."""
    ticks = [-1000.0 + 500.0 * k for k in range(5)]
    rows = [f"{x} {y} {height_at(x, y)}" for x in ticks for y in ticks]
    axis = " ".join(str(t) for t in ticks)
    return f"5 5\n{axis}\n{axis}\n" + "\n".join(rows) + "\n"


def with_seafloor(tmp_path, name, height_at):
    (tmp_path / f"{name}.bed").write_text(seafloor(height_at))
    text = EXAMPLE.read_text().replace(
        "200       WtrDpth", f"{name}.bed  SeafloorFile  bed\n200       WtrDpth", 1
    )
    deck = tmp_path / f"{name}.txt"
    deck.write_text(text)
    return deck


def fairlead_forces(deck):
    sim = stancf.Simulation(deck)
    return np.array(sim.initialize(sim.initial_positions()))


def test_a_flat_seafloor_file_is_the_flat_bed_and_a_deeper_one_moves_the_fairleads(tmp_path):
    flat = fairlead_forces(EXAMPLE)
    # The bed's heights as MoorDyn reads them, in single precision: -200
    # is exact, so the grid is the flat bed. On a grid the bed's push is
    # integrated at the axial rule, on a plane exactly where the chain is
    # in the bed (docs/method.md section 12.2, (W47a)-(W47c)): the two
    # equilibria differ by the axial rule's first-order error at the
    # touchdown (measured 8.8e-5 of the largest force; 7e-5 of H_F on the
    # OC4 chain at 40 elements), bounded at 1e-3.
    on_grid = fairlead_forces(with_seafloor(tmp_path, "level", lambda x, y: -200.0))
    assert np.max(np.abs(on_grid - flat)) <= 1e-3 * np.max(np.abs(flat))
    # 5 m deeper away from the anchors' radius, level under them: the
    # chains hang longer and pull the fairleads harder.
    def bowl(x, y):
        return -205.0 if abs(x) < 600 and abs(y) < 600 else -200.0

    deeper = fairlead_forces(with_seafloor(tmp_path, "bowl", bowl))
    assert np.max(np.abs(deeper - flat)) > 1e-3 * np.max(np.abs(flat))


def test_a_scenarios_seafloor_file_runs_and_a_bad_one_is_refused_by_line(tmp_path):
    (tmp_path / "bed.txt").write_text(seafloor(lambda x, y: -200.0 - 0.001 * abs(x)))
    scenario = tmp_path / "run.toml"
    scenario.write_text(
        f'[system]\nmoordyn = "{EXAMPLE}"\n[water.seabed]\nfile = "bed.txt"\n'
        '[analysis]\ntype = "static"\n'
    )
    res = stancf.run(stancf.Scenario.from_file(scenario), out=tmp_path / "out")
    rows = np.genfromtxt(res.directory / "tensions.csv", delimiter=",", names=True)
    assert np.all(np.isfinite(rows["tension"])) and len(rows) == 6
    (tmp_path / "bed.txt").write_text("2 2\n0 10\n0 5\n0 0 -1\n")
    with pytest.raises(stancf.ScenarioError, match=r"no row gives the node \(x, y\) = \(0, 5\)"):
        stancf.Scenario.from_file(scenario)
