//! MoorDyn's viscoelastic rope (docs/method.md §2.11, (V1)-(V5)): two
//! Kelvin-Voigt units in series along the line. The static spring k1 with
//! its dashpot c1 (MoorDyn's BA) carries the strain eps1 (MoorDyn's
//! dl_1 / l), the dynamic spring k2 with its dashpot c2 (BA_D) the rest,
//! eps - eps1. Per unit length, with one axial force N through both:
//!
//! ```text
//!   N = k1 eps1 + c1 eps1_dot = k2 (eps - eps1) + c2 (eps_dot - eps1_dot)   (V1)
//!   (c1 + c2) eps1_dot = k2 eps - (k1 + k2) eps1 + c2 eps_dot               (V2)
//!   k1 = k2 EA / (k2 - EA)    (the series k1, k2 is the static EA)        (V3)
//!   k2 = EA_D, or k2 = alpha + beta k1 eps1 (the mean-load form):
//!   k2 = (alpha + EA (1 + beta eps1) + sqrt(D)) / 2,
//!   D = alpha^2 + 2 alpha EA (beta eps1 - 1) + EA^2 (1 + beta eps1)^2     (V4)
//! ```
//!
//! (the larger root of (k2 - alpha)(k2 - EA) = beta eps1 k2 EA; k2 = alpha
//! where eps1 < 0). At rest (eps_dot = eps1_dot = 0) N = EA eps: a line's
//! static solve takes the static EA. On a space-time slab eps1 is the
//! internal state of each point of the axial rule, integrated over the
//! slab by collocation at the slab's time Gauss points and its end (V5):
//! here is the constitutive law and that integration; `visco_slab.rs`
//! puts it in the element's slab derivatives.

use crate::error::ModelError;

/// The dynamic stiffness of a viscoelastic line (MoorDyn's second and
/// third bar-separated EA values).
#[derive(Clone, Debug, PartialEq)]
pub enum DynamicStiffness {
    /// A constant k2 = EA_D (N): MoorDyn's `EA|EA_D`.
    Constant(f64),
    /// k2 = alpha + beta T1, T1 = k1 eps1 the static spring's tension (the
    /// mean load of the ABS rule): MoorDyn's `EA|alphaMBL|vbeta` (V4).
    MeanLoad { alpha: f64, beta: f64 },
    /// Syrope's working curves (docs/method.md §2.12): the static spring
    /// the working curve of the largest mean tension so far (from `tmax0`
    /// at the start), the dynamic stiffness alpha + beta T of the spring's
    /// tension T: MoorDyn's `SYROPE:<file>|alphaMBL|vbeta`.
    Syrope {
        curves: std::sync::Arc<super::syrope::Syrope>,
        tmax0: f64,
    },
}

/// A viscoelastic line's law (V1)-(V4), or Syrope's (V7)-(V10); the
/// static stiffness of (V1)-(V4) is the section's EA.
#[derive(Clone, Debug, PartialEq)]
pub struct Viscoelastic {
    pub dynamic: DynamicStiffness,
    /// c1 (N s): the dashpot beside the static spring (MoorDyn's BA).
    pub static_damping: f64,
    /// c2 (N s): the dashpot beside the dynamic spring (MoorDyn's BA_D).
    pub dynamic_damping: f64,
}

/// The springs at a state eps1 and their derivatives in eps1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Springs {
    pub k1: f64,
    pub k2: f64,
    pub dk1: f64,
    pub dk2: f64,
}

/// The rate (V2) and the axial force (V1) at one point of the axial
/// rule at one time, with their partial derivatives in (eps1, eps,
/// eps_dot).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ViscoForce {
    pub rate: f64,
    pub rate_d: [f64; 3],
    pub force: f64,
    pub force_d: [f64; 3],
}

