//! (c) Random MoorDyn v2 decks from the grammar of the format
//! (docs/interface.md, "MoorDyn v2 decks"; crates/stancf-scenario/src/moordyn).
//!
//! A deck is drawn whole and sane first: a mooring of one of a few shapes
//! (a single line from an anchor to a fairlead, two lines through a free
//! point, a bridle of two anchors to a free point and a fairlead, a line
//! hanging between two fairleads) in water 50 to 150 m deep, lines of 1
//! to 6 segments of one or two line types, every section in MoorDyn's
//! format with the spellings MoorDyn takes (section names and their
//! synonyms, 9- or 12-column points, 10-, 11- or 13-column line types,
//! attachment words, `P4`/`Point4`/`Con4` line ends), a random subset of
//! the options (the supported, the ignored) and of the output channels,
//! comments, tabs, an end marker or none; `Currents 1` comes with a
//! `current_profile.txt` beside the deck. Then, at a random level of
//! chaos, structural edits: a word replaced by an extreme, non-finite or
//! malformed number or a wrong word, a column dropped or added, rows
//! dropped, repeated or inserted (refused options, channels stancf does
//! not compute, garbage), sections dropped, repeated, swapped, renamed or
//! added (rods, bodies...), the units row dropped, the current profile
//! broken or missing.

use crate::exercise::Case;
use crate::grammar::wide_number;
use crate::mutation::Ix;
use proptest::prelude::*;
use proptest::sample::select;

/// The name a deck is given (what `check` and `run` are given).
pub const DECK_FILE: &str = "case.txt";

/// Words a deck's column should not hold, or only at its limits.
const DECK_WEIRD: &[&str] = &[
    "0",
    "-0",
    "-1",
    "0.5",
    "1e300",
    "-1e300",
    "1e-300",
    "-1e-300",
    "5e-324",
    "1.7976931348623157e308",
    "1e309",
    "nan",
    "NaN",
    "inf",
    "-inf",
    "infinity",
    "18446744073709551616",
    "9223372036854775807",
    "4294967297",
    "1000000",
    "1000001",
    "2001",
    "0x10",
    "1,5",
    "1.5.2",
    "+3",
    ".5",
    "5.",
    "1e",
    "e5",
    "abc",
    "1|2",
    "1|2|3",
    "SYROPE:1",
    "curve.txt",
    "#",
    "-",
    "P1",
    "P0",
    "Point99",
    "R1A",
    "Body1",
    "Fixed",
    "Vessel2",
    "é",
];

fn deck_weird() -> BoxedStrategy<String> {
    prop_oneof![
        4 => select(DECK_WEIRD).prop_map(String::from),
        1 => wide_number(),
    ]
    .boxed()
}

/// A point's attachment, from which its row's words are written.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    Fixed,
    Free,
    Coupled,
}

/// Points: each one's kind and position.
pub type Points = Vec<(Kind, [f64; 3])>;

/// The points and lines of a mooring: the same shapes serve the random
/// system scenarios (`system_grammar`).
#[derive(Clone, Debug)]
pub struct Mooring {
    pub depth: f64,
    /// Kind and position of each point (ids 1, 2, 3... in order).
    pub points: Points,
    /// Ends A and B (point indices) and unstretched length of each line.
    pub lines: Vec<(usize, usize, f64)>,
}

/// A number as a deck or a TOML file writes it: short, and the same
/// value wherever it is written (a point's position in a motion table).
pub fn num(v: f64) -> String {
    let r = (v * 1000.0).round() / 1000.0;
    if r == r.trunc() && r.abs() < 1e15 {
        format!("{r:.1}")
    } else {
        format!("{r}")
    }
}

