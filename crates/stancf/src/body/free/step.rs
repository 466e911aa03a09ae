//! A free body's step (docs/method.md §15.4-§15.5): the slab's rows
//! (B5)-(B6), (B8) and (B10) over its 24 slots, their exact Jacobians,
//! Newton, and the move to the step's end.

use super::*;
use crate::body::flow::FlowTime;
use crate::body::terms::moment_on_theta;

impl FreeBody {
    /// (B5) and (B10) over the slab: the action's gradient plus the drag's
    /// virtual work, per slot, and their derivatives. `slots` holds the
    /// eight blocks (the centre's from r_a).
    fn slab_rows(&self, slots: &[[f64; 3]; 8]) -> SlabRows {
        let mut ctx = self.context(&self.start_loads);
        let mut out = SlabRows {
            rows: [0.0; SLOTS],
            jacobian: [0.0; SLOTS * SLOTS],
        };
        let total = self.forces.total();
        for m in 0..4 {
            for i in 0..3 {
                out.rows[3 * m + i] += self.slab.load[m] * total[i];
            }
        }
        for point in &self.slab.points {
            let (t, v) = (&point.shape.t, self.point_variables(slots, point).1);
            ctx.time = FlowTime::At(self.time + point.offset);
            let density = ctx.density(&v);
            let wdt = point.w_dt;
            for m in 0..4 {
                for k in 0..NV {
                    let (s, wk) = variable_slot(k, m, point);
                    out.rows[s] += wdt * wk * density.g[k];
                    for n in 0..4 {
                        for l in 0..NV {
                            let (s2, wl) = variable_slot(l, n, point);
                            out.jacobian[s * SLOTS + s2] += wdt * wk * wl * density.h[k][l];
                        }
                    }
                }
            }
            if self.moment != [0.0; 3] {
                let q = moment_on_theta(&self.rotation, self.moment, &v[1]);
                for m in 0..4 {
                    for i in 0..3 {
                        let s = 12 + 3 * m + i;
                        out.rows[s] += wdt * t[m] * q[i].v;
                        for n in 0..4 {
                            for l in 0..NV {
                                let (s2, wl) = variable_slot(l, n, point);
                                out.jacobian[s * SLOTS + s2] += wdt * t[m] * wl * q[i].g[l];
                            }
                        }
                    }
                }
            }
            if let Some((on_centre, on_theta)) = ctx.drag(&v) {
                for m in 0..4 {
                    for (first, q) in [(0usize, &on_centre), (12, &on_theta)] {
                        for i in 0..3 {
                            let s = first + 3 * m + i;
                            out.rows[s] += wdt * t[m] * q[i].v;
                            for n in 0..4 {
                                for l in 0..NV {
                                    let (s2, wl) = variable_slot(l, n, point);
                                    out.jacobian[s * SLOTS + s2] += wdt * t[m] * wl * q[i].g[l];
                                }
                            }
                        }
                    }
                }
            }
        }
        out
    }

    /// The variables at time point `point` of the step whose slot blocks
    /// are `slots` (eq. 6 in time): the rates (v_G, theta, theta_dot) and
    /// the twelve jets of [`super::super::terms::NV`] with the centre r_G.
    fn point_variables(
        &self,
        slots: &[[f64; 3]; 8],
        point: &TimePoint,
    ) -> ([[f64; 3]; 3], [JetVec<NV>; 4]) {
        let at = |w: &[f64; 4], first: usize| -> [f64; 3] {
            std::array::from_fn(|i| (0..4).map(|m| w[m] * slots[first + m][i]).sum())
        };
        let (t, t_dot) = (&point.shape.t, &point.shape.t_dot);
        let rates = [at(t_dot, 0), at(t, 4), at(t_dot, 4)];
        let v = variables([rates[0], rates[1], rates[2], add(self.centre, at(t, 0))]);
        (rates, v)
    }

    /// The slot blocks of a step from its unknowns x.
    fn slots(&self, x: &[f64]) -> [[f64; 3]; 8] {
        let mut slots = [[0.0; 3]; 8];
        match self.scheme {
            TimeScheme::Galerkin => {
                for (k, &b) in GALERKIN_UNKNOWNS.iter().enumerate() {
                    slots[b] = part(x, 3 * k);
                }
            }
            TimeScheme::P2 => {
                slots[1] = self.velocity;
                slots[5] = self.body_rate;
                for (k, &b) in P2_UNKNOWNS.iter().enumerate() {
                    slots[b] = part(x, 3 * k);
                }
            }
        }
        slots
    }

