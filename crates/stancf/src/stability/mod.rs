//! The stability limit of the P2 step (docs/method.md §4.5-4.6,
//! (M20)-(M21); the Galerkin step's accurate range, §5.3).
//!
//! P2 is conditionally stable: on x'' + w^2 x = 0 its amplification matrix
//! has eigenvalues of modulus 1 only while W = w dt stays below a critical
//! value that depends on the time quadrature and the number of layers
//! (sqrt(10) with 3 Gauss points and one layer). The step of a cable is
//! bounded by its highest frequency w_max, so
//!
//! ```text
//!   stable_step = W_crit / w_max
//! ```
//!
//! Both factors are computed here from the same code the solver runs:
//! W_crit from the scheme applied to the oscillator (the time basis, the
//! quadrature and the layer assembly of [`crate::assembly`]), and w_max as
//! the largest generalized eigenvalue of the tangent stiffness and the mass
//! matrix of the actual mesh, by Lanczos iteration (work and memory linear
//! in the mesh). The Galerkin step has no stability limit, but a range of
//! w_max dt beyond which its results are not meaningful
//! ([`GALERKIN_ACCURATE_W_DT`]).

use crate::band::BandLu;
use crate::element::TimeSlab;
use crate::model::{coordinate, Model, SLOT_R};
use crate::quadrature::GaussRule;

/// The P2 step (with `layers` layers of equal length) applied to
/// x'' + w^2 x = 0 as the 2x2 map (x_a, v_a) -> (x_b, v_b), for W = w dt
/// (docs/method.md §4.5, (M20)).
pub fn p2_amplification(w_dt: f64, rule: &GaussRule, layers: usize) -> [[f64; 2]; 2] {
    // Time scaled so that w = 1 and dt = W.
    let h = w_dt / layers as f64;
    let slab = TimeSlab::new(h, rule);
    // Hessian of the layer action 1/2 int (xdot^2 - x^2) dt in y = [x0, v0, x1, v1].
    let mut hl = [[0.0; 4]; 4];
    for p in &slab.points {
        for m in 0..4 {
            for n in 0..4 {
                hl[m][n] +=
                    p.w_dt * (p.shape.t_dot[m] * p.shape.t_dot[n] - p.shape.t[m] * p.shape.t[n]);
            }
        }
    }
    // Global vector z = [x_0, v_0, x_1, v_1, ..., x_L, v_L]; unknowns z[2..].
    let nz = 2 * (layers + 1);
    let mut hg = vec![vec![0.0; nz]; nz];
    for j in 0..layers {
        for m in 0..4 {
            for n in 0..4 {
                hg[2 * j + m][2 * j + n] += hl[m][n];
            }
        }
    }
    let rows: Vec<usize> = std::iter::once(0)
        .chain((1..layers).flat_map(|i| [2 * i, 2 * i + 1]))
        .chain(std::iter::once(2 * layers))
        .collect();
    let nu = nz - 2;
    let mut out = [[0.0; 2]; 2];
    for (col, start) in [(0usize, [1.0, 0.0]), (1, [0.0, 1.0])] {
        let mut lu = BandLu::new(nu, nu, nu);
        let mut b = vec![0.0; nu];
        for (ri, &r) in rows.iter().enumerate() {
            for c in 0..nu {
                lu.matrix_mut().add(ri, c, hg[r][c + 2]);
            }
            b[ri] = -(hg[r][0] * start[0] + hg[r][1] * start[1]);
        }
        // dA/dx_0 + v_0 = 0 and dA/dx_L - v_L = 0 (unit mass).
        b[0] -= start[1];
        lu.matrix_mut().add(nu - 1, nu - 1, -1.0);
        if lu.factorize().is_err() {
            return [[f64::NAN; 2]; 2];
        }
        lu.solve(&mut b);
        out[0][col] = b[nu - 2];
        out[1][col] = b[nu - 1];
    }
    out
}

/// Spectral radius of a real 2x2 matrix.
pub fn spectral_radius_2x2(a: &[[f64; 2]; 2]) -> f64 {
    let tr = a[0][0] + a[1][1];
    let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    let disc = 0.25 * tr * tr - det;
    if disc < 0.0 {
        det.abs().sqrt()
    } else {
        (0.5 * tr).abs() + disc.sqrt()
    }
}