/// One of four shapes in water `depth` deep: the anchors on the bed
/// `reach` out from the fairlead(s) `fairlead_depth` below the surface,
/// each line its ends' distance times `slack` long (below 1: taut).
pub fn mooring(shape: usize, depth: f64, reach: f64, fairlead_depth: f64, slack: f64) -> Mooring {
    let round = |p: [f64; 3]| p.map(|c| (c * 1000.0).round() / 1000.0);
    let (points, ends): (Points, Vec<(usize, usize)>) = match shape % 4 {
        0 => (
            vec![
                (Kind::Fixed, [-reach, 0.0, -depth]),
                (Kind::Coupled, [0.0, 0.0, -fairlead_depth]),
            ],
            vec![(0, 1)],
        ),
        1 => (
            vec![
                (Kind::Fixed, [-reach, 0.0, -depth]),
                (Kind::Coupled, [0.0, 0.0, -fairlead_depth]),
                (
                    Kind::Free,
                    [
                        -reach / 2.0,
                        0.0,
                        -(depth + fairlead_depth) / 2.0 - 0.1 * depth,
                    ],
                ),
            ],
            vec![(0, 2), (2, 1)],
        ),
        2 => (
            vec![
                (Kind::Fixed, [-reach, -reach / 2.0, -depth]),
                (Kind::Fixed, [-reach, reach / 2.0, -depth]),
                (Kind::Free, [-reach / 2.0, 0.0, -depth / 2.0]),
                (Kind::Coupled, [0.0, 0.0, -fairlead_depth]),
            ],
            vec![(0, 2), (1, 2), (2, 3)],
        ),
        _ => (
            vec![
                (Kind::Coupled, [0.0, 0.0, -fairlead_depth]),
                (Kind::Coupled, [reach, 0.0, -fairlead_depth]),
            ],
            vec![(0, 1)],
        ),
    };
    let points: Points = points.into_iter().map(|(k, p)| (k, round(p))).collect();
    let lines = ends
        .into_iter()
        .map(|(a, b)| {
            let (p, q) = (points[a].1, points[b].1);
            let d = ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2) + (p[2] - q[2]).powi(2)).sqrt();
            (a, b, (d * slack * 1000.0).round() / 1000.0)
        })
        .collect();
    Mooring {
        depth,
        points,
        lines,
    }
}

/// The drawn shape of a mooring (see [`mooring`]).
pub fn any_mooring() -> BoxedStrategy<Mooring> {
    (
        0..4usize,
        select(&[50.0, 80.0, 150.0][..]),
        select(&[0.5, 0.8, 1.2][..]),
        select(&[0.0, 5.0, 10.0][..]),
        select(&[0.98, 1.02, 1.1, 1.3][..]),
    )
        .prop_map(|(shape, depth, reach, fairlead, slack)| {
            mooring(shape, depth, reach * depth, fairlead, slack)
        })
        .boxed()
}

/// A line type's row: `TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx
/// CaAx` (chain, rope, wire, a buoyant section).
const LINE_TYPES: &[[&str; 10]] = &[
    [
        "chain", "0.1", "20.0", "1.0e8", "-0.8", "0", "1.2", "1.0", "0.4", "0.5",
    ],
    [
        "rope", "0.15", "45.0", "5.0E8", "5.0E5", "2.0E4", "1.2", "1.0", "0.01", "0.0",
    ],
    [
        "wire", "0.05", "12.0", "2.0e8", "-1.0", "0", "1.2", "1.0", "0.01", "0",
    ],
    [
        "buoyant", "0.45", "120.0", "5.0e8", "0", "2.0e4", "1.2", "1.0", "0.01", "0.0",
    ],
];

/// The section names and their synonyms MoorDyn takes.
const TYPES_HEADERS: &[&str] = &["LINE TYPES", "LINE DICTIONARY", "Line Types"];
const POINTS_HEADERS: &[&str] = &[
    "POINTS",
    "POINT LIST",
    "POINT PROPERTIES",
    "CONNECTION PROPERTIES",
    "NODE PROPERTIES",
];
const LINES_HEADERS: &[&str] = &["LINES", "LINE LIST", "LINE PROPERTIES"];
const OPTIONS_HEADERS: &[&str] = &["OPTIONS", "SOLVER OPTIONS"];
const OUTPUTS_HEADERS: &[&str] = &["OUTPUTS", "OUTPUT"];

