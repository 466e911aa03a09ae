//! A line in water (docs/method.md §12.3-12.5): its Morison coefficients,
//! the water it is in, and the force per unit length the water puts on it
//! at a point of its axis (buoyancy, drag and the fluid's inertia).
//!
//! Conventions are MoorDyn v2's (Line.cpp), per unit *unstretched*
//! length, with the relative velocity v = u - r_dot of the water past the
//! line, t = r_x / |r_x| the unit tangent, P_t = t t^T, P_n = I - P_t,
//! A = pi d^2 / 4 the displaced area of the hydrodynamic diameter d and s
//! the submerged fraction (W17):
//!
//! ```text
//!   f_B = -s rho_w A g                            buoyancy             (W18)
//!   f_D = s rho_w d / 2 (Cdn |v_n| v_n + pi Cdt |v_t| v_t)
//!         v_n = P_n v, v_t = P_t v                drag                 (W19)
//!   f_I = s rho_w A ((1 + Can) P_n + (1 + Cat) P_t) a_f
//!                                                 fluid inertia        (W20)
//! ```
//!
//! g is the gravity vector (the model's gravity load), a_f the water's
//! local acceleration. The axial drag coefficient refers to the line's
//! surface pi d, as MoorDyn's CdAx does, so a deck's coefficients are used
//! as written. The added mass's reaction to the line's own acceleration,
//! -s rho_w A (Can P_n + Cat P_t) r_ddot, is not in f: it enters the action
//! as the kinetic energy of the entrained water (§12.5).

use super::host_flow::{FlowAt, NodeFlow};
use super::kinematics::{FluidKinematics, Sea};
use super::seabed::ForceAtPoint;
use super::submerged::SubmergedFraction;
use crate::vec3::{dot, mat3_mul};
use std::sync::Arc;

/// A line type's hydrodynamic coefficients (MoorDyn's LINE TYPES columns
/// Diam, Cd, CdAx, Ca, CaAx).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Morison {
    /// Hydrodynamic (volume-equivalent) diameter d (m): displaced area
    /// pi d^2 / 4, drag width d.
    pub diameter: f64,
    /// Normal drag coefficient Cdn on the width d.
    pub cd_normal: f64,
    /// Axial drag coefficient Cdt on the surface pi d (MoorDyn's CdAx).
    pub cd_axial: f64,
    /// Normal added-mass coefficient Can.
    pub ca_normal: f64,
    /// Axial added-mass coefficient Cat.
    pub ca_axial: f64,
}

impl Morison {
    /// Displaced area pi d^2 / 4 (m^2).
    pub fn area(&self) -> f64 {
        0.25 * std::f64::consts::PI * self.diameter * self.diameter
    }
}

/// The water lines are in: its density and its sea (depth, gravity for
/// the waves' dispersion, waves, current).
#[derive(Clone, Debug, PartialEq)]
pub struct Water {
    /// rho_w (kg/m^3).
    pub density: f64,
    pub sea: Sea,
}

/// The water's load on one line: the water (shared by every line of a
/// system) and the line's coefficients.
#[derive(Clone, Debug, PartialEq)]
pub struct LineInWater {
    pub water: Arc<Water>,
    pub morison: Morison,
    /// The flow a host sets at the line's nodes, when the sea's waves are
    /// the host's ([`Sea::host_waves`], (W2f)-(W2g)); None otherwise.
    pub host: Option<NodeFlow>,
}

impl LineInWater {
    pub fn new(water: Arc<Water>, morison: Morison) -> Self {
        LineInWater {
            water,
            morison,
            host: None,
        }
    }

    /// The submerged fraction (W17) of the section centred at `r`.
    #[inline]
    pub fn submerged(&self, r: &[f64; 3]) -> SubmergedFraction {
        SubmergedFraction::at(r[2], self.morison.diameter)
    }
}

/// The sea's flow `flow` with a host's `host` added to it (W2g): its
/// velocity and local acceleration, not their gradients (the host's values
/// do not depend on where the line is).
pub(crate) fn with_host_flow(mut flow: FluidKinematics, host: Option<FlowAt>) -> FluidKinematics {
    if let Some((u, a)) = host {
        for i in 0..3 {
            flow.velocity[i] += u[i];
            flow.acceleration[i] += a[i];
        }
    }
    flow
}

