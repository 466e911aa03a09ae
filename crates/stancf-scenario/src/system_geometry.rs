//! The geometry of a system checked before it is solved (issue 28, item
//! 9): a point below the seabed, or points that lines cannot reach, have
//! no static equilibrium the solver can find, and used to end as "Newton
//! did not converge at load factor 0". `check` and `run` name the point
//! (how far below the bed) or the line (its span against its length)
//! instead, as the user wrote them ([`crate::scenario::names`]).

use crate::scenario::{PointType, SystemScenario};
use crate::Failure;
use stancf::error::Sig;
use std::cmp::Reverse;
use std::collections::BinaryHeap;

pub use crate::scenario::overstretch::MAX_SPAN_STRAIN;

/// How far a point may lie below the seabed (m): 1 mm and 1e-6 of the
/// depth, the rounding of coordinates written to a few digits.
fn bed_tolerance(depth: f64) -> f64 {
    1e-3 + 1e-6 * depth
}

/// What `check` and `run` refuse in the geometry of `sc` (see the module
/// documentation): a point below the bed; a fixed, coupled or free point
/// farther from a fixed or coupled one than 1 + [`MAX_SPAN_STRAIN`] times
/// the lines between them (a free point's position is where its lines'
/// seeds start). `coupled_placed` is false where a coupling code, not the
/// scenario, places the coupled points (their positions then are not
/// checked).
pub fn check_geometry(
    file: &str,
    sc: &SystemScenario,
    coupled_placed: bool,
) -> Result<(), Failure> {
    // A point on a fixed body is placed as a fixed point, one on a
    // coupled body as a coupled point; one on a free body starts where
    // the body puts it, as a free point where its lines' seeds start.
    let placed = |p: usize| {
        if sc.point_is_coupled(p) {
            coupled_placed
        } else {
            sc.point_is_fixed(p)
        }
    };
    if let Some(w) = &sc.water {
        for (p, pt) in sc.points.iter().enumerate() {
            if !placed(p) && !sc.point_moves(p) {
                continue;
            }
            let [x, y, z] = pt.position;
            let bed = w.bed_height(x, y);
            if bed - z > bed_tolerance(w.depth) {
                let depth_key = sc
                    .names
                    .option("water.depth", crate::moordyn::SupportedOption::WaterDepth);
                return Err(Failure::Input(format!(
                    "{file}: {}, {depth_key}: point {} at z = {} m is {} m below the seabed \
                     (z = {} m there): move the point up to the bed, or give the water's \
                     depth",
                    sc.names.point(p, "position", "Z"),
                    pt.id,
                    Sig(z),
                    Sig(bed - z),
                    Sig(bed)
                )));
            }
        }
    }
    let adjacent = adjacency(sc);
    // A static solve (a static run, or a dynamic one from the equilibrium)
    // places the free points by the lines' catenary network before it
    // seeds the lines (docs/method.md (M32a)), as MoorDyn's initial
    // conditions move them: there a free point's start is a guess. Only a
    // run from the straight start starts the lines where it is.
    let statics_place_free_points = sc.analysis.kind == crate::scenario::AnalysisKind::Static
        || sc.initial == crate::scenario::InitialShape::Static;
    // Past this many lines only the lines between two placed points are
    // checked: the paths through free points cost a search from each
    // placed point.
    let through_free = sc.lines.len() <= MAX_LINES_SEARCHED;
    for a in (0..sc.points.len()).filter(|&p| placed(p)) {
        let reach = if through_free {
            reach_from(sc, &adjacent, a)
        } else {
            direct_reach(sc, &adjacent, a)
        };
        for (b, &(length, last_line)) in reach.iter().enumerate() {
            // A free point's position is where its lines' seeds start:
            // it must be within their reach too, unless a static solve
            // places it first.
            let free = sc.point_moves(b) && !statics_place_free_points;
            if b == a || !(placed(b) || free) || !length.is_finite() {
                continue;
            }
            let span = distance(sc.points[a].position, sc.points[b].position);
            // One line straight between two placed points is in
            // equilibrium at any stretch: it runs as given, statics
            // included, with a note (`overstretch`; MoorDyn's own test
            // decks stretch a line by 100 %: its static solve converges
            // since the trust radius weighs a multiplier by the
            // displacement it causes, docs/method.md §6.9).
            let direct = last_line.is_some_and(|l| reach_is_direct(sc, l, a, b));
            let runs_as_given = direct && !free;
            if !runs_as_given && span > (1.0 + MAX_SPAN_STRAIN) * length {
                let line = last_line.expect("a reached point has a line to it");
                let line_key = sc.names.line(line, "length", "UnstrLen");
                let keys = if free {
                    format!("{}, {line_key}", sc.names.point(b, "position", "X, Y, Z"))
                } else {
                    line_key
                };
                let start = if free {
                    let id = sc.points[b].id;
                    match sc.points[b].kind {
                        PointType::Body { body, .. } => format!(
                            " (point {id}, on free body {}, starts there)",
                            sc.bodies[body].id
                        ),
                        _ => format!(" (free point {id} starts there)"),
                    }
                } else {
                    String::new()
                };
                let via = if reach_is_direct(sc, line, a, b) {
                    format!("line {} is {} m long", sc.lines[line].id, Sig(length))
                } else {
                    format!(
                        "the lines between them (through free points) are {} m long at most",
                        Sig(length)
                    )
                };
                return Err(Failure::Input(format!(
                    "{file}: {}: points {} and {} are {} m apart{start} and {via}: spanning \
                     them would stretch the lines by {} %, beyond the {:.0} % of any mooring \
                     material's breaking strain; lengthen the line or move its points",
                    keys,
                    sc.points[a].id,
                    sc.points[b].id,
                    Sig(span),
                    Sig((100.0 * (span / length - 1.0)).round()),
                    100.0 * MAX_SPAN_STRAIN
                )));
            }
        }
    }
    Ok(())
}

