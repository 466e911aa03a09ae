//! (d) Random system scenarios (TOML) from the grammar of their keys
//! (docs/interface.md, "Systems of lines", "Water").
//!
//! A scenario is drawn whole and sane first, in one of two forms:
//!
//! - its own tables: `[system]` (gravity), one or two `[[line_types]]`,
//!   `[[points]]` and `[[lines]]` of one of the moorings of
//!   `deck_grammar` (ids not 1, 2, 3 at times; SAC-3 elements, gradings
//!   toward an end or in sections, clamped ends), `[[motions]]` of the
//!   coupled points (an oscillation, or a `fairlead.csv` table beside the
//!   scenario), in air or in `[water]` (`[water.seabed]`,
//!   `[water.current]` as a profile or a velocity, `[[water.waves]]`,
//!   `[water.jonswap]`);
//! - `system.moordyn` taking a random deck of `deck_grammar` beside it
//!   (sane or edited), with `[[mesh]]` of its lines, the `[water]` keys
//!   the deck leaves out, and motions of its coupled points;
//!
//! then a static or a dynamic `[analysis]` of a few steps (either scheme,
//! from the straight lines or the equilibrium, step halvings) and an
//! `[output]` (`every`, `files`, `end_forces`). Then, at a random level of
//! chaos, edits at the level of keys: a value replaced by an extreme,
//! non-finite or wrongly typed one, a key deleted or a stray one added, an
//! entry of an array of tables dropped or repeated, the motion table
//! broken.

use crate::bound::bound_work;
use crate::deck_grammar::{any_mooring, num, random_deck_model, DeckModel, Kind, Mooring};
use crate::exercise::Case;
use crate::grammar::{weird, wide_number};
use crate::mutation::Ix;
use proptest::prelude::*;
use proptest::sample::select;
use toml::{Table, Value};

fn f(v: f64) -> Value {
    Value::Float(v)
}

fn i(v: i64) -> Value {
    Value::Integer(v)
}

fn s(v: &str) -> Value {
    Value::String(v.into())
}

fn vector(v: &[f64]) -> Value {
    Value::Array(v.iter().map(|&x| f(x)).collect())
}

fn table<const N: usize>(entries: [(&str, Value); N]) -> Value {
    Value::Table(
        entries
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect(),
    )
}

/// The TOML line types: name, diameter, mass per length, EA, EI, BA.
const LINE_TYPES: &[(&str, f64, f64, f64, f64, f64)] = &[
    ("chain", 0.1, 20.0, 1.0e8, 0.0, -0.8),
    ("rope", 0.15, 45.0, 5.0e8, 2.0e4, 5.0e5),
    ("wire", 0.05, 12.0, 2.0e8, 0.0, 0.0),
    ("buoyant", 0.45, 120.0, 5.0e8, 2.0e4, 0.0),
];

/// The choices of a sane system beyond its mooring.
#[derive(Clone, Debug)]
struct Choices {
    types: Vec<usize>,
    line_type: Vec<usize>,
    elements: Vec<i64>,
    /// Per line: 0 uniform, 1 graded toward an end, 2 in sections; SAC-3.
    mesh: Vec<(usize, bool)>,
    /// Clamp end A of the first line (at a fixed or coupled point).
    clamp: bool,
    ids: i64,
    free_point: (f64, f64, f64, f64),
    /// 0 none, 1 an oscillation, 2 a table beside the scenario.
    motion: usize,
    water: Option<Water>,
    gravity: bool,
    type_extras: (bool, bool),
}

#[derive(Clone, Debug)]
struct Water {
    density: bool,
    seabed: Option<(f64, f64, f64)>,
    /// 0 none, 1 a profile, 2 a velocity.
    current: usize,
    waves: usize,
    jonswap: bool,
    ramp: bool,
}

fn water() -> impl Strategy<Value = Water> {
    (
        any::<bool>(),
        prop::option::of((
            select(&[3.0e6, 1.0e5][..]),
            select(&[3.0e5, 0.0][..]),
            select(&[0.0, 0.5][..]),
        )),
        0..3usize,
        0..=2usize,
        prop::bool::weighted(0.2),
        any::<bool>(),
    )
        .prop_map(|(density, seabed, current, waves, jonswap, ramp)| Water {
            density,
            seabed,
            current,
            waves,
            jonswap,
            ramp,
        })
}