    /// The Galerkin rows (B6) at x = [w_a, r_b - r_a, w_b, u_a, theta_b,
    /// u_b] and their exact Jacobian (row-major, 18 x 18).
    pub fn galerkin_rows_and_jacobian(&self, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        let (mut r, mut jac) = (vec![0.0; 18], vec![0.0; 18 * 18]);
        self.galerkin_rows_into(x, &mut r, &mut jac);
        (r, jac)
    }

    /// [`Self::galerkin_rows_and_jacobian`] into `rows` (18) and `jac`
    /// (18 x 18, row-major), allocating nothing.
    pub fn galerkin_rows_into(&self, x: &[f64], rows: &mut [f64], jac: &mut [f64]) {
        let slab = self.slab_rows(&self.slots(x));
        pick(&slab, &GALERKIN_ROWS, &GALERKIN_UNKNOWNS, rows, jac);
        for i in 0..3 {
            rows[i] += self.momentum[i];
            rows[9 + i] += self.body_momentum[i];
        }
    }

    /// The P2 rows (B8) at x = [r_b - r_a, v_b, theta_b, u_b] and their
    /// exact Jacobian (row-major, 12 x 12): the end slopes are the carried
    /// rates (u_a = Omega_a, J_r(0) = I; u_b = J_r(theta_b)^-1 Omega_b),
    /// the end momenta the kinetic energy's gradient in the end's rates.
    pub fn p2_rows_and_jacobian(&self, x: &[f64]) -> (Vec<f64>, Vec<f64>) {
        const M: usize = 12;
        let slab = self.slab_rows(&self.slots(x));
        let (mut r, mut jac) = (vec![0.0; M], vec![0.0; M * M]);
        pick(&slab, &P2_ROWS, &P2_UNKNOWNS, &mut r, &mut jac);
        let end = self.context(&[]).kinetic(&variables([
            part(x, 3),
            part(x, 6),
            part(x, 9),
            add(self.centre, part(x, 0)),
        ]));
        for i in 0..3 {
            r[i] += self.momentum[i];
            r[6 + i] += self.body_momentum[i];
            // -dT/dv_G and -dT/dtheta_dot at the end; their derivatives in
            // v_b (x 3..6), theta_b (6..9), u_b (9..12) and r_b (0..3).
            r[3 + i] -= end.g[i];
            r[9 + i] -= end.g[6 + i];
            for k in 0..NV {
                let column = if k < 9 { 3 + k } else { k - 9 };
                jac[(3 + i) * M + column] -= end.h[i][k];
                jac[(9 + i) * M + column] -= end.h[6 + i][k];
            }
        }
        (r, jac)
    }

    /// One step of (B6)-(B7) (Galerkin) or (B8) (P2).
    pub fn step(&mut self) -> Result<(), SolverError> {
        let dt = self.slab.dt;
        let (v_g, omega) = (self.velocity, self.body_rate);
        let guess = |position: bool, v: [f64; 3]| if position { scale(dt, v) } else { v };
        // The unknowns' blocks: whether a position (else a rate) and
        // whether the rotation's (else the centre's).
        let layout: &[(bool, bool)] = match self.scheme {
            TimeScheme::Galerkin => &[
                (false, false),
                (true, false),
                (false, false),
                (false, true),
                (true, true),
                (false, true),
            ],
            TimeScheme::P2 => &[(true, false), (false, false), (true, true), (false, true)],
        };
        let mut x: Vec<f64> = layout
            .iter()
            .flat_map(|&(position, turning)| guess(position, if turning { omega } else { v_g }))
            .collect();
        self.newton(&mut x, layout)?;
        let slots = self.slots(&x);
        let theta_b = slots[6];
        match self.scheme {
            TimeScheme::Galerkin => {
                let (p, dtheta) = self.galerkin_end_gradient(&x);
                // Pi_b solves J_r(theta_b)^T Pi_b = dA/dtheta_b.
                let pi = solve_transposed(&right_jacobian(theta_b), dtheta)
                    .ok_or_else(|| self.failure(FailureKind::SingularJacobian, 0, f64::NAN))?;
                self.advance(&x)?;
                self.momentum = p;
                self.body_momentum = pi;
                self.rates_from_momenta()?;
            }
            TimeScheme::P2 => {
                self.advance(&x)?;
                self.velocity = slots[3];
                self.body_rate = rotate(&right_jacobian(theta_b), slots[7]);
                self.momenta_from_rates();
            }
        }
        Ok(())
    }

