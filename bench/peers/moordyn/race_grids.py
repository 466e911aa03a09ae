"""The MoorDyn race's grids (see race.py): per problem, the resolutions
and steps each code runs, the reference and its check, and the runs
whose steps a force tolerance chooses."""

# Resolutions: (refinement of the deck's NumSegs, step). MoorDyn's step
# is bounded by its explicit scheme's stability, which falls with the
# segment length: each resolution is run at the largest steps that
# complete (found by trying; an unstable step either stops MoorDyn or
# shows as a large error), so its cheapest accurate run is in the table.
# stancf's step has no such bound; its Newton tolerance (a fraction of
# the line's length, docs/method.md §7.1) is a setting like the step:
# 1e-8 for the runs raced, the default 1e-10 for the reference. A
# position left off by tol L moves a stiff line's end force by up to
# (EA / l) tol L: at 1e-6 on the steep wave (EA 5e8 N, 2.5 m elements,
# 120 m) that is far above the tension's 3 kN range, and the runs at
# short steps showed it (48 elements at dt 0.0125: 0.45 % of the range at
# 1e-6, 0.022 % at 1e-8, in the same time). On OC4 1e-8 and 1e-6 give
# the same errors to three digits, 1e-8 about 10 % slower.
RACE_TOLERANCE = 1e-8
# stancf's runs: (refine, dt) on the deck's uniform mesh, (refine, dt,
# sections) with the touchdown lines in sections (element counts of
# Problem.touchdown_sections). The reference is the finest, in sections
# at the default tolerance; its check is the same with half the elements
# and twice the step (their difference, in the table, bounds the
# reference's own error: both codes converge at first order near the
# touchdown, so a halving roughly halves it).
UNIFORM = [(r, dt) for r in (0.25, 0.5, 1, 2) for dt in (0.1, 0.05, 0.025)]
GRIDS = {
    "oc4": dict(
        quick=dict(stancf=[(0.5, 0.1), (1, 0.1, (1, 4, 2))], reference=(1, 0.025, (1, 8, 3)),
                   check=None, moordyn=[(0.5, 5e-3), (1, 2.5e-3)]),
        full=dict(stancf=UNIFORM + [(4, 0.025)] + [
                      (1, dt, n) for n, dts in [((1, 2, 1), (0.1,)), ((1, 3, 1), (0.1,)),
                                                ((1, 3, 2), (0.1,)),
                                                ((1, 4, 2), (0.1,)), ((1, 5, 3), (0.1,)),
                                                ((1, 8, 3), (0.1, 0.05)), ((2, 12, 4), (0.1, 0.05)),
                                                ((2, 20, 5), (0.05, 0.025)),
                                                ((2, 28, 6), (0.05, 0.025)),
                                                ((2, 40, 8), (0.05, 0.025))]
                      for dt in dts],
                  # Steps longer than the 0.1 s output, written between
                  # them from the steps' cubics (docs/method.md §6.5a).
                  between=[(r, dt) for r in (0.75, 1) for dt in (0.5, 1.0, 2.0)] + [
                      (1, dt, n) for n in ((1, 2, 1), (1, 3, 1), (1, 3, 2), (1, 4, 2),
                                           (1, 5, 3), (1, 8, 3))
                      for dt in (0.5, 1.0, 2.0)],
                  # Steps chosen by a force tolerance, dt the largest.
                  controlled=[(1, 2.0, n, tol) for n in ((1, 3, 2), (1, 5, 3))
                              for tol in (1e-2, 3e-3, 1e-3)],
                  reference=(1, 0.00625, (8, 112, 32)), check=(1, 0.0125, (4, 56, 16)),
                  moordyn=[(0.5, 1e-2), (0.5, 5e-3), (1, 5e-3), (1, 2.5e-3), (2, 2e-3),
                           (2, 1e-3), (4, 5e-4), (4, 2.5e-4), (8, 2.5e-4), (8, 1.25e-4)])),
    "steep_wave": dict(
        quick=dict(stancf=[(1, 0.05)], reference=(1, 0.025, None), check=None,
                   moordyn=[(1, 8e-4)]),
        full=dict(stancf=[(r, dt) for r in (0.25, 0.375, 0.5, 0.75, 1, 2)
                          for dt in (0.1, 0.05, 0.025, 0.0125)],
                  # Steps longer than the 0.1 s output, written between
                  # them from the steps' cubics (docs/method.md §6.5a).
                  between=[(r, dt) for r in (0.25, 0.375, 0.5) for dt in (0.2, 0.5, 1.0)],
                  controlled=[(r, 1.0, None, tol) for r in (0.5, 0.75)
                              for tol in (1e-2, 3e-3, 1e-3)],
                  reference=(4, 0.00625, None), check=(2, 0.0125, None),
                  moordyn=[(0.5, 2e-3), (0.5, 8e-4), (1, 8e-4), (1, 4e-4), (2, 2e-4),
                           (2, 1e-4), (4, 1e-4), (4, 5e-5)])),
    "riser": dict(
        quick=dict(stancf=[(1, 0.1)], reference=(2, 0.0125, None), check=None,
                   moordyn=[(1, 5e-4)]),
        full=dict(stancf=[(r, dt) for r in (0.5, 0.7, 0.8, 1, 1.5, 2) for dt in (0.1, 0.05)],
                  controlled=[(r, 1.0, None, tol) for r in (0.7, 1)
                              for tol in (1e-2, 3e-3, 1e-3)],
                  reference=(4, 0.00625, None), check=(2, 0.0125, None),
                  moordyn=[(1, 5e-4), (2, 2.5e-4), (3, 1.25e-4), (4, 1e-4), (6, 6.25e-5)])),
    "lazy_wave": dict(
        quick=dict(stancf=[(1, 0.05)], reference=(1, 0.025, None), check=None,
                   moordyn=[(1, 8e-4)]),
        full=dict(stancf=[(r, dt) for r in (0.5, 1, 2) for dt in (0.05, 0.025, 0.0125)],
                  controlled=[(r, 1.0, None, tol) for r in (0.5, 0.75)
                              for tol in (1e-2, 3e-3, 1e-3)],
                  reference=(4, 0.00625, None), check=(2, 0.0125, None),
                  moordyn=[(0.5, 2e-3), (0.5, 8e-4), (1, 8e-4), (1, 4e-4), (2, 2e-4),
                           (2, 1e-4), (4, 1e-4), (4, 5e-5)])),
}