fn choices() -> impl Strategy<Value = Choices> {
    (
        prop::sample::subsequence(vec![0usize, 1, 2, 3], 1..=2),
        prop::collection::vec(0..2usize, 3),
        prop::collection::vec(1..=6i64, 3),
        prop::collection::vec(
            (select(&[0usize, 0, 0, 1, 2][..]), prop::bool::weighted(0.2)),
            3,
        ),
        prop::bool::weighted(0.15),
        select(&[1i64, 1, 10, -3][..]),
        (
            select(&[0.0, 100.0, 2000.0][..]),
            select(&[0.0, 0.5][..]),
            select(&[0.0, 1.0][..]),
            select(&[0.0, 1.0][..]),
        ),
        0..3usize,
        prop::option::weighted(0.6, water()),
        any::<bool>(),
        (any::<bool>(), prop::bool::weighted(0.3)),
    )
        .prop_map(
            |(
                types,
                line_type,
                elements,
                mesh,
                clamp,
                ids,
                free_point,
                motion,
                water,
                gravity,
                type_extras,
            )| {
                Choices {
                    types,
                    line_type,
                    elements,
                    mesh,
                    clamp,
                    ids,
                    free_point,
                    motion,
                    water,
                    gravity,
                    type_extras,
                }
            },
        )
}

/// A short analysis: static, or dynamic over one to eight steps.
#[derive(Clone, Debug)]
struct AnalysisChoice {
    dynamic: bool,
    galerkin: bool,
    time_step: f64,
    steps: u32,
    initial: usize,
    halvings: Option<i64>,
    solver: Option<&'static str>,
    load_steps: Option<i64>,
    every: Option<i64>,
    files: Option<Vec<&'static str>>,
    end_forces: Option<&'static str>,
}

const FILES: &[&str] = &[
    "nodes.csv",
    "stress.csv",
    "node_loads.csv",
    "points.csv",
    "tensions.csv",
    "history.csv",
    "channels.csv",
];

fn analysis_choice() -> impl Strategy<Value = AnalysisChoice> {
    (
        prop::bool::weighted(0.7),
        any::<bool>(),
        select(&[1e-4, 1e-3, 1e-2, 0.05][..]),
        1u32..=8,
        0..3usize,
        prop::option::weighted(0.2, 0..=3i64),
        prop::option::weighted(0.2, select(&["newton", "broyden", "modified-newton"][..])),
        prop::option::weighted(0.2, 1..=5i64),
        prop::option::weighted(0.3, select(&[1i64, 2, 4][..])),
        prop::option::weighted(0.2, prop::sample::subsequence(FILES.to_vec(), 1..=3)),
        prop::option::weighted(0.3, select(&["step_mean", "at_time"][..])),
    )
        .prop_map(
            |(
                dynamic,
                galerkin,
                time_step,
                steps,
                initial,
                halvings,
                solver,
                load_steps,
                every,
                files,
                end_forces,
            )| {
                AnalysisChoice {
                    dynamic,
                    galerkin,
                    time_step,
                    steps,
                    initial,
                    halvings,
                    solver,
                    load_steps,
                    every,
                    files,
                    end_forces,
                }
            },
        )
}

/// `[analysis]` and `[output]`; `channels.csv` among the files only with
/// a deck (`deck`), which fills it.
fn analysis_tables(a: &AnalysisChoice, deck: bool, doc: &mut Table) {
    let mut t = Table::new();
    t.insert(
        "type".into(),
        s(if a.dynamic { "dynamic" } else { "static" }),
    );
    if a.dynamic {
        t.insert("time_step".into(), f(a.time_step));
        t.insert("duration".into(), f(a.time_step * a.steps as f64));
        if a.galerkin {
            t.insert("time_scheme".into(), s("galerkin"));
        }
        match a.initial {
            1 => {
                t.insert("initial".into(), s("static"));
            }
            2 => {
                t.insert("initial".into(), s("reference"));
            }
            _ => {}
        }
        if let Some(h) = a.halvings {
            t.insert("step_halvings".into(), i(h));
        }
    } else if let Some(n) = a.load_steps {
        t.insert("load_steps".into(), i(n));
    }
    if let Some(solver) = a.solver {
        t.insert("solver".into(), s(solver));
    }
    doc.insert("analysis".into(), Value::Table(t));
    let mut o = Table::new();
    if let Some(e) = a.every {
        o.insert("every".into(), i(e));
    }
    if let Some(files) = &a.files {
        let files: Vec<Value> = files
            .iter()
            .filter(|n| deck || **n != "channels.csv")
            .map(|n| s(n))
            .collect();
        if !files.is_empty() {
            o.insert("files".into(), Value::Array(files));
        }
    }
    if let Some(e) = a.end_forces {
        o.insert("end_forces".into(), s(e));
    }
    if !o.is_empty() {
        doc.insert("output".into(), Value::Table(o));
    }
}

