//! Axial strain of the centre line, eq. (8), and the axial energy density
//! `1/2 EA eps^2` with its gradient and Hessian with respect to r_x
//! (docs/method.md §2.2, (M3)-(M4); the first term of eq. (12), §2.4).
//! Green strain is the paper's; engineering strain is as in Exudyn and
//! MoorDyn.

use super::AxialStrain;
use crate::vec3::dot;

/// Axial strain and its first two derivatives with respect to r_x.
pub fn axial_strain(measure: AxialStrain, rx: &[f64; 3]) -> f64 {
    let g = dot(rx, rx);
    match measure {
        AxialStrain::Green => 0.5 * (g - 1.0),
        AxialStrain::Engineering => g.sqrt() - 1.0,
    }
}

/// Axial energy density `1/2 EA eps^2` (eq. 12, first term), its gradient
/// and Hessian with respect to r_x (docs/method.md §2.2, (M3)-(M4)).
///
/// ```text
///   Green:        dU/dr_x = EA eps r_x,      d2U = EA (r_x r_x^T + eps I)
///   engineering:  dU/dr_x = EA eps n,        d2U = EA (n n^T + eps (I - n n^T) / |r_x|),
///                 n = r_x / |r_x|
/// ```
pub fn axial_energy_density(
    measure: AxialStrain,
    ea: f64,
    rx: &[f64; 3],
) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    axial_energy_terms(measure, ea, rx, true, false)
}

/// [`axial_energy_density`] without the Hessian (a residual evaluation).
#[inline]
pub fn axial_energy_gradient(measure: AxialStrain, ea: f64, rx: &[f64; 3]) -> (f64, [f64; 3]) {
    let (e, g, _) = axial_energy_terms(measure, ea, rx, false, false);
    (e, g)
}

/// [`axial_energy_density`] of a line without compression (M4a): zero
/// energy, force and stiffness where eps < 0. The energy is C1: the
/// force falls continuously to zero as the line goes slack, and the
/// stiffness steps from EA to 0 there (a blend would either leave a
/// residual compression or shift the tension of a stretched line).
pub fn tension_only_energy_density(
    measure: AxialStrain,
    ea: f64,
    rx: &[f64; 3],
) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    axial_energy_terms(measure, ea, rx, true, true)
}

#[inline(always)]
pub(super) fn axial_energy_terms(
    measure: AxialStrain,
    ea: f64,
    rx: &[f64; 3],
    with_hessian: bool,
    tension_only: bool,
) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    if tension_only && axial_strain(measure, rx) < 0.0 {
        return (0.0, [0.0; 3], [[0.0; 3]; 3]);
    }
    let g = dot(rx, rx);
    let mut grad = [0.0; 3];
    let mut hess = [[0.0; 3]; 3];
    match measure {
        AxialStrain::Green => {
            let eps = 0.5 * (g - 1.0);
            for i in 0..3 {
                grad[i] = ea * eps * rx[i];
            }
            if with_hessian {
                for i in 0..3 {
                    for j in 0..3 {
                        hess[i][j] = ea * rx[i] * rx[j];
                    }
                    hess[i][i] += ea * eps;
                }
            }
            (0.5 * ea * eps * eps, grad, hess)
        }
        AxialStrain::Engineering => {
            let len = g.sqrt();
            let eps = len - 1.0;
            let n = [rx[0] / len, rx[1] / len, rx[2] / len];
            let c = eps / len;
            for i in 0..3 {
                grad[i] = ea * eps * n[i];
            }
            if with_hessian {
                for i in 0..3 {
                    for j in 0..3 {
                        hess[i][j] = ea * (1.0 - c) * n[i] * n[j];
                    }
                    hess[i][i] += ea * c;
                }
            }
            (0.5 * ea * eps * eps, grad, hess)
        }
    }
}

/// The axial strain's first and second derivatives with respect to r_x,
/// `a = d eps / d r_x` and `H = d2 eps / d r_x2` (symmetric), for the
/// strain rate `eps_dot = a . r_x_dot` of the axial damping
/// (docs/method.md §2.10, (M34)):
///
/// ```text
///   Green:        a = r_x,   H = I
///   engineering:  a = n,     H = (I - n n^T) / |r_x|,    n = r_x / |r_x|
/// ```
#[inline]
pub fn axial_strain_derivatives(measure: AxialStrain, rx: &[f64; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    match measure {
        AxialStrain::Green => {
            let mut h = [[0.0; 3]; 3];
            for (i, row) in h.iter_mut().enumerate() {
                row[i] = 1.0;
            }
            (*rx, h)
        }
        AxialStrain::Engineering => {
            let len = dot(rx, rx).sqrt();
            let n = rx.map(|c| c / len);
            let mut h = [[0.0; 3]; 3];
            for i in 0..3 {
                for j in 0..3 {
                    h[i][j] = -n[i] * n[j] / len;
                }
                h[i][i] += 1.0 / len;
            }
            (n, h)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Stretched, a line without compression has the elastic energy of
    /// (M3)-(M4); shortened, none: energy, force and stiffness zero.
    #[test]
    fn a_line_without_compression_is_elastic_stretched_and_slack_shortened() {
        for measure in [AxialStrain::Green, AxialStrain::Engineering] {
            let stretched = [0.9, 0.5, 0.2];
            assert_eq!(
                tension_only_energy_density(measure, 3.0, &stretched),
                axial_energy_density(measure, 3.0, &stretched)
            );
            let shortened = [0.7, 0.3, -0.2];
            assert!(axial_strain(measure, &shortened) < 0.0);
            let (e, g, h) = tension_only_energy_density(measure, 3.0, &shortened);
            assert_eq!((e, g, h), (0.0, [0.0; 3], [[0.0; 3]; 3]));
            // The force falls continuously to zero at eps = 0.
            let len = (stretched.iter().map(|c| c * c).sum::<f64>()).sqrt();
            let unit = stretched.map(|c| c / len * (1.0 + 1e-9));
            let (_, g0, _) = tension_only_energy_density(measure, 3.0, &unit);
            assert!(g0.iter().all(|c| c.abs() < 1e-8), "{g0:?}");
        }
    }
}
