//! Natural coordinates of a rigid body (docs/method.md §15.1): the
//! reference point r and the columns a_1, a_2, a_3 of the rotation matrix,
//! `q = [r, a_1, a_2, a_3]` (twelve numbers, `q[3 k + i]` component i of
//! column k, column 0 being r).

use crate::vec3::{add, cross, scale};

/// The twelve natural coordinates (or their rates) of one body.
pub type Natural = [f64; 12];

/// Column k of q (k = 0: r; k = 1..3: a_k).
pub fn column(q: &Natural, k: usize) -> [f64; 3] {
    [q[3 * k], q[3 * k + 1], q[3 * k + 2]]
}

/// The natural coordinates of a body at `position` with rotation matrix
/// `rotation` (body axes to global; its columns are a_1, a_2, a_3).
pub fn from_pose(position: [f64; 3], rotation: &[[f64; 3]; 3]) -> Natural {
    let mut q = [0.0; 12];
    q[..3].copy_from_slice(&position);
    for k in 0..3 {
        for i in 0..3 {
            q[3 * (k + 1) + i] = rotation[i][k];
        }
    }
    q
}

/// The rates of the natural coordinates of a body whose reference point
/// moves at `velocity` and which turns at `angular_velocity` (global):
/// `a_k_dot = w x a_k`.
pub fn rates_from(velocity: [f64; 3], angular_velocity: [f64; 3], q: &Natural) -> Natural {
    let mut v = [0.0; 12];
    v[..3].copy_from_slice(&velocity);
    for k in 1..4 {
        let a = cross(angular_velocity, column(q, k));
        v[3 * k..3 * k + 3].copy_from_slice(&a);
    }
    v
}

/// The rotation matrix whose columns are a_1, a_2, a_3.
pub fn rotation(q: &Natural) -> [[f64; 3]; 3] {
    let mut r = [[0.0; 3]; 3];
    for k in 0..3 {
        for i in 0..3 {
            r[i][k] = q[3 * (k + 1) + i];
        }
    }
    r
}

/// The global position of the body-fixed point `xi` (B1):
/// `x = r + xi_1 a_1 + xi_2 a_2 + xi_3 a_3`.
pub fn point(q: &Natural, xi: [f64; 3]) -> [f64; 3] {
    let mut x = column(q, 0);
    for k in 0..3 {
        x = add(x, scale(xi[k], column(q, k + 1)));
    }
    x
}

/// The weights of (B1): x = sum_k s_k q_k over the four columns, s =
/// [1, xi_1, xi_2, xi_3]; a force F at xi does the generalized work
/// `s_k F . q_k`.
pub fn point_weights(xi: [f64; 3]) -> [f64; 4] {
    [1.0, xi[0], xi[1], xi[2]]
}

/// The angular velocity (global) of a body moving with rates `v`:
/// `w = 1/2 sum_k a_k x a_k_dot` (B8), exact while the columns are
/// orthonormal (`a x (w x a) = w - (a . w) a` summed over an orthonormal
/// basis is 2 w).
pub fn angular_velocity(q: &Natural, v: &Natural) -> [f64; 3] {
    let mut w = [0.0; 3];
    for k in 1..4 {
        w = add(w, cross(column(q, k), column(v, k)));
    }
    scale(0.5, w)
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
    crate::vec3::mat3_mul(&crate::vec3::mat3_mul(&rx, &ry), &rz)
}

/// The roll, pitch and yaw (degrees) of MoorDyn's convention
/// ([`rotation_from_moordyn_angles`]) of the rotation of q, pitch in
/// [-90, 90]: `R[0][2] = sin(pitch)`, `R[1][2] / R[2][2] = -tan(roll)`,
/// `R[0][1] / R[0][0] = -tan(yaw)`.
pub fn moordyn_angles(q: &Natural) -> [f64; 3] {
    let r = rotation(q);
    let pitch = r[0][2].clamp(-1.0, 1.0).asin();
    let roll = (-r[1][2]).atan2(r[2][2]);
    let yaw = (-r[0][1]).atan2(r[0][0]);
    [roll, pitch, yaw].map(f64::to_degrees)
}

#[cfg(test)]
mod tests {
    use super::*;

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
        let q = from_pose([1.0, 2.0, 3.0], &rotation_from_moordyn_angles(angles));
        let back = moordyn_angles(&q);
        for k in 0..3 {
            assert!((back[k] - angles[k]).abs() < 1e-12, "{back:?}");
        }
    }

    #[test]
    fn the_angular_velocity_comes_back_from_the_rates() {
        let q = from_pose([0.0; 3], &rotation_from_moordyn_angles([10.0, 20.0, 30.0]));
        let w = [0.3, -1.2, 2.5];
        let v = rates_from([1.0, 0.0, 0.0], w, &q);
        let back = angular_velocity(&q, &v);
        for k in 0..3 {
            assert!((back[k] - w[k]).abs() < 1e-15, "{back:?}");
        }
        let x = point(&q, [1.0, 2.0, 3.0]);
        let r = rotation(&q);
        for i in 0..3 {
            let expected = r[i][0] + 2.0 * r[i][1] + 3.0 * r[i][2];
            assert!((x[i] - expected).abs() < 1e-15);
        }
    }
}