/// The derivatives of (W18)-(W20), for the slab's Jacobian, with
/// G_u = grad u, G_a = grad a_f, q(k, w) = k |w| w and
/// Q(k, w) = dq/dw = k (|w| I + w w^T / |w|) (zero at w = 0):
///
/// ```text
///   f_D = s f_D0,  f_D0 = q(k_n, v_n) + q(k_t, v_t),
///   k_n = rho_w d Cdn / 2,  k_t = rho_w pi d Cdt / 2,   D_v = Q_n P_n + Q_t P_t
///   df_D/dr_dot = -s D_v
///   df_D/dr     =  s D_v G_u + f_D0 s' e_z^T
///   df_D/dr_x   =  s (Q_n - Q_t) dv_n/dr_x,
///                  dv_n/dr_x = -(t v^T + (v . t) I) P_n / |r_x|          (W21)
///   f_I = s f_I0,  f_I0 = c_n a_f + (c_t - c_n) (t . a_f) t,
///   c_n = rho_w A (1 + Can),  c_t = rho_w A (1 + Cat)
///   df_I/dr     =  s (c_n I + (c_t - c_n) P_t) G_a + f_I0 s' e_z^T
///   df_I/dr_x   =  s (c_t - c_n) (t a_f^T + (t . a_f) I) P_n / |r_x|      (W22)
///   df_B/dr     = -s' rho_w A g e_z^T                                     (W23)
/// ```
///
/// (dt/dr_x = P_n / |r_x|; the flow's gradients carry the dependence of
/// u and a_f on where the line is.)
impl LineInWater {
    /// The water's force per unit length on the line at `r` with tangent
    /// `rx` and velocity `rdot` at time `t`, under gravity `gravity`
    /// (W18)-(W20), with its derivatives (W21)-(W23), in the sea's own
    /// flow (a host's, (W2g), which belongs to a point of an element, is
    /// added where the step knows the point).
    pub fn force(
        &self,
        r: &[f64; 3],
        rx: &[f64; 3],
        rdot: &[f64; 3],
        t: f64,
        gravity: &[f64; 3],
    ) -> ForceAtPoint {
        self.force_at(r, rx, rdot, t, gravity, true, None)
    }

    /// [`Self::force`], its derivatives only when `derivatives` (else
    /// zero): a residual without a Jacobian skips them, with the same
    /// force to the bit. `host`: the flow a host has set there, added to
    /// the sea's (W2g).
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn force_at(
        &self,
        r: &[f64; 3],
        rx: &[f64; 3],
        rdot: &[f64; 3],
        t: f64,
        gravity: &[f64; 3],
        derivatives: bool,
        host: Option<FlowAt>,
    ) -> ForceAtPoint {
        let s = self.submerged(r);
        if s.is_dry() {
            return ForceAtPoint::default();
        }
        let flow = with_host_flow(self.water.sea.kinematics(r, t), host);
        self.force_in(&s, rx, rdot, &flow, gravity, derivatives)
    }

    /// The force on a line at rest in the steady current (no waves, the
    /// current at full strength whatever its ramp): the water's load in
    /// statics (docs/method.md §12.4).
    pub fn static_force(&self, r: &[f64; 3], rx: &[f64; 3], gravity: &[f64; 3]) -> ForceAtPoint {
        let s = self.submerged(r);
        if s.is_dry() {
            return ForceAtPoint::default();
        }
        let flow = self.water.sea.steady_current(r);
        self.force_in(&s, rx, &[0.0; 3], &flow, gravity, true)
    }

