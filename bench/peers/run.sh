#!/usr/bin/env bash
# The race against Exudyn (issue 6): builds stancf, makes a virtual
# environment with Exudyn, numpy and matplotlib from PyPI, and runs the
# sweeps. Up to ~20 minutes on a 2-core machine; `./run.sh --quick` runs a
# few points only (a smoke test). Results: bench/peers/out/.
# `./run.sh --repeat-cheapest [N]` runs race_repeat.py: the last race's
# cheapest runs at 0.1 mm, each N times (out/race_repeat.md).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
(cd "$root" && cargo build --release -p stancf-cli)
venv="$here/.venv"
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet exudyn numpy matplotlib
fi
cd "$here"
if [ "${1:-}" = "--repeat-cheapest" ]; then
  # race_repeat.py: the last race's cheapest runs at 0.1 mm, each run N
  # times in alternation (out/race_repeat.md, about a minute)
  shift
  exec env PYTHONWARNINGS=ignore "$venv/bin/python" race_repeat.py "$@"
fi
PYTHONWARNINGS=ignore "$venv/bin/python" race.py "$@"
