//! The mooring stiffness of a free body at a static equilibrium
//! (docs/method.md §15.9, (B16)): how the force and moment of its lines
//! change as the body is moved, everything else (lines, free points,
//! other free bodies) staying in equilibrium.
//!
//! The lines' condensed stiffness at the body's points, K_PQ = d(rows at
//! P)/d x_Q = -d f_P / d x_Q (f_P the lines' force on P), is the Schur
//! complement of the static Jacobian onto the points' unknowns, with the
//! body taken out (its points' rows left as the lines' rows). Moving the
//! body's reference point by dr and turning it by a small rotation dphi
//! (global axes, about the reference point) moves P by dr + dphi x a_P
//! (a_P = x_P - r) and turns the arm, so the lines' force F = sum f_P and
//! moment M = sum a_P x f_P about the reference point change by
//!
//! ```text
//!   K = -d[F; M]/d[dr; dphi]
//!     = sum_PQ [ K_PQ          -K_PQ [a_Q x]        ]
//!              [ [a_P x] K_PQ  -[a_P x] K_PQ [a_Q x] ]  -  sum_P [ 0  0                        ]   (B16)
//!                                                               [ 0  a_P f_P^T - (a_P . f_P) I ]
//! ```
//!
//! exact (the derivatives of the lines' rows, not differences), the
//! matrix designers take from MoorPy's finite differences; not symmetric
//! where the lines pull (the last term is the moment of the pull turning
//! with the body).

use super::SystemStatics;
use crate::bordered::{BorderedLu, BorderedMatrix};
use crate::linear::{AddEntries, Factorization, Jacobian};
use crate::statics::StaticEquations;
use crate::vec3::{dot, sub};

/// [a x], the cross-product matrix.
fn hat(a: [f64; 3]) -> [[f64; 3]; 3] {
    [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]]
}

fn mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    crate::vec3::mat3_mul(a, b)
}

impl SystemStatics {
    /// The mooring stiffness (B16) of free body b at the last converged
    /// increment (the equilibrium once [`SystemStatics::solve`] is done):
    /// rows F_x, F_y, F_z, M_x, M_y, M_z of the lines' force and moment
    /// about its reference point (global axes), columns its reference
    /// point's displacement and its small rotation about global axes
    /// through the reference point; N/m, N/rad, N m/m, N m/rad. None for a
    /// fixed body, if the rest of the system is singular with the body
    /// held, or for a body lines are clamped to (§15.19: (B16) would miss
    /// the change of the clamps' moments as it turns; not built yet).
    pub fn body_stiffness(&mut self, b: usize) -> Option<[[f64; 6]; 6]> {
        if self.system().holds_clamps(b) {
            return None;
        }
        let body = self.system().bodies().get(b)?;
        if body.kind == super::BodyKind::Coupled {
            return self.coupled_body_stiffness(b, body.position);
        }
        if body.pin.is_some() {
            // A pinned body does not translate: no 6 x 6 of its own.
            return None;
        }
        let (reference, _) = self.body_pose(b)?;
        let k = self.equations.bodies.iter().position(|s| s.index == b)?;
        let x = self.newton.x.clone();
        let eq = &mut self.equations;
        let body = eq.bodies.remove(k);
        let points: Vec<usize> = body.points.iter().map(|bp| bp.point).collect();
        let body_unknowns: Vec<usize> = (0..6)
            .map(|q| eq.layout.body_unknown(b, 0, q).expect("a free body"))
            .collect();
        let kpq = condensed(eq, &x, &points, &body_unknowns);
        eq.bodies.insert(k, body);
        let kpq = kpq?;
        Some(self.assemble_at(&kpq, &points, reference))
    }

    /// (B16) from the condensed K_PQ at `points` about `reference`.
    fn assemble_at(&self, kpq: &[f64], points: &[usize], reference: [f64; 3]) -> [[f64; 6]; 6] {
        let arms: Vec<[f64; 3]> = points
            .iter()
            .map(|&p| sub(self.point_position(p), reference))
            .collect();
        let forces: Vec<[f64; 3]> = points.iter().map(|&p| self.point_force(p)).collect();
        assemble_stiffness(kpq, &arms, &forces)
    }

    /// The mooring stiffness (B16) of coupled body b (moved by a host) at
    /// the last converged increment, about `reference` (its reference
    /// point where the host holds it), as [`Self::body_stiffness`]: how
    /// the lines' force and moment on it change as the host moves it,
    /// everything free staying in equilibrium. Its points are coupled
    /// points; their condensed K_PQ comes from the system with them made
    /// free ([`Self::coupled_condensed`]). None for a body that is not
    /// coupled, without lines, or where the rest of the system is
    /// singular with its points held.
    pub fn coupled_body_stiffness(&self, b: usize, reference: [f64; 3]) -> Option<[[f64; 6]; 6]> {
        let body = self.system().bodies().get(b)?;
        if body.kind != super::BodyKind::Coupled {
            return None;
        }
        let points: Vec<usize> = self
            .system()
            .body_points(b)
            .iter()
            .map(|&(p, _)| p)
            .filter(|&p| self.system().attachments(p).next().is_some())
            .collect();
        if points.is_empty() {
            return None;
        }
        let kpq = self.coupled_condensed(&points)?;
        Some(self.assemble_at(&kpq, &points, reference))
    }

