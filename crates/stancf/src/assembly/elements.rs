//! The elements' share of a step's rows and Jacobian: the element actions
//! of every layer (docs/method.md §3.1-3.2), on several threads for the
//! residual of a long line (§7.8), with each element's row targets found
//! once per layout (§7.6), and the static element rows (§6.8).

use super::layout::NONE;
use super::system::{AssemblyScratch, StepProblem, Target};
use super::Kind;
use crate::element::{CableElement, SlabDerivatives, SlabLoads};
use crate::linear::AddEntries;
use crate::model::{coordinate, gather, SLOT_R};
use rayon::prelude::*;

/// Elements of a line from which its residual's slab derivatives are
/// evaluated on several threads (below, on one: the hand-offs would cost
/// more than they save; measured in docs/method.md §7.8).
pub const PARALLEL_ELEMENTS: usize = 1024;

/// How many elements of a line of `elements` are evaluated at once before
/// their rows are added: all of them on rayon's threads for a residual of
/// a long enough line, one at a time (the serial loop) otherwise. With the
/// Jacobian, the serial loop: the Hessian blocks are added serially and
/// outweigh the share that would run in parallel (measured, §7.8).
fn element_batch(elements: usize, with_jacobian: bool) -> usize {
    if with_jacobian
        || elements < PARALLEL_ELEMENTS
        || !crate::threads::usable()
        || rayon::current_num_threads() < 2
    {
        1
    } else {
        elements
    }
}

/// (time node, kind) of the four slots of a layer j's element: e_j, v_j,
/// e_j+1, v_j+1 (the order of the element's time shape functions).
#[inline]
pub(super) fn layer_slots(j: usize) -> [(usize, Kind); 4] {
    [
        (j, Kind::Position),
        (j, Kind::Velocity),
        (j + 1, Kind::Position),
        (j + 1, Kind::Velocity),
    ]
}

/// (node, coordinate of the node) of entry d of element k's coordinates
/// (the element spans nodes k and k + 1; docs/method.md §1.1).
#[inline]
fn element_entry(dpn: usize, k: usize, d: usize) -> (usize, usize) {
    if d < dpn {
        (k, d)
    } else {
        (k + 1, d - dpn)
    }
}

/// Global rows (or columns) of an element's entries, per slot: `None` for
/// a slot without rows (columns), NONE for an entry without one.
type SlotIndices<const ND: usize> = [Option<[usize; ND]>; 4];

