#!/usr/bin/env bash
# The race against MoorDyn (issue 15): builds stancf, makes a virtual
# environment with MoorDyn (2.7 or later), numpy and matplotlib from PyPI,
# and runs both codes on the same decks (OC4, the steep wave, the riser).
# `./run.sh --quick` runs a few coarse points only (a smoke test,
# minutes); the full race takes about an hour on a 2-core machine. Results: bench/peers/moordyn/out/, copied
# to docs/race/ by `./run.sh --publish`. `./run.sh --coupling-check` runs
# coupling_check.py instead (why MoorDyn is driven at its own step);
# `--added-mass-check` runs added_mass_check.py (why the steep wave is
# raced without added mass); `--bodies-check` runs bodies_check.py (with its
# modules bodies_common, bodies_decks, bodies_codes, bodies_studies)
# (MoorDyn's own body and rod decks: both codes' static equilibria,
# out/bodies_check.{csv,md}, about 20 minutes); `--decks-check` runs
# decks_check.py (every other third-party deck: both codes' static
# equilibria, out/decks_check.{csv,md}); `--visco-check` runs
# visco_check.py (viscoelastic lines driven against MoorDyn, seconds);
# `--viv-check` runs viv_check.py (MoorDyn's VIV riser in both codes and
# the published frequency, out/viv_check.md, minutes);
# `--check-all` runs check_all.py (`stancf check` over every third-party
# deck, bodies and rods included: out/check_all.md, a minute, no MoorDyn);
# `--tables-only` redraws the table and figure from out/moordyn_race.csv;
# `--repeat-cheapest [N]` runs race_repeat.py (the last race's cheapest
# runs at 1 %, each N times: out/race_repeat.md, a few minutes).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../../.." && pwd)"
(cd "$root" && cargo build --release -p stancf-cli)
if [ "${1:-}" = "--check-all" ]; then
  exec python3 "$here/check_all.py"
fi
venv="$here/.venv"
if [ ! -x "$venv/bin/python" ]; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet "moordyn>=2.7" numpy matplotlib scipy
fi
cd "$here"
if [ "${1:-}" = "--added-mass-check" ]; then
  exec env PYTHONWARNINGS=ignore "$venv/bin/python" added_mass_check.py
fi
if [ "${1:-}" = "--visco-check" ]; then
  exec env PYTHONWARNINGS=ignore "$venv/bin/python" visco_check.py
fi
if [ "${1:-}" = "--viv-check" ]; then
  exec env PYTHONWARNINGS=ignore "$venv/bin/python" viv_check.py
fi
if [ "${1:-}" = "--decks-check" ]; then
  shift
  exec env PYTHONWARNINGS=ignore "$venv/bin/python" decks_check.py "$@"
fi
if [ "${1:-}" = "--bodies-check" ]; then
  shift
  exec env PYTHONWARNINGS=ignore "$venv/bin/python" bodies_check.py "$@"
fi
if [ "${1:-}" = "--repeat-cheapest" ]; then
  # race_repeat.py: the last race's cheapest runs at 1 % of OC4 and the
  # steep wave, each run N times in alternation (out/race_repeat.md)
  shift
  exec env PYTHONWARNINGS=ignore "$venv/bin/python" race_repeat.py "$@"
fi
if [ "${1:-}" = "--coupling-check" ]; then
  "$venv/bin/python" -c "import scipy" 2>/dev/null || "$venv/bin/pip" install --quiet scipy
  exec "$venv/bin/python" coupling_check.py
fi
if [ "${1:-}" = "--coupled-body-check" ]; then
  # coupled_body_check.py: the OC4 body through libstancf_c against MoorDyn
  # (out/coupled_body/coupled_body_check.md, about 20 minutes)
  shift
  (cd "$root" && cargo build --release -p stancf-capi)
  "$venv/bin/python" -c "import scipy" 2>/dev/null || "$venv/bin/pip" install --quiet scipy
  exec env PYTHONWARNINGS=ignore "$venv/bin/python" coupled_body_check.py "$@"
fi
PYTHONWARNINGS=ignore "$venv/bin/python" race.py "$@"
