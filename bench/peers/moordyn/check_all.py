"""`stancf check` over every third-party MoorDyn deck (issue 31's count):
MoorDyn's tests, benchmarks and examples at v2.7.1, OpenFAST's r-test
MoorDyn decks and MoorPy's examples and tests, body and rod decks
included. Needs no MoorDyn: a minute.

Run through ./run.sh --check-all (it builds stancf), or directly with
$STANCF set. The decks: every .txt or .dat file under $MOORDYN_DECKS
(default /tmp/decks/md, an extracted tree of MoorDyn's repository at
v2.7.1: `git -C $MOORDYN_REPO archive v2.7.1 tests bench example | tar -x
-C /tmp/decks/md`) and $PEER_DECKS (default ../shared/peer-decks) that
has a MoorDyn section header, as decks_check.py finds them, and under
$MOORPY_DECKS (default /tmp/decks/moorpy: MoorPy's repository's .txt and
.dat files, `git -C <MoorPy> archive HEAD examples tests | tar -x -C
/tmp/decks/moorpy`; said and left out when absent). Each is
checked from its own folder (MoorDyn's own suite names its files
relative to its tests folder; stancf also looks beside the deck and one
folder up). Writes out/check_all.md: each deck, passed or the first
line of its refusal.
"""
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
STANCF = os.environ.get("STANCF", os.path.join(ROOT, "target", "release", "stancf"))
MD = os.environ.get("MOORDYN_DECKS", "/tmp/decks/md")
PEER = os.environ.get("PEER_DECKS", os.path.join(ROOT, "..", "shared", "peer-decks"))
MOORPY = os.environ.get("MOORPY_DECKS", "/tmp/decks/moorpy")
HEADER = re.compile(r"^-+ *(LINE TYPES|LINE DICTIONARY|LINES|LINE PROPERTIES|POINTS|RODS|BODIES|"
                    r"ROD TYPES)", re.IGNORECASE | re.MULTILINE)


def decks():
    """(name, path) of every deck under both roots, sorted."""
    found = []
    roots = [("md", MD), ("peer", PEER)]
    if os.path.isdir(MOORPY):
        roots.append(("moorpy", MOORPY))
    else:
        print("MoorPy's decks: none at %s, left out" % MOORPY)
    for base, root in roots:
        if not os.path.isdir(root):
            sys.exit("no decks at %s (see this file's docstring)" % root)
        for folder, _, files in os.walk(root):
            for f in files:
                path = os.path.join(folder, f)
                if not f.endswith((".txt", ".dat")):
                    continue
                with open(path, errors="replace") as h:
                    if HEADER.search(h.read(200000)):
                        found.append(("%s:%s" % (base, os.path.relpath(path, root)), path))
    return sorted(found)


def check(path):
    """(exit code, the first line of the refusal or "")."""
    o = subprocess.run([STANCF, "check", path], cwd=os.path.dirname(path),
                       capture_output=True, text=True, timeout=120)
    first = next((l for l in o.stderr.splitlines() if l.startswith("error")), "")
    return o.returncode, first.replace(os.path.dirname(path) + "/", "")


def main():
    rows = [(name,) + check(path) for name, path in decks()]
    passed = sum(1 for _, code, _ in rows if code == 0)
    lines = ["%d of %d decks pass `stancf check`." % (passed, len(rows)), "",
             "| deck | check |", "|---|---|"]
    for name, code, first in rows:
        lines.append("| %s | %s |" % (name, "passes" if code == 0
                                      else "exit %d: %s" % (code, first.replace("|", "/"))))
    os.makedirs(os.path.join(HERE, "out"), exist_ok=True)
    with open(os.path.join(HERE, "out", "check_all.md"), "w") as h:
        h.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
