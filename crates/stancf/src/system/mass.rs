//! The end rates of a Galerkin step of a system with free points
//! (docs/method.md §11.10, (M37)).
//!
//! The Galerkin step carries momentum, not velocity: after convergence
//! p_b = dA/de_b, and the state's rates solve M v_b = p_b (M22). In a
//! system the coordinates of line ends at a free point are the point's,
//! so M is the system's mass matrix: each line's (constant) band, the
//! point's r rows summing the attached lines' end entries and the
//! point's own mass m I, with the constrained coordinates' rates given:
//!
//! ```text
//!   M_ff v_f = p_f - M_fc v_c          (f: free coordinates, c: constrained)
//!   p_f = sum over lines of (dA_line/de_b)_f + (dA_point/de_b)_f
//! ```
//!
//! M_ff is numbered like a static solve with the constrained coordinates
//! eliminated ([`SystemLayout`] with one slot), a band per line bordered
//! by 3 unknowns per free point, factorized once by block elimination
//! ([`BorderedLu`]): M is constant (docs/method.md §2.1), unless a line has
//! added mass, whose M_a(e_b) (W31) makes it refactorize at every step.

use super::layout::{LineView, SystemLayout};
use super::Topology;
use crate::assembly::Scheme;
use crate::bordered::BorderedLu;
use crate::constraints::ConstraintMethod;
use crate::error::ModelError;
use crate::integrator::Simulation;
use crate::linear::{AddEntries, Factorization, Jacobian};
use crate::model::{coordinate, Model};

/// The factors of a system's mass matrix over its free coordinates and
/// the buffer of the end momenta, allocated once.
#[derive(Clone)]
pub(super) struct SystemMass {
    layout: SystemLayout,
    lu: BorderedLu,
    /// p_f, then v_f.
    rates: Vec<f64>,
    /// Whether a line has added mass: M_ff is then M + M_a(e_b) (W31),
    /// refactorized at every step's end.
    entrained: bool,
}

impl SystemMass {
    /// Numbers and factorizes M_ff of `system` with line models `lines`.
    pub fn new(system: &Topology, lines: &[&Model]) -> Result<Self, ModelError> {
        let layout =
            SystemLayout::new(system, lines, Scheme::Static, ConstraintMethod::Elimination);
        let mut lu = BorderedLu::new(&layout.shapes, layout.border);
        fill_mass(&mut lu, &layout, system, |i| (lines[i], None));
        lu.factorize().map_err(|_| {
            ModelError::invalid(
                "lines",
                "the system's mass matrix is singular (a free point without mass on lines \
                 without mass?)",
            )
        })?;
        Ok(SystemMass {
            rates: vec![0.0; layout.size],
            entrained: lines.iter().any(|m| m.added_mass().is_some()),
            layout,
            lu,
        })
    }

    /// With added mass, refills M_ff at the lines' step-end coordinates
    /// and factorizes it (after every line's [`Simulation::expand_step`]).
    fn refactorize(&mut self, system: &Topology, lines: &[Simulation]) {
        if !self.entrained {
            return;
        }
        self.lu.matrix_mut().clear();
        fill_mass(&mut self.lu, &self.layout, system, |i| {
            (lines[i].model(), Some(lines[i].end_coordinates()))
        });
        self.lu
            .factorize()
            .expect("M + M_a is positive definite (Ca >= 0, validated)");
    }

    /// Solves M_ff v_f = p_f from the lines' expanded steps and the free
    /// points' end momenta `point_momentum[p]` (dA_point/de_b), and sets
    /// every line's end rates (each line after its
    /// [`Simulation::expand_step`]).
    pub fn set_end_rates(
        &mut self,
        system: &Topology,
        lines: &mut [Simulation],
        point_momentum: &[[f64; 3]],
    ) {
        self.refactorize(system, lines);
        self.rates.fill(0.0);
        for (i, line) in lines.iter_mut().enumerate() {
            let q = line.free_end_momentum();
            let numbering = &self.layout.lines[i];
            let map = &self.layout.maps[i];
            for (g, &qg) in q.iter().enumerate() {
                if let Some(u) = numbering.unknown_at(0, g) {
                    self.rates[map.global[u]] += qg;
                }
            }
        }
        for (p, momentum) in point_momentum.iter().enumerate() {
            for (c, &pc) in momentum.iter().enumerate() {
                if let Some(g) = self.layout.point_unknown(p, 0, c) {
                    self.rates[g] += pc;
                }
            }
        }
        self.lu.solve(&mut self.rates);
        for (i, line) in lines.iter_mut().enumerate() {
            let numbering = &self.layout.lines[i];
            let map = &self.layout.maps[i];
            let rates = &self.rates;
            // Constrained coordinates are not read: set_end_rates takes
            // their prescribed rates.
            line.set_end_rates(|g| {
                numbering
                    .unknown_at(0, g)
                    .map_or(0.0, |u| rates[map.global[u]])
            });
        }
    }

    /// v_b of free point p after [`Self::set_end_rates`].
    pub fn point_rate(&self, p: usize) -> Option<[f64; 3]> {
        self.layout.point_base[p]?;
        Some(std::array::from_fn(|c| {
            self.rates[self.layout.point_unknown(p, 0, c).expect("free point")]
        }))
    }
}

/// Adds the system's mass matrix over the free coordinates to `lu`: each
/// line's band (with its added mass M_a(e) (W31) where `line(i)` gives the
/// coordinates e) and the free points' masses.
fn fill_mass<'a>(
    lu: &mut BorderedLu,
    layout: &SystemLayout,
    system: &Topology,
    line: impl Fn(usize) -> (&'a Model, Option<&'a [f64]>),
) {
    for i in 0..layout.lines.len() {
        let (model, end) = line(i);
        let numbering = &layout.lines[i];
        let mut view = LineView::new(lu.matrix_mut().block_entries(i), &layout.maps[i]);
        let dpn = model.dofs_per_node();
        crate::with_elements!(&model.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                for (a, row) in el.mass.iter().enumerate() {
                    for (b, &m_ab) in row.iter().enumerate() {
                        for c in 0..3 {
                            let ga = coordinate(dpn, k, a, c);
                            let gb = coordinate(dpn, k, b, c);
                            if let (Some(r), Some(s)) =
                                (numbering.unknown_at(0, ga), numbering.unknown_at(0, gb))
                            {
                                view.add(r, s, m_ab);
                            }
                        }
                    }
                }
            }
        });
        if let Some(e) = end {
            model.for_entrained_mass(e, |ga, gb, m| {
                if let (Some(r), Some(s)) =
                    (numbering.unknown_at(0, ga), numbering.unknown_at(0, gb))
                {
                    view.add(r, s, m);
                }
            });
        }
    }
    for p in 0..system.points().len() {
        let inertia = system.point_inertia(p);
        for c in 0..3 {
            if let Some(g) = layout.point_unknown(p, 0, c) {
                lu.matrix_mut().add(g, g, inertia);
            }
        }
    }
}
