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
//!
//! A free body adds its rates nu = [v_G; Omega] (6 unknowns) and its
//! kinetic energy's Hessian H; a point P on it moves with it, v_P = G_P nu,
//! G_P = [I, -R_b [xi' x]] (B11), so P's rows (the lines' mass rows there)
//! are carried to the body's by G_P^T and replaced by v_P - G_P nu = 0
//! (docs/method.md §15.7, (B14)); G_P turns with the body, so M_ff is
//! refactorized at every step.
//!
//! A line end clamped in a direction (docs/method.md §6.10) has its r_x
//! rows turned to (M43): d . (M v - p) = 0 and the hold's rates
//! n_k . v = 0; at a free body (§15.19, (B40)) the rates are
//! n_k . v + c_k . Omega = 0 and the hold's impulse reaches the body's
//! rows ([`ClampMass`]).

use super::body_clamps::ClampStepEnd;
use super::body_terms::StepBody;
use super::clamp_mass::{ClampMass, HeldEntry};
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
    /// Whether the system has a free body: M_ff is then refactorized at
    /// every step's end (its points' G_P turn with it).
    turning: bool,
    /// Each line's direction holds' r_x momenta before (M43) turns them.
    held: Vec<Vec<[f64; 3]>>,
}

impl SystemMass {
    /// Numbers and factorizes M_ff of `system` with line models `lines`.
    pub fn new(
        system: &Topology,
        lines: &[&Model],
        bodies: &[StepBody],
    ) -> Result<Self, ModelError> {
        let layout =
            SystemLayout::new(system, lines, Scheme::Static, ConstraintMethod::Elimination);
        let mut lu = BorderedLu::new(&layout.shapes, layout.border);
        fill_mass(&mut lu, &layout, system, |i| (lines[i], None));
        for body in bodies {
            add_body_mass(lu.matrix_mut(), &layout, body);
            // A connector's Omega rows are its clamps' (B40), which need
            // a step's end; held here for the check (refactorized then).
            if system.bodies()[body.index].connector {
                for j in 3..6 {
                    let g = layout.body_unknown(body.index, 0, j).expect("free body");
                    lu.matrix_mut().add(g, g, 1.0);
                }
            }
        }
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
            turning: system.has_free_bodies(),
            held: lines
                .iter()
                .map(|m| Vec::with_capacity(m.constraints.directions.len()))
                .collect(),
            layout,
            lu,
        })
    }

    /// With added mass, refills M_ff at the lines' step-end coordinates
    /// and factorizes it (after every line's [`Simulation::expand_step`]).
    fn refactorize(
        &mut self,
        system: &Topology,
        lines: &[Simulation],
        bodies: &[StepBody],
    ) -> Result<(), crate::band::SingularMatrix> {
        if !self.entrained && !self.turning {
            return Ok(());
        }
        self.lu.matrix_mut().clear();
        let held = fill_mass(&mut self.lu, &self.layout, system, |i| {
            (
                lines[i].model(),
                self.entrained.then(|| lines[i].end_coordinates()),
            )
        });
        for body in bodies {
            add_body_mass(self.lu.matrix_mut(), &self.layout, body);
        }
        for clamp in system.body_clamps() {
            let at = ClampMass::of(clamp, &self.layout, lines, bodies);
            at.add_rows(self.lu.matrix_mut(), &held);
        }
        for g in connector_spins(system, &self.layout, bodies) {
            let m = self.lu.matrix_mut();
            m.clear_border_row(g);
            m.add(g, g, 1.0);
        }
        self.lu.factorize()
    }

    /// Solves M_ff v_f = p_f from the lines' expanded steps and the free
    /// points' end momenta `point_momentum[p]` (dA_point/de_b), and sets
    /// every line's end rates (each line after its
    /// [`Simulation::expand_step`]).
    ///
    /// The free bodies (already moved to the step's end) take part with
    /// `body_momentum[k]`, body k's generalized momentum less its points'
    /// share ([`StepBody::end_momentum`]); their rates are set too. Fails
    /// only if M_ff is singular (a free body without mass or inertia on
    /// lines without mass).
    pub fn set_end_rates(
        &mut self,
        system: &Topology,
        lines: &mut [Simulation],
        point_momentum: &[[f64; 3]],
        bodies: &mut [StepBody],
        body_momentum: &[[f64; 6]],
        clamp_ends: &[ClampStepEnd],
    ) -> Result<(), crate::band::SingularMatrix> {
        self.refactorize(system, lines, bodies)?;
        self.rates.fill(0.0);
        let held = &mut self.held;
        for (i, line) in lines.iter_mut().enumerate() {
            let q = line.free_end_momentum(&mut held[i]);
            let numbering = &self.layout.lines[i];
            let map = &self.layout.maps[i];
            for (g, &qg) in q.iter().enumerate() {
                if let Some(u) = numbering.unknown_at(0, g) {
                    self.rates[map.global[u]] += qg;
                }
            }
        }
        for (clamp, end) in system.body_clamps().iter().zip(clamp_ends) {
            let at = ClampMass::of(clamp, &self.layout, lines, bodies);
            let raw = held[clamp.line][clamp.hold];
            at.add_momentum(
                &mut self.rates,
                crate::vec3::add(raw, end.on_line),
                end.on_line,
            );
        }
        for (p, momentum) in point_momentum.iter().enumerate() {
            for (c, &pc) in momentum.iter().enumerate() {
                if let Some(g) = self.layout.point_unknown(p, 0, c) {
                    self.rates[g] += pc;
                }
            }
        }
        for (body, momentum) in bodies.iter().zip(body_momentum) {
            carry_body_momentum(&mut self.rates, &self.layout, body, momentum);
        }
        for g in connector_spins(system, &self.layout, bodies) {
            self.rates[g] = 0.0;
        }
        self.lu.solve(&mut self.rates);
        for body in bodies.iter_mut() {
            let nu: [f64; 6] = std::array::from_fn(|k| {
                self.rates[self
                    .layout
                    .body_unknown(body.index, 0, k)
                    .expect("free body")]
            });
            body.body
                .set_rates([nu[0], nu[1], nu[2]], [nu[3], nu[4], nu[5]]);
        }
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
        Ok(())
    }

    /// v_b of free point p after [`Self::set_end_rates`].
    pub fn point_rate(&self, p: usize) -> Option<[f64; 3]> {
        self.layout.point_base[p]?;
        Some(std::array::from_fn(|c| {
            self.rates[self.layout.point_unknown(p, 0, c).expect("free point")]
        }))
    }
}