/// Headers an edit may put in place of a section's: other sections,
/// unknown ones, one naming two sections.
const OTHER_HEADERS: &[&str] = &[
    "RODS",
    "BODIES",
    "ROD TYPES",
    "FAILURE",
    "CONTROL",
    "EXTERNAL LOADS",
    "SYROPE IC",
    "END",
    "need this line",
    "MYSTERY",
    "LINES AND POINTS",
    "",
];

/// A section as written: its header text, its rows of column names and
/// units (tables only), its rows of words.
#[derive(Clone, Debug)]
pub struct DeckSection {
    header: String,
    columns: Option<(String, String)>,
    rows: Vec<Vec<String>>,
}

/// A deck before it is written out (see [`DeckModel::text`]).
#[derive(Clone, Debug)]
pub struct DeckModel {
    title: Vec<String>,
    sections: Vec<DeckSection>,
    end_marker: Option<String>,
    tabs: bool,
    /// The current profile beside the deck (`Currents 1`), if any.
    profile: Option<String>,
}

impl DeckModel {
    /// The deck's text.
    pub fn text(&self) -> String {
        let sep = if self.tabs { "\t" } else { "   " };
        let mut s =
            String::from("---------------------- MoorDyn v2 input file ----------------------\n");
        for t in &self.title {
            s.push_str(t);
            s.push('\n');
        }
        for sec in &self.sections {
            s.push_str(&format!(
                "---------------------- {} ----------------------\n",
                sec.header
            ));
            if let Some((names, units)) = &sec.columns {
                s.push_str(names);
                s.push('\n');
                s.push_str(units);
                s.push('\n');
            }
            for row in &sec.rows {
                s.push_str(&row.join(sep));
                s.push('\n');
            }
        }
        if let Some(m) = &self.end_marker {
            s.push_str(&format!(
                "---------------------- {m} ----------------------\n"
            ));
        }
        s
    }

    /// The deck as a case of its own, `current_profile.txt` beside it
    /// when it has one.
    pub fn case(&self) -> Case {
        Case {
            name: DECK_FILE.into(),
            text: self.text(),
            beside: self.beside(),
        }
    }

    /// The files beside the deck.
    pub fn beside(&self) -> Vec<(String, String)> {
        self.profile
            .iter()
            .map(|p| ("current_profile.txt".to_string(), p.clone()))
            .collect()
    }
}

/// How the sane deck is written: the words of each choice the format
/// leaves open.
#[derive(Clone, Debug)]
struct Spelling {
    headers: [usize; 5],
    /// 12-column points (`... Volume FX FY FZ CdA Ca`).
    wide_points: bool,
    /// 10, 11 or 13 line type columns (the VIV columns with Cl = 0).
    type_columns: usize,
    /// Attachment words and line end notations, drawn per point and end.
    attachment_words: Vec<usize>,
    end_prefixes: Vec<usize>,
    tabs: bool,
    comments: bool,
    title: usize,
    end_marker: usize,
}

fn spelling() -> impl Strategy<Value = Spelling> {
    (
        prop::array::uniform5(0..5usize),
        prop::bool::weighted(0.2),
        select(&[10usize, 10, 10, 11, 13][..]),
        prop::collection::vec(0..5usize, 4),
        prop::collection::vec(0..5usize, 6),
        prop::bool::weighted(0.2),
        prop::bool::weighted(0.3),
        0..4usize,
        0..4usize,
    )
        .prop_map(
            |(
                headers,
                wide_points,
                type_columns,
                attachment_words,
                end_prefixes,
                tabs,
                comments,
                title,
                end_marker,
            )| {
                Spelling {
                    headers,
                    wide_points,
                    type_columns,
                    attachment_words,
                    end_prefixes,
                    tabs,
                    comments,
                    title,
                    end_marker,
                }
            },
        )
}

