//! Numbering of a system's step (docs/method.md §11.3): every line keeps
//! its own [`SlabLayout`] (its unknowns and rows numbered node by node,
//! a band), and the position coordinates of line ends at free points are
//! taken out of the lines' bands into the border, the free points'
//! unknowns, shared by every line attached there. The Jacobian is then
//! a [`crate::bordered::BorderedMatrix`]: one band per line, bordered by
//! the points.

use super::{AttachedEnd, Topology};
use crate::assembly::{Scheme, SlabLayout};
use crate::bordered::{BlockEntries, BlockShape, BorderedMatrix};
use crate::constraints::ConstraintMethod;
use crate::linear::{AddEntries, Jacobian};
use crate::model::Model;

/// Marks a local index that goes to the border while numbering.
const TO_BORDER: usize = 1 << (usize::BITS - 1);

/// Where one line's local unknowns and rows go in the system.
#[derive(Clone, Debug)]
pub struct LineMap {
    /// Local index -> index in the line's block of the bordered matrix
    /// (below `size`: the band; `size + k`: the block's k-th border index).
    pub place: Vec<usize>,
    /// Local index -> global index.
    pub global: Vec<usize>,
    /// Unknowns in the line's band.
    pub size: usize,
    /// First global index of the band.
    pub start: usize,
}

impl LineMap {
    /// The line's local unknowns from the system's x.
    pub fn gather(&self, x: &[f64], local: &mut [f64]) {
        for (u, &g) in self.global.iter().enumerate() {
            local[u] = x[g];
        }
    }

    /// Sets the system's x at the line's unknowns from its local ones.
    pub fn scatter(&self, local: &[f64], x: &mut [f64]) {
        for (u, &g) in self.global.iter().enumerate() {
            x[g] = local[u];
        }
    }

    /// Adds the line's local rows to the system's (a free point's rows
    /// sum the lines attached there).
    pub fn add_rows(&self, local: &[f64], rows: &mut [f64]) {
        for (u, &g) in self.global.iter().enumerate() {
            rows[g] += local[u];
        }
    }
}

/// The numbering of a system's step or static solve.
#[derive(Clone, Debug)]
pub struct SystemLayout {
    /// Each line's own numbering.
    pub lines: Vec<SlabLayout>,
    /// The step's time slots (the points' and bodies' unknowns and rows,
    /// the lines' too), without nodes.
    pub time: SlabLayout,
    pub maps: Vec<LineMap>,
    /// The block shapes of the bordered matrix.
    pub shapes: Vec<BlockShape>,
    /// Border index of point p's first unknown (free points and points
    /// on free bodies).
    pub point_base: Vec<Option<usize>>,
    /// Border index of body b's first unknown (free bodies only): 6 per
    /// slot, the centre's 3 then the rotation's 3 (docs/method.md §15.7).
    pub body_base: Vec<Option<usize>>,
    /// Unknown slots (= row slots) per coordinate.
    pub slots: usize,
    /// Unknowns of the border (3 per slot per free point).
    pub border: usize,
    /// All unknowns.
    pub size: usize,
}

impl SystemLayout {
    /// Numbers the step of `system` whose lines are the models `lines`
    /// (the system's, as the line simulations hold them).
    pub fn new(
        system: &Topology,
        lines: &[&Model],
        scheme: Scheme,
        method: ConstraintMethod,
    ) -> Self {
        let layouts: Vec<SlabLayout> = lines
            .iter()
            .map(|m| SlabLayout::new(m, scheme, method))
            .collect();
        let time = SlabLayout::of_time(scheme, method);
        let slots = time.unknown_slots.len();
        let mut point_base = vec![None; system.points().len()];
        let mut border = 0;
        for (p, pt) in system.points().iter().enumerate() {
            if pt.is_unknown() {
                point_base[p] = Some(border);
                border += 3 * slots;
            }
        }
        let mut body_base = vec![None; system.bodies().len()];
        for b in system.free_bodies() {
            body_base[b] = Some(border);
            border += 6 * slots;
        }
        let mut maps = Vec::with_capacity(lines.len());
        let mut shapes = Vec::with_capacity(lines.len());
        let mut start = 0;
        for (li, layout) in layouts.iter().enumerate() {
            let ends = system.attached_ends(li, lines[li]);
            // A line end on a free body's point loads the body's rows
            // (§15.7): the line's block couples with the body's unknowns,
            // and up the body's joints with each joint's point and the
            // body it is on (§15.14).
            let mut reached: Vec<usize> = Vec::new();
            for e in system.attached_ends(li, lines[li]) {
                let (points, bodies) = system.joint_chain(e.point);
                let points = points.into_iter().filter_map(|p| point_base[p]);
                reached.extend(points.flat_map(|base| base..base + 3 * slots));
                let bodies = bodies.into_iter().filter_map(|b| body_base[b]);
                reached.extend(bodies.flat_map(|base| base..base + 6 * slots));
            }
            let (map, shape) = line_map(layout, ends, &point_base, reached, start);
            start += map.size;
            maps.push(map);
            shapes.push(shape);
        }
        let border_start = start;
        for map in &mut maps {
            for (u, g) in map.global.iter_mut().enumerate() {
                if map.place[u] >= map.size {
                    *g += border_start;
                }
            }
        }
        SystemLayout {
            lines: layouts,
            time,
            maps,
            shapes,
            point_base,
            body_base,
            slots,
            border,
            size: border_start + border,
        }
    }

    /// First global index of the border.
    pub fn border_start(&self) -> usize {
        self.size - self.border
    }

