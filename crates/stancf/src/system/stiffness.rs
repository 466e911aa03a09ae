//! The mooring stiffness of a free body at a static equilibrium
//! (docs/method.md §15.9, (B16)): how the force and moment of its lines
//! change as the body is moved, everything else (lines, free points,
//! other free bodies) staying in equilibrium.
//!
//! A free body's: the Schur complement of the static Jacobian onto the
//! body's own unknowns q = [r_G; theta] (R = R* exp([theta]), the chart
//! centred at the equilibrium's rotation R*), with the body *bare*: its
//! own weight, buoyancy, water, loads and holds taken off, so that its
//! rows rho(q) = -[F; J_r(theta)^T R^T M_G] are the lines' (their force
//! F and moment M_G about the centre of mass, the points' pull and the
//! clamps' reactions alike, §15.19). With S = d rho / d q condensed,
//! c = R* xi_G the centre from the reference point, and the body moved
//! by dr at its reference point and turned by dphi about global axes
//! through it (dq = A [dr; dphi], A = [[I, -[c x]], [0, R*^T]]),
//!
//! ```text
//!   T = S A,   K = -d[F; M]/d[dr; dphi]
//!     = [ T_r                                                      ]   (B16)
//!       [ R* T_theta + [c x] T_r + [0,  1/2 [M_G x] - [F x][c x]]  ]
//! ```
//!
//! (M = M_G + c x F about the reference point; the 1/2 [M_G x] is the
//! chart's: R J_r^-T = R* (I + [theta x]/2) to first order). Not
//! symmetric where the lines pull. A coupled body's points are held by
//! the host: theirs is condensed onto its points (K_PQ), made free
//! points of nothing of their own, and carried to the body by
//!
//! ```text
//!   K = sum_PQ [ K_PQ          -K_PQ [a_Q x]        ]
//!              [ [a_P x] K_PQ  -[a_P x] K_PQ [a_Q x] ]  -  sum_P [ 0  0                        ]   (B16a)
//!                                                               [ 0  a_P f_P^T - (a_P . f_P) I ]
//! ```
//!
//! (a_P = x_P - r). Both exact (the derivatives of the rows, not
//! differences): the matrix designers take from MoorPy's finite
//! differences.

use super::body_statics::StaticBody;
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
    /// about its reference point (global axes; the moments of the clamps
    /// of §15.19 included), columns its reference point's displacement
    /// and its small rotation about global axes through the reference
    /// point; N/m, N/rad, N m/m, N m/rad. None for a fixed body, a
    /// pinned body (its pin holds its translation), a connector (§15.20:
    /// a joint of its lines, no body of its own), or if the rest of the
    /// system is singular with the body held.
    pub fn body_stiffness(&mut self, b: usize) -> Option<[[f64; 6]; 6]> {
        let body = self.system().bodies().get(b)?;
        if body.kind == super::BodyKind::Coupled {
            return self.coupled_body_stiffness(b, body.position);
        }
        if body.pin.is_some() || body.connector {
            return None;
        }
        // The body bare, its chart centred at the equilibrium (theta = 0
        // at R*): its rows are the lines' force and moment.
        let ((s, rows), rotation) = self.condensed_body(b, 0, |body, r| body.bare(r))?;
        let k = self.equations.bodies.iter().position(|s| s.index == b)?;
        let centre = crate::body::pose::rotate(&rotation, self.equations.bodies[k].centre_of_mass);
        Some(from_chart(&s, &rows, &rotation, centre))
    }

    /// Free body b's static rows condensed onto its unknowns `from..6`,
    /// everything else in equilibrium ([`condensed_onto`]: S and the
    /// rows), with its chart centred at the equilibrium's rotation R*
    /// (theta = 0 there) and the body evaluated as `body_at(its statics,
    /// R*)` makes it; and R*. None where the rest of the system is
    /// singular with those unknowns held.
    pub(super) fn condensed_body(
        &mut self,
        b: usize,
        from: usize,
        body_at: impl Fn(&StaticBody, [[f64; 3]; 3]) -> StaticBody,
    ) -> Option<(Condensed, [[f64; 3]; 3])> {
        let k = self.equations.bodies.iter().position(|s| s.index == b)?;
        let eq = &mut self.equations;
        let unknown = |q: usize| eq.layout.body_unknown(b, 0, q).expect("a free body");
        let unknowns: Vec<usize> = (from..6).map(unknown).collect();
        let turns: Vec<usize> = (3..6).map(unknown).collect();
        let saved = eq.bodies[k].clone();
        let mut x = self.newton.x.clone();
        let rotation = saved.rotation_at(&saved.unknowns(&eq.layout, &x));
        eq.bodies[k] = body_at(&saved, rotation);
        for i in turns {
            x[i] = 0.0;
        }
        let condensed = condensed_onto(eq, &x, &unknowns);
        eq.bodies[k] = saved;
        Some((condensed?, rotation))
    }

    /// (B16a) from the condensed K_PQ at `points` about `reference`.
    fn assemble_at(&self, kpq: &[f64], points: &[usize], reference: [f64; 3]) -> [[f64; 6]; 6] {
        let arms: Vec<[f64; 3]> = points
            .iter()
            .map(|&p| sub(self.point_position(p), reference))
            .collect();
        let forces: Vec<[f64; 3]> = points.iter().map(|&p| self.point_force(p)).collect();
        assemble_stiffness(kpq, &arms, &forces)
    }

    /// The mooring stiffness (B16a) of coupled body b (moved by a host) at
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
        let eq = &mut statics.equations;
        let ys = points
            .iter()
            .flat_map(|&p| (0..3).map(move |c| (p, c)))
            .map(|(p, c)| eq.layout.point_unknown(p, 0, c))
            .collect::<Option<Vec<usize>>>()?;
        condensed_onto(eq, &x, &ys).map(|(k, _)| k)
    }
}

