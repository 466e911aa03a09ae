//! The space-time ANCF cable element (SAC-2 and SAC-3): its action over one
//! slab, eq. (10), the gradient of the action with respect to the element's
//! unknowns and its exact Hessian (docs/method.md §1.5, §2.1-2.4 and
//! §3.1-3.2).
//!
//! One generic kernel serves both elements: `CableElement<NS, ND>` with NS
//! spatial shape functions (4 for SAC-2, eq. 4; 6 for SAC-3, eq. 5) and
//! ND = 3 NS coordinates. The element coordinates are stored node by node,
//! `q = [r(0), r_x(0), (r_xx(0)), r(l), r_x(l), (r_xx(l))]`, so entry
//! `3 k + i` is component i of the coordinate carried by shape function k.
//!
//! Over one slab [t_a, t_b] the element's unknowns are
//! `y = [e_a, v_a, e_b, v_b]` (4 x ND numbers) and every coordinate moves as
//! `q(t) = sum_m phi_m(t) y_m` with the time Hermite functions of eq. (6).
//! The slab action, Gauss-integrated in time with weights w_g ((M13)-(M14)
//! of docs/method.md §3.1-3.2),
//!
//! ```text
//!   A^e = sum_g w_g dt [ 1/2 qdot^T M qdot - U(q) + f_g . q ]          eq. (10)-(13)
//!   dA^e/dy_m = sum_g w_g dt [ phidot_m M qdot - phi_m (dU/dq - f_g) ]
//!   d2A^e/dy_m dy_n = C_mn M - sum_g w_g dt phi_m phi_n d2U/dq2(q(t_g))
//! ```
//!
//! with `C_mn = sum_g w_g dt phidot_m phidot_n` and the constant consistent
//! mass matrix M = int rho A S^T S dx (eq. 11). The strain energy U (eq. 12)
//! is integrated in space with its own Gauss rules (one for the axial term,
//! one for the bending term; the paper uses one rule for both).
//!
//! The kernel is split by what it holds:
//!
//! | file | contents | docs/method.md |
//! |---|---|---|
//! | `mod.rs` | the element, its section and measures, mass matrix and gravity load | §1.5, §2.1, §2.5 |
//! | `strain` | axial strain and its energy density, gradient, Hessian | §2.2 |
//! | `curvature` | curvature and the smooth kappa^2 bending density | §2.3 |
//! | `energy` | the elastic energy U and its derivatives by spatial quadrature | §2.4 |
//! | `drag` | air drag virtual work and its Jacobian | §2.8, §6.8 |
//! | `damping` | axial (Kelvin-Voigt) damping virtual work and its Jacobian | §2.10 |
//! | `added_mass` | the entrained water's kinetic energy, its momentum and derivatives | §12.5 |
//! | `viscoelastic` | the viscoelastic rope's law and its collocation over a slab | §2.11 |
//! | `visco_slab` | its axial forces in the slab derivatives, their Jacobian | §2.11 |
//! | `viv` | MoorDyn's VIV law at a point: shedding phase rate and lift | §12.7 |
//! | `viv_slab` | the phase collocated over a slab, the lift's work and Jacobian | §12.7 |
//! | `dual` | forward-mode dual numbers for the VIV law's derivatives | §12.7 |
//! | `slab` | time slabs and the quadrature of the action, gradient, Hessian | §3.1-3.2 |

mod added_mass;
mod axial_curve;
mod contact_rule;
mod curvature;
mod damping;
mod drag;
mod dual;
mod energy;
mod point_force;
mod seabed;
mod slab;
mod strain;
mod syrope;
mod visco_slab;
mod viscoelastic;
mod viv;
mod viv_slab;
mod water;

pub use added_mass::AddedMassDerivatives;
pub use axial_curve::AxialCurve;
pub use curvature::{bending_energy_density, bending_energy_gradient, curvature};
pub use slab::{SlabDerivatives, SlabLoads, TimePoint, TimeSlab};
pub use strain::{
    axial_energy_density, axial_energy_gradient, axial_strain, axial_strain_derivatives,
    tension_only_energy_density,
};
pub use syrope::{Syrope, WorkingCurveForm};
pub use viscoelastic::ViscoDerivatives;
pub use viscoelastic::{DynamicStiffness, Viscoelastic};
pub use viv::{Viv, VivDerivatives, VIV_VALUES};

use crate::quadrature::GaussRule;
use crate::shape::SpatialShape;

/// Axial strain of the centre line.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum AxialStrain {
    /// eps = (r_x . r_x - 1) / 2, eq. (8) (Green strain; the paper's).
    #[default]
    Green,
    /// eps = |r_x| - 1 (engineering strain, as in Exudyn and MoorDyn).
    Engineering,
}

/// Curvature of the centre line (docs/method.md §2.3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum Curvature {
    /// kappa = |r_x x r_xx| / |r_x|^2, eq. (9) as printed.
    #[default]
    Paper,
    /// kappa = |r_x x r_xx| / |r_x|^3, the exact curvature.
    Exact,
}

