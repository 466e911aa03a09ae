//! The lines and points of a system at the time reached
//! (docs/interface.md, "C library"): counts and ids, and per node (as
//! MoorDyn's `MoorDyn_GetLineNodePos`, `_GetLineNodeTen`) or per line
//! in one call (`stancf_line_positions`, `stancf_line_tensions`).
//! Lines and points are numbered from 0 in the scenario's order; their
//! ids are the scenario's. Node values need `stancf_init` first.

use crate::args;
use crate::error::{guard, Error};
use crate::StancfSystem;
use std::ffi::{c_int, c_uint};

/// The number of lines.
///
/// # Safety
/// `s` is looked up, never read; `n` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_nlines(s: *mut StancfSystem, n: *mut c_uint) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            *args::place(n, "n")? = sys.coupled.line_ids.len() as c_uint;
            Ok(())
        })
    })
}

/// The id of line `line` (0-based).
///
/// # Safety
/// `s` is looked up, never read; `id` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_line_id(s: *mut StancfSystem, line: c_uint, id: *mut i64) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let known = *sys
                .coupled
                .line_ids
                .get(line as usize)
                .ok_or_else(|| no_line(sys, line))?;
            *args::place(id, "id")? = known;
            Ok(())
        })
    })
}

/// The number of nodes of line `line`.
///
/// # Safety
/// `s` is looked up, never read; `n` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_line_nnodes(
    s: *mut StancfSystem,
    line: c_uint,
    n: *mut c_uint,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let model = sys
                .coupled
                .handle
                .line_model(line as usize)
                .ok_or_else(|| no_line(sys, line))?;
            *args::place(n, "n")? = model.nodes() as c_uint;
            Ok(())
        })
    })
}

/// The position of node `node` of line `line` (m, 3 values).
///
/// # Safety
/// `s` is looked up, never read; `pos` is NULL or has room for 3.
#[no_mangle]
pub unsafe extern "C" fn stancf_line_node_pos(
    s: *mut StancfSystem,
    line: c_uint,
    node: c_uint,
    pos: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let nodes = node_values(sys, line, |h, i| h.line_nodes(i))?;
            let v = vector_at(&nodes, line, node)?;
            args::room(pos, 3, "pos")?.copy_from_slice(v);
            Ok(())
        })
    })
}

/// The velocity of node `node` of line `line` (m/s, 3 values).
///
/// # Safety
/// `s` is looked up, never read; `vel` is NULL or has room for 3.
#[no_mangle]
pub unsafe extern "C" fn stancf_line_node_vel(
    s: *mut StancfSystem,
    line: c_uint,
    node: c_uint,
    vel: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let nodes = node_values(sys, line, |h, i| h.line_velocities(i))?;
            let v = vector_at(&nodes, line, node)?;
            args::room(vel, 3, "vel")?.copy_from_slice(v);
            Ok(())
        })
    })
}

/// The axial force EA eps at node `node` of line `line` (N; a scalar,
/// where MoorDyn's `MoorDyn_GetLineNodeTen` gives a vector).
///
/// # Safety
/// `s` is looked up, never read; `ten` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_line_node_ten(
    s: *mut StancfSystem,
    line: c_uint,
    node: c_uint,
    ten: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let values = scalars(sys, line, |h, i| h.line_tensions(i))?;
            *args::place(ten, "ten")? = scalar_at(&values, line, node)?;
            Ok(())
        })
    })
}

/// The curvature at node `node` of line `line` (1/m).
///
/// # Safety
/// `s` is looked up, never read; `curv` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_line_node_curv(
    s: *mut StancfSystem,
    line: c_uint,
    node: c_uint,
    curv: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let values = scalars(sys, line, |h, i| h.line_curvatures(i))?;
            *args::place(curv, "curv")? = scalar_at(&values, line, node)?;
            Ok(())
        })
    })
}

/// Every node position of line `line` at once (3 per node, m).
///
/// # Safety
/// `s` is looked up, never read; `pos` is NULL or has room for 3 values
/// per node.
#[no_mangle]
pub unsafe extern "C" fn stancf_line_positions(
    s: *mut StancfSystem,
    line: c_uint,
    pos: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let nodes = node_values(sys, line, |h, i| h.line_nodes(i))?;
            args::room(pos, nodes.len(), "pos")?.copy_from_slice(&nodes);
            Ok(())
        })
    })
}