impl StepProblem<'_> {
    /// Element actions of every layer, eq. (10) (docs/method.md §3.1-3.2,
    /// (M13)-(M14)).
    ///
    /// The elements' slab derivatives are independent of one another: for
    /// a residual of a line of [`PARALLEL_ELEMENTS`] or more (and more than
    /// one thread) they are evaluated on rayon's threads, each into its
    /// own [`SlabDerivatives`], and then added to the rows one element
    /// after the other in the element order, as the serial loop adds them:
    /// the same sums in the same order, so the result is the serial one to
    /// the bit, whatever the number of threads (docs/method.md §7.8).
    pub(super) fn slab_elements<const NS: usize, const ND: usize, J: AddEntries>(
        &self,
        elements: &[CableElement<NS, ND>],
        derivs: &mut Vec<SlabDerivatives<ND>>,
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
        scratch: &mut AssemblyScratch,
    ) {
        let layout = self.layout;
        let n = self.model.dofs();
        let dpn = layout.dpn;
        let g = &self.model.gravity;
        let mut loads = SlabLoads {
            gravity: g.map(|c| c * self.start.load_factor),
            drag: &self.model.drag,
            seabed: self.model.seabed.as_ref(),
            water: self.model.water.as_ref(),
            host_flow: None,
            time: self.start.t,
            in_plane: self.model.constraints.in_plane,
        };
        let batch = element_batch(elements.len(), jacobian.is_some());
        if derivs.len() < batch {
            derivs.resize_with(batch, SlabDerivatives::default);
        }
        let with_jacobian = jacobian.is_some();
        let mut block = [[0.0; ND]; ND];
        // Where every element's gradient entries go, per layer: fixed by
        // the layout, so found once (the first evaluation) and kept.
        let mut all_targets = std::mem::take(&mut scratch.element_targets);
        let per_element = 4 * ND;
        if all_targets.len() != layout.layers() * elements.len() * per_element {
            all_targets.clear();
            for j in 0..layout.layers() {
                let row_slots = layer_slots(j).map(|(i, k)| layout.row_slot(i, k));
                for k in 0..elements.len() {
                    let targets = self.element_targets::<ND>(k, &row_slots);
                    all_targets.extend(targets.iter().flatten());
                }
            }
        }
        for j in 0..layout.layers() {
            loads.time = self.start.t + j as f64 * self.slab.dt;
            let slots = layer_slots(j);
            let row_slots = slots.map(|(i, k)| layout.row_slot(i, k));
            let col_slots = slots.map(|(i, k)| layout.unknown_slot(i, k));
            for first in (0..elements.len()).step_by(batch) {
                let count = batch.min(elements.len() - first);
                let chunk = &mut derivs[..count];
                let (node_e, node_v) = (&scratch.node_e, &scratch.node_v);
                let evaluate = |(i, d): (usize, &mut SlabDerivatives<ND>)| {
                    let k = first + i;
                    let o = coordinate(dpn, k, SLOT_R, 0);
                    let mut y = [[0.0; ND]; 4];
                    for (ym, &(i, kind)) in y.iter_mut().zip(&slots) {
                        let src = match kind {
                            Kind::Position => node_e,
                            Kind::Velocity => node_v,
                        };
                        *ym = gather(src, i * n + o);
                    }
                    let history = self.model.element_internal(&self.start.internal, k);
                    let el = &elements[k];
                    let host = self.model.water.as_ref().and_then(|w| w.host.as_ref());
                    let loads = SlabLoads {
                        host_flow: host.map(|h| h.element(k)),
                        ..loads
                    };
                    el.slab_derivatives_from(self.slab, &y, &loads, history, with_jacobian, d);
                };
                if count > 1 {
                    chunk.par_iter_mut().enumerate().for_each(evaluate);
                } else {
                    chunk.iter_mut().enumerate().for_each(evaluate);
                }
                for (i, d) in chunk.iter().enumerate() {
                    let k = first + i;
                    scratch.drag_work += d.drag_work;
                    scratch.damping_work += d.damping_work;
                    scratch.seabed_work += d.seabed_work;
                    scratch.water_work += d.water_work;
                    if d.visco.active || d.viv.active {
                        // The element's internal state at the slab's end:
                        // the viscoelastic law's, then the VIV's.
                        let el = &elements[k];
                        let per = el.axial_rule_points() * el.internal_values_per_point();
                        let end = &mut scratch.internal_end[k * per..(k + 1) * per];
                        let pv = d.visco.end.len() * usize::from(d.visco.active);
                        end[..pv].copy_from_slice(&d.visco.end[..pv]);
                        if d.viv.active {
                            end[pv..].copy_from_slice(&d.viv.end);
                        }
                    }
                    let at = (j * elements.len() + k) * per_element;
                    let targets = &all_targets[at..at + per_element];
                    for m in 0..4 {
                        for dd in 0..ND {
                            self.add(targets[m * ND + dd], d.grad[m][dd], residual, scratch);
                        }
                    }
                    let Some(jac) = jacobian.as_deref_mut() else {
                        continue;
                    };
                    let mut rows: SlotIndices<ND> = [None; 4];
                    for m in 0..4 {
                        rows[m] = row_slots[m].map(|_| {
                            std::array::from_fn(|dd| match targets[m * ND + dd] {
                                Target::Row(r) => r,
                                _ => NONE,
                            })
                        });
                    }
                    let cols = col_slots.map(|s| s.map(|s| self.element_unknowns::<ND>(k, s)));
                    add_slab_hessian(&elements[k], self.slab, d, &rows, &cols, &mut block, jac);
                }
            }
        }
        scratch.element_targets = all_targets;
    }

    /// Where each entry of element k's gradient goes, per slot of the
    /// layer (Galerkin: slot 2, e_b, is the end momentum).
    #[inline]
    fn element_targets<const ND: usize>(
        &self,
        k: usize,
        row_slots: &[Option<usize>; 4],
    ) -> [[Target; ND]; 4] {
        let layout = self.layout;
        let n = self.model.dofs();
        let dpn = layout.dpn;
        let o = coordinate(dpn, k, SLOT_R, 0);
        let mut targets = row_slots.map(|rs| {
            let mut out = [Target::Nothing; ND];
            if let Some(s) = rs {
                for (d, t) in out.iter_mut().enumerate() {
                    let (node, dd) = element_entry(dpn, k, d);
                    *t = match layout.row_of_node(s, node, dd) {
                        Some(r) => Target::Row(r),
                        None if self.model.constraints.is_constrained(o + d) => {
                            Target::Reaction(s * n + o + d)
                        }
                        None => Target::Nothing,
                    };
                }
            }
            out
        });
        if layout.scheme.end_variation_is_momentum() {
            for (d, t) in targets[2].iter_mut().enumerate() {
                *t = Target::Momentum(o + d);
            }
        }
        targets
    }

    /// Global unknowns of element k's entries in unknown slot s (NONE
    /// where eliminated).
    #[inline]
    fn element_unknowns<const ND: usize>(&self, k: usize, s: usize) -> [usize; ND] {
        let dpn = self.layout.dpn;
        let mut out = [NONE; ND];
        for (d, v) in out.iter_mut().enumerate() {
            let (node, dd) = element_entry(dpn, k, d);
            *v = self.layout.unknown_of_node(s, node, dd).unwrap_or(NONE);
        }
        out
    }

    /// Static rows dU/de - f_g (the load factor scales the loads).
    pub(super) fn static_elements<const NS: usize, const ND: usize, J: AddEntries>(
        &self,
        elements: &[CableElement<NS, ND>],
        residual: &mut [f64],
        mut jacobian: Option<&mut J>,
        scratch: &mut AssemblyScratch,
    ) {
        let layout = self.layout;
        let dpn = layout.dpn;
        let gravity = self.model.gravity.map(|c| c * self.start.load_factor);
        let mut grad = [0.0; ND];
        let mut hess = [[0.0; ND]; ND];
        let mut initial = self.start.initial_axial_force.as_slice();
        for (k, el) in elements.iter().enumerate() {
            let o = coordinate(dpn, k, SLOT_R, 0);
            let q: [f64; ND] = gather(&scratch.node_e, o);
            let want = jacobian.is_some();
            el.strain_energy_derivatives(&q, &mut grad, if want { Some(&mut hess) } else { None });
            // The initial axial forces of a system's static path (M32b).
            if !initial.is_empty() {
                let (force, rest) = initial.split_at(el.axial_rule_points());
                el.add_axial_forces(&q, force, &mut grad, want.then_some(&mut hess));
                initial = rest;
            }
            // A cable at rest in a moving fluid: drag f(0, r_x) is a load.
            for drag in &self.model.drag {
                el.add_static_drag(
                    drag,
                    self.start.load_factor,
                    &q,
                    &mut grad,
                    want.then_some(&mut hess),
                );
            }
            // A line at rest on the bed: its contact force f(r, r_x, 0),
            // whole at every load factor (the bed is there from the start),
            // its friction against the slide from the seed (start.e, W48).
            if let Some(contact) = &self.model.seabed {
                let seed: [f64; ND] = gather(&self.start.e, o);
                let h = want.then_some(&mut hess);
                el.add_static_seabed(contact, 1.0, (&q, &seed), &mut grad, h);
            }
            // Buoyancy grows with the weight; the steady current's drag
            // with the other loads (§12.4).
            if let Some(water) = &self.model.water {
                let (factor, g) = (self.start.load_factor, &self.model.gravity);
                el.add_static_water(water, factor, g, &q, &mut grad, want.then_some(&mut hess));
            }
            let fg = el.gravity_load(&gravity);
            for d in 0..ND {
                let t = self.target(Some(0), o + d);
                self.add(t, grad[d] - fg[d], residual, scratch);
            }
            if let Some(jac) = jacobian.as_deref_mut() {
                for a in 0..ND {
                    let Some(r) = layout.row_at(0, o + a) else {
                        continue;
                    };
                    for b in 0..ND {
                        if let Some(c) = layout.unknown_at(0, o + b) {
                            jac.add(r, c, hess[a][b]);
                        }
                    }
                }
            }
        }
    }
}

/// Adds the Hessian blocks (M14) of one element's slab action at the
/// global rows and columns of its entries (docs/method.md §3.2).
fn add_slab_hessian<const NS: usize, const ND: usize, J: AddEntries>(
    el: &CableElement<NS, ND>,
    slab: &crate::element::TimeSlab,
    derivs: &SlabDerivatives<ND>,
    rows: &SlotIndices<ND>,
    cols: &SlotIndices<ND>,
    block: &mut [[f64; ND]; ND],
    jac: &mut J,
) {
    for m in 0..4 {
        let Some(rows) = &rows[m] else {
            continue;
        };
        for nn in 0..4 {
            let Some(cols) = &cols[nn] else {
                continue;
            };
            el.slab_hessian_block(slab, derivs, m, nn, block);
            for (a, brow) in block.iter().enumerate() {
                let r = rows[a];
                if r == NONE {
                    continue;
                }
                for (b, &val) in brow.iter().enumerate() {
                    let c = cols[b];
                    if c != NONE && val != 0.0 {
                        jac.add(r, c, val);
                    }
                }
            }
        }
    }
}
