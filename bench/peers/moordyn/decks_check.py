"""Static equilibria of every third-party MoorDyn deck against MoorDyn 2.7
(issue 31's check; CI does not run it). Writes out/decks_check.csv and
out/decks_check.md; its scratch is out/decks_check/.

Run through ./run.sh --decks-check (it builds stancf and makes the
virtual environment with MoorDyn 2.7 or later from PyPI); `--deck=<part>`
runs only the decks whose path contains it.

The decks: every file under $MOORDYN_DECKS (an extracted tree of
MoorDyn's repository, default /tmp/decks/md: its tests, benchmarks and
examples) and $PEER_DECKS (default ../shared/peer-decks from the
repository: OpenFAST's MoorDyn regression decks) that has a MoorDyn
section header (LINE TYPES, LINE DICTIONARY, LINES, LINE PROPERTIES,
POINTS, RODS, BODIES, ROD TYPES), less the body and rod decks that
bodies_check.py compares with its own studies (out/bodies_check.md).
Each deck's folder is copied (the files a deck names beside it come
along: current profiles, wave files); the originals are never edited.
Per deck, as bodies_check.py does (its steps 1 to 4, shared code):
`stancf check`; stancf's static equilibrium (`stancf run`, a deck alone
is static); MoorDyn's initial-condition solvers run until they settle
(each chunk's deck beside the deck's own files), the coupled degrees of
freedom held where the deck puts them; each line end's tension and each
free point's position compared. A deck's `SeafloorFile` is named
relative to the working directory: both codes run from the suite's
`tests/` folder, as MoorDyn's own test suite does.
"""
import os
import shutil
import sys

from bodies_common import *  # noqa: F401,F403
from bodies_decks import *  # noqa: F401,F403
from bodies_codes import *  # noqa: F401,F403
from bodies_studies import *  # noqa: F401,F403
import bodies_check as bc

PEER_DECKS = os.environ.get("PEER_DECKS", os.path.join(race.ROOT, "..", "shared", "peer-decks"))
# The tables' and scratch's name (another for a second run in parallel).
NAME = os.environ.get("DECKS_CHECK_NAME", "decks_check")
DECKS_WORK = os.path.join(OUT, NAME)
HEADER = re.compile(r"^-+ *(LINE TYPES|LINE DICTIONARY|LINES|LINE PROPERTIES|POINTS|RODS|BODIES|"
                    r"ROD TYPES)", re.IGNORECASE | re.MULTILINE)
# MoorDyn's wall budget per solver and deck (s): lines settle within it
# or come close (the table says which settled).
WALL = 60.0
# ... checked between MoorDyn's chunks of pseudo-time; a chunk that does
# not return (a deck whose step is tiny: tripod.txt, 3D_seafloor's
# hanging_lines.txt with dtIC 1e-5 s) is stopped after this many seconds
# of wall time, MoorDyn running in a child process.
DECK_WALL = 600.0


def discover():
    """(name, absolute path) of every deck, sorted; bodies_check.py's
    decks left out."""
    theirs = {os.path.join(DECKS_DIR, p) for _, p in DECKS}
    found = []
    for root in (DECKS_DIR, PEER_DECKS):
        for folder, _, files in os.walk(root):
            for f in files:
                if not f.endswith((".txt", ".dat")):
                    continue
                path = os.path.join(folder, f)
                try:
                    with open(path, errors="replace") as h:
                        text = h.read(200000)
                except OSError:
                    continue
                if HEADER.search(text) and path not in theirs:
                    base = "md" if root == DECKS_DIR else "peer"
                    found.append(("%s:%s" % (base, os.path.relpath(path, root)), path))
    return sorted(found)


def check_one(name, path):
    """One deck: check, both equilibria, the comparison rows (as
    bodies_check.check_deck, on a copy of the deck's folder)."""
    folder = os.path.join(DECKS_WORK, re.sub(r"[^A-Za-z0-9_.-]+", "_", name))
    if os.path.exists(folder):
        shutil.rmtree(folder)
    src = os.path.join(folder, "src")
    shutil.copytree(os.path.dirname(path), src,
                    ignore=lambda d, names: [n for n in names if os.path.isdir(os.path.join(d, n))])
    deck = os.path.join(src, os.path.basename(path))
    with open(deck, errors="replace") as f:
        text = f.read()
    res = dict(name=name, path=path, text=text, folder=folder, deck=deck,
               contents=contents(text), rows=[])
    # Both codes run from the suite's `tests/` folder, where a deck's
    # SeafloorFile is named from (`Mooring/3D_seafloor/...`), as MoorDyn's
    # tests run.
    cwd = os.getcwd()
    tests = path.split(os.sep + "tests" + os.sep)
    os.chdir(os.path.join(tests[0], "tests") if len(tests) > 1 else os.path.dirname(path))
    try:
        return run_both(name, path, text, res, folder, src)
    finally:
        os.chdir(cwd)


