"""Design load cases of the OC4 DeepCwind mooring on a Dask cluster: 2 Hs
x 2 Tp x 3 headings x 3 seeds of JONSWAP seas, 36 runs of 600 s.

    python examples/python/oc4_design_load_cases.py [--workers 2] [--out out/oc4-dlc]
                                                    [--duration 600] [--serial]

The deck (examples/oc4-deepcwind-moordyn.txt, its fairleads held where the
deck puts them) is swept as the scenario that takes it: the sea
(`water.jonswap.*`), the run (600 s of Galerkin steps of 0.5 s from the
static equilibrium), the statistics after a 100 s transient, and an
illustrative breaking load of the chain, 4.96 MN (DNV's R3 studless
formula, 0.0223 d^2 (44 - 0.08 d) kN at d = 76.6 mm). Starts a
dask.distributed.LocalCluster (replace it by a Client of your cluster:
only scenarios and figures cross the wire, each worker writes its full
results to OUT/run_<k>/, which every worker must see), runs the sweep,
prints each sea state's most probable largest fairlead tension over its
seeds (OUT/extremes.csv, a Gumbel fit) and draws it against Hs for each
heading, with the MBL, to OUT/fairlead-tension.png. `--serial` runs the
same 36 runs one after another in this process instead (for the
speed-up).
"""
import argparse
import csv
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import stancf

ROOT = Path(__file__).resolve().parents[2]
MBL = 4.96e6
SEAS = {
    "water.jonswap.hs": [6.0, 10.0],
    "water.jonswap.tp": [10.0, 14.0],
    "water.jonswap.heading": [0.0, 30.0, 60.0],
    "water.jonswap.seed": [1, 2, 3],
}


def scenario(duration):
    """The deck, taken by a scenario with the run's keys set."""
    deck = stancf.Scenario.from_file(ROOT / "examples" / "oc4-deepcwind-moordyn.txt")
    return deck.with_values({
        "analysis.duration": duration,
        "analysis.time_step": 0.5,
        "analysis.time_scheme": "galerkin",
        "output.statistics_after": min(100.0, duration / 6),
        "output.files": ["tensions.csv", "points.csv"],
        "system.mbl.chain": MBL,
    })


def fairlead_mpm(state):
    """The largest of the three fairleads' (ends B) most probable maxima."""
    return max(float(state["tension_max_line%d_B_mpm" % k]) for k in (1, 2, 3))


def draw(states, png):
    """The largest fairlead MPM against Hs, per heading and Tp: at the
    MBL's scale (left) and at its own (right)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for ax, unit in zip(axes, [1e6, 1e3]):
        for heading, marker in zip(SEAS["water.jonswap.heading"], "osd"):
            for tp, style in zip(SEAS["water.jonswap.tp"], ["-", "--"]):
                pts = [(float(s["water.jonswap.hs"]), fairlead_mpm(s) / unit) for s in states
                       if float(s["water.jonswap.heading"]) == heading
                       and float(s["water.jonswap.tp"]) == tp]
                ax.plot(*zip(*pts), style, marker=marker,
                        label="heading %g deg, Tp %g s" % (heading, tp))
        ax.set_xlabel("Hs (m)")
    axes[0].axhline(MBL / 1e6, color="k", lw=1)
    axes[0].text(SEAS["water.jonswap.hs"][0], MBL / 1e6, " MBL %.2f MN" % (MBL / 1e6),
                 va="bottom")
    axes[0].set_ylim(0, 1.1 * MBL / 1e6)
    axes[0].set_ylabel("largest fairlead tension, MPM of 3 seeds (MN)")
    axes[1].set_ylabel("the same (kN)")
    axes[1].legend(fontsize=8)
    fig.suptitle("OC4 DeepCwind mooring in JONSWAP seas, fairleads held: "
                 "the waves' load on the lines alone")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--out", default=str(ROOT / "out" / "oc4-dlc"))
    ap.add_argument("--duration", type=float, default=600.0)
    ap.add_argument("--serial", action="store_true")
    ap.add_argument("--replot", action="store_true",
                    help="draw the figure from OUT/extremes.csv, running nothing")
    args = ap.parse_args()
    if not args.replot:
        run(args)
    with open(Path(args.out) / "extremes.csv", newline="") as f:
        states = list(csv.DictReader(f))
    print("%6s %6s %8s %6s %22s %8s" % ("Hs", "Tp", "heading", "seeds", "fairlead MPM (kN)",
                                       "SF"))
    for s in states:
        mpm = fairlead_mpm(s)
        print("%6s %6s %8s %6s %22.1f %8.2f" % (
            s["water.jonswap.hs"], s["water.jonswap.tp"], s["water.jonswap.heading"],
            s["seeds"], mpm / 1e3, MBL / mpm))
    png = Path(args.out) / "fairlead-tension.png"
    draw(states, png)
    print("figure:", png)


def run(args):
    """The 36 runs on a Dask LocalCluster (or in series), timed."""
    deck, grid = scenario(args.duration), SEAS
    t0 = time.perf_counter()
    if args.serial:
        with ThreadPoolExecutor(max_workers=1) as one:
            stancf.sweep(deck, grid, executor=one, out=args.out)
    else:
        from dask.distributed import Client, LocalCluster
        with LocalCluster(n_workers=args.workers, threads_per_worker=1,
                          dashboard_address=None) as cluster, Client(cluster) as client:
            stancf.sweep(deck, grid, executor=client, out=args.out)
    print("36 runs of %g s in %.1f s (%s)" % (
        args.duration, time.perf_counter() - t0,
        "in series" if args.serial else "%d workers" % args.workers))


if __name__ == "__main__":
    main()
