"""The shared imports and settings of bodies_check.py's modules: the paths,
the decks, MoorDyn's initial-condition budgets and the limits of a
settled state and of a difference worth explaining."""

import csv
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import race  # noqa: E402,F401  (Quiet, STANCF, OUT)

OUT = race.OUT
WORK = os.path.join(OUT, "bodies_check")
STANCF = race.STANCF
DECKS_DIR = os.environ.get("MOORDYN_DECKS", "/tmp/decks/md")
MOORDYN_REPO = os.environ.get("MOORDYN_REPO", "/work/.mirror/FloatingArrayDesign+MoorDyn/repo")

# (name in the tables, path in MoorDyn's repository)
DECKS = [
    ("BodiesAndRods.dat", "tests/Mooring/BodiesAndRods.dat"),
    ("RodHanging.txt", "tests/Mooring/RodHanging.txt"),
    ("RodPinnedFloating.txt", "tests/Mooring/RodPinnedFloating.txt"),
    ("body_tests/bodyDrag.txt", "tests/Mooring/body_tests/bodyDrag.txt"),
    ("body_tests/orbitalBody.txt", "tests/Mooring/body_tests/orbitalBody.txt"),
    ("body_tests/pinnedBody.txt", "tests/Mooring/body_tests/pinnedBody.txt"),
    ("body_tests/rotatingBody.txt", "tests/Mooring/body_tests/rotatingBody.txt"),
    ("rod_tests/AddedMass.txt", "tests/Mooring/rod_tests/AddedMass.txt"),
    ("riser/riser.txt", "tests/Mooring/riser/riser.txt"),
    ("riser/riser_ic1.txt", "tests/Mooring/riser/riser_ic1.txt"),
    ("riser/riser_ic2.txt", "tests/Mooring/riser/riser_ic2.txt"),
    ("rotations/nwu.txt", "tests/Mooring/rotations/nwu.txt"),
    ("local_euler/complex_system.txt", "tests/Mooring/local_euler/complex_system.txt"),
    ("bench/Mooring/floating_rods.txt", "bench/Mooring/floating_rods.txt"),
    ("example/body.txt", "example/body.txt"),
]

# MoorDyn's initial-condition solver: chunk of pseudo-time (s), largest
# pseudo-time, wall budget (s) per deck. The stationary solver's step is
# bounded by the deck's dtM (kept), so a deck with a small dtM and a heavy
# body (BodiesAndRods: dtM 5e-4, 1e6 kg) moves slowly.
MD_CHUNK, MD_MAX_TIME, MD_WALL = 500.0, 40000.0, 400.0
# Settled: the change over a chunk, extrapolated, below these.
SETTLE_TENSION, SETTLE_POSITION, SETTLE_ANGLE = 1e-6, 1e-4, 1e-3
# A difference worth explaining.
LIMIT = 0.01