def run_both(name, path, text, res, folder, src):
    """check_one's runs, from the working directory it chose."""
    st = check_and_solve(res)
    if st is None:
        return res
    # Each MoorDyn chunk's deck beside the deck's own files.
    md_folder = os.path.join(folder, "moordyn")
    for sub in ("first", "second"):
        shutil.copytree(src, os.path.join(md_folder, sub))
    md, runs = settle_within(text, md_folder, DECK_WALL)
    res["moordyn"], res["moordyn_runs"] = md, runs
    for r in runs:
        print("%-50s MoorDyn %s: %s after %g s (%.0f s wall) %s" % (
            name, r["solver"], "settled" if r["settled"] else "stalled" if r["stalled"]
            else "NOT settled", r["time"], r["wall"], r["failed"]), flush=True)
    if st["rc"] == 0 and "snapshot" in md:
        st["objects"] = stancf_objects(st, text)
        res["rows"] = compare(st, dict(tensions=md["snapshot"]["tensions"],
                                       objects=md["snapshot"]["objects"]))
    return res


def settle_within(text, md_folder, limit):
    """moordyn_settle in a child process, stopped after `limit` s of
    wall time: (md, runs) as it returns them, or no snapshot and one run
    saying that MoorDyn did not return."""
    import multiprocessing
    pool = multiprocessing.get_context("fork").Pool(1)
    try:
        job = pool.apply_async(moordyn_settle, (text, md_folder), dict(wall_budget=WALL))
        return job.get(timeout=limit)
    except multiprocessing.TimeoutError:
        solver = "dynamic relaxation" if options(text).get("ICgenDynamic", "0") != "0" \
            else "stationary"
        return {}, [dict(solver=solver, settled=False, stalled=False, time=0.0, wall=limit,
                         error="", history=[],
                         failed="no result: a chunk of %g s of pseudo-time did not return "
                                "within %.0f s of wall time" % (MD_CHUNK, limit))]
    finally:
        pool.terminate()


def write_tables(results, total, t_start):
    """out/decks_check.{csv,md} of the decks run so far (of `total`)."""
    compared = [r for r in results if r["rows"]]
    within = [r for r in compared
              if max((x["difference"] for x in r["rows"] if x["unit"] == "%"), default=0.0)
              <= 100 * LIMIT]
    md = ["# Static equilibria of third-party MoorDyn decks against MoorDyn 2.7", "",
          "stancf `%s`; MoorDyn %s (Python package). Written by decks_check.py "
          "(the body and rod decks: bodies_check.md)." % (bc.git_describe(), bc.moordyn_version()),
          "", "%d of %d decks run; %d pass `stancf check`; %d compared with a MoorDyn "
          "equilibrium, %d of them with every line end tension within 1 %%." % (
              len(results), total, sum(1 for r in results if r["check"][0] == 0),
              len(compared), len(within)), ""]
    md += bc.summary_table(results)
    for res in compared:
        md += ["", "## %s" % res["name"], ""] + bc.detail_table(res)
    md += ["", "Time so far %.0f s." % (time.perf_counter() - t_start)]
    bc.write_csv(results, os.path.join(OUT, NAME + ".csv"))
    with open(os.path.join(OUT, NAME + ".md"), "w") as f:
        f.write("\n".join(md) + "\n")
    return md


def main():
    os.makedirs(DECKS_WORK, exist_ok=True)
    t_start = time.perf_counter()
    only = [a.split("=", 1)[1] for a in sys.argv if a.startswith("--deck=")]
    decks = [(n, p) for n, p in discover() if not only or any(o in p for o in only)]
    results = []
    for n, p in decks:
        results.append(check_one(n, p))
        md = write_tables(results, len(decks), t_start)
    print("\n".join(md[:6]))


if __name__ == "__main__":
    main()