/// What the sane deck says besides its mooring.
#[derive(Clone, Debug)]
struct Contents {
    /// Indices into [`LINE_TYPES`] (one or two types) and each line's type.
    types: Vec<usize>,
    line_type: Vec<usize>,
    segments: Vec<usize>,
    /// A free point's Mass, Volume, CdA, Ca.
    free_point: (&'static str, &'static str, &'static str, &'static str),
    options: Vec<bool>,
    option_values: Vec<usize>,
    /// Each output channel's template and the object it names.
    outputs: Vec<(usize, usize, usize)>,
    /// `Currents 1` (with `current_profile.txt` beside the deck).
    currents: bool,
}

fn contents() -> impl Strategy<Value = Contents> {
    (
        prop::sample::subsequence(vec![0usize, 1, 2, 3], 1..=2),
        prop::collection::vec(0..2usize, 3),
        prop::collection::vec(1..=6usize, 3),
        (
            select(&["0", "100", "2000"][..]),
            select(&["0", "0.1", "0.5"][..]),
            select(&["0", "0", "1.0"][..]),
            select(&["0", "0", "1.0"][..]),
        ),
        prop::collection::vec(prop::bool::weighted(0.5), OPTIONS.len()),
        prop::collection::vec(0..3usize, OPTIONS.len()),
        prop::collection::vec((0..CHANNELS.len(), 0..4usize, 0..7usize), 0..=5),
        prop::bool::weighted(0.1),
    )
        .prop_map(
            |(
                types,
                line_type,
                segments,
                free_point,
                options,
                option_values,
                outputs,
                currents,
            )| {
                Contents {
                    types,
                    line_type,
                    segments,
                    free_point,
                    options,
                    option_values,
                    outputs,
                    currents,
                }
            },
        )
}

/// The options a sane deck may set (besides `WtrDpth`, which it sets
/// unless an edit drops it): name and three values.
const OPTIONS: &[(&str, [&str; 3])] = &[
    ("dtM", ["0.001", "0.0005", "0.01"]),
    ("g", ["9.81", "9.80665", "9.8"]),
    ("WtrDnsty", ["1025", "1025.0", "1000"]),
    ("kBot", ["3.0e6", "1.0e5", "3e6"]),
    ("cBot", ["3.0e5", "1.0e4", "0"]),
    ("FrictionCoefficient", ["0.5", "0.0", "1.0"]),
    ("FricDamp", ["200", "0", "50"]),
    ("StatDynFricScale", ["1.0", "0.8", "1.2"]),
    ("dtOut", ["0", "0.1", "0.5"]),
    ("writeLog", ["0", "1", "2"]),
    ("dtIC", ["1.0", "0.5", "2"]),
    ("TmaxIC", ["100", "10", "60"]),
    ("CdScaleIC", ["4.0", "2", "1"]),
    ("threshIC", ["0.001", "0.01", "1e-4"]),
    ("WaveKin", ["0", "0", "0"]),
    ("inertialF", ["0", "0", "0"]),
    ("disableOutTime", ["1", "0", "1"]),
    ("fileIC", ["ic.txt", "lines.ic", "x"]),
];

/// Rows an edit may insert in OPTIONS: refused options and values.
const BAD_OPTIONS: &[&str] = &[
    "1 WaveKin",
    "2 Currents",
    "RK4 tScheme",
    "0.5 CFL",
    "bed.txt SeafloorFile",
    "1 WaterKin",
    "0.3 mu_kT",
    "0.3 mu_kA",
    "1 inertialF",
    "0 dtM",
    "-9.81 g",
    "0 WtrDpth",
    "1.0 NoSuchOption",
    "1e-300 dtM",
    "1e300 WtrDpth",
    "5e-324 WtrDnsty",
    "1e300 kBot",
    "0.001",
    "0.001 DTM",
    "0.001 dt",
];

/// Output channel templates: `{l}` a line, `{p}` a point, `{k}` a node.
const CHANNELS: &[&str] = &[
    "FairTen{l}",
    "AnchTen{l}",
    "L{l}N{k}PX",
    "L{l}NAPZ",
    "L{l}NBVX",
    "Line{l}N{k}PY",
    "L{l}TA",
    "L{l}TenB",
    "P{p}PX",
    "Point{p}VZ",
    "Con{p}PZ",
    "fairten{l}",
];

