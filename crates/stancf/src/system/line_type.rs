//! The mechanics of a line type as a mooring code gives it (a MoorDyn
//! deck's LINE TYPES, a scenario's `[[line_types]]`): the section's
//! material, the bending stiffness a line of EI = 0 is simulated with
//! (docs/method.md §11.7, (M33)), the axial damping of a damping ratio
//! (§2.10, (M36)), the weight left in water (§11.8), and the stable P2
//! step of a system (§4.6).

use super::{taut_states, System};
use crate::integrator::TimeScheme;
use crate::model::Material;
use crate::quadrature::GaussRule;
use crate::stability;

/// The factor c in the bending stiffness EI = c w L^3 a line of EI = 0
/// is given (docs/method.md §11.7, (M33)): bending then changes the
/// tensions of a line of weight w L under tension T by about c w L / T,
/// 1e-7 at T = w L.
pub const EI_FACTOR: f64 = 1e-7;

/// A line type's section: its area A = pi d^2 / 4 (d the diameter), its
/// mass per length w and its axial stiffness EA.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineSection {
    /// Area (m^2).
    pub area: f64,
    /// Mass per length (kg/m).
    pub mass_per_length: f64,
    /// Axial stiffness EA (N).
    pub ea: f64,
}

impl LineSection {
    /// The section of a line of diameter `diameter` (A = pi d^2 / 4).
    pub fn of_diameter(diameter: f64, mass_per_length: f64, ea: f64) -> Self {
        LineSection {
            area: std::f64::consts::PI * diameter * diameter / 4.0,
            mass_per_length,
            ea,
        }
    }

    /// The material of the section with bending stiffness `ei`:
    /// E = EA / A, rho = w / A, I = EI / E, without damping (a line's BA
    /// is added by [`Material::with_axial_damping`]).
    pub fn material(&self, ei: f64) -> Material {
        let youngs_modulus = self.ea / self.area;
        Material {
            youngs_modulus,
            density: self.mass_per_length / self.area,
            area: self.area,
            second_moment: ei / youngs_modulus,
            axial_damping: 0.0,
        }
    }

    /// The fraction of the line's weight left in water of density
    /// `water_density` (None: in air, 1): its weight per length w g less
    /// the buoyancy rho_w A g of the water it displaces, over w g; the
    /// weight a submerged line hangs by, which sets its catenary seed
    /// (§11.6, §11.8) and the EI of EI = 0 ((M33)).
    pub fn wet_weight_fraction(&self, water_density: Option<f64>) -> f64 {
        match water_density {
            Some(rho) => 1.0 - rho * self.area / self.mass_per_length,
            None => 1.0,
        }
    }

    /// The bending stiffness a line of length `length` is simulated with
    /// (docs/method.md §11.7, (M33)): `ei` when positive; for EI = 0
    /// (chain, wire rope) c w L^3 with c = [`EI_FACTOR`] and w the weight
    /// per length `gravity` w `wet_fraction` ([`Self::wet_weight_fraction`]);
    /// without weight, c EA L^2 / 1000.
    pub fn bending_stiffness(&self, ei: f64, length: f64, gravity: f64, wet_fraction: f64) -> f64 {
        if ei > 0.0 {
            return ei;
        }
        let w = (self.mass_per_length * gravity * wet_fraction).abs();
        let reference_tension = if w > 0.0 { w * length } else { 1e-3 * self.ea };
        EI_FACTOR * reference_tension * length * length
    }

    /// The axial damping BA (N s) of a line type's `ba` (docs/method.md
    /// §2.10): `ba` itself when >= 0; for `ba` < 0, minus a damping ratio
    /// zeta as in MoorDyn, BA = zeta l sqrt(EA w) (M36) with l the line's
    /// element length `segment` (MoorDyn's segment length).
    pub fn axial_damping(&self, ba: f64, segment: f64) -> f64 {
        if ba >= 0.0 {
            return ba;
        }
        self.material(0.0).axial_damping_for_ratio(-ba, segment)
    }
}

/// The largest P2 step every line of `system` is stable with
/// (docs/method.md §4.5-4.6): the smallest over the lines of
/// (w_max dt)_crit / w_max of its taut straight state ([`taut_states`]:
/// a slack line judged on its compressed straight start would have no
/// axial stiffness and a limit far above its axial modes'), with `time_points`
/// Gauss points in time over `time_layers` layers. None for the Galerkin
/// step (§5) or a quadrature without a limit.
pub fn stable_step(
    system: &System,
    scheme: TimeScheme,
    time_points: usize,
    time_layers: usize,
) -> Option<f64> {
    if !scheme.conditionally_stable() {
        return None;
    }
    let rule = GaussRule::new(time_points).ok()?;
    let critical = stability::p2_critical_w_dt(&rule, time_layers)?;
    let states = taut_states(system);
    system
        .lines()
        .iter()
        .zip(&states)
        .map(|(l, s)| critical / stability::highest_frequency(&l.model, &s.e))
        .fold(None, |m: Option<f64>, s| Some(m.map_or(s, |m| m.min(s))))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A chain of 80 kg/m, EA 1e9 N, 100 m long in air and in sea water.
    fn chain() -> LineSection {
        LineSection::of_diameter(0.1, 80.0, 1e9)
    }

    #[test]
    fn a_line_of_ei_zero_is_given_c_w_l_cubed_of_its_wet_weight() {
        let s = chain();
        let (l, g) = (100.0, 9.81);
        let in_air = s.bending_stiffness(0.0, l, g, 1.0);
        assert!((in_air - EI_FACTOR * 80.0 * g * l.powi(3)).abs() <= 1e-12 * in_air);
        let wet = s.wet_weight_fraction(Some(1025.0));
        assert!((wet - (1.0 - 1025.0 * s.area / 80.0)).abs() < 1e-15);
        let in_water = s.bending_stiffness(0.0, l, g, wet);
        assert!((in_water - wet * in_air).abs() <= 1e-12 * in_air);
        // Without weight, c EA L^2 / 1000; a given EI is kept.
        let weightless = s.bending_stiffness(0.0, l, 0.0, 1.0);
        assert!((weightless - EI_FACTOR * 1e-3 * 1e9 * l * l).abs() <= 1e-12 * weightless);
        assert_eq!(s.bending_stiffness(5.0, l, g, 1.0), 5.0);
    }

    #[test]
    fn a_negative_ba_is_moordyns_damping_ratio_on_the_segment() {
        let s = chain();
        let ba = s.axial_damping(-0.8, 2.0);
        assert!((ba - 0.8 * 2.0 * (1e9f64 * 80.0).sqrt()).abs() <= 1e-12 * ba);
        assert_eq!(s.axial_damping(300.0, 2.0), 300.0);
    }
}