/// The motion table of a coupled point at `p`: at rest, then moving.
fn motion_table(p: [f64; 3]) -> String {
    format!(
        "t,x,y,z\n-1.0,{x},{y},{z}\n0.0,{x},{y},{z}\n10.0,{},{y},{z}\n",
        num(p[0] + 1.0),
        x = num(p[0]),
        y = num(p[1]),
        z = num(p[2])
    )
}

fn water_table(w: &Water, depth: f64, deck: bool) -> Value {
    let mut t = Table::new();
    if !deck {
        t.insert("depth".into(), f(depth));
        if w.density {
            t.insert("density".into(), f(1025.0));
        }
    }
    if w.ramp {
        t.insert("wave_ramp".into(), f(1.0));
    }
    let mut seabed = Table::new();
    if let (Some((k, c, mu)), false) = (w.seabed, deck) {
        seabed.insert("stiffness".into(), f(k));
        seabed.insert("damping".into(), f(c));
        seabed.insert("friction_axial".into(), f(mu));
        seabed.insert("friction_transverse".into(), f(mu));
    }
    if w.ramp {
        seabed.insert("slip_velocity".into(), f(0.01));
        seabed.insert("slope".into(), vector(&[0.0, 0.01]));
    }
    if !seabed.is_empty() {
        t.insert("seabed".into(), Value::Table(seabed));
    }
    match w.current {
        1 => {
            t.insert(
                "current".into(),
                table([(
                    "profile",
                    Value::Array(vec![
                        vector(&[-depth, 0.1, 0.0, 0.0]),
                        vector(&[0.0, 0.5, 0.0, 0.0]),
                    ]),
                )]),
            );
        }
        2 => {
            t.insert(
                "current".into(),
                table([("velocity", vector(&[0.3, 0.1, 0.0])), ("ramp", f(0.5))]),
            );
        }
        _ => {}
    }
    if w.waves > 0 {
        let waves = (0..w.waves)
            .map(|k| {
                table([
                    ("amplitude", f(1.0)),
                    ("period", f(8.0 + 2.0 * k as f64)),
                    ("heading", f(30.0 * k as f64)),
                ])
            })
            .collect();
        t.insert("waves".into(), Value::Array(waves));
    }
    if w.jonswap {
        t.insert(
            "jonswap".into(),
            table([("hs", f(2.0)), ("tp", f(8.0)), ("components", i(8))]),
        );
    }
    Value::Table(t)
}