/// A condensed Jacobian S (row-major) and the rows it is of.
pub(super) type Condensed = (Vec<f64>, Vec<f64>);

/// The static Jacobian condensed onto the unknowns `ys`: S = J_yy -
/// J_y,rest J_rest^-1 J_rest,y (row-major, m x m), the derivative of
/// their rows as they move with everything else in equilibrium, and
/// their rows at x. None where the rest is singular with them held.
pub(super) fn condensed_onto(
    eq: &mut super::statics::SystemEquations,
    x: &[f64],
    ys: &[usize],
) -> Option<Condensed> {
    let n = eq.layout.size;
    let mut jac = BorderedMatrix::new(&eq.layout.shapes, eq.layout.border);
    let mut residual = vec![0.0; n];
    eq.evaluate(x, &mut residual, Some(&mut jac));
    let layout = &eq.layout;
    let column = |j: usize| -> Vec<f64> { (0..n).map(|i| jac.get(i, j)).collect() };
    let row = |i: usize| -> Vec<f64> { (0..n).map(|j| jac.get(i, j)).collect() };
    let columns: Vec<Vec<f64>> = ys.iter().map(|&j| column(j)).collect();
    let rows: Vec<Vec<f64>> = ys.iter().map(|&i| row(i)).collect();
    // The rest of the system with the unknowns ys held: their rows and
    // columns made the identity.
    for &i in ys {
        jac.clear_border_row(i);
        jac.clear_border_column(i);
        jac.add(i, i, 1.0);
    }
    let mut lu = BorderedLu::new(&layout.shapes, layout.border);
    lu.matrix_mut().copy_from(&jac);
    lu.factorize().ok()?;
    let m = ys.len();
    let mut s = vec![0.0; m * m];
    for (c, col) in columns.iter().enumerate() {
        let mut w = col.clone();
        for &i in ys {
            w[i] = 0.0;
        }
        lu.solve(&mut w);
        for (r, row) in rows.iter().enumerate() {
            s[r * m + c] = row[ys[c]] - dot_all(row, &w);
        }
    }
    Some((s, ys.iter().map(|&i| residual[i]).collect()))
}

/// (B16) of a free body from its condensed S = d rho / d q (6 x 6,
/// row-major) and its rows rho in the chart centred at `rotation` (R*),
/// its centre of mass at `centre` (c) from its reference point: see the
/// module's text.
fn from_chart(s: &[f64], rho: &[f64], rotation: &[[f64; 3]; 3], centre: [f64; 3]) -> [[f64; 6]; 6] {
    // dq = A [dr; dphi]: dr_G = dr - [c x] dphi, dtheta = R*^T dphi.
    let mut a = [[0.0; 6]; 6];
    let hc = hat(centre);
    for i in 0..3 {
        a[i][i] = 1.0;
        for j in 0..3 {
            a[i][3 + j] = -hc[i][j];
            a[3 + i][3 + j] = rotation[j][i];
        }
    }
    let t: [[f64; 6]; 6] = std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..6).map(|l| s[6 * i + l] * a[l][j]).sum())
    });
    let force = [-rho[0], -rho[1], -rho[2]];
    let moment = crate::body::pose::rotate(rotation, [-rho[3], -rho[4], -rho[5]]);
    let turning = mul(&hat(force), &hc);
    let hm = hat(moment);
    let mut k = [[0.0; 6]; 6];
    for j in 0..6 {
        for i in 0..3 {
            k[i][j] = t[i][j];
            k[3 + i][j] = (0..3)
                .map(|l| rotation[i][l] * t[3 + l][j] + hc[i][l] * t[l][j])
                .sum();
        }
    }
    for i in 0..3 {
        for j in 0..3 {
            k[3 + i][3 + j] += 0.5 * hm[i][j] - turning[i][j];
        }
    }
    k
}

/// sum_i a_i b_i.
fn dot_all(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// (B16a) from the condensed K_PQ (row-major over the points' 3 n
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
