//! Rotations over a step as a rotation vector from the step's start
//! (docs/method.md §15.4): R(t) = R_a exp([theta(t)]), theta(0) = 0, and
//! the angular velocity in body axes
//!
//! ```text
//!   Omega = J_r(theta) theta_dot,
//!   J_r(theta) = I - f_1(s) [theta] + f_2(s) [theta]^2,   s = |theta|^2           (B3)
//!   f_0(s) = sin x / x,  f_1(s) = (1 - cos x) / x^2,  f_2(s) = (x - sin x) / x^3,  x = sqrt(s)
//!   exp([theta]) = I + f_0(s) [theta] + f_1(s) [theta]^2                          (B4)
//! ```
//!
//! The f_k are entire functions of s = |theta|^2,
//! `f_k(s) = sum_j (-1)^j s^j / (2 j + k + 1)!`, so they and their
//! derivatives are evaluated by their series, smooth through theta = 0
//! (where sqrt is not), for every rotation a step may take (|theta| <= pi).

use super::jet::{cross, Jet, JetVec};

/// Terms of the series: at |theta| = pi the last one is below 1e-30 of
/// the first.
const TERMS: usize = 24;

/// f_k(s) and its first two derivatives in s (B3)-(B4): the sums of
/// `c_j s^j`, `c_j j s^(j-1)` and `c_j j (j-1) s^(j-2)`,
/// `c_j = (-1)^j / (2 j + k + 1)!`.
pub fn series(k: usize, s: f64) -> (f64, f64, f64) {
    let (mut f, mut df, mut d2f) = (0.0, 0.0, 0.0);
    let mut c = 1.0 / (1..=k + 1).map(|i| i as f64).product::<f64>();
    // s^j, s^(j-1) and s^(j-2) as the sum goes (0 before their first
    // term, where j or j (j - 1) is 0 too).
    let (mut p0, mut p1, mut p2) = (1.0, 0.0, 0.0);
    for j in 0..TERMS {
        let jf = j as f64;
        f += c * p0;
        df += c * jf * p1;
        d2f += c * jf * (jf - 1.0) * p2;
        (p2, p1, p0) = (p1, p0, p0 * s);
        c /= -(((2 * j + k + 2) * (2 * j + k + 3)) as f64);
    }
    (f, df, d2f)
}

/// f_k(s) on a jet.
fn series_jet<const N: usize, const H: usize>(k: usize, s: Jet<N, H>) -> Jet<N, H> {
    let (f, df, d2f) = series(k, s.v);
    s.compose(f, df, d2f)
}

/// (B3): the angular velocity in body axes of R_a exp([theta]) moving
/// at theta_dot, on jets.
pub fn body_rate<const N: usize, const H: usize>(
    theta: &JetVec<N, H>,
    theta_dot: &JetVec<N, H>,
) -> JetVec<N, H> {
    let s = super::jet::dot(theta, theta);
    let f1 = series_jet(1, s);
    let f2 = series_jet(2, s);
    let t_x_td = cross(theta, theta_dot);
    let t_x_t_x_td = cross(theta, &t_x_td);
    std::array::from_fn(|i| theta_dot[i] - f1 * t_x_td[i] + f2 * t_x_t_x_td[i])
}

/// exp([theta]) v (sign +1) or exp([theta])^T v (sign -1), (B4), on jets.
pub fn turn<const N: usize, const H: usize>(
    theta: &JetVec<N, H>,
    v: &JetVec<N, H>,
    sign: f64,
) -> JetVec<N, H> {
    let s = super::jet::dot(theta, theta);
    let (f0, f1) = (series_jet(0, s), series_jet(1, s));
    let t_x_v = cross(theta, v);
    let t_x_t_x_v = cross(theta, &t_x_v);
    std::array::from_fn(|i| v[i] + (f0 * t_x_v[i]).scale(sign) + f1 * t_x_t_x_v[i])
}