/// Every node's axial force of line `line` at once (N, one per node).
///
/// # Safety
/// `s` is looked up, never read; `ten` is NULL or has room for one value
/// per node.
#[no_mangle]
pub unsafe extern "C" fn stancf_line_tensions(
    s: *mut StancfSystem,
    line: c_uint,
    ten: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let values = scalars(sys, line, |h, i| h.line_tensions(i))?;
            args::room(ten, values.len(), "ten")?.copy_from_slice(&values);
            Ok(())
        })
    })
}

/// The number of points (fixed, coupled and free).
///
/// # Safety
/// `s` is looked up, never read; `n` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_npoints(s: *mut StancfSystem, n: *mut c_uint) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            *args::place(n, "n")? = sys.coupled.point_ids.len() as c_uint;
            Ok(())
        })
    })
}

/// The id of point `point` (0-based).
///
/// # Safety
/// `s` is looked up, never read; `id` is NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn stancf_point_id(
    s: *mut StancfSystem,
    point: c_uint,
    id: *mut i64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let known = *sys
                .coupled
                .point_ids
                .get(point as usize)
                .ok_or_else(|| no_point(sys, point))?;
            *args::place(id, "id")? = known;
            Ok(())
        })
    })
}

/// Point `point`'s position (m), velocity (m/s) and the net force of its
/// lines on it (N; the mean over the last step), 3 values each; any of
/// the three may be NULL.
///
/// # Safety
/// `s` is looked up, never read; `pos`, `vel`, `force` are each NULL or
/// have room for 3 values.
#[no_mangle]
pub unsafe extern "C" fn stancf_point_state(
    s: *mut StancfSystem,
    point: c_uint,
    pos: *mut f64,
    vel: *mut f64,
    force: *mut f64,
) -> c_int {
    guard(|| {
        args::with_system(s, |sys| {
            let reading = sys
                .coupled
                .handle
                .point(point as usize)
                .ok_or_else(|| no_point(sys, point))?;
            for (out, v) in [
                (pos, reading.position),
                (vel, reading.velocity),
                (force, reading.force),
            ] {
                if !out.is_null() {
                    std::slice::from_raw_parts_mut(out, 3).copy_from_slice(&v);
                }
            }
            Ok(())
        })
    })
}

type Handle = stancf::coupling::CoupledSystem;

/// Line `line`'s node vectors, flat (3 per node).
fn node_values(
    sys: &StancfSystem,
    line: c_uint,
    get: impl Fn(&Handle, usize) -> Option<Vec<[f64; 3]>>,
) -> Result<Vec<f64>, Error> {
    let v = get(&sys.coupled.handle, line as usize).ok_or_else(|| no_line(sys, line))?;
    Ok(v.into_iter().flatten().collect())
}

/// Line `line`'s node scalars.
fn scalars(
    sys: &StancfSystem,
    line: c_uint,
    get: impl Fn(&Handle, usize) -> Option<Vec<f64>>,
) -> Result<Vec<f64>, Error> {
    get(&sys.coupled.handle, line as usize).ok_or_else(|| no_line(sys, line))
}

/// Node `node`'s vector in a line's flat vectors (3 per node).
fn vector_at(values: &[f64], line: c_uint, node: c_uint) -> Result<&[f64], Error> {
    let k = node as usize;
    values
        .get(3 * k..3 * k + 3)
        .ok_or_else(|| no_node(values.len() / 3, line, node))
}

/// Node `node`'s value in a line's scalars (1 per node).
fn scalar_at(values: &[f64], line: c_uint, node: c_uint) -> Result<f64, Error> {
    values
        .get(node as usize)
        .copied()
        .ok_or_else(|| no_node(values.len(), line, node))
}

fn no_node(nodes: usize, line: c_uint, node: c_uint) -> Error {
    Error::input(format!(
        "no node {node} on line {line}: it has {nodes} nodes (0 to {})",
        nodes.saturating_sub(1)
    ))
}

/// The error for a line that does not exist (or a system not yet
/// initialized).
fn no_line(sys: &StancfSystem, line: c_uint) -> Error {
    let n = sys.coupled.line_ids.len();
    if (line as usize) < n {
        Error::input("no line values before stancf_init")
    } else {
        Error::input(format!(
            "no line {line}: the system has {n} lines (0 to {})",
            n.saturating_sub(1)
        ))
    }
}

/// The error for a point that does not exist (or a system not yet
/// initialized).
fn no_point(sys: &StancfSystem, point: c_uint) -> Error {
    let n = sys.coupled.point_ids.len();
    if (point as usize) < n {
        Error::input("no point values before stancf_init")
    } else {
        Error::input(format!(
            "no point {point}: the system has {n} points (0 to {})",
            n.saturating_sub(1)
        ))
    }
}