/// A system of its own tables (see the module's documentation) and the
/// files beside it.
fn own_system(m: &Mooring, c: &Choices, an: &AnalysisChoice) -> (Table, Vec<(String, String)>) {
    let mut doc = Table::new();
    let mut beside = Vec::new();
    doc.insert("title".into(), s("a random system"));
    if c.gravity {
        doc.insert(
            "system".into(),
            table([("gravity", vector(&[0.0, 0.0, -9.81]))]),
        );
    }
    let types: Vec<Value> = c
        .types
        .iter()
        .map(|&k| {
            let (name, d, w, ea, ei, ba) = LINE_TYPES[k];
            let mut t: Table = [
                ("name", s(name)),
                ("diameter", f(d)),
                ("mass_per_length", f(w)),
                ("ea", f(ea)),
            ]
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect();
            if c.type_extras.0 {
                t.insert("ei".into(), f(ei));
                t.insert("ba".into(), f(ba));
            }
            if c.water.is_some() {
                for (k, v) in [("cd", 1.2), ("ca", 1.0), ("cdax", 0.01), ("caax", 0.0)] {
                    t.insert(k.into(), f(v));
                }
            }
            if c.type_extras.1 {
                t.insert("compression".into(), Value::Boolean(false));
            }
            Value::Table(t)
        })
        .collect();
    doc.insert("line_types".into(), Value::Array(types));
    let id = |k: usize| c.ids * (k as i64 + 1);
    let points: Vec<Value> = m
        .points
        .iter()
        .enumerate()
        .map(|(k, (kind, p))| {
            let mut t: Table = [
                ("id", i(id(k))),
                (
                    "type",
                    s(match kind {
                        Kind::Fixed => "fixed",
                        Kind::Free => "free",
                        Kind::Coupled => "coupled",
                    }),
                ),
                ("position", vector(p)),
            ]
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect();
            if *kind == Kind::Free {
                let (mass, volume, cda, ca) = c.free_point;
                t.insert("mass".into(), f(mass));
                if c.water.is_some() {
                    t.insert("volume".into(), f(volume));
                    t.insert("cda".into(), f(cda));
                    t.insert("ca".into(), f(ca));
                }
            }
            Value::Table(t)
        })
        .collect();
    doc.insert("points".into(), Value::Array(points));
    let clampable = |p: usize| m.points[p].0 != Kind::Free;
    let lines: Vec<Value> = m
        .lines
        .iter()
        .enumerate()
        .map(|(k, &(a, b, length))| {
            let type_index = c.types[c.line_type[k % 3] % c.types.len()];
            let n = c.elements[k % 3];
            let mut t: Table = [
                ("id", i(id(k))),
                ("type", s(LINE_TYPES[type_index].0)),
                ("length", f(length)),
                ("a", i(id(a))),
                ("b", i(id(b))),
            ]
            .into_iter()
            .map(|(k, v)| (k.to_string(), v))
            .collect();
            let (mesh, sac3) = c.mesh[k % 3];
            let ratio_allowed = !(c.type_extras.0 && LINE_TYPES[type_index].5 < 0.0);
            match mesh {
                1 if ratio_allowed => {
                    t.insert("elements".into(), i(n + 1));
                    t.insert(
                        "grading".into(),
                        table([("toward", s("B")), ("ratio", f(2.0))]),
                    );
                }
                2 if ratio_allowed => {
                    let sections = Value::Array(vec![
                        table([("length", f(length / 2.0)), ("elements", i(1))]),
                        table([("length", f(length - length / 2.0)), ("elements", i(n))]),
                    ]);
                    t.insert("grading".into(), table([("sections", sections)]));
                }
                _ => {
                    t.insert("elements".into(), i(n));
                }
            }
            if sac3 {
                t.insert("element".into(), s("SAC-3"));
            }
            let p2 = !an.dynamic || !an.galerkin;
            if k == 0 && c.clamp && p2 && clampable(a) {
                t.insert("clamp_a".into(), vector(&[0.0, 0.0, 1.0]));
            }
            Value::Table(t)
        })
        .collect();
    doc.insert("lines".into(), Value::Array(lines));
    if let Some(k) = m.points.iter().position(|(kind, _)| *kind == Kind::Coupled) {
        match c.motion {
            1 => {
                doc.insert(
                    "motions".into(),
                    Value::Array(vec![table([
                        ("point", i(id(k))),
                        ("amplitude", vector(&[0.5, 0.0, 0.2])),
                        ("period", f(5.0)),
                        ("ramp", f(1.0)),
                    ])]),
                );
            }
            2 => {
                doc.insert(
                    "motions".into(),
                    Value::Array(vec![table([
                        ("point", i(id(k))),
                        ("file", s("fairlead.csv")),
                    ])]),
                );
                beside.push(("fairlead.csv".to_string(), motion_table(m.points[k].1)));
            }
            _ => {}
        }
    }
    if let Some(w) = &c.water {
        doc.insert("water".into(), water_table(w, m.depth, false));
    }
    analysis_tables(an, false, &mut doc);
    (doc, beside)
}