/// A x with a constant 3 x 3 matrix, on jets.
pub fn times<const N: usize, const H: usize>(a: &[[f64; 3]; 3], x: &JetVec<N, H>) -> JetVec<N, H> {
    std::array::from_fn(|r| x[0].scale(a[r][0]) + x[1].scale(a[r][1]) + x[2].scale(a[r][2]))
}

/// [v], the cross-product matrix.
fn hat(v: [f64; 3]) -> [[f64; 3]; 3] {
    [[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]]
}

fn combine(a: f64, b: f64, theta: [f64; 3]) -> [[f64; 3]; 3] {
    let h = hat(theta);
    let h2 = crate::vec3::mat3_mul(&h, &h);
    std::array::from_fn(|r| {
        std::array::from_fn(|c| if r == c { 1.0 } else { 0.0 } + a * h[r][c] + b * h2[r][c])
    })
}

/// (B4): exp([theta]).
pub fn exp_map(theta: [f64; 3]) -> [[f64; 3]; 3] {
    let s = crate::vec3::dot(theta, theta);
    combine(series(0, s).0, series(1, s).0, theta)
}

/// The rotation vector theta of `r` (|theta| <= pi): exp([theta]) = r,
/// the inverse of [`exp_map`]. Near pi the axis comes from r + I = 2 a
/// a^T (the sine vanishes there).
pub fn log_map(r: &[[f64; 3]; 3]) -> [f64; 3] {
    let cos = ((r[0][0] + r[1][1] + r[2][2] - 1.0) / 2.0).clamp(-1.0, 1.0);
    let angle = cos.acos();
    let skew = [r[2][1] - r[1][2], r[0][2] - r[2][0], r[1][0] - r[0][1]];
    if angle < 1e-4 {
        // theta = vee(R - R^T) / 2 * angle / sin(angle), the ratio's series.
        let ratio = 1.0 + angle * angle / 6.0;
        return skew.map(|c| 0.5 * ratio * c);
    }
    if std::f64::consts::PI - angle > 1e-4 {
        return skew.map(|c| 0.5 * angle / angle.sin() * c);
    }
    // R + R^T - 2 cos I = 2 (1 - cos) a a^T: its row of the largest
    // diagonal entry is along the axis; the sense from the skew part.
    let k = (0..3)
        .max_by(|&a, &b| r[a][a].total_cmp(&r[b][b]))
        .expect("3");
    let mut axis: [f64; 3] =
        std::array::from_fn(|j| r[k][j] + r[j][k] - if j == k { 2.0 * cos } else { 0.0 });
    let n = crate::vec3::norm(axis);
    axis = axis.map(|c| c / n);
    if crate::vec3::dot(axis, skew) < 0.0 {
        axis = axis.map(|c| -c);
    }
    axis.map(|c| angle * c)
}

/// Solves J_r(theta) x = b (B3): the chart's rate theta_dot of a body
/// turning at Omega = b (body axes) at theta.
pub fn chart_rate(theta: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    let a = right_jacobian(theta);
    let det = crate::vec3::dot(a[0], crate::vec3::cross(a[1], a[2]));
    // Cramer's rule on the rows: x_k = det(A with column k = b) / det.
    std::array::from_fn(|k| {
        let mut m = a;
        for (row, &bv) in m.iter_mut().zip(&b) {
            row[k] = bv;
        }
        crate::vec3::dot(m[0], crate::vec3::cross(m[1], m[2])) / det
    })
}