impl Viscoelastic {
    /// Checks the law against the static stiffness `ea`: the damping
    /// non-negative and not both zero ((V2) divides by c1 + c2), the
    /// dynamic stiffness above the static one (k1 of (V3) is positive
    /// only then). `key` names the input.
    pub fn check(&self, ea: f64, key: &str) -> Result<(), ModelError> {
        let (c1, c2) = (self.static_damping, self.dynamic_damping);
        if !(c1 >= 0.0 && c2 >= 0.0 && c1.is_finite() && c2.is_finite()) || c1 + c2 == 0.0 {
            return Err(ModelError::invalid(
                key,
                format!(
                    "a viscoelastic line needs dashpots BA >= 0 and BA_D >= 0, not both zero \
                     (got {c1:e} and {c2:e} N s): the static spring's strain moves at the rate \
                     (k2 eps - (k1 + k2) eps1 + BA_D eps_dot) / (BA + BA_D)"
                ),
            ));
        }
        let (lowest, what) = match &self.dynamic {
            DynamicStiffness::Syrope { curves, tmax0 } => return curves.check_tmax(*tmax0, key),
            &DynamicStiffness::Constant(k2) => (k2, "the dynamic stiffness EA_D"),
            &DynamicStiffness::MeanLoad { alpha, beta } => {
                if !(beta >= 0.0 && beta.is_finite()) {
                    return Err(ModelError::invalid(
                        key,
                        format!(
                            "the dynamic stiffness's load slope beta is {beta}; it must be >= 0"
                        ),
                    ));
                }
                (alpha, "the dynamic stiffness at zero load, alpha")
            }
        };
        if !(lowest > ea && lowest.is_finite()) {
            return Err(ModelError::invalid(
                key,
                format!(
                    "{what} is {lowest:e} N, not above the static EA {ea:e} N: the spring in \
                     series with it, k1 = k2 EA / (k2 - EA), would not be positive"
                ),
            ));
        }
        Ok(())
    }

    /// The values of the internal state at each axial point: eps1, and
    /// for Syrope the largest mean tension Tmax so far and the work done
    /// on the law per length since the start (its energy: a hysteretic
    /// law's stored and dissipated energies do not separate).
    pub fn values_per_point(&self) -> usize {
        match self.dynamic {
            DynamicStiffness::Syrope { .. } => 3,
            _ => 1,
        }
    }

    /// The history at the start (Syrope's Tmax0; 0 for the others).
    pub fn initial_history(&self) -> f64 {
        match self.dynamic {
            DynamicStiffness::Syrope { tmax0, .. } => tmax0,
            _ => 0.0,
        }
    }

    /// k1, k2 at eps1 (V3)-(V4) with their derivatives in eps1 (of the
    /// two-spring forms; a Syrope law has its curves instead).
    pub fn springs(&self, ea: f64, eps1: f64) -> Springs {
        let (k2, dk2) = match self.dynamic {
            DynamicStiffness::Syrope { .. } => unreachable!("Syrope has no k1, k2"),
            DynamicStiffness::Constant(k2) => (k2, 0.0),
            DynamicStiffness::MeanLoad { alpha, .. } if eps1 < 0.0 => (alpha, 0.0),
            DynamicStiffness::MeanLoad { alpha, beta } => {
                let u = 1.0 + beta * eps1;
                let d = alpha * alpha + 2.0 * alpha * ea * (beta * eps1 - 1.0) + ea * ea * u * u;
                let root = d.sqrt();
                let dd = 2.0 * alpha * ea * beta + 2.0 * ea * ea * u * beta;
                (
                    0.5 * (alpha + ea * u + root),
                    0.5 * (ea * beta + 0.5 * dd / root),
                )
            }
        };
        let gap = k2 - ea;
        Springs {
            k1: k2 * ea / gap,
            k2,
            dk1: -ea * ea / (gap * gap) * dk2,
            dk2,
        }
    }

