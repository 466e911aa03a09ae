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

/// The rotation (body axes to global) of a platform at OpenFAST's roll,
/// pitch and yaw (phi, theta, psi, rad): the transpose of the direction
/// cosine matrix `EulerConstructZYX` that OpenFAST's MoorDyn-F (v4.0 on)
/// builds from a driver's initial platform angles,
///
/// ```text
///   R = R_z(psi) R_y(theta) R_x(phi)                                    (D2)
/// ```
///
/// (yaw, then pitch, then roll about the turned axes; the same single-axis
/// rotations as MoorDyn's body angles, [`rotation_from_moordyn_angles`],
/// composed in the other order). It is exact at any angle (OpenFAST v3's
/// small-angle `SmllRotTrans` it replaced turned by atan(theta)).
pub fn openfast_platform_rotation(roll_pitch_yaw: [f64; 3]) -> [[f64; 3]; 3] {
    let [phi, theta, psi] = roll_pitch_yaw.map(f64::to_degrees);
    let about = |k: usize, angle: f64| {
        let mut a = [0.0; 3];
        a[k] = angle;
        rotation_from_moordyn_angles(a)
    };
    mat3_mul(&mat3_mul(&about(2, psi), &about(1, theta)), &about(0, phi))
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

    /// (D2): roll, pitch and yaw each turn as MoorDyn's angles do, and
    /// together as yaw of the pitched and rolled platform: a point on the
    /// platform's x axis, pitched 30 deg (bow down) and yawed 90 deg, lies
    /// along +y, 30 deg down, whatever the roll; to first order R is
    /// I + [theta]x.
    #[test]
    fn openfasts_platform_rotation_is_yaw_of_the_pitched_and_rolled_platform() {
        let (p, y) = (30f64.to_radians(), 90f64.to_radians());
        for roll in [0.0, 0.4, -1.0] {
            let r = openfast_platform_rotation([roll, p, y]);
            let bow = rotate(&r, [1.0, 0.0, 0.0]);
            let want = [0.0, p.cos(), -p.sin()];
            for k in 0..3 {
                assert!((bow[k] - want[k]).abs() < 1e-15, "{roll}: {bow:?}");
            }
        }
        let small = openfast_platform_rotation([1e-6, -2e-6, 3e-6]);
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
