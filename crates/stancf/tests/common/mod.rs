//! Helpers shared by the integration tests.
#![allow(dead_code)]

use stancf::element::{CableElement, Measures, Section, SpaceRules, TimeSlab};
use stancf::quadrature::GaussRule;
use stancf::shape::{cubic_hermite, quintic_hermite};
use stancf::{AxialStrain, Curvature};

/// Deterministic pseudo-random numbers in [-1, 1) (xorshift64).
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }
}

/// Relative difference |a - b| / max(|b|, floor) of two vectors (2-norm).
pub fn rel_diff(a: &[f64], b: &[f64]) -> f64 {
    let num: f64 = a
        .iter()
        .zip(b)
        .map(|(x, y)| (x - y).powi(2))
        .sum::<f64>()
        .sqrt();
    let den: f64 = b.iter().map(|y| y * y).sum::<f64>().sqrt();
    num / den.max(1e-300)
}

pub const ALL_MEASURES: [Measures; 4] = [
    Measures {
        axial_strain: AxialStrain::Green,
        curvature: Curvature::Paper,
    },
    Measures {
        axial_strain: AxialStrain::Green,
        curvature: Curvature::Exact,
    },
    Measures {
        axial_strain: AxialStrain::Engineering,
        curvature: Curvature::Paper,
    },
    Measures {
        axial_strain: AxialStrain::Engineering,
        curvature: Curvature::Exact,
    },
];

pub fn section() -> Section {
    Section {
        ea: 3.0,
        ei: 0.2,
        rho_a: 1.3,
    }
}

pub fn rules(axial: usize, bending: usize) -> SpaceRules {
    SpaceRules {
        axial: GaussRule::new(axial).unwrap(),
        bending: GaussRule::new(bending).unwrap(),
    }
}

pub fn sac2(l: f64, m: Measures, r: &SpaceRules) -> CableElement<4, 12> {
    CableElement::new(cubic_hermite, l, section(), m, r)
}

pub fn sac3(l: f64, m: Measures, r: &SpaceRules) -> CableElement<6, 18> {
    CableElement::new(quintic_hermite, l, section(), m, r)
}

pub fn slab(dt: f64, points: usize) -> TimeSlab {
    TimeSlab::new(dt, &GaussRule::new(points).unwrap())
}

/// Random slab unknowns near a bent, stretched, moving element: the
/// straight reference plus perturbations of size `amp`, velocities of
/// order 1.
pub fn random_slab_state<const NS: usize, const ND: usize>(
    rng: &mut Rng,
    l: f64,
    amp: f64,
) -> [[f64; ND]; 4] {
    let vpn = NS / 2;
    let mut y = [[0.0; ND]; 4];
    for t in [0, 2] {
        for a in 0..NS {
            let node = a / vpn;
            let kind = a % vpn;
            for i in 0..3 {
                let base = match (kind, i) {
                    (0, 0) => node as f64 * l,
                    (1, 0) => 1.0,
                    _ => 0.0,
                };
                y[t][3 * a + i] = base + amp * rng.next();
            }
        }
    }
    for t in [1, 3] {
        for d in 0..ND {
            y[t][d] = rng.next();
        }
    }
    y
}