/// Output channel words an edit may insert: values stancf does not
/// compute, objects that do not exist, names that are not channels.
const BAD_CHANNELS: &[&str] = &[
    "P1AX",
    "P2FZ",
    "P1T",
    "L1N1T",
    "L1N1FX",
    "L1N0AX",
    "L9N1PX",
    "L1N99PX",
    "FairTen0",
    "FairTen9",
    "AnchTen",
    "R1PX",
    "Rod1PX",
    "B1PX",
    "Body1PX",
    "Foo",
    "P1QQ",
    "L1TAX",
    "L1NATA",
    "P0PX",
    "L1N18446744073709551616PX",
    "P99999999999999999999PX",
    "END",
    "END x",
    "FairTen1,AnchTen1",
];

/// Rows an edit may insert anywhere.
const BAD_ROWS: &[&str] = &[
    "# a comment",
    "   ",
    "END",
    "-----",
    "--- LINES ---",
    "(m) (m)",
    "1 2 3 4 5 6 7 8 9 10 11 12 13 14",
    "x",
    "\u{0}",
    "\u{feff}1",
];

const ATTACHMENTS: &[(Kind, [&str; 5])] = &[
    (Kind::Fixed, ["Fixed", "Anchor", "Fix", "fixed", "FIXED"]),
    (Kind::Free, ["Free", "Point", "Connect", "Con", "free"]),
    (
        Kind::Coupled,
        ["Coupled", "Vessel", "Fairlead", "Ves", "Cpld"],
    ),
];

fn attachment_word(kind: Kind, pick: usize) -> &'static str {
    let words = ATTACHMENTS.iter().find(|(k, _)| *k == kind).unwrap().1;
    words[pick % 5]
}

fn end_word(point: usize, pick: usize) -> String {
    let prefix = ["", "", "P", "Point", "Con"][pick % 5];
    format!("{prefix}{}", point + 1)
}

/// The current profile MoorDyn-C reads beside a deck (`Currents 1`).
fn profile(depth: f64) -> String {
    format!(
        "current profile\nz ux uy uz\n(m) (m/s) (m/s) (m/s)\n{} 0.1 0.0 0.0\n{} 0.3 0.0 0.0\n0.0 0.5 0.1 0.0\n",
        num(-depth),
        num(-depth / 2.0)
    )
}