/// J_r(theta) of (B3).
pub fn right_jacobian(theta: [f64; 3]) -> [[f64; 3]; 3] {
    let s = crate::vec3::dot(theta, theta);
    combine(-series(1, s).0, series(2, s).0, theta)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_series_are_the_closed_forms_and_their_derivatives() {
        for &x in &[1e-3, 0.3, 1.0, 2.5, std::f64::consts::PI] {
            let s: f64 = x * x;
            let closed = [
                x.sin() / x,
                (1.0 - x.cos()) / (x * x),
                (x - x.sin()) / (x * x * x),
            ];
            for k in 0..3 {
                let (f, df, d2f) = series(k, s);
                let tol = if x < 0.01 { 1e-9 } else { 1e-14 };
                assert!(
                    (f - closed[k]).abs() < tol,
                    "f_{k}({x}) {f} vs {}",
                    closed[k]
                );
                let h = 1e-4 * s.max(1e-2);
                let (fu, dfu, _) = series(k, s + h);
                let (fd, dfd, _) = series(k, s - h);
                assert!((df - (fu - fd) / (2.0 * h)).abs() < 1e-8, "f_{k}' at {x}");
                assert!(
                    (d2f - (dfu - dfd) / (2.0 * h)).abs() < 1e-7,
                    "f_{k}'' at {x}"
                );
            }
        }
    }

    /// (B3) is R^T R_dot of (B4) along a path theta(t), by central
    /// differences, and exp is a rotation.
    #[test]
    fn the_body_rate_is_the_derivative_of_the_exponential() {
        let path = |t: f64| [0.9 * t, -0.4 + 0.7 * t * t, 1.3 * t.sin()];
        let t = 0.8;
        let h = 1e-6;
        let (up, down) = (exp_map(path(t + h)), exp_map(path(t - h)));
        let r = exp_map(path(t));
        let rt_rdot: [[f64; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|j| {
                (0..3)
                    .map(|k| r[k][i] * (up[k][j] - down[k][j]) / (2.0 * h))
                    .sum()
            })
        });
        let omega_fd = [rt_rdot[2][1], rt_rdot[0][2], rt_rdot[1][0]];
        let theta = path(t);
        let theta_dot = [
            (path(t + h)[0] - path(t - h)[0]) / (2.0 * h),
            1.4 * t,
            1.3 * t.cos(),
        ];
        let jr = right_jacobian(theta);
        let omega: [f64; 3] =
            std::array::from_fn(|i| (0..3).map(|k| jr[i][k] * theta_dot[k]).sum());
        for i in 0..3 {
            assert!(
                (omega[i] - omega_fd[i]).abs() < 1e-8,
                "{omega:?} vs {omega_fd:?}"
            );
        }
        let jets: JetVec<1> = theta.map(Jet::constant);
        let jet_rates: JetVec<1> = theta_dot.map(Jet::constant);
        let rate = body_rate(&jets, &jet_rates);
        for i in 0..3 {
            assert!((rate[i].v - omega[i]).abs() < 1e-14);
        }
        let rrt = crate::vec3::mat3_mul(&r, &crate::vec3::mat3_transpose(&r));
        for i in 0..3 {
            for j in 0..3 {
                let e = if i == j { 1.0 } else { 0.0 };
                assert!((rrt[i][j] - e).abs() < 1e-15);
            }
        }
    }

    /// The log map undoes the exponential, from small angles to pi, and
    /// the chart's rate gives back the body rate it solves for.
    #[test]
    fn the_log_map_undoes_the_exponential_and_chart_rates_invert_j_r() {
        let axis = crate::vec3::normalized([0.3, -0.8, 0.5]);
        for angle in [0.0, 1e-9, 3e-5, 0.4, 2.0, 3.0, std::f64::consts::PI - 1e-7] {
            let theta = axis.map(|c| angle * c);
            let back = log_map(&exp_map(theta));
            for k in 0..3 {
                assert!(
                    (back[k] - theta[k]).abs() < 2e-8,
                    "{angle}: {back:?} {theta:?}"
                );
            }
        }
        let theta = [0.4, -0.9, 1.3];
        let omega = [0.7, 0.2, -1.1];
        let rate = chart_rate(theta, omega);
        let jr = right_jacobian(theta);
        for r in 0..3 {
            let got: f64 = (0..3).map(|k| jr[r][k] * rate[k]).sum();
            assert!((got - omega[r]).abs() < 1e-14, "{got} {}", omega[r]);
        }
    }
}