    /// The rate eps1_dot (V2) and the force N (V1) at (eps1, eps,
    /// eps_dot), and their partial derivatives. `slack`: the line carries
    /// no compression and eps < 0, where the springs' share k1 eps1 is
    /// dropped (MoorDyn's "cable can't push"; the dashpot's share stays).
    ///
    /// `history` is Syrope's Tmax (unused by the others): there the
    /// spring's tension is T(eps1) of the curve (V9) and the rate
    /// ((eps - X(T)) (alpha + beta T) + c2 eps_dot) / (c1 + c2) (V10).
    pub fn force(
        &self,
        ea: f64,
        eps1: f64,
        history: f64,
        eps: f64,
        eps_dot: f64,
        slack: bool,
    ) -> ViscoForce {
        let (c1, c2) = (self.static_damping, self.dynamic_damping);
        let c = c1 + c2;
        if let DynamicStiffness::Syrope { curves, .. } = &self.dynamic {
            let s = curves.spring(eps1, history);
            let k = curves.alpha + curves.beta * s.tension;
            let stretch = eps - s.strain_at_rest;
            let rate = (stretch * k + c2 * eps_dot) / c;
            let d_stretch = -s.d_strain_at_rest * s.d_tension;
            let rate_d = [
                (d_stretch * k + stretch * curves.beta * s.d_tension) / c,
                k / c,
                c2 / c,
            ];
            let (spring, spring_d) = if slack {
                (0.0, 0.0)
            } else {
                (s.tension, s.d_tension)
            };
            return ViscoForce {
                rate,
                rate_d,
                force: spring + c1 * rate,
                force_d: [spring_d + c1 * rate_d[0], c1 * rate_d[1], c1 * rate_d[2]],
            };
        }
        let s = self.springs(ea, eps1);
        let rate = (s.k2 * eps - (s.k1 + s.k2) * eps1 + c2 * eps_dot) / c;
        let rate_d = [
            (s.dk2 * eps - (s.dk1 + s.dk2) * eps1 - (s.k1 + s.k2)) / c,
            s.k2 / c,
            c2 / c,
        ];
        let (spring, spring_d) = if slack {
            (0.0, 0.0)
        } else {
            (s.k1 * eps1, s.k1 + s.dk1 * eps1)
        };
        ViscoForce {
            rate,
            rate_d,
            force: spring + c1 * rate,
            force_d: [spring_d + c1 * rate_d[0], c1 * rate_d[1], c1 * rate_d[2]],
        }
    }

    /// The state at rest under the strain eps: the eps1 where the rate
    /// (V2) vanishes with eps_dot = 0, k2(eps1) eps = (k1 + k2) eps1, so
    /// that N = k1 eps1 = EA eps. Syrope's: the slow strain of the
    /// tension at rest at eps on the curve of `history` (Tmax).
    pub fn rest_state(&self, ea: f64, eps: f64, history: f64) -> f64 {
        if let DynamicStiffness::Syrope { curves, .. } = &self.dynamic {
            let t = curves.tension_at_rest(eps, history);
            return curves.slow_strain_at_rest(t, history.max(t));
        }
        let mut eps1 = eps * (1.0 - ea / self.springs(ea, 0.0).k2);
        for _ in 0..50 {
            let s = self.springs(ea, eps1);
            let r = s.k2 * eps - (s.k1 + s.k2) * eps1;
            let dr = s.dk2 * eps - (s.dk1 + s.dk2) * eps1 - (s.k1 + s.k2);
            let step = r / dr;
            eps1 -= step;
            if step.abs() <= 1e-15 * (eps1.abs() + eps.abs()) {
                break;
            }
        }
        eps1
    }

    /// The stored energy per length of the two springs at (eps1, eps),
    /// 1/2 k1 eps1^2 + 1/2 k2 (eps - eps1)^2 (with the springs of the
    /// state; exact for a constant k2).
    /// Syrope's is the work done on its law (the third internal value).
    pub fn stored_energy(&self, ea: f64, state: &[f64], eps: f64) -> f64 {
        if let DynamicStiffness::Syrope { .. } = &self.dynamic {
            return state[2];
        }
        let eps1 = state[0];
        let s = self.springs(ea, eps1);
        0.5 * s.k1 * eps1 * eps1 + 0.5 * s.k2 * (eps - eps1) * (eps - eps1)
    }

    /// The history after a slab whose internal strains at its nodes are
    /// `states`: Syrope's Tmax raised to the largest spring tension met
    /// (the others have none).
    pub fn history_after(&self, history: f64, states: &[f64]) -> f64 {
        match &self.dynamic {
            DynamicStiffness::Syrope { curves, .. } => states
                .iter()
                .map(|&z| curves.spring(z, history).tension)
                .fold(history, f64::max),
            _ => history,
        }
    }

    /// The stiffness a fast motion meets at rest under the strain eps
    /// (the static spring's dashpot holds): k2, or Syrope's
    /// alpha + beta T.
    pub fn fast_stiffness(&self, ea: f64, eps: f64, history: f64) -> f64 {
        if let DynamicStiffness::Syrope { curves, .. } = &self.dynamic {
            return curves.alpha + curves.beta * curves.tension_at_rest(eps, history);
        }
        self.springs(ea, self.rest_state(ea, eps, history)).k2
    }