/// A scenario taking `deck` (`system.moordyn`) and the files beside it.
fn deck_system(
    deck: &DeckModel,
    mesh: Option<(i64, i64)>,
    w: &Option<Water>,
    motion: bool,
    a: &AnalysisChoice,
) -> (Table, Vec<(String, String)>) {
    let mut doc = Table::new();
    doc.insert("system".into(), table([("moordyn", s("deck.txt"))]));
    if let Some((line, elements)) = mesh {
        doc.insert(
            "mesh".into(),
            Value::Array(vec![table([
                ("lines", Value::Array(vec![i(line)])),
                ("elements", i(elements)),
            ])]),
        );
    }
    if motion {
        // Point 2 is coupled in the shapes with a fixed anchor (point 1
        // in the others).
        doc.insert(
            "motions".into(),
            Value::Array(vec![table([
                ("point", i(2)),
                ("amplitude", vector(&[0.5, 0.0, 0.0])),
                ("period", f(5.0)),
            ])]),
        );
    }
    if let Some(w) = w {
        doc.insert("water".into(), water_table(w, 100.0, true));
    }
    analysis_tables(a, true, &mut doc);
    let mut beside = vec![("deck.txt".to_string(), deck.text())];
    beside.extend(deck.beside());
    (doc, beside)
}

/// Where a value sits in a TOML document: keys and array indices.
#[derive(Clone, Debug)]
enum Step {
    Key(String),
    Index(usize),
}

/// Every key of a document, at every depth (the keys of tables in
/// arrays of tables included), and every table (`None` last step: the
/// table itself, where a stray key may go).
fn paths(v: &Value, at: &mut Vec<Step>, keys: &mut Vec<Vec<Step>>, tables: &mut Vec<Vec<Step>>) {
    match v {
        Value::Table(t) => {
            tables.push(at.clone());
            for (k, v) in t {
                at.push(Step::Key(k.clone()));
                keys.push(at.clone());
                paths(v, at, keys, tables);
                at.pop();
            }
        }
        Value::Array(a) => {
            for (n, v) in a.iter().enumerate() {
                if v.is_table() {
                    at.push(Step::Index(n));
                    paths(v, at, keys, tables);
                    at.pop();
                }
            }
        }
        _ => {}
    }
}

fn get<'a>(v: &'a Value, path: &[Step]) -> Option<&'a Value> {
    path.iter().try_fold(v, |v, step| match step {
        Step::Key(k) => v.as_table()?.get(k),
        Step::Index(n) => v.as_array()?.get(*n),
    })
}

fn get_mut<'a>(v: &'a mut Value, path: &[Step]) -> Option<&'a mut Value> {
    path.iter().try_fold(v, |v, step| match step {
        Step::Key(k) => v.as_table_mut()?.get_mut(k),
        Step::Index(n) => v.as_array_mut()?.get_mut(*n),
    })
}

/// A change to a scenario's keys; an index is taken modulo the number of
/// things it picks from.
#[derive(Clone, Debug)]
pub enum TomlEdit {
    Replace(Ix, String),
    Delete(Ix),
    Stray(Ix, String, String),
    DropEntry(Ix),
    DuplicateEntry(Ix),
    BreakBeside(String),
}

fn toml_edit() -> impl Strategy<Value = TomlEdit> {
    let value = prop_oneof![3 => weird(), 1 => wide_number()];
    prop_oneof![
        6 => (any::<Ix>(), value.clone()).prop_map(|(i, v)| TomlEdit::Replace(i, v)),
        2 => any::<Ix>().prop_map(TomlEdit::Delete),
        1 => (
            any::<Ix>(),
            select(&["bogus", "type", "depth", "elements", "moordyn", "file", "id", "lines", "initial"][..]),
            value,
        )
            .prop_map(|(i, k, v)| TomlEdit::Stray(i, k.to_string(), v)),
        1 => any::<Ix>().prop_map(TomlEdit::DropEntry),
        1 => any::<Ix>().prop_map(TomlEdit::DuplicateEntry),
        1 => select(&[
            "t,x,y,z\n0.0,0,0,0\n",
            "t,x,y\n0,0,0\n1,0,0\n",
            "t,x,y,z\n0,nan,0,0\n1,0,0,0\n",
            "t,x,y,z\n1,0,0,0\n0,0,0,0\n",
            "",
            "--- LINES ---\n",
        ][..])
        .prop_map(|t| TomlEdit::BreakBeside(t.to_string())),
    ]
}

/// A TOML value from its text (`v = <text>`); text that is no TOML value
/// stays a string of itself.
fn toml_value(text: &str) -> Value {
    toml::from_str::<Table>(&format!("v = {text}"))
        .ok()
        .and_then(|mut t| t.remove("v"))
        .unwrap_or_else(|| s(text))
}

