//! A rigid body's pose (docs/method.md §15.1): the position of a point of
//! it and its rotation R (body axes to global), a body-fixed point xi
//! being at `x = r + R xi`; MoorDyn's angles.

use crate::vec3::{add, mat3_mul};

/// A body's pose: its reference point and its rotation (body axes to
/// global).
pub type Pose = ([f64; 3], [[f64; 3]; 3]);

/// `R v`.
pub fn rotate(r: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| (0..3).map(|k| r[i][k] * v[k]).sum())
}

/// `R^T v`: a global vector in body axes.
pub fn rotate_back(r: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| (0..3).map(|k| r[k][i] * v[k]).sum())
}

/// The global position `r + R xi` of the body point xi.
pub fn point(position: [f64; 3], r: &[[f64; 3]; 3], xi: [f64; 3]) -> [f64; 3] {
    add(position, rotate(r, xi))
}

/// MoorDyn's rotation of a body from its roll, pitch and yaw in degrees
/// (BODIES columns r0, p0, y0): `R = R_x(roll) R_y(pitch) R_z(yaw)`, the
/// intrinsic x-y'-z'' sequence (MoorDyn `Euler2Quat`): +roll lifts the +y
/// side, +pitch puts +x down, +yaw turns +x toward +y.
pub fn rotation_from_moordyn_angles(roll_pitch_yaw_deg: [f64; 3]) -> [[f64; 3]; 3] {
    let [r, p, y] = roll_pitch_yaw_deg.map(f64::to_radians);
    let (sr, cr) = r.sin_cos();
    let (sp, cp) = p.sin_cos();
    let (sy, cy) = y.sin_cos();
    let rx = [[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]];
    let ry = [[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]];
    let rz = [[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]];
    mat3_mul(&mat3_mul(&rx, &ry), &rz)
}

/// The roll, pitch and yaw (degrees) of MoorDyn's convention
/// ([`rotation_from_moordyn_angles`]) of R, pitch in [-90, 90]:
/// `R[0][2] = sin(pitch)`, `R[1][2] / R[2][2] = -tan(roll)`,
/// `R[0][1] / R[0][0] = -tan(yaw)`.
pub fn moordyn_angles(r: &[[f64; 3]; 3]) -> [f64; 3] {
    let pitch = r[0][2].clamp(-1.0, 1.0).asin();
    let roll = (-r[1][2]).atan2(r[2][2]);
    let yaw = (-r[0][1]).atan2(r[0][0]);
    [roll, pitch, yaw].map(f64::to_degrees)
}

/// The rotation (body axes to global) of a platform turned by the small
/// angles theta = (theta_1, theta_2, theta_3) (rad, about global x, y, z)
/// as OpenFAST places it: the transpose of its `SmllRotTrans`, the
/// orthonormal matrix nearest the linearised transformation I - [theta]x
/// (global to body axes), which with S = |theta|^2 and Q = sqrt(1 + S) is
///
/// ```text
///   T_ii = (theta_i^2 Q + S - theta_i^2) / (S Q)
///   T_ij = (e_ijk theta_k S + theta_i theta_j (Q - 1)) / (S Q)   (i != j)   (D2)
/// ```
///
/// (e_ijk the permutation symbol; T = I at theta = 0). About one axis it
/// is the rotation by atan(theta), not theta: OpenFAST's small-angle
/// convention, which MoorDyn-F's MD_Init applies to a driver's initial
/// platform offsets (docs/method.md §13.7).
pub fn openfast_small_rotation(theta: [f64; 3]) -> [[f64; 3]; 3] {
    let s: f64 = theta.iter().map(|t| t * t).sum();
    if s == 0.0 {
        return [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    }
    let q = (1.0 + s).sqrt();
    let denominator = s * q;
    // T (global to body); its transpose is returned.
    let t: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            if i == j {
                (theta[i] * theta[i] * q + s - theta[i] * theta[i]) / denominator
            } else {
                let k = 3 - i - j;
                let sign = if (j + 3 - i) % 3 == 1 { 1.0 } else { -1.0 };
                (sign * theta[k] * s + theta[i] * theta[j] * (q - 1.0)) / denominator
            }
        })
    });
    crate::vec3::mat3_transpose(&t)
}

/// R brought back to a rotation by one step of the polar decomposition's
/// Newton iteration, `R (3 I - R^T R) / 2`: an R off orthonormal by e
/// (round-off of a product of steps) comes back to e^2.
pub fn reorthonormalized(r: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let rtr = mat3_mul(&crate::vec3::mat3_transpose(r), r);
    let c: [[f64; 3]; 3] = std::array::from_fn(|i| {
        std::array::from_fn(|j| 0.5 * (if i == j { 3.0 } else { 0.0 } - rtr[i][j]))
    });
    mat3_mul(r, &c)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// (D2) about one axis is the rotation by atan(theta) about it, in
    /// MoorDyn's sense (+pitch puts +x down); about all three it is a
    /// rotation (orthonormal, det 1) that is I + [theta]x to first order.
    #[test]
    fn openfasts_small_rotation_is_a_rotation_by_atan_of_each_angle() {
        for (axis, angles) in [
            (0, [0.3, 0.0, 0.0]),
            (1, [0.0, 0.3, 0.0]),
            (2, [0.0, 0.0, 0.3]),
        ] {
            let mut deg = [0.0; 3];
            deg[axis] = 0.3f64.atan().to_degrees();
            let exact = rotation_from_moordyn_angles(deg);
            let r = openfast_small_rotation(angles);
            for i in 0..3 {
                for j in 0..3 {
                    assert!(
                        (r[i][j] - exact[i][j]).abs() < 1e-15,
                        "{axis}: {r:?} {exact:?}"
                    );
                }
            }
        }
        let theta = [0.05, -0.12, 0.3];
        let r = openfast_small_rotation(theta);
        let rtr = mat3_mul(&crate::vec3::mat3_transpose(&r), &r);
        for i in 0..3 {
            for j in 0..3 {
                let delta = if i == j { 1.0 } else { 0.0 };
                assert!((rtr[i][j] - delta).abs() < 1e-15, "{rtr:?}");
            }
        }
        let small = openfast_small_rotation([1e-6, -2e-6, 3e-6]);
        let linear = [[1.0, -3e-6, -2e-6], [3e-6, 1.0, -1e-6], [2e-6, 1e-6, 1.0]];
        for i in 0..3 {
            for j in 0..3 {
                assert!((small[i][j] - linear[i][j]).abs() < 1e-11, "{small:?}");
            }
        }
    }

    /// MoorDyn's documented signs (its test_rotations.py): +roll lifts
    /// the +y side, +pitch puts the bow (+x) down, +yaw turns it to +y;
    /// and the angles come back from the rotation.
    #[test]
    fn moordyn_angles_turn_the_way_moordyn_documents_and_come_back() {
        let roll = rotation_from_moordyn_angles([30.0, 0.0, 0.0]);
        assert!(roll[2][1] > 0.4, "+y side up: {roll:?}");
        let pitch = rotation_from_moordyn_angles([0.0, 30.0, 0.0]);
        assert!(pitch[2][0] < -0.4, "+x down: {pitch:?}");
        let yaw = rotation_from_moordyn_angles([0.0, 0.0, 30.0]);
        assert!(yaw[1][0] > 0.4, "+x to +y: {yaw:?}");
        let angles = [12.0, -35.0, 160.0];
        let back = moordyn_angles(&rotation_from_moordyn_angles(angles));
        for k in 0..3 {
            assert!((back[k] - angles[k]).abs() < 1e-12, "{back:?}");
        }
    }
}