fn sane_deck_of(m: &Mooring, sp: &Spelling, c: &Contents) -> DeckModel {
    let w = |s: &str| s.to_string();
    // LINE TYPES
    let type_rows: Vec<Vec<String>> = c
        .types
        .iter()
        .map(|&t| {
            let mut row: Vec<String> = LINE_TYPES[t].iter().map(|s| w(s)).collect();
            match sp.type_columns {
                11 => row.push(w("0")),
                13 => row.extend([w("0.0"), w("0.18"), w("0.08")]),
                _ => {}
            }
            row
        })
        .collect();
    let mut type_names = w("TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx");
    let mut type_units = w("(name) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)");
    match sp.type_columns {
        11 => {
            type_names.push_str(" Cl");
            type_units.push_str(" (-)");
        }
        13 => {
            type_names.push_str(" Cl dF cF");
            type_units.push_str(" (-) (-) (-)");
        }
        _ => {}
    }
    // POINTS
    let point_rows: Vec<Vec<String>> = m
        .points
        .iter()
        .enumerate()
        .map(|(i, (kind, p))| {
            let (mass, volume, cda, ca) = match kind {
                Kind::Free => c.free_point,
                _ => ("0", "0", "0", "0"),
            };
            let mut row = vec![
                (i + 1).to_string(),
                w(attachment_word(*kind, sp.attachment_words[i % 4])),
                num(p[0]),
                num(p[1]),
                num(p[2]),
                w(mass),
                w(volume),
            ];
            if sp.wide_points {
                row.extend([w("0"), w("0"), w("0")]);
            }
            row.extend([w(cda), w(ca)]);
            row
        })
        .collect();
    let (point_names, point_units) = if sp.wide_points {
        (
            "ID Attachment X Y Z Mass Volume FX FY FZ CdA Ca",
            "(#) (-) (m) (m) (m) (kg) (m^3) (N) (N) (N) (m^2) (-)",
        )
    } else {
        (
            "ID Attachment X Y Z Mass Volume CdA Ca",
            "(#) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)",
        )
    };
    // LINES
    let line_rows: Vec<Vec<String>> = m
        .lines
        .iter()
        .enumerate()
        .map(|(i, &(a, b, length))| {
            let t = c.types[c.line_type[i % 3] % c.types.len()];
            vec![
                (i + 1).to_string(),
                w(LINE_TYPES[t][0]),
                end_word(a, sp.end_prefixes[2 * i % 6]),
                end_word(b, sp.end_prefixes[(2 * i + 1) % 6]),
                num(length),
                c.segments[i % 3].to_string(),
                w(["-", "p", "pt", "-"][i % 4]),
            ]
        })
        .collect();
    // OPTIONS
    let comment = |text: &str| -> Vec<String> {
        if sp.comments {
            text.split(' ').map(String::from).collect()
        } else {
            Vec::new()
        }
    };
    let mut option_rows = vec![{
        let mut r = vec![num(m.depth), w("WtrDpth")];
        r.extend(comment("water depth (m)"));
        r
    }];
    for (k, (name, values)) in OPTIONS.iter().enumerate() {
        if c.options[k] {
            let mut r = vec![w(values[c.option_values[k]]), w(name)];
            r.extend(comment("- an option"));
            option_rows.push(r);
        }
    }
    if c.currents {
        option_rows.push(vec![w("1"), w("Currents")]);
    }
    // OUTPUTS
    let mut output_rows: Vec<Vec<String>> = c
        .outputs
        .iter()
        .map(|&(t, object, node)| {
            let line = object % m.lines.len();
            let text = CHANNELS[t]
                .replace("{l}", &(line + 1).to_string())
                .replace("{p}", &(object % m.points.len() + 1).to_string())
                .replace("{k}", &(node % (c.segments[line % 3] + 1)).to_string());
            vec![text]
        })
        .collect();
    if !output_rows.is_empty() {
        output_rows.push(vec![w("END")]);
    }
    let table = |names: &str, units: &str| Some((names.to_string(), units.to_string()));
    let mut sections = vec![
        DeckSection {
            header: w(TYPES_HEADERS[sp.headers[0] % TYPES_HEADERS.len()]),
            columns: table(&type_names, &type_units),
            rows: type_rows,
        },
        DeckSection {
            header: w(POINTS_HEADERS[sp.headers[1] % POINTS_HEADERS.len()]),
            columns: table(point_names, point_units),
            rows: point_rows,
        },
        DeckSection {
            header: w(LINES_HEADERS[sp.headers[2] % LINES_HEADERS.len()]),
            columns: table(
                "ID LineType AttachA AttachB UnstrLen NumSegs Outputs",
                "(#) (name) (#) (#) (m) (-) (-)",
            ),
            rows: line_rows,
        },
        DeckSection {
            header: w(OPTIONS_HEADERS[sp.headers[3] % OPTIONS_HEADERS.len()]),
            columns: None,
            rows: option_rows,
        },
    ];
    if !output_rows.is_empty() || sp.headers[4] == 0 {
        sections.push(DeckSection {
            header: w(OUTPUTS_HEADERS[sp.headers[4] % OUTPUTS_HEADERS.len()]),
            columns: None,
            rows: output_rows,
        });
    }
    let title = match sp.title {
        0 => vec![],
        1 => vec![w("a random deck")],
        2 => vec![
            w("a random deck"),
            w("of several lines (m), 3 # not a comment"),
        ],
        _ => vec![w("--------------------------------------------")],
    };
    DeckModel {
        title,
        sections,
        end_marker: match sp.end_marker {
            0 => None,
            1 => Some(w("END")),
            _ => Some(w("need this line")),
        },
        tabs: sp.tabs,
        profile: c.currents.then(|| profile(m.depth)),
    }
}