/// The spin rates' rows of the connectors (docs/method.md §15.20): Omega
/// about each connector's z axis, held at zero.
fn connector_spins<'a>(
    system: &'a Topology,
    layout: &'a SystemLayout,
    bodies: &'a [StepBody],
) -> impl Iterator<Item = usize> + 'a {
    bodies
        .iter()
        .filter(|b| system.bodies()[b.index].connector)
        .map(|b| layout.body_unknown(b.index, 0, 5).expect("free body"))
}

/// G_P of a point at `arm` from the centre of a body turned by `rotation`:
/// v_P = G_P [v_G; Omega], G_P = [I, -R [arm x]] (B11).
fn point_rate_map(rotation: &[[f64; 3]; 3], arm: [f64; 3]) -> [[f64; 6]; 3] {
    std::array::from_fn(|c| {
        std::array::from_fn(|k| {
            if k < 3 {
                if k == c {
                    1.0
                } else {
                    0.0
                }
            } else {
                // -(R [arm x])_cj = -r_c . (arm x e_j) = (arm x r_c)_j, r_c row c of R
                let e: [f64; 3] = std::array::from_fn(|i| rotation[c][i]);
                crate::vec3::cross(arm, e)[k - 3]
            }
        })
    })
}

/// A body point's rate unknowns (global indices) and its G_P (B14).
type PointRateMap = ([usize; 3], [[f64; 6]; 3]);

/// Body `body`'s rate unknowns (global indices) and its points'
/// [`PointRateMap`]s.
fn body_rate_maps<'a>(
    layout: &'a SystemLayout,
    body: &'a StepBody,
) -> ([usize; 6], impl Iterator<Item = PointRateMap> + 'a) {
    let q = std::array::from_fn(|k| layout.body_unknown(body.index, 0, k).expect("free body"));
    let rotation = body.body.rotation();
    let points = body.points.iter().map(move |bp| {
        let y = std::array::from_fn(|c| layout.point_unknown(bp.point, 0, c).expect("border"));
        (y, point_rate_map(&rotation, bp.arm))
    });
    (q, points)
}

