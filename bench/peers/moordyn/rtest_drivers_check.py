#!/usr/bin/env python3
"""OpenFAST's MoorDyn regression cases run through their driver files.

Each case folder of OpenFAST's r-test, modules/moordyn/<case>/, holds a
MoorDyn driver file (md_driver.inp or *.dvr), the deck it names and
MoorDyn-F's reference output, driver.MD.out. This script runs
`stancf run <driver>` on each (docs/interface.md, "MoorDyn driver
files"), reads stancf's channels.csv and the reference, and compares every
channel both have at the reference's times (stancf's rows interpolated
linearly between its written times): the largest difference over the run
and the difference at the last time, relative to the largest magnitude of
the channel in the reference (angles modulo a full turn; a channel that is
round-off in the reference compared absolutely).

usage: rtest_drivers_check.py <r-test>/modules/moordyn [case ...]
       (STANCF_BIN names the binary; default target/release/stancf)

Prints a Markdown table (the README's "OpenFAST's MoorDyn regression
cases").
"""

import csv
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[3]
BIN = os.environ.get("STANCF_BIN", str(ROOT / "target" / "release" / "stancf"))


def driver_file(case: Path):
    """The case's driver file: md_driver.inp, else a *.dvr."""
    inp = case / "md_driver.inp"
    if inp.exists():
        return inp
    dvr = sorted(case.glob("*.dvr"))
    return dvr[0] if dvr else None


def read_reference(path: Path):
    """MoorDyn-F's output file: the row starting with Time names the
    channels, the next gives units, then one row of numbers per time."""
    lines = path.read_text().splitlines()
    start = next(i for i, l in enumerate(lines) if l.split()[:1] == ["Time"])
    names = lines[start].split()
    rows = []
    for l in lines[start + 2:]:
        w = l.split()
        if len(w) != len(names):
            continue
        try:
            rows.append([float(v) for v in w])
        except ValueError:
            continue
    return names, rows


def read_channels(path: Path):
    with open(path) as f:
        r = csv.reader(f)
        names = next(r)
        rows = [[float(v) if v else float("nan") for v in row] for row in r]
    return names, rows


def interpolate(ts, vs, t):
    """vs at t, linear between the written times ts (None outside)."""
    if t < ts[0] - 1e-9 or t > ts[-1] + 1e-9:
        return None
    lo, hi = 0, len(ts) - 1
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if ts[mid] <= t:
            lo = mid
        else:
            hi = mid
    if ts[hi] == ts[lo]:
        return vs[lo]
    f = min(max((t - ts[lo]) / (ts[hi] - ts[lo]), 0.0), 1.0)
    return vs[lo] + f * (vs[hi] - vs[lo])


# A reference channel whose largest magnitude is below this is round-off
# in MoorDyn-F (md_vertical's ROD1PX, 1e-20 m): compared absolutely only.
ROUND_OFF = 1e-9


def is_angle(name: str) -> bool:
    """MoorDyn's rotation channels (Body<n>RX.., Rod<n>RX..), in degrees."""
    return name.upper()[-2:] in ("RX", "RY", "RZ") and name.upper().startswith(("BODY", "ROD"))


def difference(name, a, b):
    """|a - b|, angles (degrees) taken modulo a full turn."""
    d = abs(a - b)
    if is_angle(name):
        d = d % 360.0
        d = min(d, 360.0 - d)
    return d


def compare(case: Path, out: Path):
    """Every channel both have: (name, largest difference over the run,
    difference at the reference's last time, the reference's largest
    magnitude)."""
    ref_names, ref_rows = read_reference(case / "driver.MD.out")
    names, rows = read_channels(out / "channels.csv")
    ts = [r[0] for r in rows]
    by_lower = {n.lower(): k for k, n in enumerate(names)}
    found = []
    for c, name in enumerate(ref_names[1:], start=1):
        k = by_lower.get(name.lower())
        if k is None:
            continue
        vs = [r[k] for r in rows]
        scale = max(abs(r[c]) for r in ref_rows)
        diff, end = 0.0, None
        for r in ref_rows:
            v = interpolate(ts, vs, r[0])
            if v is not None:
                d = difference(name, v, r[c])
                diff = max(diff, d)
                end = d
        found.append((name, diff, end, scale))
    return found, len(ref_names) - 1


def summary(found):
    """The channel of largest relative difference over the run and at the
    end (channels at round-off named with their absolute difference)."""
    real = [f for f in found if f[3] >= ROUND_OFF]
    tiny = [f for f in found if f[3] < ROUND_OFF]
    words = []
    if real:
        w = max(real, key=lambda f: f[1] / f[3])
        words.append(f"{w[0]}: {w[1] / w[3]:.3e} ({w[1]:.4g})")
        e = max(real, key=lambda f: (f[2] or 0.0) / f[3])
        words.append(f"at the end {e[0]}: {(e[2] or 0.0) / e[3]:.3e}")
    for f in tiny:
        words.append(f"{f[0]} round-off in MoorDyn-F, {f[1]:.2g} absolute")
    return "; ".join(words)


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    root = Path(sys.argv[1])
    cases = sys.argv[2:] or sorted(p.name for p in root.iterdir() if p.is_dir())
    print("| case | stancf | wall s | channels compared | largest difference over the run, and at the end (of the channel's largest magnitude) |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        for name in cases:
            case = root / name
            dvr = driver_file(case)
            if dvr is None or not (case / "driver.MD.out").exists():
                continue
            out = Path(tmp) / name
            start = time.time()
            p = subprocess.run([BIN, "run", "-q", str(dvr), "--out", str(out)],
                               capture_output=True, text=True)
            wall = time.time() - start
            if p.returncode != 0:
                why = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""
                print(f"| {name} | exit {p.returncode}: {why[:160]} | {wall:.1f} | | |")
                continue
            found, total = compare(case, out)
            print(f"| {name} | ran | {wall:.1f} | {len(found)} of {total} | {summary(found)} |")


if __name__ == "__main__":
    main()