/// A structural change to a deck (see the module's documentation); an
/// index is taken modulo the number of things it picks from.
#[derive(Clone, Debug)]
pub enum DeckEdit {
    ReplaceWord(Ix, String),
    DropWord(Ix),
    ExtraWord(Ix, String),
    DropRow(Ix),
    DuplicateRow(Ix),
    InsertRow(Ix, String),
    InsertOption(String),
    InsertChannel(String),
    DropSection(Ix),
    DuplicateSection(Ix),
    SwapSections(Ix, Ix),
    RenameSection(Ix, String),
    DropUnitsRow(Ix),
    AddSection(String, Option<String>),
    DropEndMarker,
    DropProfile,
    BreakProfile(String),
}

fn deck_edit() -> impl Strategy<Value = DeckEdit> {
    let header = prop_oneof![
        select(OTHER_HEADERS),
        select(TYPES_HEADERS),
        select(POINTS_HEADERS),
        select(LINES_HEADERS),
        select(OPTIONS_HEADERS),
        select(OUTPUTS_HEADERS),
    ]
    .prop_map(String::from);
    prop_oneof![
        8 => (any::<Ix>(), deck_weird()).prop_map(|(i, v)| DeckEdit::ReplaceWord(i, v)),
        2 => any::<Ix>().prop_map(DeckEdit::DropWord),
        2 => (any::<Ix>(), deck_weird()).prop_map(|(i, v)| DeckEdit::ExtraWord(i, v)),
        1 => any::<Ix>().prop_map(DeckEdit::DropRow),
        1 => any::<Ix>().prop_map(DeckEdit::DuplicateRow),
        1 => (any::<Ix>(), select(BAD_ROWS)).prop_map(|(i, r)| DeckEdit::InsertRow(i, r.into())),
        2 => select(BAD_OPTIONS).prop_map(|o| DeckEdit::InsertOption(o.into())),
        2 => select(BAD_CHANNELS).prop_map(|c| DeckEdit::InsertChannel(c.into())),
        1 => any::<Ix>().prop_map(DeckEdit::DropSection),
        1 => any::<Ix>().prop_map(DeckEdit::DuplicateSection),
        1 => (any::<Ix>(), any::<Ix>()).prop_map(|(a, b)| DeckEdit::SwapSections(a, b)),
        1 => (any::<Ix>(), header.clone()).prop_map(|(i, h)| DeckEdit::RenameSection(i, h)),
        1 => any::<Ix>().prop_map(DeckEdit::DropUnitsRow),
        1 => (header, prop::option::of(select(BAD_ROWS).prop_map(String::from)))
            .prop_map(|(h, r)| DeckEdit::AddSection(h, r)),
        1 => Just(DeckEdit::DropEndMarker),
        1 => Just(DeckEdit::DropProfile),
        1 => select(&[
            "x\ny\nz\n0 0.1 0 0\n-10 0.2 0 0\n0 0.3 0 0\n",
            "x\ny\nz\n0 0.1 0\n",
            "x\ny\nz\n",
            "x\ny\nz\n0 nan 0 0\n",
            "",
        ][..])
        .prop_map(|p| DeckEdit::BreakProfile(p.into())),
    ]
}

/// The (section, row) of every row, for edits that pick a row.
fn rows_of(d: &DeckModel) -> Vec<(usize, usize)> {
    d.sections
        .iter()
        .enumerate()
        .flat_map(|(s, sec)| (0..sec.rows.len()).map(move |r| (s, r)))
        .collect()
}

