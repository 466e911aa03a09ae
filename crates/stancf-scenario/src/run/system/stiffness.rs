//! The free and coupled bodies' mooring stiffness at a system's static
//! equilibrium (docs/interface.md, "Systems"; docs/method.md §15.9,
//! (B16)): `stiffness.csv` and summary.json's `stiffness` of each free
//! or coupled body (a coupled body's about its reference point where the
//! scenario puts it).
//!
//! K = -d[F; M]/d[dr; dphi]: rows the lines' force F and moment M about
//! the body's reference point (global axes), columns the reference
//! point's displacement dr and a small rotation dphi about global axes
//! through it. The lines' stiffness only: the body's own weight,
//! buoyancy and hydrostatics are not in it.

use crate::output::{json_num, Dest, Num};
use crate::scenario::SystemScenario;
use serde_json::Value;
use stancf::system::SystemStatics;
use std::io::Write;

/// The header of stiffness.csv.
pub(super) const HEADER: &str = "body,row,dx,dy,dz,rx,ry,rz";

/// The names of the matrix's rows in stiffness.csv's `row` column.
const ROWS: [&str; 6] = ["fx", "fy", "fz", "mx", "my", "mz"];

/// One free body's matrix at the equilibrium: its index in the system's
/// (and the scenario's) bodies and K, None where the core gives none or
/// gives one with a value that is not finite, with why ([`missing`]).
pub(super) type BodyStiffness = (usize, Option<[[f64; 6]; 6]>, &'static str);

/// Why a free body has no matrix (summary.json's `stiffness_note`).
const MISSING: &str = "no mooring stiffness: the rest of the system is singular with the body \
                       held (or the matrix is not finite); stiffness.csv has no rows for it";

/// Why a pinned rod's body has none: the core gives a pinned body no
/// 6 x 6 matrix (its translation is its pin's).
const PINNED: &str = "no mooring stiffness: a pinned rod's body turns about its pin, which \
                      holds its translation (no 6 x 6 matrix); stiffness.csv has no rows for it";

/// Why a connector has none (docs/method.md §15.20): a joint of its
/// lines, not a body of its own.
const CONNECTOR: &str = "no mooring stiffness: a connector (a free rod of zero length) is a \
                         joint of its lines with no mass, loads or 6 x 6 matrix of its own; \
                         stiffness.csv has no rows for it";

/// Why body b has no matrix.
fn missing(sc: &SystemScenario, system: &stancf::system::System, b: usize) -> &'static str {
    let pinned = sc
        .rods
        .iter()
        .any(|r| r.own_body() == Some(b) && r.pin_point().is_some());
    if pinned {
        PINNED
    } else if system.bodies()[b].connector {
        CONNECTOR
    } else {
        MISSING
    }
}

/// Each free body's matrix at the equilibrium `st` has converged to (in
/// the order of the system's bodies); warns of a body without one (not
/// of a pinned rod's or a connector's, which have none by construction).
pub(super) fn at_equilibrium(st: &mut SystemStatics, sc: &SystemScenario) -> Vec<BodyStiffness> {
    let moving: Vec<usize> = (0..st.system().bodies().len())
        .filter(|&b| st.system().bodies()[b].kind != stancf::system::BodyKind::Fixed)
        .collect();
    moving
        .into_iter()
        .map(|b| {
            let k = st
                .body_stiffness(b)
                .filter(|k| k.iter().flatten().all(|v| v.is_finite()));
            let why = missing(sc, st.system(), b);
            if k.is_none() && why == MISSING {
                eprintln!("warning: bodies (id {}): {why}", sc.bodies[b].id);
            }
            (b, k, why)
        })
        .collect()
}

/// Writes stiffness.csv into `dest`: one row per (free body, row of its
/// matrix), none for a body without a matrix. Nothing is written without
/// free bodies or where `output.files` leaves the file out.
pub(super) fn write_csv(
    dest: Dest,
    sc: &SystemScenario,
    matrices: &[BodyStiffness],
) -> std::io::Result<()> {
    if matrices.is_empty() || !sc.output_files.writes("stiffness.csv") {
        return Ok(());
    }
    let mut file = dest.create("stiffness.csv")?;
    let w = file.writer();
    writeln!(w, "{HEADER}")?;
    for (b, k, _) in matrices {
        let Some(k) = k else { continue };
        for (name, row) in ROWS.iter().zip(k) {
            write!(w, "{},{name}", sc.bodies[*b].id)?;
            for v in row {
                write!(w, ",{}", Num(*v))?;
            }
            writeln!(w)?;
        }
    }
    file.commit()
}

/// Adds each free body's `stiffness` (6 rows of 6, the rows and columns
/// of stiffness.csv) to its entry of summary.json's `bodies` (in the
/// order of the scenario's bodies); a body without a matrix gets
/// `stiffness: null` and a `stiffness_note` saying why.
pub(super) fn add_to_summary(bodies: &mut [Value], matrices: &[BodyStiffness]) {
    for (b, k, why) in matrices {
        let Some(entry) = bodies.get_mut(*b) else {
            continue;
        };
        match k {
            Some(k) => {
                entry["stiffness"] = Value::Array(
                    k.iter()
                        .map(|row| Value::Array(row.iter().map(|v| json_num(*v)).collect()))
                        .collect(),
                );
            }
            None => {
                entry["stiffness"] = Value::Null;
                entry["stiffness_note"] = Value::String(why.to_string());
            }
        }
    }
}