/// Body `body`'s share of M_ff: its points' rows carried to its own by
/// G_P^T and replaced by v_P - G_P nu = 0, and its kinetic Hessian H.
fn add_body_mass(m: &mut crate::bordered::BorderedMatrix, layout: &SystemLayout, body: &StepBody) {
    let (q, points) = body_rate_maps(layout, body);
    let q = |k: usize| q[k];
    for (ys, g) in points {
        let y = |c: usize| ys[c];
        for (c, row) in g.iter().enumerate() {
            for (k, &w) in row.iter().enumerate() {
                if w != 0.0 {
                    m.add_border_row(q(k), y(c), w);
                }
            }
        }
        for (c, row) in g.iter().enumerate() {
            m.clear_border_row(y(c));
            m.add(y(c), y(c), 1.0);
            for (k, &w) in row.iter().enumerate() {
                if w != 0.0 {
                    m.add(y(c), q(k), -w);
                }
            }
        }
    }
    let (_, h) = body.body.rate_hessian();
    for (a, row) in h.iter().enumerate() {
        for (b, &v) in row.iter().enumerate() {
            m.add(q(a), q(b), v);
        }
    }
    if let Some(pin) = body.pin_rate_map(layout) {
        super::pins::pin_mass(m, std::array::from_fn(q), &pin);
    }
}

/// The right side of the body's rows: the lines' end momenta at its
/// points carried by G_P^T (their rows become constraints, right side
/// 0), plus the body's own `momentum` less the kinetic energy's gradient
/// at rest g0 (a current's share, (B9)).
fn carry_body_momentum(
    rates: &mut [f64],
    layout: &SystemLayout,
    body: &StepBody,
    momentum: &[f64; 6],
) {
    let (q, points) = body_rate_maps(layout, body);
    let q = |k: usize| q[k];
    for (ys, g) in points {
        let y = |c: usize| ys[c];
        for (c, row) in g.iter().enumerate() {
            let raw = rates[y(c)];
            for (k, &w) in row.iter().enumerate() {
                rates[q(k)] += w * raw;
            }
            rates[y(c)] = 0.0;
        }
    }
    let (g0, _) = body.body.rate_hessian();
    for k in 0..6 {
        rates[q(k)] += momentum[k] - g0[k];
    }
    if let Some(pin) = body.pin_rate_map(layout) {
        super::pins::pin_momentum(rates, std::array::from_fn(q), &pin);
    }
}

/// Adds the system's mass matrix over the free coordinates to `lu`: each
/// line's band (with its added mass M_a(e) (W31) where `line(i)` gives the
/// coordinates e) and the free points' masses.
///
/// Returns the entries (line, r_x coordinate, column coordinate, m) of
/// the rows of r_x held by a clamp at a free body before (M43) turns them
/// (B40 carries them to the body's rows).
fn fill_mass<'a>(
    lu: &mut BorderedLu,
    layout: &SystemLayout,
    system: &Topology,
    line: impl Fn(usize) -> (&'a Model, Option<&'a [f64]>),
) -> Vec<HeldEntry> {
    let mut held = Vec::new();
    for i in 0..layout.lines.len() {
        let (model, end) = line(i);
        let numbering = &layout.lines[i];
        let mut view = LineView::new(lu.matrix_mut().block_entries(i), &layout.maps[i]);
        let dpn = model.dofs_per_node();
        let constraints = &model.constraints;
        // Coordinates' entry (ga, gb) at unknowns, a held node's r_x
        // rows turned to (M43).
        let mut add = |ga: usize, gb: usize, m: f64| {
            if let (Some(_), Some(_)) = (numbering.unknown_at(0, ga), numbering.unknown_at(0, gb)) {
                if let Some((hold, _, _)) = constraints.held_direction(dpn, ga) {
                    if hold.turning {
                        held.push(HeldEntry {
                            line: i,
                            row: ga,
                            column: gb,
                            mass: m,
                        });
                    }
                }
                constraints.add_mass_entry(dpn, ga, gb, m, |a, b, v| {
                    let (r, s) = (numbering.unknown_at(0, a), numbering.unknown_at(0, b));
                    view.add(r.expect("a held r_x is free"), s.expect("free"), v);
                });
            }
        };
        crate::with_elements!(&model.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                for (a, row) in el.mass.iter().enumerate() {
                    for (b, &m_ab) in row.iter().enumerate() {
                        for c in 0..3 {
                            add(coordinate(dpn, k, a, c), coordinate(dpn, k, b, c), m_ab);
                        }
                    }
                }
            }
        });
        if let Some(e) = end {
            model.for_entrained_mass(e, &mut add);
        }
        constraints.add_hold_rate_rows(dpn, |a, b, v| {
            let (r, s) = (numbering.unknown_at(0, a), numbering.unknown_at(0, b));
            view.add(r.expect("a held r_x is free"), s.expect("free"), v);
        });
    }
    for p in 0..system.points().len() {
        let inertia = system.point_inertia(p);
        for c in 0..3 {
            if let Some(g) = layout.point_unknown(p, 0, c) {
                lu.matrix_mut().add(g, g, inertia);
            }
        }
    }
    held
}