fn apply_toml(doc: &mut Table, beside: &mut [(String, String)], e: &TomlEdit) {
    let mut root = Value::Table(std::mem::take(doc));
    let (mut keys, mut tables) = (Vec::new(), Vec::new());
    paths(&root, &mut Vec::new(), &mut keys, &mut tables);
    let entries: Vec<Vec<Step>> = keys
        .iter()
        .filter(|p| {
            get(&root, p).is_some_and(|v| {
                v.as_array()
                    .is_some_and(|a| !a.is_empty() && a.iter().all(Value::is_table))
            })
        })
        .cloned()
        .collect();
    match e {
        TomlEdit::Replace(ix, v) if !keys.is_empty() => {
            if let Some(slot) = get_mut(&mut root, &keys[ix.0 % keys.len()]) {
                *slot = toml_value(v);
            }
        }
        TomlEdit::Delete(ix) if !keys.is_empty() => {
            let path = keys[ix.0 % keys.len()].clone();
            if let (Some(Step::Key(k)), Some(parent)) =
                (path.last(), get_mut(&mut root, &path[..path.len() - 1]))
            {
                if let Some(t) = parent.as_table_mut() {
                    t.remove(k);
                }
            }
        }
        TomlEdit::Stray(ix, k, v) if !tables.is_empty() => {
            if let Some(t) = get_mut(&mut root, &tables[ix.0 % tables.len()]) {
                if let Some(t) = t.as_table_mut() {
                    t.insert(k.clone(), toml_value(v));
                }
            }
        }
        TomlEdit::DropEntry(ix) | TomlEdit::DuplicateEntry(ix) if !entries.is_empty() => {
            let path = entries[ix.0 % entries.len()].clone();
            if let Some(Value::Array(a)) = get_mut(&mut root, &path) {
                if !a.is_empty() {
                    let n = (ix.0 / 7) % a.len();
                    if matches!(e, TomlEdit::DropEntry(_)) {
                        a.remove(n);
                    } else {
                        let entry = a[n].clone();
                        a.push(entry);
                    }
                }
            }
        }
        TomlEdit::BreakBeside(text) => {
            if let Some((_, t)) = beside.iter_mut().find(|(n, _)| n.ends_with(".csv")) {
                *t = text.clone();
            }
        }
        _ => {}
    }
    if let Value::Table(t) = root {
        *doc = t;
    }
}

/// The scenario's text and the case: bounded as the other generators'
/// are (`bound_work`).
fn case_of(doc: &Table, beside: Vec<(String, String)>) -> Case {
    let text = toml::to_string(doc).expect("a TOML table serializes");
    Case {
        name: "case.toml".into(),
        text: bound_work(text),
        beside,
    }
}

/// A random system scenario (see the module's documentation): sane in
/// about a third of the cases, else with one to four edits of its keys.
pub fn random_system() -> BoxedStrategy<Case> {
    let own =
        (any_mooring(), choices(), analysis_choice()).prop_map(|(m, c, a)| own_system(&m, &c, &a));
    let with_deck = (
        random_deck_model(),
        prop::option::weighted(0.3, (1..=2i64, 1..=8i64)),
        prop::option::weighted(0.4, water()),
        any::<bool>(),
        analysis_choice(),
    )
        .prop_map(|(deck, mesh, w, motion, a)| deck_system(&deck, mesh, &w, motion, &a));
    let edits = prop_oneof![
        1 => Just(Vec::new()),
        2 => prop::collection::vec(toml_edit(), 1..=4),
    ];
    (prop_oneof![2 => own, 1 => with_deck], edits)
        .prop_map(|((mut doc, mut beside), edits)| {
            for e in &edits {
                apply_toml(&mut doc, &mut beside, e);
            }
            case_of(&doc, beside)
        })
        .boxed()
}

/// The sane systems alone (no edits, a sane deck), for the test that the
/// grammar writes what stancf reads.
pub fn sane_system() -> BoxedStrategy<Case> {
    (any_mooring(), choices(), analysis_choice())
        .prop_map(|(m, c, a)| {
            let (doc, beside) = own_system(&m, &c, &a);
            case_of(&doc, beside)
        })
        .boxed()
}
