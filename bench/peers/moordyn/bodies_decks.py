"""bodies_check.py's decks: reading them, their sections and options, the
copies with options or rows changed or lines refined, what each holds,
and MoorDyn's rotations."""

from bodies_common import *  # noqa: F401,F403


# --------------------------------------------------------------------------
# Decks


def deck_text(path):
    """The text of a deck of MoorDyn's repository (path in it): from
    $MOORDYN_DECKS, a checkout at $MOORDYN_REPO, or its git objects."""
    for base in (DECKS_DIR, MOORDYN_REPO):
        p = os.path.join(base, path)
        if os.path.isfile(p):
            with open(p) as f:
                return f.read()
    p = subprocess.run(["git", "-C", MOORDYN_REPO, "show", "HEAD:" + path],
                       capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("deck %s: not in %s nor in the repository %s" % (path, DECKS_DIR, MOORDYN_REPO))
    return p.stdout


SECTION_KEYS = [("LINE TYPES", "LINE TYPES"), ("LINE DICTIONARY", "LINE TYPES"),
                ("ROD TYPES", "ROD TYPES"), ("ROD DICTIONARY", "ROD TYPES"),
                ("BODIES", "BODIES"), ("BODY LIST", "BODIES"), ("BODY PROPERTIES", "BODIES"),
                ("RODS", "RODS"), ("ROD LIST", "RODS"), ("ROD PROPERTIES", "RODS"),
                ("POINTS", "POINTS"), ("POINT LIST", "POINTS"), ("POINT PROPERTIES", "POINTS"),
                ("CONNECTION PROPERTIES", "POINTS"), ("NODE PROPERTIES", "POINTS"),
                ("LINES", "LINES"), ("LINE LIST", "LINES"), ("LINE PROPERTIES", "LINES"),
                ("OPTIONS", "OPTIONS"), ("OUTPUTS", "OUTPUTS")]


def section_of(line):
    """The section a header line opens (MoorDyn's rule: a line with
    "---" and a keyword), "" for another dashed line, None for a line
    that is no header."""
    if "---" not in line:
        return None
    up = line.upper()
    for key, name in SECTION_KEYS:
        if key in up:
            return name
    return ""


def table_rows(text, section):
    """(line index, fields) of a table's data rows: MoorDyn's rows start
    two lines (names, units) after the header, OPTIONS and OUTPUTS right
    after it; a table ends at the next dashed line."""
    lines = text.splitlines()
    out, current, skip = [], None, 0
    for i, line in enumerate(lines):
        s = section_of(line)
        if s is not None:
            current, skip = s, (0 if s in ("OPTIONS", "OUTPUTS") else 2)
            continue
        if current != section:
            continue
        if skip:
            skip -= 1
            continue
        f = line.split()
        if f:
            out.append((i, f))
    return out


def options(text):
    """The deck's OPTIONS as {name: value string}."""
    return {f[1]: f[0] for _, f in table_rows(text, "OPTIONS") if len(f) >= 2}


def with_options(text, drop, add):
    """The deck with the OPTIONS rows named in `drop` removed and the
    rows `add` ("value name") put first in the section."""
    lines = text.splitlines()
    dropped = {i for i, f in table_rows(text, "OPTIONS") if len(f) >= 2 and f[1] in drop}
    out = []
    for i, line in enumerate(lines):
        if i in dropped:
            continue
        out.append(line)
        if section_of(line) == "OPTIONS":
            out += add
    return "\n".join(out) + "\n"


def with_rows_replaced(text, section, change):
    """The deck with each data row of `section` replaced by change(fields)
    (a list of fields, or None to drop the row)."""
    lines = text.splitlines()
    rows = dict(table_rows(text, section))
    out = []
    for i, line in enumerate(lines):
        if i in rows:
            f = change(list(rows[i]))
            if f is None:
                continue
            line = "  ".join(f)
        out.append(line)
    return "\n".join(out) + "\n"


def refined(text, factor):
    """The deck with every line's NumSegs times `factor`."""
    def times(f):
        """A LINES row with its NumSegs times `factor`."""
        f[5] = str(int(f[5]) * factor)
        return f
    return with_rows_replaced(text, "LINES", times)


def word(attachment):
    """The first run of letters of an attachment word, upper case
    (MoorDyn's decomposeString)."""
    m = re.match(r"[A-Za-z]*", attachment)
    return m.group(0).upper()


def body_kind(f):
    """A BODIES row's kind as MoorDyn reads it."""
    w = word(f[1])
    if w in ("FIXED", "FIX", "ANCHOR"):
        return "fixed"
    if w in ("COUPLED", "VESSEL", "VES", "CPLD"):
        return "coupled"
    if w in ("COUPLEDPINNED", "VESSELPINNED", "VESPIN", "CPLDPIN"):
        return "coupled pinned"
    return "free"


def rod_kind(f):
    """A RODS row's kind: fixed, pinned, body, body-pinned, free,
    coupled, coupled pinned."""
    a = f[2].upper()
    m = re.match(r"(BODY)(\d+)(PIN|PINNED)?$", a)
    if m:
        return "pinned to a body" if m.group(3) else "fixed in a body"
    w = word(f[2])
    if w in ("FIXED", "FIX", "ANCHOR"):
        return "fixed"
    if w in ("PINNED", "PIN"):
        return "pinned"
    if w in ("FREE", "POINT", "CON"):
        return "free"
    if w in ("COUPLEDPINNED", "VESSELPINNED", "VESPIN", "CPLDPIN"):
        return "coupled pinned"
    return "coupled"


def point_kind(f):
    """A POINTS row's kind: fixed, body, coupled, free."""
    w = word(f[1])
    if w in ("FIXED", "FIX", "ANCHOR"):
        return "fixed"
    if w == "BODY":
        return "body"
    if w in ("FAIRLEAD", "VESSEL", "VES", "COUPLED", "CPLD"):
        return "coupled"
    return "free"


def count(kinds):
    """ "2 free, 1 fixed" from a list of kinds."""
    names = []
    for k in dict.fromkeys(kinds):
        names.append("%d %s" % (kinds.count(k), k))
    return ", ".join(names)


def contents(text):
    """What a deck has, in words: its bodies, rods (NumSegs), lines,
    free and coupled points, g."""
    bodies = [body_kind(f) for _, f in table_rows(text, "BODIES") if len(f) >= 14]
    rods = [(rod_kind(f), f[9]) for _, f in table_rows(text, "RODS") if len(f) >= 10]
    lines = [f for _, f in table_rows(text, "LINES") if len(f) >= 6]
    points = [point_kind(f) for _, f in table_rows(text, "POINTS") if len(f) >= 5]
    parts = []
    if bodies:
        parts.append("bodies: " + count(bodies))
    if rods:
        parts.append("rods: " + count(["%s (N %s)" % r for r in rods]))
    parts.append("%d line%s" % (len(lines), "" if len(lines) == 1 else "s"))
    free = points.count("free")
    cpl = points.count("coupled")
    if free:
        parts.append("%d free point%s" % (free, "" if free == 1 else "s"))
    if cpl:
        parts.append("%d coupled point%s" % (cpl, "" if cpl == 1 else "s"))
    return "; ".join(parts)


def coupled_dofs(text):
    """The coupled positions MoorDyn's Init takes, in its order (coupled
    bodies: x, y, z and the angles in radians, a CoupledPinned body x, y,
    z; coupled rods: end A and the angles, a pinned one end A; coupled
    points: x, y, z), where the deck puts them. MoorDyn's Init and Step
    read 3 numbers for a CoupledPinned body, but its NCoupledDOF (the
    length its Python wrapper asks for) counts 6: zeros pad the end."""
    x, pad = [], 0
    for _, f in table_rows(text, "BODIES"):
        if len(f) >= 14 and body_kind(f) == "coupled":
            x += [float(v) for v in f[2:5]] + [math.radians(float(v)) for v in f[5:8]]
        elif len(f) >= 14 and body_kind(f) == "coupled pinned":
            x += [float(v) for v in f[2:5]]
            pad += 3
    for _, f in table_rows(text, "RODS"):
        if len(f) >= 10 and rod_kind(f) == "coupled":
            x += [float(v) for v in f[3:6]] + [0.0, 0.0, 0.0]
        elif len(f) >= 10 and rod_kind(f) == "coupled pinned":
            x += [float(v) for v in f[3:6]]
    for _, f in table_rows(text, "POINTS"):
        if len(f) >= 5 and point_kind(f) == "coupled":
            x += [float(v) for v in f[2:5]]
    return x + [0.0] * pad


# --------------------------------------------------------------------------
# Rotations (MoorDyn's angles: R = R_x(roll) R_y(pitch) R_z(yaw))


def rotation(angles_deg):
    """The rotation matrix of MoorDyn's roll, pitch, yaw (degrees)."""
    a, b, c = (math.radians(v) for v in angles_deg)
    rx = np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])
    ry = np.array([[math.cos(b), 0, math.sin(b)], [0, 1, 0], [-math.sin(b), 0, math.cos(b)]])
    rz = np.array([[math.cos(c), -math.sin(c), 0], [math.sin(c), math.cos(c), 0], [0, 0, 1]])
    return rx @ ry @ rz


def rotation_angle(r1, r2):
    """The angle (degrees) of the rotation taking r1 to r2."""
    c = (np.trace(r1.T @ r2) - 1.0) / 2.0
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


def angle_between(u, v):
    """The angle (degrees) between two directions."""
    c = np.dot(u, v) / (np.linalg.norm(u) * np.linalg.norm(v))
    return math.degrees(math.acos(max(-1.0, min(1.0, c))))