/// The smallest W = w dt at which P2 stops being stable (spectral radius
/// above 1), found by a scan in steps of 0.001 and bisection to 1e-12.
/// With several layers the first unstable band is narrow (about 0.015 wide
/// near W = pi for two layers), hence the fine scan. `None` if it stays
/// stable up to W = 50 (docs/method.md §4.5).
pub fn p2_critical_w_dt(rule: &GaussRule, layers: usize) -> Option<f64> {
    let unstable = |w: f64| spectral_radius_2x2(&p2_amplification(w, rule, layers)) > 1.0 + 1e-9;
    let mut lo = 0.0;
    let mut w = 0.001;
    while w <= 50.0 {
        if unstable(w) {
            let mut hi = w;
            while hi - lo > 1e-12 {
                let mid = 0.5 * (lo + hi);
                if unstable(mid) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return Some(lo);
        }
        lo = w;
        w += 0.001;
    }
    None
}

/// Number of eigenvalues of the symmetric tridiagonal matrix (alpha, beta)
/// below s (Sturm sequence of the LDL^T factors of T - s I).
fn tridiagonal_count_below(alpha: &[f64], beta: &[f64], s: f64) -> usize {
    let mut c = 0;
    let mut d = 1.0;
    for i in 0..alpha.len() {
        let b2 = if i > 0 {
            beta[i - 1] * beta[i - 1]
        } else {
            0.0
        };
        d = alpha[i] - s - if i > 0 { b2 / d } else { 0.0 };
        if d == 0.0 {
            d = -f64::EPSILON * (s.abs() + 1.0);
        }
        if d < 0.0 {
            c += 1;
        }
    }
    c
}

/// Largest eigenvalue of the symmetric tridiagonal matrix (alpha, beta) by
/// Sturm-sequence bisection.
fn tridiagonal_max_eigenvalue(alpha: &[f64], beta: &[f64]) -> f64 {
    let n = alpha.len();
    let mut hi = f64::MIN;
    let mut lo = f64::MAX;
    for i in 0..n {
        let r = if i > 0 { beta[i - 1].abs() } else { 0.0 }
            + if i + 1 < n { beta[i].abs() } else { 0.0 };
        hi = hi.max(alpha[i] + r);
        lo = lo.min(alpha[i] - r);
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if tridiagonal_count_below(alpha, beta, mid) >= n {
            hi = mid;
        } else {
            lo = mid;
        }
        if hi - lo <= 1e-15 * hi.abs().max(lo.abs()) {
            break;
        }
    }
    hi
}

/// |last component| of the unit eigenvector of the tridiagonal T for its
/// largest eigenvalue `theta`: two steps of inverse iteration with the
/// shift sigma just above theta, where T - sigma I is negative definite, so
/// its LDL^T factors need no pivoting.
fn tridiagonal_top_vector_tail(
    alpha: &[f64],
    beta: &[f64],
    theta: f64,
    work: &mut Vec<f64>,
) -> f64 {
    let n = alpha.len();
    let scale = alpha
        .iter()
        .chain(beta.iter())
        .fold(0.0f64, |m, v| m.max(v.abs()));
    let sigma = theta + 1e-10 * scale.max(f64::MIN_POSITIVE);
    // d (the pivots) and the right-hand side / solution x.
    work.clear();
    work.resize(2 * n, 1.0);
    let (d, x) = work.split_at_mut(n);
    d[0] = alpha[0] - sigma;
    for i in 1..n {
        d[i] = alpha[i] - sigma - beta[i - 1] * beta[i - 1] / d[i - 1];
    }
    for _ in 0..2 {
        // (T - sigma I) x_new = x: L D L^T with unit lower L, L(i, i-1) = beta / d.
        for i in 1..n {
            x[i] -= beta[i - 1] / d[i - 1] * x[i - 1];
        }
        for i in 0..n {
            x[i] /= d[i];
        }
        for i in (0..n - 1).rev() {
            x[i] -= beta[i] / d[i] * x[i + 1];
        }
        let norm = x.iter().map(|v| v * v).sum::<f64>().sqrt();
        if !(norm.is_finite() && norm > 0.0) {
            return f64::NAN;
        }
        x.iter_mut().for_each(|v| *v /= norm);
    }
    x[n - 1].abs()
}

/// The consistent mass matrix of the mesh, factorized. Every element's
/// mass acts on x, y and z alike (`CableElement::mass`, M_e = M_s (x) I_3),
/// and a node's coordinates are numbered g = 3 s + c (s the node's scalar
/// coordinate r, r_x[, r_xx], c the direction), so M = M_s (x) I_3 with
/// the scalar mass M_s of vpn = dpn / 3 unknowns per node and half
/// bandwidth 2 vpn - 1. It is factorized as M_s = L L^T (band Cholesky,
/// M_s is symmetric positive definite): a ninth of the rows of M and a
/// third of its band, which is what keeps the memory of the frequency
/// estimate linear in the mesh with a small constant.
struct MassFactor {
    /// Scalar unknowns and half bandwidth.
    size: usize,
    band: usize,
    /// L(i, i - d) at `l[i * (band + 1) + d]`, d = 0..=band.
    l: Vec<f64>,
}

impl MassFactor {
    /// None if M_s is not positive definite (or not finite).
    fn new(model: &Model) -> Option<Self> {
        let vpn = model.element_type().vectors_per_node();
        let size = model.nodes() * vpn;
        let band = 2 * vpn - 1;
        let w = band + 1;
        let mut l = vec![0.0; size * w];
        crate::with_elements!(&model.mesh, els => {
            for (k, el) in els.iter().enumerate() {
                let o = k * vpn;
                for a in 0..el.mass.len() {
                    for b in 0..=a {
                        l[(o + a) * w + a - b] += el.mass[a][b];
                    }
                }
            }
        });
        // In place: row i of A becomes row i of L.
        for i in 0..size {
            for d in (0..=band.min(i)).rev() {
                let j = i - d;
                let mut s = l[i * w + d];
                // sum over k < j with |i - k|, |j - k| <= band of L(i,k) L(j,k)
                for k in i.saturating_sub(band)..j {
                    s -= l[i * w + i - k] * l[j * w + j - k];
                }
                if d == 0 {
                    if !(s > 0.0 && s.is_finite()) {
                        return None;
                    }
                    l[i * w] = s.sqrt();
                } else {
                    l[i * w + d] = s / l[j * w];
                }
            }
        }
        Some(MassFactor { size, band, l })
    }

    /// x <- M^-1 x for a vector of the mesh's coordinates.
    fn solve(&self, x: &mut [f64]) {
        let w = self.band + 1;
        // L y = x, then L^T z = y, for the three directions at once.
        for i in 0..self.size {
            for c in 0..3 {
                let mut s = x[3 * i + c];
                for k in i.saturating_sub(self.band)..i {
                    s -= self.l[i * w + i - k] * x[3 * k + c];
                }
                x[3 * i + c] = s / self.l[i * w];
            }
        }
        for i in (0..self.size).rev() {
            for c in 0..3 {
                let mut s = x[3 * i + c];
                for k in i + 1..(i + self.band + 1).min(self.size) {
                    s -= self.l[k * w + k - i] * x[3 * k + c];
                }
                x[3 * i + c] = s / self.l[i * w];
            }
        }
    }

    /// y = M x = L (L^T x).
    fn multiply(&self, x: &[f64], y: &mut [f64]) {
        let w = self.band + 1;
        for i in 0..self.size {
            for c in 0..3 {
                let mut s = 0.0;
                for k in i..(i + self.band + 1).min(self.size) {
                    s += self.l[k * w + k - i] * x[3 * k + c];
                }
                y[3 * i + c] = s;
            }
        }
        for i in (0..self.size).rev() {
            for c in 0..3 {
                let mut s = 0.0;
                for k in i.saturating_sub(self.band)..=i {
                    s += self.l[i * w + i - k] * y[3 * k + c];
                }
                y[3 * i + c] = s;
            }
        }
    }
}

/// The tangent stiffness K = d2U/de2 of the mesh at coordinates e,
/// symmetric with half bandwidth 2 dpn - 1 (an element couples two nodes),
/// stored as its upper band only.
struct Stiffness {
    band: usize,
    /// K(i, i + d) at `k[i * (band + 1) + d]`.
    k: Vec<f64>,
}

impl Stiffness {
    fn new(model: &Model, e: &[f64]) -> Self {
        let dpn = model.dofs_per_node();
        let band = 2 * dpn - 1;
        let w = band + 1;
        let mut k = vec![0.0; model.dofs() * w];
        crate::with_elements!(&model.mesh, els => add_element_stiffness(els, dpn, e, w, &mut k));
        Stiffness { band, k }
    }

    /// y = K x.
    fn multiply(&self, x: &[f64], y: &mut [f64]) {
        let n = x.len();
        y.fill(0.0);
        for (i, row) in self.k.chunks_exact(self.band + 1).enumerate() {
            let m = self.band.min(n - 1 - i);
            let xi = x[i];
            let (row, xs) = (&row[1..=m], &x[i + 1..=i + m]);
            let mut s = 0.0;
            for ((kij, xj), yj) in row.iter().zip(xs).zip(&mut y[i + 1..=i + m]) {
                s += kij * xj;
                *yj += kij * xi;
            }
            y[i] += self.k[i * (self.band + 1)] * xi + s;
        }
    }
}

fn add_element_stiffness<const NS: usize, const ND: usize>(
    els: &[crate::element::CableElement<NS, ND>],
    dpn: usize,
    e: &[f64],
    w: usize,
    k: &mut [f64],
) {
    let mut grad = [0.0; ND];
    let mut hess = [[0.0; ND]; ND];
    for (j, el) in els.iter().enumerate() {
        let o = coordinate(dpn, j, SLOT_R, 0);
        let q: [f64; ND] = crate::model::gather(e, o);
        match el.instantaneous(&q) {
            Some(stiff) => stiff.strain_energy_derivatives(&q, &mut grad, Some(&mut hess)),
            None => el.strain_energy_derivatives(&q, &mut grad, Some(&mut hess)),
        };
        for a in 0..ND {
            for b in a..ND {
                k[(o + a) * w + b - a] += hess[a][b];
            }
        }
    }
}

/// Lanczos steps at most in [`highest_frequency`].
const LANCZOS_MAX_STEPS: usize = 300;

/// Relative residual of the top Ritz pair at which [`highest_frequency`]
/// stops: the Ritz value is then within (1e-10 theta)^2 / gap of the
/// eigenvalue, round-off for any gap above 1e-3 theta.
const LANCZOS_TOLERANCE: f64 = 1e-10;

/// Highest angular frequency w_max of the mesh linearized at coordinates
/// `e`: the square root of the largest eigenvalue of K phi = lambda M phi,
/// K the tangent of the strain energy, M the consistent mass (constraints
/// ignored: they can only lower it; docs/method.md §4.6).
///
/// Lanczos in the M inner product (Parlett, The Symmetric Eigenvalue
/// Problem, ch. 13), with p = M q carried along so that each step costs one
/// product with K and one solve with M:
///
/// ```text
///   u = K q_j - beta_j p_{j-1},  alpha_j = q_j . u,  u -= alpha_j p_j,
///   r = M^-1 u,  beta_{j+1} = sqrt(r . u),  q_{j+1} = r / beta_{j+1},  p_{j+1} = u / beta_{j+1}
/// ```
///
/// and the largest eigenvalue theta of the tridiagonal (alpha, beta)
/// approximates lambda_max from below. Without reorthogonalization: the
/// largest Ritz value converges all the same, and loss of orthogonality
/// only adds copies of converged Ritz values (Paige), so storage is four
/// vectors and the work per step linear in the mesh. It stops when the
/// residual of the top Ritz pair, beta_{j+1} |y_j| (y the unit eigenvector
/// of the tridiagonal), is below `LANCZOS_TOLERANCE` theta. The top mode of
/// a free cable is an end mode well above the rest of the spectrum (9.548
/// c/l for SAC-2 against about 6.5 c/l for the interior band), so this
/// takes a few tens of steps whatever the mesh.
///
/// NaN if the mass matrix is not positive definite (no finite figures).
pub fn highest_frequency(model: &Model, e: &[f64]) -> f64 {
    let n = model.dofs();
    let Some(mass) = MassFactor::new(model) else {
        return f64::NAN;
    };
    let stiffness = Stiffness::new(model, e);
    let dot = |a: &[f64], b: &[f64]| a.iter().zip(b).map(|(x, y)| x * y).sum::<f64>();
    // Deterministic start vector with every mode present.
    let mut q: Vec<f64> = (0..n)
        .map(|i| 1.0 + ((i * 7919) % 97) as f64 / 97.0)
        .collect();
    let mut p = vec![0.0; n];
    mass.multiply(&q, &mut p);
    let s = dot(&q, &p).sqrt();
    q.iter_mut().for_each(|v| *v /= s);
    p.iter_mut().for_each(|v| *v /= s);
    let mut p_prev = vec![0.0; n];
    let mut u = vec![0.0; n];
    let mut alpha = Vec::new();
    let mut beta: Vec<f64> = Vec::new();
    let mut work = Vec::new();
    let mut theta = 0.0;
    for _ in 0..LANCZOS_MAX_STEPS {
        stiffness.multiply(&q, &mut u);
        let b = beta.last().copied().unwrap_or(0.0);
        let mut a = 0.0;
        for ((ui, pi), qi) in u.iter_mut().zip(&p_prev).zip(&q) {
            *ui -= b * pi;
            a += qi * *ui;
        }
        for ((ui, pi), qi) in u.iter_mut().zip(&p).zip(q.iter_mut()) {
            *ui -= a * pi;
            *qi = *ui;
        }
        alpha.push(a);
        mass.solve(&mut q);
        let b = dot(&q, &u).max(0.0).sqrt();
        theta = tridiagonal_max_eigenvalue(&alpha, &beta);
        if !theta.is_finite() || !b.is_finite() {
            return f64::NAN;
        }
        // An invariant subspace (b = 0) holds its eigenvalues exactly.
        if b <= 1e-14 * theta.abs() {
            break;
        }
        let tail = tridiagonal_top_vector_tail(&alpha, &beta, theta, &mut work);
        if b * tail <= LANCZOS_TOLERANCE * theta.abs() {
            break;
        }
        beta.push(b);
        // q <- r / b, p <- u / b, p_prev <- p.
        std::mem::swap(&mut p_prev, &mut p);
        for ((qi, pi), ui) in q.iter_mut().zip(p.iter_mut()).zip(&u) {
            *qi /= b;
            *pi = ui / b;
        }
    }
    theta.max(0.0).sqrt()
}

/// The largest w_max dt at which the Galerkin step is shown to give a
/// meaningful result: ten times P2's limit (sqrt(10) with one layer and 3
/// Gauss points in time), 10 sqrt(10) = 31.62 (docs/method.md §5.3).
///
/// The Galerkin step is stable at every step (|amplification| = 1) but
/// not accurate at every step. Its own error on the oscillator: the phase
/// it advances per step, 2 arg(1 + z/2 + z^2/10 + z^3/120) at z = i w dt
/// (the (3,3) Pade approximant of e^z), falls behind w dt by 5e-3 of it at
/// w dt = 3, 0.30 at 10 and 0.73 at 31.6, and never exceeds 3 pi: a mode
/// with w dt of tens is carried with a frequency unrelated to its own. The
/// result is still meaningful while such modes carry little energy and
/// couple weakly with the resolved motion, which the tests establish up to
/// this value and no further: the paper's transverse impact at ten times
/// P2's step agrees with P2 at a tenth of P2's step within the Galerkin
/// step's own step-doubling error estimate, energy error 1.5e-2
/// (`transverse_impact_at_ten_times_the_p2_limit`, tests/library/galerkin.rs).
/// Beyond it the examples (impacts, pendulums, with `stancf run`) stop
/// with an energy jump in one step (Newton lands on a spurious solution of
/// the step's equations) erratically from w_max dt = 25 on, almost all by
/// 47 and every one by 95; at 316 (100 times P2's step) in the first one
/// or two steps, the energy up 85 %.
pub const GALERKIN_ACCURATE_W_DT: f64 = 31.622776601683793;

/// The longest Galerkin step with w_max dt within
/// [`GALERKIN_ACCURATE_W_DT`], rounded down to four significant digits
/// (so that the step as printed satisfies it).
pub fn galerkin_accurate_step(w_max: f64) -> f64 {
    let s = GALERKIN_ACCURATE_W_DT / w_max;
    if !(s.is_finite() && s > 0.0) {
        return s;
    }
    let unit = 10f64.powi(s.log10().floor() as i32 - 3);
    let mut digits = (s / unit).floor();
    // With a margin of 1e-12 for the rounding of digits * unit, and of the
    // decimal as printed and read back.
    while digits * unit * w_max > GALERKIN_ACCURATE_W_DT * (1.0 - 1e-12) {
        digits -= 1.0;
    }
    digits * unit
}

/// Largest stable P2 step of the model at coordinates `e` for this time
/// quadrature and number of layers per step, or None if the oscillator
/// shows no limit: W_crit / w_max, (M21) of docs/method.md §4.6.
pub fn stable_step(model: &Model, e: &[f64], time_rule: &GaussRule, layers: usize) -> Option<f64> {
    let w_max = highest_frequency(model, e);
    p2_critical_w_dt(time_rule, layers).map(|wc| wc / w_max)
}

#[cfg(test)]
mod tests;