    /// Moves the body to the end of the step whose unknowns are x (the
    /// centre by r_b - r_a, the rotation to R_a exp([theta_b]), brought
    /// back to orthonormal) and its clock on; the rates are the caller's
    /// to set. The chart (B3)-(B4) holds a step's turn below pi (J_r is
    /// singular at 2 pi): a longer turn is refused as a step too long for
    /// the body's rotation.
    pub fn advance(&mut self, x: &[f64]) -> Result<(), SolverError> {
        let slots = self.slots(x);
        self.water_work += self.drag_work(&slots);
        if self.own_impulse.is_some() {
            self.own_impulse = Some(self.own_impulse_over(&slots));
        }
        self.moment_work += self.moment_power_integral(&slots);
        let theta_b = slots[6];
        let turn = crate::vec3::norm(theta_b);
        if turn > std::f64::consts::PI {
            let mut e = self.failure(FailureKind::NotConverged, self.last_iterations, f64::NAN);
            e.detail = format!(
                "{}: the body turns by {turn:.3} rad in one step, more than pi; take a shorter step",
                e.detail
            );
            return Err(e);
        }
        self.centre = add(self.centre, slots[2]);
        self.rotation =
            pose::reorthonormalized(&crate::vec3::mat3_mul(&self.rotation, &exp_map(theta_b)));
        self.refresh_loads();
        self.time += self.slab.dt;
        Ok(())
    }

    /// The drag's work over the step whose slot blocks are `slots`: its
    /// power at the time points (the same quadrature as its virtual work
    /// in the rows).
    fn drag_work(&self, slots: &[[f64; 3]; 8]) -> f64 {
        if self.water.is_none() {
            return 0.0;
        }
        let mut ctx = self.context(&self.start_loads);
        let mut work = 0.0;
        for point in &self.slab.points {
            ctx.time = FlowTime::At(self.time + point.offset);
            let (rates, v) = self.point_variables(slots, point);
            if let Some((on_centre, on_theta)) = ctx.drag(&v) {
                let power: f64 = (0..3)
                    .map(|i| on_centre[i].v * rates[0][i] + on_theta[i].v * rates[2][i])
                    .sum();
                work += point.w_dt * power;
            }
        }
        work
    }

    /// The impulse on the centre over the step whose slot blocks are
    /// `slots` of the body's own loads, those of its rows on r_G summed
    /// over the step (its position shapes sum to one): the constant
    /// forces times dt, and at the time points dL/dr_G (the rods'
    /// buoyancy, and their added mass as the wet part moves) and the
    /// water's Q_r (B10), (B32), by the rows' quadrature. The rest of the
    /// body's momentum change is what holds it: its lines and a pin
    /// (§15.17).
    fn own_impulse_over(&self, slots: &[[f64; 3]; 8]) -> [f64; 3] {
        let total = self.forces.total();
        let mut impulse = total.map(|f| f * self.slab.dt);
        let mut ctx = self.context(&self.start_loads);
        for point in &self.slab.points {
            ctx.time = FlowTime::At(self.time + point.offset);
            let v = self.point_variables(slots, point).1;
            let density = ctx.density(&v);
            let water = ctx.drag(&v).map(|(on_centre, _)| on_centre.map(|q| q.v));
            for i in 0..3 {
                let q = water.map_or(0.0, |w| w[i]);
                impulse[i] += point.w_dt * (density.g[9 + i] + q);
            }
        }
        impulse
    }

    /// The constant moment's work over the step whose slot blocks are
    /// `slots` (B27): Q_theta . theta_dot at the time points.
    fn moment_power_integral(&self, slots: &[[f64; 3]; 8]) -> f64 {
        if self.moment == [0.0; 3] {
            return 0.0;
        }
        let mut work = 0.0;
        for point in &self.slab.points {
            let at = |w: &[f64; 4]| -> [f64; 3] {
                std::array::from_fn(|i| (0..4).map(|m| w[m] * slots[4 + m][i]).sum())
            };
            let (theta, theta_dot) = (at(&point.shape.t), at(&point.shape.t_dot));
            let q = moment_on_theta::<1>(&self.rotation, self.moment, &theta.map(Jet::constant));
            work += point.w_dt * (0..3).map(|i| q[i].v * theta_dot[i]).sum::<f64>();
        }
        work
    }

    /// The Galerkin step's end gradients at its unknowns x: dA/dr_b (the
    /// end momentum p_b of (B7)) and dA/dtheta_b (= J_r(theta_b)^T Pi_b).
    pub fn galerkin_end_gradient(&self, x: &[f64]) -> ([f64; 3], [f64; 3]) {
        let slab = self.slab_rows(&self.slots(x));
        (part(&slab.rows, 6), part(&slab.rows, 18))
    }