impl Curvature {
    /// Power p of |r_x|^2 in kappa^2 = |r_x x r_xx|^2 / (|r_x|^2)^p.
    fn power(self) -> i32 {
        match self {
            Curvature::Paper => 2,
            Curvature::Exact => 3,
        }
    }
}

/// Cross-section stiffnesses and line density.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    /// Axial stiffness EA (N).
    pub ea: f64,
    /// Bending stiffness EI (N m^2); the paper's "EJ".
    pub ei: f64,
    /// Mass per unit length rho A (kg/m).
    pub rho_a: f64,
    /// Axial (Kelvin-Voigt) damping BA (N s): the axial force is
    /// EA eps + BA eps_dot (docs/method.md §2.10, (M34)); 0 for none.
    pub ba: f64,
    /// No compression (chains, ropes; docs/method.md §2.2, (M4a)): the
    /// axial energy is 1/2 EA eps^2 where eps >= 0 and 0 where eps < 0.
    pub tension_only: bool,
    /// A nonlinear axial law from a table (docs/method.md §2.2a, (M4b)),
    /// taking the place of EA eps (engineering strain only); None: EA.
    pub curve: Option<std::sync::Arc<AxialCurve>>,
    /// A viscoelastic law (docs/method.md §2.11, (V1)-(V4)): in a
    /// slab the axial force is the law's, from the internal strain of
    /// every axial point; EA is its static stiffness (statics). None:
    /// elastic.
    pub visco: Option<Viscoelastic>,
    /// MoorDyn's VIV lift (docs/method.md §12.7, (V20)-(V26)), acting
    /// where the line is in water; None: no VIV.
    pub viv: Option<Viv>,
}

/// Which strain and curvature the elastic energy uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Measures {
    pub axial_strain: AxialStrain,
    pub curvature: Curvature,
}

/// Shape function values at one spatial quadrature point, with the
/// quadrature weight times the element length (int dx = sum w l).
#[derive(Clone, Copy, Debug)]
struct SpacePoint<const NS: usize> {
    /// Where the point is along the element, 0 to 1.
    xi: f64,
    wl: f64,
    shape: SpatialShape<NS>,
}

/// One element of length l: everything about it that does not change
/// during a simulation (shape functions at the quadrature points, mass
/// matrix, load integrals).
#[derive(Clone, Debug)]
pub struct CableElement<const NS: usize, const ND: usize> {
    /// Element length l (reference, stress-free).
    pub length: f64,
    pub section: Section,
    pub measures: Measures,
    axial_points: Vec<SpacePoint<NS>>,
    bending_points: Vec<SpacePoint<NS>>,
    /// The NS Gauss points that integrate the mass matrix exactly; the
    /// added mass's rule (docs/method.md §12.5, (W28)).
    mass_points: Vec<SpacePoint<NS>>,
    /// The Gauss points exact for the seabed's push in its ramp on a plane
    /// bed, of degree 3 (NS - 1) along the element (docs/method.md §12.2,
    /// (W47a)), on [0, 1], to be mapped onto a piece in the bed.
    bed_points: Vec<SpacePoint<NS>>,
    /// The shapes at the NS equally spaced points xi_j = j / (NS - 1)
    /// through whose penetrations the seabed's gap polynomial is found
    /// (docs/method.md §12.2, (W47c)).
    bed_samples: Vec<SpatialShape<NS>>,
    /// Consistent mass matrix per coordinate direction,
    /// `M_kl = int rho A N_k N_l dx` (exact); the element mass matrix is M (x) I_3
    /// (docs/method.md §2.1, (M2)).
    pub mass: [[f64; NS]; NS],
    /// `int rho A N_k dx`: the gravity load of eq. (13) is this times g.
    pub weight_integrals: [f64; NS],
    /// The shape functions (to evaluate the element between its
    /// quadrature points).
    shape: ShapeFn<NS>,
}

/// The NS shape functions as a function of (xi, l).
pub type ShapeFn<const NS: usize> = fn(f64, f64) -> SpatialShape<NS>;

