//! Material and cross-section, and the figures derived from them: the
//! section stiffnesses EA, EI and mass per length rho A (docs/method.md
//! §2.1, §2.4), the axial damping BA (§2.10) and the longitudinal wave
//! speed (docs/method.md §4.6).

use crate::element::Section;

/// Material and cross-section (Tables 2 and 9).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// E (Pa).
    pub youngs_modulus: f64,
    /// rho (kg/m^3).
    pub density: f64,
    /// A (m^2).
    pub area: f64,
    /// I (m^4).
    pub second_moment: f64,
    /// Axial (Kelvin-Voigt) damping BA (N s): the axial force is
    /// EA eps + BA d(eps)/dt (docs/method.md §2.10, (M34)). 0: none, and
    /// the element then costs what it did without it.
    pub axial_damping: f64,
}

impl Material {
    /// The paper's PVC cable (Table 2): E 3.4 GPa, rho 1380 kg/m^3,
    /// I 1.25e-13 m^4, A 3e-6 m^2.
    pub fn chen2023_pvc() -> Self {
        Material {
            youngs_modulus: 3.4e9,
            density: 1380.0,
            area: 3.0e-6,
            second_moment: 1.25e-13,
            axial_damping: 0.0,
        }
    }

    /// The paper's gutta-percha cable (Table 9): E 0.91 MPa,
    /// rho 1202 kg/m^3, I 9.15e-12 m^4, A 1.075e-5 m^2.
    pub fn chen2023_gutta_percha() -> Self {
        Material {
            youngs_modulus: 0.91e6,
            density: 1202.0,
            area: 1.075e-5,
            second_moment: 9.15e-12,
            axial_damping: 0.0,
        }
    }

    pub fn section(&self) -> Section {
        Section {
            ea: self.youngs_modulus * self.area,
            ei: self.youngs_modulus * self.second_moment,
            rho_a: self.density * self.area,
            ba: self.axial_damping,
            tension_only: false,
            curve: None,
            visco: None,
            viv: None,
        }
    }

    /// The material with axial damping BA (N s).
    pub fn with_axial_damping(mut self, ba: f64) -> Self {
        self.axial_damping = ba;
        self
    }

    /// MoorDyn's axial damping for a damping ratio `zeta` (its negative
    /// `BA/-zeta` entry) on segments (here: elements) of length
    /// `segment_length` (docs/method.md §2.10, (M36)):
    ///
    /// ```text
    ///   BA = zeta l sqrt(EA rho A)
    /// ```
    ///
    /// the damping that gives the axial mode of wave number ~ 1 / l
    /// (MoorDyn's highest lumped-mass mode, omega = 2 c / l) the damping
    /// ratio zeta: zeta(omega) = BA omega / (2 EA) (M35).
    pub fn axial_damping_for_ratio(&self, zeta: f64, segment_length: f64) -> f64 {
        let s = self.section();
        zeta * segment_length * (s.ea * s.rho_a).sqrt()
    }

    /// Longitudinal wave speed c = sqrt(E / rho).
    pub fn wave_speed(&self) -> f64 {
        (self.youngs_modulus / self.density).sqrt()
    }
}