    /// The power per length the dashpots dissipate at rate eps1_dot and
    /// eps_dot: c1 eps1_dot^2 + c2 (eps_dot - eps1_dot)^2.
    pub fn dissipation(&self, eps1_dot: f64, eps_dot: f64) -> f64 {
        let d = eps_dot - eps1_dot;
        self.static_damping * eps1_dot * eps1_dot + self.dynamic_damping * d * d
    }
}

/// What the slab derivatives keep of a viscoelastic line's axial forces.
#[derive(Clone, Debug, Default)]
pub struct ViscoDerivatives {
    /// Whether the element is viscoelastic.
    pub active: bool,
    /// N at [g * points + s]: time point g, axial point s.
    pub force: Vec<f64>,
    /// The internal state at the slab's end at each axial point (the next
    /// step's start): eps1 (and Syrope's Tmax), point after point.
    pub end: Vec<f64>,
    /// a_sg at [s * time points + g] (with the Hessian).
    pub a: Vec<[f64; 3]>,
    /// V_sgn at [s * time points + g], n = 0..4 (with the Hessian).
    pub v: Vec<[[f64; 3]; 4]>,
}

/// The largest number of collocation nodes: the slab's time Gauss points
/// and its end.
pub const MAX_NODES: usize = 12;

/// The collocation of (V2) over a slab of length dt (V5): nodes at the
/// slab's time Gauss points tau_1..tau_n and at its end, tau = 1; eps1 is
/// the polynomial of degree n + 1 through eps1(0) whose slope is the rate
/// (V2) at every node,
///
/// ```text
///   Z_i = eps1(0) + dt sum_j A_ij rate(Z_j, eps_j, eps_dot_j),
///   A_ij = int_0^tau_i L_j(s) ds
/// ```
///
/// (L_j the Lagrange basis on the nodes). The last row makes it stiffly
/// accurate: its stability function vanishes at infinity (L-stable) and
/// is at most 1 in modulus on the left half plane (A-stable), so a
/// dashpot's time scale far below dt is followed without oscillation; its
/// order is 2n (the nodes' polynomial is orthogonal to degree n - 2),
/// checked in the tests.
#[derive(Clone, Debug, PartialEq)]
pub struct Collocation {
    /// Nodes (n + 1).
    pub nodes: usize,
    /// dt A, row-major.
    pub dt_a: [[f64; MAX_NODES]; MAX_NODES],
}

impl Collocation {
    /// The collocation on nodes `taus` (in [0, 1], the last 1) over dt.
    pub fn new(taus: &[f64], dt: f64) -> Self {
        let n = taus.len();
        assert!(n <= MAX_NODES, "at most {MAX_NODES} collocation nodes");
        // L_j has degree n - 1: ceil(n / 2) Gauss points integrate it.
        let rule = crate::quadrature::GaussRule::shared(n.div_ceil(2).max(1));
        let lagrange = |j: usize, s: f64| -> f64 {
            (0..n)
                .filter(|&k| k != j)
                .map(|k| (s - taus[k]) / (taus[j] - taus[k]))
                .product()
        };
        let mut dt_a = [[0.0; MAX_NODES]; MAX_NODES];
        for i in 0..n {
            for j in 0..n {
                dt_a[i][j] = dt
                    * rule
                        .iter()
                        .map(|(x, w)| w * taus[i] * lagrange(j, x * taus[i]))
                        .sum::<f64>();
            }
        }
        Collocation { nodes: n, dt_a }
    }
}

/// eps1 at the collocation nodes and the derivatives of the force at the
/// slab's time points (all nodes but the last) in the strains and
/// strain rates at every node.
#[derive(Clone, Debug)]
pub struct CollocatedForce {
    /// eps1 at the nodes (the last: at the slab's end).
    pub state: [f64; MAX_NODES],
    /// The rate eps1_dot at the nodes.
    pub rate: [f64; MAX_NODES],
    /// N at the nodes.
    pub force: [f64; MAX_NODES],
    /// dN_g / d eps_h and dN_g / d eps_dot_h.
    pub d_eps: [[f64; MAX_NODES]; MAX_NODES],
    pub d_rate: [[f64; MAX_NODES]; MAX_NODES],
}