    /// The first guess of a Galerkin step's unknowns [w_a, r_b - r_a, w_b,
    /// u_a, theta_b, u_b]: at the carried rates.
    pub fn galerkin_guess(&self) -> [f64; 18] {
        let dt = self.slab.dt;
        let (v, w) = (self.velocity, self.body_rate);
        let blocks = [v, scale(dt, v), v, w, scale(dt, w), w];
        std::array::from_fn(|i| blocks[i / 3][i % 3])
    }

    /// Newton on the scheme's rows from x; `layout` says which blocks of
    /// three are positions (else rates, whose change counts times dt) and
    /// which are the rotation's (else the centre's, whose change counts
    /// relative to the centre's size).
    fn newton(&mut self, x: &mut [f64], layout: &[(bool, bool)]) -> Result<(), SolverError> {
        let n = x.len();
        let dt = self.slab.dt;
        let scale_r = 1.0 + self.centre.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        let mut pivots = vec![0usize; n];
        let mut change = f64::INFINITY;
        let mut previous = f64::INFINITY;
        for k in 1..=MAX_ITERATIONS {
            let (mut delta, mut jac) = match self.scheme {
                TimeScheme::Galerkin => self.galerkin_rows_and_jacobian(x),
                TimeScheme::P2 => self.p2_rows_and_jacobian(x),
            };
            if delta.iter().any(|v| !v.is_finite()) {
                return Err(self.failure(FailureKind::NonFinite, k, f64::NAN));
            }
            if dense_lu(&mut jac, n, &mut pivots).is_err() {
                return Err(self.failure(FailureKind::SingularJacobian, k, f64::NAN));
            }
            dense_solve(&jac, n, &pivots, &mut delta);
            change = 0.0;
            for i in 0..n {
                x[i] -= delta[i];
                let (position, turning) = layout[i / 3];
                let size = if position { delta[i] } else { dt * delta[i] };
                let unit = if turning { 1.0 } else { scale_r };
                change = change.max(size.abs() / unit);
            }
            self.last_iterations = k;
            // Converged: the change at round-off, or below 1e-10 and no
            // longer halving (the round-off floor of a body whose
            // couplings amplify the rows' round-off).
            if change <= 1e-14 || (change <= 1e-10 && change > 0.5 * previous) {
                return Ok(());
            }
            previous = change;
        }
        Err(self.failure(FailureKind::NotConverged, MAX_ITERATIONS, change))
    }

    pub(super) fn failure(
        &self,
        kind: FailureKind,
        iterations: usize,
        residual: f64,
    ) -> SolverError {
        SolverError {
            kind,
            time: self.time,
            step: (self.time / self.slab.dt).round() as usize + 1,
            residual,
            iterations,
            detail: match self.scheme {
                TimeScheme::Galerkin => "free body's Galerkin step (B6)".into(),
                TimeScheme::P2 => "free body's P2 step (B8)".into(),
            },
        }
    }
}

/// The rows of the slot blocks `rows` into `r` and their derivatives in
/// the slot blocks `unknowns` into `jac` (row-major).
fn pick(slab: &SlabRows, rows: &[usize], unknowns: &[usize], r: &mut [f64], jac: &mut [f64]) {
    let n = 3 * rows.len();
    for (a, &ra) in rows.iter().enumerate() {
        for i in 0..3 {
            r[3 * a + i] = slab.rows[3 * ra + i];
            for (b, &ub) in unknowns.iter().enumerate() {
                for j in 0..3 {
                    jac[(3 * a + i) * n + 3 * b + j] =
                        slab.jacobian[(3 * ra + i) * SLOTS + 3 * ub + j];
                }
            }
        }
    }
}

/// x[a..a + 3].
fn part(x: &[f64], a: usize) -> [f64; 3] {
    [x[a], x[a + 1], x[a + 2]]
}

/// y with A^T y = b (None if A is singular).
pub(crate) fn solve_transposed(a: &[[f64; 3]; 3], b: [f64; 3]) -> Option<[f64; 3]> {
    let mut m: [f64; 9] = std::array::from_fn(|k| a[k % 3][k / 3]);
    let mut pivots = [0usize; 3];
    dense_lu(&mut m, 3, &mut pivots).ok()?;
    let mut y = b;
    dense_solve(&m, 3, &pivots, &mut y);
    Some(y)
}
