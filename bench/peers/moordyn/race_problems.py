"""The MoorDyn race's problems (see race.py): each deck, the motion of
its coupled points, its resolutions as decks for MoorDyn and stancf
(NumSegs refined, BA fixed, added mass left out where the problem says),
and the sections stancf may mesh its touchdown lines in."""
import math
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", "..", ".."))
OUTPUT_DT = 0.1


class Problem:
    """A race problem: a deck, its coupled points moved along x by
    f(t) A sin(2 pi t / T) (ramp over one period), the resolutions, and
    the lines stancf may mesh in sections (`touchdown_lines`, from end A:
    `touchdown_sections` metres each, the middle one where the line
    touches down as the motion moves it; a `[[mesh]]` of the scenario)."""

    def __init__(self, name, deck, coupled, amplitude, period, duration, ba, title,
                 touchdown_lines, touchdown_sections, without_added_mass=False):
        self.name, self.deck, self.coupled = name, deck, coupled
        self.amplitude, self.period, self.duration = amplitude, period, duration
        self.ba, self.title = ba, title
        self.touchdown_lines, self.touchdown_sections = touchdown_lines, touchdown_sections
        self.without_added_mass = without_added_mass


# OC4: BA = zeta l sqrt(EA m) at zeta = 1, l = 835.35 / 20 m (docs/method.md (M36)).
# The chains touch down between about 125 m and 345 m from their anchors
# (line 1, in line with the surge; lines 2 and 3: 195 m to 300 m).
OC4 = Problem("oc4", os.path.join(ROOT, "examples", "oc4-deepcwind-moordyn.txt"), [4, 5, 6],
              8.0, 100.0, 300.0, 1.0 * 835.35 / 20 * math.sqrt(7.536e8 * 113.35),
              "OC4 DeepCwind, 8 m surge at 100 s, 300 s", [1, 2, 3], [100.0, 280.0, 455.35])
# The steep wave: the lazy wave's cable ending on a riser base above the
# bed (no contact); its deck fixes its own BA. Raced without added mass
# (Ca = CaAx = 0 in both codes): the codes' added masses are different
# laws. stancf's is the entrained water's kinetic energy (docs/method.md
# §12.5, (W25)), whose Lagrange equations hold the terms of the turning
# tangent, -(dM_a/dt) r_dot + dT_a/dq; MoorDyn's is the force -M_a r_ddot
# alone. On this cable, whose tangents turn as it swings, they differ by
# 0.8 % of the tension's range: with the deck's Ca = 1, MoorDyn's runs at
# 96 and 192 segments stay 0.812 and 0.781 % from stancf's converged
# line (the error mostly at twice and three times the motion's
# frequency), where without added mass they converge to it (0.535 % at
# 48 segments, 0.195 % at 96). MoorDyn's stable step is set by the axial
# waves, whose inertia CaAx = 0 leaves as it was.
STEEP = Problem("steep_wave", os.path.join(ROOT, "examples", "steep-wave-moordyn.txt"), [1],
                5.0, 20.0, 120.0, None, "steep-wave cable (EI > 0, Ca = 0), 5 m at 20 s, "
                "120 s", [], [], without_added_mass=True)
# The lazy wave's deck fixes its own BA. Its line 3 touches down between
# about 60 m and 73 m from point 3. Raced only when asked
# (--problem=lazy_wave): the bed contact makes both codes' fairlead
# tension ring (a few tens of newtons, 1 % of its range) and stancf's
# own references at 192 and 384 elements differ by 1.1 %, so neither
# 1 % nor 0.1 % can be judged (README).
LAZY = Problem("lazy_wave", os.path.join(ROOT, "examples", "lazy-wave-moordyn.txt"), [1],
               5.0, 20.0, 120.0, None, "lazy-wave cable, 5 m at 20 s, 120 s", [3],
               [50.0, 35.0, 35.0])


# The riser (issue 33): a free-hanging flexible pipe, 150 m from a base on
# the bed 80 m down to a hang-off 1 m below the surface, 100 m away,
# moved 8 m at 20 s after a one-period ramp, 100 s. It touches down
# between about 38 m and 60 m from the base as the hang-off moves (the
# quasi-static catenary). Raced without added mass, as the steep wave
# (see STEEP): with the deck's Ca = 1, MoorDyn at 100 and 150 segments
# stayed 3.95 and 3.54 % from stancf's converged line (200 elements, dt
# 0.00625 s), without it 1.27 and 1.11 % (against 100 elements at
# 0.0125 s, itself within 0.05 % of the 200).
RISER = Problem("riser", os.path.join(ROOT, "examples", "riser-moordyn.txt"), [2],
                8.0, 20.0, 100.0, None, "flexible riser (EI > 0, Ca = 0), 8 m at 20 s, 100 s",
                [], [], without_added_mass=True)