    /// The mooring stiffness of coupled point p at the last converged
    /// increment: K = -d f_P / d x_P (f_P the lines' force on it), the
    /// rest of the system staying in equilibrium; N/m, row-major by
    /// global axes. None for a point that is not coupled, holds no line,
    /// or where the rest is singular with it held.
    pub fn coupled_point_stiffness(&self, p: usize) -> Option<[[f64; 3]; 3]> {
        let point = self.system().points().get(p)?;
        let coupled = matches!(point.kind, super::PointKind::Coupled(_)) && point.body().is_none();
        if !coupled || self.system().attachments(p).next().is_none() {
            return None;
        }
        let k = self.coupled_condensed(&[p])?;
        Some(std::array::from_fn(|i| {
            std::array::from_fn(|j| k[3 * i + j])
        }))
    }

    /// The condensed K_PQ (row-major over the points' 3 n coordinates) at
    /// the coupled `points`: the system at this equilibrium with them made
    /// free points of nothing of their own where they are
    /// ([`System::with_points_freed`]), its static Jacobian at the lines'
    /// converged states, condensed onto their unknowns.
    fn coupled_condensed(&self, points: &[usize]) -> Option<Vec<f64>> {
        let system = self
            .system_at_equilibrium()
            .with_points_freed(points)
            .ok()?;
        let mut statics =
            SystemStatics::new(system, self.line_states(), self.settings.clone()).ok()?;
        // At the end of the path (M32): the seeds' axial forces gone.
        statics.equations.set_load_factor(1.0);
        let x = statics.newton.x.clone();
        condensed(&mut statics.equations, &x, points, &[])
    }
}

/// The condensed stiffness K_PQ = J_PP - J_P,rest J_rest^-1 J_rest,P of
/// the static rows at `points` (row-major over their 3 n coordinates),
/// with `points` and `also_held` (global unknowns) held: the derivative
/// of the rows at the points (the lines' and the other loads' there, -f_P)
/// as the points move, everything else in equilibrium. None where the
/// rest is singular.
fn condensed(
    eq: &mut super::statics::SystemEquations,
    x: &[f64],
    points: &[usize],
    also_held: &[usize],
) -> Option<Vec<f64>> {
    let n = eq.layout.size;
    let mut jac = BorderedMatrix::new(&eq.layout.shapes, eq.layout.border);
    let mut residual = vec![0.0; n];
    eq.evaluate(x, &mut residual, Some(&mut jac));
    let layout = &eq.layout;
    let ys: Vec<usize> = points
        .iter()
        .flat_map(|&p| (0..3).map(move |c| (p, c)))
        .map(|(p, c)| layout.point_unknown(p, 0, c))
        .collect::<Option<Vec<usize>>>()?;
    let held: Vec<usize> = ys.iter().chain(also_held).copied().collect();
    let column = |j: usize| -> Vec<f64> { (0..n).map(|i| jac.get(i, j)).collect() };
    let row = |i: usize| -> Vec<f64> { (0..n).map(|j| jac.get(i, j)).collect() };
    let columns: Vec<Vec<f64>> = ys.iter().map(|&j| column(j)).collect();
    let rows: Vec<Vec<f64>> = ys.iter().map(|&i| row(i)).collect();
    // The rest of the system with the points (and the body) held: their
    // rows and columns made the identity.
    for &i in &held {
        jac.clear_border_row(i);
        jac.clear_border_column(i);
        jac.add(i, i, 1.0);
    }
    let mut lu = BorderedLu::new(&layout.shapes, layout.border);
    lu.matrix_mut().copy_from(&jac);
    lu.factorize().ok()?;
    let m = ys.len();
    let mut kpq = vec![0.0; m * m];
    for (c, col) in columns.iter().enumerate() {
        let mut w = col.clone();
        for &i in &held {
            w[i] = 0.0;
        }
        lu.solve(&mut w);
        for (r, row) in rows.iter().enumerate() {
            kpq[r * m + c] = row[ys[c]] - dot_all(row, &w);
        }
    }
    Some(kpq)
}

/// sum_i a_i b_i.
fn dot_all(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// (B16) from the condensed K_PQ (row-major over the points' 3 n
/// coordinates), the arms a_P and the lines' forces f_P.
fn assemble_stiffness(kpq: &[f64], arms: &[[f64; 3]], forces: &[[f64; 3]]) -> [[f64; 6]; 6] {
    let m = 3 * arms.len();
    let mut k6 = [[0.0; 6]; 6];
    for (p, ap) in arms.iter().enumerate() {
        for (q, aq) in arms.iter().enumerate() {
            let block: [[f64; 3]; 3] =
                std::array::from_fn(|i| std::array::from_fn(|j| kpq[(3 * p + i) * m + 3 * q + j]));
            let (hp, hq) = (hat(*ap), hat(*aq));
            let k_aq = mul(&block, &hq);
            let ap_k = mul(&hp, &block);
            let ap_k_aq = mul(&hp, &k_aq);
            for i in 0..3 {
                for j in 0..3 {
                    k6[i][j] += block[i][j];
                    k6[i][3 + j] -= k_aq[i][j];
                    k6[3 + i][j] += ap_k[i][j];
                    k6[3 + i][3 + j] -= ap_k_aq[i][j];
                }
            }
        }
        let f = forces[p];
        let af = dot(*ap, f);
        for i in 0..3 {
            for j in 0..3 {
                let identity = if i == j { af } else { 0.0 };
                k6[3 + i][3 + j] -= ap[i] * f[j] - identity;
            }
        }
    }
    k6
}