    /// (W18)-(W23) in the flow `flow` at the section; the derivatives
    /// (W21)-(W23) only when `derivatives`.
    fn force_in(
        &self,
        s: &SubmergedFraction,
        rx: &[f64; 3],
        rdot: &[f64; 3],
        flow: &FluidKinematics,
        gravity: &[f64; 3],
        derivatives: bool,
    ) -> ForceAtPoint {
        let m = &self.morison;
        let rho = self.water.density;
        let area = m.area();
        let len = dot(rx, rx).sqrt();
        let t = rx.map(|c| c / len);
        // Drag (W19) on the normal and tangential relative velocities.
        let v: [f64; 3] = std::array::from_fn(|i| flow.velocity[i] - rdot[i]);
        let vt_s = dot(v, t);
        let v_t = t.map(|c| vt_s * c);
        let v_n: [f64; 3] = std::array::from_fn(|i| v[i] - v_t[i]);
        let k_n = 0.5 * rho * m.diameter * m.cd_normal;
        let k_t = 0.5 * rho * std::f64::consts::PI * m.diameter * m.cd_axial;
        let q_n = crate::loads::quadratic_drag_force(-k_n, &v_n);
        let q_t = crate::loads::quadratic_drag_force(-k_t, &v_t);
        // Fluid inertia (W20).
        let (c_n, c_t) = (
            rho * area * (1.0 + m.ca_normal),
            rho * area * (1.0 + m.ca_axial),
        );
        let a = &flow.acceleration;
        let at_s = dot(a, t);
        let f_i0: [f64; 3] = std::array::from_fn(|i| c_n * a[i] + (c_t - c_n) * at_s * t[i]);
        // Buoyancy (W18) and the sum.
        let mut out = ForceAtPoint::default();
        for i in 0..3 {
            out.force[i] = -s.value * rho * area * gravity[i];
            out.force[i] += s.value * (q_n[i] + q_t[i] + f_i0[i]);
        }
        if !derivatives {
            return out;
        }
        let mut p_t = [[0.0; 3]; 3];
        let mut p_n = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                p_t[i][j] = t[i] * t[j];
                p_n[i][j] = f64::from(u8::from(i == j)) - p_t[i][j];
            }
        }
        // Buoyancy (W23).
        for i in 0..3 {
            out.d_r[i][2] = -s.slope * rho * area * gravity[i];
        }
        // Drag (W21).
        let (_, dq_n) = quadratic(k_n, &v_n);
        let (_, dq_t) = quadratic(k_t, &v_t);
        let d_v = add(&mat3_mul(&dq_n, &p_n), &mat3_mul(&dq_t, &p_t));
        let mut lever = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                lever[i][j] = -(t[i] * v[j] + if i == j { vt_s } else { 0.0 }) / len;
            }
        }
        let dvn_drx = mat3_mul(&lever, &p_n);
        let dq_diff = sub(&dq_n, &dq_t);
        let drag_rx = mat3_mul(&dq_diff, &dvn_drx);
        let drag_r = mat3_mul(&d_v, &flow.velocity_gradient);
        // Fluid inertia (W22).
        let mut inertia_mass = [[0.0; 3]; 3];
        let mut swing = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                inertia_mass[i][j] = (c_t - c_n) * p_t[i][j] + if i == j { c_n } else { 0.0 };
                swing[i][j] = (c_t - c_n) * (t[i] * a[j] + if i == j { at_s } else { 0.0 }) / len;
            }
        }
        let inertia_r = mat3_mul(&inertia_mass, &flow.acceleration_gradient);
        let inertia_rx = mat3_mul(&swing, &p_n);
        for i in 0..3 {
            out.d_r[i][2] += s.slope * (q_n[i] + q_t[i] + f_i0[i]);
            for j in 0..3 {
                out.d_rdot[i][j] = -s.value * d_v[i][j];
                out.d_r[i][j] += s.value * (drag_r[i][j] + inertia_r[i][j]);
                out.d_rx[i][j] = s.value * (drag_rx[i][j] + inertia_rx[i][j]);
            }
        }
        out
    }
}

/// q(k, w) = k |w| w and Q = dq/dw = k (|w| I + w w^T / |w|), zero at
/// w = 0 (where q is C1): the air drag's law with the sign of a force
/// along w.
fn quadratic(k: f64, w: &[f64; 3]) -> ([f64; 3], [[f64; 3]; 3]) {
    crate::loads::quadratic_drag(-k, w)
}

fn add(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] + b[i][j]))
}

fn sub(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j] - b[i][j]))
}

#[cfg(test)]
#[path = "hydro_tests.rs"]
mod tests;