/// Spatial quadrature of the strain energy: Gauss points for the axial term
/// and for the bending term (the paper uses the same rule for both).
#[derive(Clone, Debug, PartialEq)]
pub struct SpaceRules {
    pub axial: GaussRule,
    pub bending: GaussRule,
}

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// The least axial strain (eq. 8) at the points of the axial rule,
    /// where the axial energy is evaluated, for coordinates `q`.
    pub fn least_axial_strain(&self, q: &[f64]) -> f64 {
        self.axial_points
            .iter()
            .map(|p| axial_strain(self.measures.axial_strain, &p.shape.gradients(q).0))
            .fold(f64::INFINITY, f64::min)
    }

    /// The points of the axial rule.
    pub fn axial_rule_points(&self) -> usize {
        self.axial_points.len()
    }

    /// The interpolation defect of the axial strain (eq. 8) at the points
    /// of the axial rule, for coordinates `q`: the strain there minus the
    /// strains at the element's two ends (its nodes' r_x) interpolated
    /// linearly between them (docs/method.md §11.6, (M32b)).
    pub fn axial_strain_defects(&self, q: &[f64]) -> Vec<f64> {
        let measure = self.measures.axial_strain;
        let end = |o: usize| axial_strain(measure, &[q[o], q[o + 1], q[o + 2]]);
        let (a, b) = (end(3), end(ND / 2 + 3));
        self.axial_points
            .iter()
            .map(|p| axial_strain(measure, &p.shape.gradients(q).0) - ((1.0 - p.xi) * a + p.xi * b))
            .collect()
    }

    /// The potential of constant axial forces `force` (N, one per point
    /// of the axial rule), V = sum w l N eps, at coordinates `q`: what
    /// [`Self::add_axial_forces`] differentiates.
    pub fn axial_force_potential(&self, q: &[f64], force: &[f64]) -> f64 {
        let measure = self.measures.axial_strain;
        self.axial_points
            .iter()
            .zip(force)
            .map(|(p, &n)| p.wl * n * axial_strain(measure, &p.shape.gradients(q).0))
            .sum()
    }

    /// Adds the virtual work of the axial forces `force` (N, one per
    /// point of the axial rule) at coordinates `q` to the gradient,
    /// sum w l N d eps/dq, and (if asked) its derivative, sum w l N
    /// d2 eps/dq2, to the Hessian: an initial axial force along the line.
    pub fn add_axial_forces(
        &self,
        q: &[f64; ND],
        force: &[f64],
        grad: &mut [f64; ND],
        hess: Option<&mut [[f64; ND]; ND]>,
    ) {
        let mut hess = hess;
        for (p, &n) in self.axial_points.iter().zip(force) {
            let (rx, _) = p.shape.gradients(q);
            let (d, h) = axial_strain_derivatives(self.measures.axial_strain, &rx);
            let a = &p.shape.n_x;
            for k in 0..NS {
                for i in 0..3 {
                    grad[3 * k + i] += p.wl * n * a[k] * d[i];
                }
            }
            if let Some(hm) = hess.as_deref_mut() {
                for k in 0..NS {
                    for l in 0..NS {
                        let c = p.wl * n * a[k] * a[l];
                        for i in 0..3 {
                            for j in 0..3 {
                                hm[3 * k + i][3 * l + j] += c * h[i][j];
                            }
                        }
                    }
                }
            }
        }
    }

    /// Builds the element. The mass matrix and weight integrals are exact
    /// (NS Gauss points integrate the degree 2 NS - 2 products); the strain
    /// energy uses `rules`.
    pub fn new(
        shape: ShapeFn<NS>,
        length: f64,
        section: Section,
        measures: Measures,
        rules: &SpaceRules,
    ) -> Self {
        assert_eq!(ND, 3 * NS, "ND must be 3 NS");
        let at = |rule: &GaussRule| -> Vec<SpacePoint<NS>> {
            rule.iter()
                .map(|(xi, w)| SpacePoint {
                    xi,
                    wl: w * length,
                    shape: shape(xi, length),
                })
                .collect()
        };
        let exact = GaussRule::new(NS).expect("NS <= 10");
        // m points are exact to degree 2 m - 1 >= 3 (NS - 1).
        let bed_rule = GaussRule::new((3 * (NS - 1) + 1).div_ceil(2)).expect("NS <= 6");
        let mut mass = [[0.0; NS]; NS];
        let mut weight_integrals = [0.0; NS];
        for (xi, w) in exact.iter() {
            let s = shape(xi, length);
            for k in 0..NS {
                weight_integrals[k] += w * length * section.rho_a * s.n[k];
                for l in 0..NS {
                    mass[k][l] += w * length * section.rho_a * s.n[k] * s.n[l];
                }
            }
        }
        CableElement {
            length,
            section,
            measures,
            axial_points: at(&rules.axial),
            bending_points: at(&rules.bending),
            mass_points: at(&exact),
            bed_points: at(&bed_rule),
            bed_samples: (0..NS)
                .map(|j| shape(j as f64 / (NS - 1) as f64, length))
                .collect(),
            mass,
            weight_integrals,
            shape,
        }
    }

    /// `M q` for element coordinates (the mass matrix is M (x) I_3).
    pub fn mass_times(&self, q: &[f64; ND]) -> [f64; ND] {
        let mut out = [0.0; ND];
        for k in 0..NS {
            for l in 0..NS {
                let m = self.mass[k][l];
                for i in 0..3 {
                    out[3 * k + i] += m * q[3 * l + i];
                }
            }
        }
        out
    }

    /// Gravity load vector f_g = int rho A N^T g dx (eq. 13).
    pub fn gravity_load(&self, g: &[f64; 3]) -> [f64; ND] {
        let mut f = [0.0; ND];
        for k in 0..NS {
            for i in 0..3 {
                f[3 * k + i] = self.weight_integrals[k] * g[i];
            }
        }
        f
    }
}

fn dot_n<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter().zip(b.iter()).map(|(x, y)| x * y).sum()
}