impl Viscoelastic {
    /// Solves the collocation (V5) from eps1(0) = `start` for the strains
    /// `eps` and rates `eps_dot` at the nodes (Newton: one step for a
    /// constant k2, where the equations are linear), and the derivatives
    /// of the forces by the implicit function theorem,
    ///
    /// ```text
    ///   J = I - dt A diag(d rate / d eps1),
    ///   dZ/d eps = J^-1 dt A diag(d rate / d eps),   (and so for eps_dot)
    ///   dN_g/d eps_h = dN_g/d eps1 dZ_g/d eps_h + delta_gh dN_g/d eps.
    /// ```
    ///
    /// `slack[i]`: no compression and eps < 0 at node i; `history`:
    /// Syrope's Tmax at the slab's start, held over it (its new value,
    /// [`Self::history_after`], is taken at the end).
    pub fn collocate(
        &self,
        ea: f64,
        colloc: &Collocation,
        (start, history): (f64, f64),
        eps: &[f64],
        eps_dot: &[f64],
        slack: &[bool],
    ) -> CollocatedForce {
        let n = colloc.nodes;
        let a = &colloc.dt_a;
        let mut z = [start; MAX_NODES];
        let mut f = [ViscoForce::default(); MAX_NODES];
        let mut jac = [[0.0; MAX_NODES]; MAX_NODES];
        for _ in 0..60 {
            for i in 0..n {
                f[i] = self.force(ea, z[i], history, eps[i], eps_dot[i], slack[i]);
            }
            let mut r = [0.0; MAX_NODES];
            for i in 0..n {
                r[i] = -(z[i] - start - (0..n).map(|j| a[i][j] * f[j].rate).sum::<f64>());
                for j in 0..n {
                    jac[i][j] = f64::from(u8::from(i == j)) - a[i][j] * f[j].rate_d[0];
                }
            }
            let dz = solve_small(n, &jac, &r);
            let mut size = 0.0f64;
            for i in 0..n {
                z[i] += dz[i];
                size = size.max(dz[i].abs() / (z[i].abs() + eps[i].abs() + 1e-300));
            }
            if size <= 1e-14 {
                break;
            }
        }
        for i in 0..n {
            f[i] = self.force(ea, z[i], history, eps[i], eps_dot[i], slack[i]);
            for j in 0..n {
                jac[i][j] = f64::from(u8::from(i == j)) - a[i][j] * f[j].rate_d[0];
            }
        }
        let mut out = CollocatedForce {
            state: z,
            rate: [0.0; MAX_NODES],
            force: [0.0; MAX_NODES],
            d_eps: [[0.0; MAX_NODES]; MAX_NODES],
            d_rate: [[0.0; MAX_NODES]; MAX_NODES],
        };
        // Column h of dZ/d eps: J^-1 (dt A e_h) d rate_h / d eps_h.
        for h in 0..n {
            let col: [f64; MAX_NODES] = std::array::from_fn(|i| a[i][h]);
            let dz = solve_small(n, &jac, &col);
            for g in 0..n {
                out.d_eps[g][h] = f[g].force_d[0] * dz[g] * f[h].rate_d[1];
                out.d_rate[g][h] = f[g].force_d[0] * dz[g] * f[h].rate_d[2];
            }
            out.d_eps[h][h] += f[h].force_d[1];
            out.d_rate[h][h] += f[h].force_d[2];
        }
        for i in 0..n {
            out.rate[i] = f[i].rate;
            out.force[i] = f[i].force;
        }
        out
    }
}

/// Solves the n x n system `m x = b` by Gaussian elimination with partial
/// pivoting (n at most [`MAX_NODES`]).
pub(super) fn solve_small(
    n: usize,
    m: &[[f64; MAX_NODES]; MAX_NODES],
    b: &[f64; MAX_NODES],
) -> [f64; MAX_NODES] {
    let mut a = *m;
    let mut x = *b;
    for c in 0..n {
        let p = (c..n)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap_or(c);
        a.swap(c, p);
        x.swap(c, p);
        for r in c + 1..n {
            let f = a[r][c] / a[c][c];
            if f != 0.0 {
                for k in c..n {
                    a[r][k] -= f * a[c][k];
                }
                x[r] -= f * x[c];
            }
        }
    }
    for c in (0..n).rev() {
        let s: f64 = (c + 1..n).map(|k| a[c][k] * x[k]).sum();
        x[c] = (x[c] - s) / a[c][c];
    }
    x
}

#[cfg(test)]
#[path = "viscoelastic_tests.rs"]
mod tests;
