"""The paper's Fig. 8 as a sweep on a Dask cluster: the free pendulum at
t = 0.68 s for drag coefficients 0 to 2.

    python examples/python/pendulum_drag_sweep.py [--workers 2] [--out out/pendulum-sweep]

Starts a dask.distributed.LocalCluster (replace it by a Client of your
cluster: only scenarios and summary figures cross the wire, each worker
writes its full results to OUT/run_<k>/, which must be a folder every
worker sees), runs the sweep, prints the table and draws the shapes with
matplotlib to OUT/fig8.png.
"""
import argparse
from pathlib import Path

import numpy as np
import stancf

ROOT = Path(__file__).resolve().parents[2]


def centre_line(res, step, per_element=12):
    """The cubic Hermite centre line through the nodes and slopes of a
    written step (what one SAC-2 element is)."""
    r, d = res.nodes[step], res.slopes[step]
    l = res.summary["length"] / res.summary["elements"]
    xi = np.linspace(0.0, 1.0, per_element + 1)
    h = np.stack([2 * xi**3 - 3 * xi**2 + 1, l * (xi**3 - 2 * xi**2 + xi),
                  -2 * xi**3 + 3 * xi**2, l * (xi**3 - xi**2)], axis=1)
    parts = [h @ np.stack([r[k], d[k], r[k + 1], d[k + 1]]) for k in range(len(r) - 1)]
    return np.vstack([p if k == 0 else p[1:] for k, p in enumerate(parts)])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--out", default=str(ROOT / "out" / "pendulum-sweep"))
    args = ap.parse_args()
    from dask.distributed import Client, LocalCluster

    scenario = stancf.Scenario.from_file(ROOT / "examples" / "pendulum-drag.toml")
    scenario = scenario.with_values({"analysis.duration": 0.68, "output.every": 100})
    grid = {"loads.1.drag_coefficient": [0.0, 0.5, 1.0, 1.5, 2.0]}
    with LocalCluster(n_workers=args.workers, threads_per_worker=1, dashboard_address=None) as cluster, \
            Client(cluster) as client:
        table = stancf.sweep(scenario, grid, executor=client, out=args.out)
    rows = table.to_dict("records") if hasattr(table, "to_dict") else table
    print("%6s %8s %12s %12s %10s" % ("C", "status", "tip x (mm)", "tip y (mm)", "wall (s)"))
    for r in rows:
        print("%6.2f %8s %12.4f %12.4f %10.3f" % (r["loads.1.drag_coefficient"], r["status"],
                                                1e3 * r["tip_x"], 1e3 * r["tip_y"], r["wall_time_s"]))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4.5))
    colors = plt.cm.viridis(np.linspace(0, 0.9, len(rows)))
    for r, color in zip(rows, colors):
        res = stancf.Result.read(Path(args.out) / ("run_%04d" % r["run"]))
        step = int(np.argmin(np.abs(res.t - 0.68)))
        line = centre_line(res, step)
        ax.plot(line[:, 0], line[:, 1], color=color, label="C = %g" % r["loads.1.drag_coefficient"])
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_title("Free pendulum at t = 0.68 s (Chen et al. 2023, Fig. 8), 4 SAC-2")
    ax.grid(alpha=0.3)
    ax.legend()
    fig.tight_layout()
    out = Path(args.out) / "fig8.png"
    fig.savefig(out, dpi=120)
    print("shapes in", out)


if __name__ == "__main__":
    main()