    /// Global index of unknown (and row) slot s, component c of free
    /// point p.
    pub fn point_unknown(&self, p: usize, slot: usize, c: usize) -> Option<usize> {
        self.point_base[p].map(|b| self.border_start() + b + 3 * slot + c)
    }

    /// Global index of unknown (and row) slot s, component k of free
    /// body b: k 0..3 its centre's, 3..6 its rotation's.
    pub fn body_unknown(&self, b: usize, slot: usize, k: usize) -> Option<usize> {
        self.body_base[b].map(|base| self.border_start() + base + 6 * slot + k)
    }
}

/// The map of one line's local indices: the position coordinates of its
/// ends at free points to the points' border indices, the rest to its
/// band in order; and the block's shape, whose border also holds the
/// border indices `reached` (bodies' and joints' unknowns the block
/// couples with). `global` holds border indices relative to the border's
/// start (the caller shifts them).
fn line_map(
    layout: &SlabLayout,
    ends: impl Iterator<Item = AttachedEnd>,
    point_base: &[Option<usize>],
    reached: Vec<usize>,
    start: usize,
) -> (LineMap, BlockShape) {
    let n = layout.size();
    let slots = layout.unknown_slots.len();
    let mut place = vec![0usize; n];
    for AttachedEnd { point, node, .. } in ends {
        let Some(base) = point_base[point] else {
            continue;
        };
        for s in 0..slots {
            for c in 0..3 {
                let u = layout
                    .unknown_of_node(s, node, c)
                    .expect("a line end at a free point is not constrained");
                debug_assert_eq!(layout.row_of_node(s, node, c), Some(u));
                place[u] = TO_BORDER | (base + 3 * s + c);
            }
        }
    }
    let mut border: Vec<usize> = place
        .iter()
        .filter(|&&p| p & TO_BORDER != 0)
        .map(|&p| p & !TO_BORDER)
        .chain(reached)
        .collect();
    border.sort_unstable();
    border.dedup();
    let own_count = place.iter().filter(|&&p| p & TO_BORDER == 0).count();
    let mut global = vec![0usize; n];
    let mut own = 0;
    for u in 0..n {
        if place[u] & TO_BORDER != 0 {
            let b = place[u] & !TO_BORDER;
            global[u] = b;
            place[u] = own_count + border.binary_search(&b).expect("border index");
        } else {
            place[u] = own;
            global[u] = start + own;
            own += 1;
        }
    }
    let (kl, ku) = layout.bandwidths();
    let shape = BlockShape {
        size: own,
        kl: kl.min(own.saturating_sub(1)),
        ku: ku.min(own.saturating_sub(1)),
        border,
    };
    let map = LineMap {
        place,
        global,
        size: own,
        start,
    };
    (map, shape)
}

/// Adds line `block`'s rows at the system's x to `residual`, and its
/// Jacobian entries to `jacobian` through a [`LineView`]: `assemble`
/// evaluates the line at its local unknowns (gathered into `local_x`)
/// into `local_rows`.
pub(super) fn add_line_rows(
    map: &LineMap,
    block: usize,
    x: &[f64],
    (local_x, local_rows): (&mut [f64], &mut [f64]),
    residual: &mut [f64],
    jacobian: Option<&mut BorderedMatrix>,
    assemble: impl FnOnce(&[f64], &mut [f64], Option<&mut LineView>),
) {
    map.gather(x, local_x);
    match jacobian {
        Some(matrix) => {
            let mut view = LineView::new(matrix.block_entries(block), map);
            assemble(local_x, local_rows, Some(&mut view));
        }
        None => assemble(local_x, local_rows, None),
    }
    map.add_rows(local_rows, residual);
}

/// Every line's rows at the system's x into `residual` and their
/// Jacobian entries into `jacobian`, both cleared first
/// ([`add_line_rows`] line by line; the points' own terms are added
/// after):
/// `assemble(line, x_line, rows_line, view)` evaluates one line in its
/// own numbering; `locals` are the lines' buffers for their unknowns and
/// rows.
pub(super) fn add_lines_rows<L>(
    lines: &mut [L],
    maps: &[LineMap],
    (x_local, rows_local): (&mut [Vec<f64>], &mut [Vec<f64>]),
    x: &[f64],
    residual: &mut [f64],
    mut jacobian: Option<&mut BorderedMatrix>,
    assemble: impl Fn(&mut L, &[f64], &mut [f64], Option<&mut LineView>),
) {
    residual.fill(0.0);
    if let Some(j) = jacobian.as_deref_mut() {
        j.clear();
    }
    for (i, line) in lines.iter_mut().enumerate() {
        add_line_rows(
            &maps[i],
            i,
            x,
            (&mut x_local[i][..], &mut rows_local[i][..]),
            residual,
            jacobian.as_deref_mut(),
            |xl, rl, view| assemble(line, xl, rl, view),
        );
    }
}

/// One line's share of the bordered Jacobian, in the line's numbering.
pub(super) struct LineView<'a> {
    entries: BlockEntries<'a>,
    place: &'a [usize],
}

impl<'a> LineView<'a> {
    pub fn new(entries: BlockEntries<'a>, map: &'a LineMap) -> Self {
        LineView {
            entries,
            place: &map.place,
        }
    }
}

impl AddEntries for LineView<'_> {
    #[inline(always)]
    fn add(&mut self, i: usize, j: usize, value: f64) {
        self.entries.add(self.place[i], self.place[j], value);
    }
}
