//! How much of a line's cross-section is under water (docs/method.md
//! §12.3, (W17)).
//!
//! Linear wave theory puts the water's loads below the still water level
//! z = 0 (the sea's kinematics, §12.1, are those of linear theory). A
//! section of diameter d whose centre is at height z is taken to be
//! submerged by the fraction
//!
//! ```text
//!   xi = clamp(1/2 - z/d, 0, 1),   s(z) = xi^2 (3 - 2 xi)              (W17)
//!   s'(z) = -6 xi (1 - xi) / d,    s''(z) = (6 - 12 xi) / d^2
//! ```
//!
//! s = 1 below z = -d/2, 0 above z = d/2, 1/2 at z = 0, and C1: a line
//! piercing the surface gets loads that vary smoothly enough for Newton.
//! The smoothstep stands in for the exact area of a circular segment
//! (which has an infinite slope at the section's top and bottom); the two
//! agree at z = 0 and outside the band and differ by less than 0.04 of
//! the section inside it.

/// The submerged fraction s(z) of a section of diameter `diameter` centred
/// at height `z` above the still water level, with s' and s'' (W17).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SubmergedFraction {
    pub value: f64,
    /// ds/dz (1/m, never positive).
    pub slope: f64,
    /// d2s/dz2 (1/m^2).
    pub curvature: f64,
}

impl SubmergedFraction {
    /// (W17) at `z` for a section of diameter `diameter` (> 0).
    #[inline]
    pub fn at(z: f64, diameter: f64) -> SubmergedFraction {
        let xi = 0.5 - z / diameter;
        if xi >= 1.0 {
            return SubmergedFraction {
                value: 1.0,
                slope: 0.0,
                curvature: 0.0,
            };
        }
        if xi <= 0.0 {
            return SubmergedFraction {
                value: 0.0,
                slope: 0.0,
                curvature: 0.0,
            };
        }
        SubmergedFraction {
            value: xi * xi * (3.0 - 2.0 * xi),
            slope: -6.0 * xi * (1.0 - xi) / diameter,
            curvature: (6.0 - 12.0 * xi) / (diameter * diameter),
        }
    }

    /// Whether the section is entirely in air (s = 0 with zero slope).
    #[inline]
    pub fn is_dry(&self) -> bool {
        self.value == 0.0 && self.slope == 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::SubmergedFraction;

    #[test]
    fn a_section_is_wholly_wet_below_half_a_diameter_and_dry_above() {
        let d = 0.2;
        assert_eq!(SubmergedFraction::at(-0.1, d).value, 1.0);
        assert_eq!(SubmergedFraction::at(-5.0, d).value, 1.0);
        assert_eq!(SubmergedFraction::at(0.1, d).value, 0.0);
        assert!(SubmergedFraction::at(0.3, d).is_dry());
        assert_eq!(SubmergedFraction::at(0.0, d).value, 0.5);
    }

    #[test]
    fn the_fraction_is_continuously_differentiable_with_exact_derivatives() {
        let d = 0.3;
        let h = 1e-6;
        for &z in &[-0.149, -0.1, -0.03, 0.0, 0.02, 0.1, 0.149] {
            let s = SubmergedFraction::at(z, d);
            let (sp, sm) = (
                SubmergedFraction::at(z + h, d),
                SubmergedFraction::at(z - h, d),
            );
            let slope = (sp.value - sm.value) / (2.0 * h);
            let curvature = (sp.slope - sm.slope) / (2.0 * h);
            // Central differences of a cubic: error h^2 s'''/6 = h^2 2/d^3.
            assert!(
                (slope - s.slope).abs() < 1e-8,
                "z {z}: {slope} vs {}",
                s.slope
            );
            assert!((curvature - s.curvature).abs() < 1e-6, "z {z}");
        }
        // C1 at the band's edges: the slope vanishes there.
        assert!(SubmergedFraction::at(-0.15 + 1e-12, d).slope.abs() < 1e-9);
        assert!(SubmergedFraction::at(0.15 - 1e-12, d).slope.abs() < 1e-9);
    }

    #[test]
    fn the_fraction_is_within_four_hundredths_of_a_circular_segment() {
        // Exact submerged area of a circle of radius 1 with its centre at
        // height z: (acos(z) - z sqrt(1 - z^2)) / pi.
        let d = 2.0;
        for i in 0..=200 {
            let z = -1.0 + 2.0 * i as f64 / 200.0;
            let exact = ((z).acos() - z * (1.0 - z * z).sqrt()) / std::f64::consts::PI;
            let s = SubmergedFraction::at(z, d).value;
            assert!((s - exact).abs() < 0.04, "z {z}: {s} vs {exact}");
        }
    }
}