/// The most lines whose paths through free points are searched (a
/// search from each fixed or coupled point: 10 000 lines take well under
/// a second).
const MAX_LINES_SEARCHED: usize = 10_000;

/// Each point's lines and the points at their other ends.
fn adjacency(sc: &SystemScenario) -> Vec<Vec<(usize, usize)>> {
    let mut adjacent = vec![Vec::new(); sc.points.len()];
    for (i, l) in sc.lines.iter().enumerate() {
        if let [Some(a), Some(b)] = l.ends {
            adjacent[a].push((i, b));
            if b != a {
                adjacent[b].push((i, a));
            }
        }
    }
    adjacent
}

/// The shortest line from point `a` to each point it joins directly (as
/// [`reach_from`], without passing through free points).
fn direct_reach(
    sc: &SystemScenario,
    adjacent: &[Vec<(usize, usize)>],
    a: usize,
) -> Vec<(f64, Option<usize>)> {
    let mut best = vec![(f64::INFINITY, None); sc.points.len()];
    best[a].0 = 0.0;
    for &(i, other) in &adjacent[a] {
        if sc.lines[i].length < best[other].0 {
            best[other] = (sc.lines[i].length, Some(i));
        }
    }
    best
}

/// Whether `line` alone joins points `a` and `b`.
fn reach_is_direct(sc: &SystemScenario, line: usize, a: usize, b: usize) -> bool {
    let ends = sc.lines[line].ends;
    (ends == [Some(a), Some(b)]) || (ends == [Some(b), Some(a)])
}

/// The shortest total length of lines from point `a` to each point, the
/// path passing through free points only (a fixed or coupled point ends
/// it), and the last line of that path (Dijkstra's algorithm; infinite
/// where no such path goes).
fn reach_from(
    sc: &SystemScenario,
    adjacent: &[Vec<(usize, usize)>],
    a: usize,
) -> Vec<(f64, Option<usize>)> {
    let n = sc.points.len();
    let mut best = vec![(f64::INFINITY, None); n];
    best[a].0 = 0.0;
    // Lengths are positive: their bits order as the lengths do.
    let mut queue = BinaryHeap::from([Reverse((0u64, a))]);
    while let Some(Reverse((bits, p))) = queue.pop() {
        let d = f64::from_bits(bits);
        if d > best[p].0 {
            continue;
        }
        if p != a && !sc.point_moves(p) {
            continue;
        }
        for &(i, other) in &adjacent[p] {
            let through = d + sc.lines[i].length;
            if through < best[other].0 {
                best[other] = (through, Some(i));
                queue.push(Reverse((through.to_bits(), other)));
            }
        }
    }
    best
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}