def surge(t, pb):
    """x offset and rate of the coupled points at t (stancf's [[motions]])."""
    s = min(t / pb.period, 1.0)
    f = s * s * s * (s * (6.0 * s - 15.0) + 10.0)
    df = 30.0 * s * s * (s - 1.0) ** 2 / pb.period if t < pb.period else 0.0
    w = 2.0 * math.pi / pb.period
    a = pb.amplitude
    return f * a * math.sin(w * t), df * a * math.sin(w * t) + f * a * w * math.cos(w * t)


def deck_text(pb, refine, dtm):
    """The race's deck: every line's NumSegs times `refine`, BA set (when
    the problem fixes it here), Ca and CaAx zero (when the problem is
    raced without added mass), dtM set, no OUTPUTS channels, a tight
    initial-condition threshold for MoorDyn."""
    out, section = [], None
    with open(pb.deck) as f:
        for line in f:
            if line.startswith("---"):
                section = line.strip("- \n").upper()
                out.append(line)
                continue
            fields = line.split()
            data = bool(fields) and not fields[0].startswith("(") and fields[0] != "TypeName" \
                and fields[0] != "ID"
            if section == "LINE TYPES" and data and (pb.ba is not None
                                                     or pb.without_added_mass):
                if pb.ba is not None:
                    fields[4] = "%.6e" % pb.ba
                if pb.without_added_mass:
                    # Ca and CaAx (see STEEP).
                    fields[7] = fields[9] = "0.0"
                line = "  ".join(fields) + "\n"
            elif section == "LINES" and data:
                fields[5] = str(int(round(int(fields[5]) * refine)))
                line = "  ".join(fields) + "\n"
            elif section == "OPTIONS" and data and fields[1] == "dtM":
                line = "%r  dtM\n" % dtm
            elif section == "OPTIONS" and data and fields[1] in ("threshIC", "TmaxIC"):
                continue
            elif section == "OUTPUTS" and data and fields[0] != "END":
                continue
            out.append(line)
    k = next(i for i, line in enumerate(out) if line.startswith("---") and "OUTPUTS" in line)
    return "".join(out[:k] + ["0.0001  threshIC\n", "200.0  TmaxIC\n"] + out[k:])


def deck_rows(pb, section):
    """The fields of the data rows (first field a number) of a section of
    the problem's deck."""
    current = None
    with open(pb.deck) as f:
        for line in f:
            if line.startswith("---"):
                current = line.strip("- \n").upper()
                continue
            fields = line.split()
            if current == section and fields and fields[0].isdigit():
                yield fields


def segments(pb, refine, sections=None):
    """The total segments (elements) of a resolution: the deck's NumSegs
    times `refine`, the touchdown lines in `sections` (element counts) if
    given."""
    return sum(sum(sections) if sections and int(f[0]) in pb.touchdown_lines
               else int(round(int(f[5]) * refine)) for f in deck_rows(pb, "LINES"))


def mesh_name(sections, between=False, force_tolerance=None):
    """The CSV's name of a mesh: "uniform" or "sections a/b/c", with ",
    between steps" for a run written at the 0.1 s outputs from its steps'
    cubics (`[output] interval`, its step longer than 0.1 s), and ",
    force tolerance <tol>" for a run whose steps that tolerance chose
    (`analysis.force_tolerance`, its dt the largest step)."""
    name = "sections " + "/".join(str(n) for n in sections) if sections else "uniform"
    name += ", between steps" if between else ""
    return name + (", force tolerance %g" % force_tolerance if force_tolerance else "")


def mesh_entry(pb, sections):
    """The scenario's `[[mesh]]` putting the touchdown lines in sections."""
    parts = ", ".join("{ length = %r, elements = %d }" % (length, n)
                      for length, n in zip(pb.touchdown_sections, sections))
    return "[[mesh]]\nlines = %r\ngrading = { sections = [%s] }\n" % (pb.touchdown_lines, parts)


def positions0(pb):
    """The coupled points' positions in the deck."""
    rows = {int(f[0]): [float(v) for v in f[2:5]] for f in deck_rows(pb, "POINTS")}
    return np.array([rows[i] for i in pb.coupled])


PROBLEMS = (OC4, STEEP, RISER, LAZY)
