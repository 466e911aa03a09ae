//! The stability limit of the P2 step (method notes, "Stability and
//! accuracy of P2").
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
//! matrix of the actual mesh, by Lanczos iteration.

use crate::assembly::stiffness_and_mass;
use crate::band::BandLu;
use crate::element::TimeSlab;
use crate::model::Model;
use crate::quadrature::GaussRule;

/// The P2 step (with `layers` layers of equal length) applied to
/// x'' + w^2 x = 0 as the 2x2 map (x_a, v_a) -> (x_b, v_b), for W = w dt.
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
/// stable up to W = 50.
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
    // Number of eigenvalues below s.
    let count_below = |s: f64| {
        let mut c = 0;
        let mut d = 1.0;
        for i in 0..n {
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
    };
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if count_below(mid) >= n {
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

/// Highest angular frequency w_max of the mesh linearized at coordinates
/// `e`: the square root of the largest eigenvalue of K phi = lambda M phi,
/// K the tangent of the strain energy, M the consistent mass. Lanczos in
/// the M inner product with full reorthogonalization (exact when the
/// iteration count reaches the dimension).
pub fn highest_frequency(model: &Model, e: &[f64]) -> f64 {
    let n = model.dofs();
    let dpn = model.dofs_per_node();
    let bw = 2 * dpn - 1;
    let (k, m) = stiffness_and_mass(model, e);
    let mut m_lu = BandLu::new(n, bw, bw);
    *m_lu.matrix_mut() = m.clone();
    if m_lu.factorize().is_err() {
        return f64::NAN;
    }
    let steps = n.min(120);
    let mut basis: Vec<Vec<f64>> = Vec::with_capacity(steps + 1);
    let mut alpha = Vec::with_capacity(steps);
    let mut beta = Vec::with_capacity(steps);
    // Deterministic start vector with every mode present.
    let mut q: Vec<f64> = (0..n)
        .map(|i| 1.0 + ((i * 7919) % 97) as f64 / 97.0)
        .collect();
    let mut mq = vec![0.0; n];
    let mut w = vec![0.0; n];
    let m_norm = |x: &[f64], mx: &mut [f64]| {
        m.mul_vec(x, mx);
        x.iter()
            .zip(mx.iter())
            .map(|(a, b)| a * b)
            .sum::<f64>()
            .sqrt()
    };
    let s = m_norm(&q, &mut mq);
    q.iter_mut().for_each(|v| *v /= s);
    for it in 0..steps {
        // w = M^-1 K q
        k.mul_vec(&q, &mut w);
        let a: f64 = q.iter().zip(w.iter()).map(|(x, y)| x * y).sum();
        m_lu.solve(&mut w);
        alpha.push(a);
        basis.push(q.clone());
        // Full reorthogonalization against all basis vectors (twice).
        for _ in 0..2 {
            m.mul_vec(&w, &mut mq);
            for b in &basis {
                let c: f64 = b.iter().zip(mq.iter()).map(|(x, y)| x * y).sum();
                w.iter_mut()
                    .zip(b.iter())
                    .for_each(|(wi, bi)| *wi -= c * bi);
            }
        }
        let bnorm = m_norm(&w, &mut mq);
        if it + 1 == steps || bnorm <= 1e-12 * a.abs().max(1e-300) {
            break;
        }
        beta.push(bnorm);
        q.iter_mut()
            .zip(w.iter())
            .for_each(|(qi, wi)| *qi = wi / bnorm);
    }
    beta.truncate(alpha.len().saturating_sub(1));
    tridiagonal_max_eigenvalue(&alpha, &beta).max(0.0).sqrt()
}

/// Largest stable P2 step of the model at coordinates `e` for this time
/// quadrature and number of layers per step, or None if the oscillator
/// shows no limit.
pub fn stable_step(model: &Model, e: &[f64], time_rule: &GaussRule, layers: usize) -> Option<f64> {
    let w_max = highest_frequency(model, e);
    p2_critical_w_dt(time_rule, layers).map(|wc| wc / w_max)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The method notes' closed form for one layer, 3 Gauss points:
    /// det = 1, trace = 2 (3 W^4 - 104 W^2 + 240) / (W^4 + 16 W^2 + 240).
    #[test]
    fn amplification_matches_the_closed_form() {
        let rule = GaussRule::new(3).unwrap();
        for &w in &[0.1, 1.0, 2.5, 3.3, 7.0, 10.0] {
            let a = p2_amplification(w, &rule, 1);
            let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
            let tr = a[0][0] + a[1][1];
            let w2 = w * w;
            let w4 = w2 * w2;
            let expect = 2.0 * (3.0 * w4 - 104.0 * w2 + 240.0) / (w4 + 16.0 * w2 + 240.0);
            assert!((det - 1.0).abs() < 1e-12, "W={w}: det {det}");
            assert!((tr - expect).abs() < 1e-12, "W={w}: trace {tr} vs {expect}");
        }
        // Spectral radius 3 at W = 10 (method notes).
        let r = spectral_radius_2x2(&p2_amplification(10.0, &rule, 1));
        assert!((r - 3.0).abs() < 0.05, "{r}");
    }

    /// W_crit = sqrt(10) for one layer and 3 points; about pi / n per
    /// layer with n layers, i.e. about pi for the whole step (method notes:
    /// 1.571 per layer for 2 layers, 1.048 for 3).
    #[test]
    fn critical_products() {
        let rule = GaussRule::new(3).unwrap();
        let w1 = p2_critical_w_dt(&rule, 1).unwrap();
        assert!((w1 - 10f64.sqrt()).abs() < 1e-9, "{w1}");
        let w2 = p2_critical_w_dt(&rule, 2).unwrap();
        assert!((w2 / 2.0 - 1.571).abs() < 1e-3, "{w2}");
        let w3 = p2_critical_w_dt(&rule, 3).unwrap();
        assert!((w3 / 3.0 - 1.048).abs() < 1e-3, "{w3}");
    }

    /// x'' + x = 0, x(0) = 1, to t = 1 with steps of 1/8: the errors the
    /// issue quotes (one layer 1.4e-7, two layers 5.9e-9, one layer at
    /// 1/16 8.9e-9).
    #[test]
    fn oscillator_errors_with_layers() {
        let rule = GaussRule::new(3).unwrap();
        let err = |dt: f64, layers: usize| {
            let a = p2_amplification(dt, &rule, layers);
            let (mut x, mut v) = (1.0, 0.0);
            for _ in 0..(1.0 / dt).round() as usize {
                let nx = a[0][0] * x + a[0][1] * v;
                let nv = a[1][0] * x + a[1][1] * v;
                x = nx;
                v = nv;
            }
            (x - 1f64.cos()).abs()
        };
        let e1 = err(0.125, 1);
        let e2 = err(0.125, 2);
        let e3 = err(0.0625, 1);
        assert!((e1 / 1.4255e-7 - 1.0).abs() < 1e-3, "{e1:e}");
        assert!((e2 / 5.9405e-9 - 1.0).abs() < 1e-3, "{e2:e}");
        assert!((e3 / 8.9147e-9 - 1.0).abs() < 1e-3, "{e3:e}");
    }
}