/// Applies an edit; one that has nothing to act on changes nothing.
pub fn edit(mut d: DeckModel, e: &DeckEdit) -> DeckModel {
    let rows = rows_of(&d);
    let sections = d.sections.len();
    let section_named = |d: &DeckModel, names: &[&str]| {
        d.sections
            .iter()
            .position(|s| names.iter().any(|n| s.header == *n))
    };
    match e {
        DeckEdit::ReplaceWord(i, v) => {
            let words: Vec<(usize, usize, usize)> = rows
                .iter()
                .flat_map(|&(s, r)| (0..d.sections[s].rows[r].len()).map(move |k| (s, r, k)))
                .collect();
            if !words.is_empty() {
                let (s, r, k) = words[i.0 % words.len()];
                d.sections[s].rows[r][k] = v.clone();
            }
        }
        DeckEdit::DropWord(i) if !rows.is_empty() => {
            let (s, r) = rows[i.0 % rows.len()];
            d.sections[s].rows[r].pop();
        }
        DeckEdit::ExtraWord(i, v) if !rows.is_empty() => {
            let (s, r) = rows[i.0 % rows.len()];
            d.sections[s].rows[r].push(v.clone());
        }
        DeckEdit::DropRow(i) if !rows.is_empty() => {
            let (s, r) = rows[i.0 % rows.len()];
            d.sections[s].rows.remove(r);
        }
        DeckEdit::DuplicateRow(i) if !rows.is_empty() => {
            let (s, r) = rows[i.0 % rows.len()];
            let row = d.sections[s].rows[r].clone();
            d.sections[s].rows.insert(r, row);
        }
        DeckEdit::InsertRow(i, text) if sections > 0 => {
            let s = i.0 % sections;
            let at = (i.0 / sections) % (d.sections[s].rows.len() + 1);
            d.sections[s].rows.insert(at, vec![text.clone()]);
        }
        DeckEdit::InsertOption(o) => {
            if let Some(s) = section_named(&d, OPTIONS_HEADERS) {
                d.sections[s].rows.push(vec![o.clone()]);
            }
        }
        DeckEdit::InsertChannel(c) => {
            if let Some(s) = section_named(&d, OUTPUTS_HEADERS) {
                d.sections[s].rows.insert(0, vec![c.clone()]);
            }
        }
        DeckEdit::DropSection(i) if sections > 0 => {
            d.sections.remove(i.0 % sections);
        }
        DeckEdit::DuplicateSection(i) if sections > 0 => {
            let s = d.sections[i.0 % sections].clone();
            d.sections.push(s);
        }
        DeckEdit::SwapSections(a, b) if sections > 0 => {
            d.sections.swap(a.0 % sections, b.0 % sections);
        }
        DeckEdit::RenameSection(i, h) if sections > 0 => {
            d.sections[i.0 % sections].header = h.clone();
        }
        DeckEdit::DropUnitsRow(i) if sections > 0 => {
            if let Some((names, _)) = &d.sections[i.0 % sections].columns {
                let names = names.clone();
                d.sections[i.0 % sections].rows.insert(0, vec![names]);
                d.sections[i.0 % sections].columns = None;
            }
        }
        DeckEdit::AddSection(h, row) => {
            d.sections.push(DeckSection {
                header: h.clone(),
                columns: Some(("Name Col".into(), "(-) (-)".into())),
                rows: row.iter().map(|r| vec![r.clone()]).collect(),
            });
        }
        DeckEdit::DropEndMarker => d.end_marker = None,
        DeckEdit::DropProfile => d.profile = None,
        DeckEdit::BreakProfile(p) => d.profile = Some(p.clone()),
        _ => {}
    }
    d
}

/// A sane random deck (see the module's documentation).
pub fn sane_deck() -> BoxedStrategy<DeckModel> {
    (any_mooring(), spelling(), contents())
        .prop_map(|(m, sp, c)| sane_deck_of(&m, &sp, &c))
        .boxed()
}

/// A random deck: sane in about a third of the cases, else with one to
/// four edits.
pub fn random_deck_model() -> BoxedStrategy<DeckModel> {
    (
        sane_deck(),
        prop_oneof![
            1 => Just(Vec::new()),
            2 => prop::collection::vec(deck_edit(), 1..=4),
        ],
    )
        .prop_map(|(deck, edits)| edits.iter().fold(deck, edit))
        .boxed()
}

/// A random deck as a case: the deck alone (`current_profile.txt`
/// beside it when it has one).
pub fn random_deck() -> BoxedStrategy<Case> {
    random_deck_model().prop_map(|d| d.case()).boxed()
}
