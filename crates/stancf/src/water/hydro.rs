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

use super::kinematics::Sea;
use super::submerged::SubmergedFraction;
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
}

impl LineInWater {
    pub fn new(water: Arc<Water>, morison: Morison) -> Self {
        LineInWater { water, morison }
    }

    /// The submerged fraction (W17) of the section centred at `r`.
    #[inline]
    pub fn submerged(&self, r: &[f64; 3]) -> SubmergedFraction {
        SubmergedFraction::at(r[2], self.morison.diameter)
    }
}
