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

use crate::quadrature::GaussRule;
use crate::shape::{SpatialShape, TimeShape};

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
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Section {
    /// Axial stiffness EA (N).
    pub ea: f64,
    /// Bending stiffness EI (N m^2); the paper's "EJ".
    pub ei: f64,
    /// Mass per unit length rho A (kg/m).
    pub rho_a: f64,
}

/// Which strain and curvature the elastic energy uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Measures {
    pub axial_strain: AxialStrain,
    pub curvature: Curvature,
}

/// Axial strain and its first two derivatives with respect to r_x.
pub fn axial_strain(measure: AxialStrain, rx: &[f64; 3]) -> f64 {
    let g = dot(rx, rx);
    match measure {
        AxialStrain::Green => 0.5 * (g - 1.0),
        AxialStrain::Engineering => g.sqrt() - 1.0,
    }
}

/// Curvature of the centre line from r_x and r_xx (eq. 9 or the exact form).
pub fn curvature(form: Curvature, rx: &[f64; 3], rxx: &[f64; 3]) -> f64 {
    let c = cross(rx, rxx);
    let g = dot(rx, rx);
    dot(&c, &c).sqrt() / g.powf(0.5 * form.power() as f64)
}

/// Axial energy density `1/2 EA eps^2` (eq. 12, first term), its gradient
/// and Hessian with respect to r_x (docs/method.md §2.2, (M3)-(M4)).
///
/// ```text
///   Green:        dU/dr_x = EA eps r_x,      d2U = EA (r_x r_x^T + eps I)
///   engineering:  dU/dr_x = EA eps n,        d2U = EA (n n^T + eps (I - n n^T) / |r_x|),
///                 n = r_x / |r_x|
/// ```
pub fn axial_energy_density(
    measure: AxialStrain,
    ea: f64,
    rx: &[f64; 3],
) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    axial_energy_terms(measure, ea, rx, true)
}

/// [`axial_energy_density`] without the Hessian (a residual evaluation).
#[inline]
pub fn axial_energy_gradient(measure: AxialStrain, ea: f64, rx: &[f64; 3]) -> (f64, [f64; 3]) {
    let (e, g, _) = axial_energy_terms(measure, ea, rx, false);
    (e, g)
}

#[inline(always)]
fn axial_energy_terms(
    measure: AxialStrain,
    ea: f64,
    rx: &[f64; 3],
    with_hessian: bool,
) -> (f64, [f64; 3], [[f64; 3]; 3]) {
    let g = dot(rx, rx);
    let mut grad = [0.0; 3];
    let mut hess = [[0.0; 3]; 3];
    match measure {
        AxialStrain::Green => {
            let eps = 0.5 * (g - 1.0);
            for i in 0..3 {
                grad[i] = ea * eps * rx[i];
            }
            if with_hessian {
                for i in 0..3 {
                    for j in 0..3 {
                        hess[i][j] = ea * rx[i] * rx[j];
                    }
                    hess[i][i] += ea * eps;
                }
            }
            (0.5 * ea * eps * eps, grad, hess)
        }
        AxialStrain::Engineering => {
            let len = g.sqrt();
            let eps = len - 1.0;
            let n = [rx[0] / len, rx[1] / len, rx[2] / len];
            let c = eps / len;
            for i in 0..3 {
                grad[i] = ea * eps * n[i];
            }
            if with_hessian {
                for i in 0..3 {
                    for j in 0..3 {
                        hess[i][j] = ea * (1.0 - c) * n[i] * n[j];
                    }
                    hess[i][i] += ea * c;
                }
            }
            (0.5 * ea * eps * eps, grad, hess)
        }
    }
}

/// Bending energy density `1/2 EI kappa^2` (eq. 12, second term), with its
/// gradient and Hessian with respect to `(r_x, r_xx)` (6 numbers;
/// docs/method.md §2.3, (M5)-(M6)).
///
/// Written with x = r_x, y = r_xx, g = x.x, h = y.y, m = x.y and
/// s = |x cross y|^2 = g h - m^2, so kappa^2 = s g^-p (p = 2 for eq. 9,
/// p = 3 for the exact curvature): a form that is smooth at the straight
/// state (s = 0), unlike kappa itself.
///
/// ```text
///   ds/dx = 2h x - 2m y                 ds/dy = 2g y - 2m x
///   d2s/dxdx = 2h I - 2 y y^T           d2s/dydy = 2g I - 2 x x^T
///   d2s/dxdy = 4 x y^T - 2 y x^T - 2m I
///   f = s g^-p:
///   df/dx = g^-p ds/dx - 2p s g^-p-1 x,           df/dy = g^-p ds/dy
///   d2f/dxdx = g^-p d2s/dxdx - 2p g^-p-1 (ds/dx x^T + x ds/dx^T)
///              + 4p(p+1) s g^-p-2 x x^T - 2p s g^-p-1 I
///   d2f/dxdy = g^-p d2s/dxdy - 2p g^-p-1 x ds/dy^T,  d2f/dydy = g^-p d2s/dydy
/// ```
pub fn bending_energy_density(
    form: Curvature,
    ei: f64,
    rx: &[f64; 3],
    rxx: &[f64; 3],
) -> (f64, [f64; 6], [[f64; 6]; 6]) {
    bending_energy_terms(form, ei, rx, rxx, true)
}

/// [`bending_energy_density`] without the Hessian (a residual evaluation).
#[inline]
pub fn bending_energy_gradient(
    form: Curvature,
    ei: f64,
    rx: &[f64; 3],
    rxx: &[f64; 3],
) -> (f64, [f64; 6]) {
    let (e, g, _) = bending_energy_terms(form, ei, rx, rxx, false);
    (e, g)
}

#[inline(always)]
fn bending_energy_terms(
    form: Curvature,
    ei: f64,
    rx: &[f64; 3],
    rxx: &[f64; 3],
    with_hessian: bool,
) -> (f64, [f64; 6], [[f64; 6]; 6]) {
    let x = rx;
    let y = rxx;
    let g = dot(x, x);
    let h = dot(y, y);
    let m = dot(x, y);
    let s = g * h - m * m;
    let p = form.power();
    let pf = p as f64;
    let gp = g.powi(-p);
    let gp1 = gp / g;
    let gp2 = gp1 / g;
    let mut ds_x = [0.0; 3];
    let mut ds_y = [0.0; 3];
    for i in 0..3 {
        ds_x[i] = 2.0 * h * x[i] - 2.0 * m * y[i];
        ds_y[i] = 2.0 * g * y[i] - 2.0 * m * x[i];
    }
    let c = 0.5 * ei;
    let mut grad = [0.0; 6];
    for i in 0..3 {
        grad[i] = c * (gp * ds_x[i] - 2.0 * pf * s * gp1 * x[i]);
        grad[3 + i] = c * gp * ds_y[i];
    }
    let mut hess = [[0.0; 6]; 6];
    if !with_hessian {
        return (c * s * gp, grad, hess);
    }
    for i in 0..3 {
        for j in 0..3 {
            let d = if i == j { 1.0 } else { 0.0 };
            let s_xx = 2.0 * h * d - 2.0 * y[i] * y[j];
            let s_yy = 2.0 * g * d - 2.0 * x[i] * x[j];
            let s_xy = 4.0 * x[i] * y[j] - 2.0 * y[i] * x[j] - 2.0 * m * d;
            let f_xx = gp * s_xx - 2.0 * pf * gp1 * (ds_x[i] * x[j] + x[i] * ds_x[j])
                + 4.0 * pf * (pf + 1.0) * s * gp2 * x[i] * x[j]
                - 2.0 * pf * s * gp1 * d;
            let f_xy = gp * s_xy - 2.0 * pf * gp1 * x[i] * ds_y[j];
            let f_yy = gp * s_yy;
            hess[i][3 + j] = c * f_xy;
            hess[3 + j][i] = c * f_xy;
            if j >= i {
                // Exactly symmetric diagonal blocks: computed once, mirrored.
                hess[i][j] = c * f_xx;
                hess[j][i] = c * f_xx;
                hess[3 + i][3 + j] = c * f_yy;
                hess[3 + j][3 + i] = c * f_yy;
            }
        }
    }
    (c * s * gp, grad, hess)
}

/// Shape function values at one spatial quadrature point, with the
/// quadrature weight times the element length (int dx = sum w l).
#[derive(Clone, Copy, Debug)]
struct SpacePoint<const NS: usize> {
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
    /// Consistent mass matrix per coordinate direction,
    /// `M_kl = int rho A N_k N_l dx` (exact); the element mass matrix is M (x) I_3
    /// (docs/method.md §2.1, (M2)).
    pub mass: [[f64; NS]; NS],
    /// `int rho A N_k dx`: the gravity load of eq. (13) is this times g.
    pub weight_integrals: [f64; NS],
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
                    wl: w * length,
                    shape: shape(xi, length),
                })
                .collect()
        };
        let exact = GaussRule::new(NS).expect("NS <= 10");
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
            mass,
            weight_integrals,
        }
    }

    /// Strain energy U of eq. (12) at element coordinates q.
    pub fn strain_energy(&self, q: &[f64; ND]) -> f64 {
        let mut u = 0.0;
        for p in &self.axial_points {
            let (rx, _) = p.shape.gradients(q);
            let eps = axial_strain(self.measures.axial_strain, &rx);
            u += p.wl * 0.5 * self.section.ea * eps * eps;
        }
        for p in &self.bending_points {
            let (rx, rxx) = p.shape.gradients(q);
            let k = curvature(self.measures.curvature, &rx, &rxx);
            u += p.wl * 0.5 * self.section.ei * k * k;
        }
        u
    }

    /// Strain energy, its gradient dU/dq and (if asked) its Hessian d2U/dq2.
    ///
    /// With a = N_x and b = N_xx at a point, dU/dq_k = a_k dU/dr_x + b_k
    /// dU/dr_xx and the (k, l) 3x3 block of the Hessian is
    /// a_k a_l H_xx + a_k b_l H_xy + b_k a_l H_yx + b_k b_l H_yy.
    pub fn strain_energy_derivatives(
        &self,
        q: &[f64; ND],
        grad: &mut [f64; ND],
        hess: Option<&mut [[f64; ND]; ND]>,
    ) -> f64 {
        *grad = [0.0; ND];
        let mut hess = hess;
        if let Some(h) = hess.as_deref_mut() {
            *h = [[0.0; ND]; ND];
        }
        let mut u = 0.0;
        let with_hessian = hess.is_some();
        for p in &self.axial_points {
            let (rx, _) = p.shape.gradients(q);
            let (e, g, h) = axial_energy_terms(
                self.measures.axial_strain,
                self.section.ea,
                &rx,
                with_hessian,
            );
            u += p.wl * e;
            let a = &p.shape.n_x;
            for k in 0..NS {
                for i in 0..3 {
                    grad[3 * k + i] += p.wl * a[k] * g[i];
                }
            }
            if let Some(hm) = hess.as_deref_mut() {
                for k in 0..NS {
                    for l in k..NS {
                        let c = p.wl * a[k] * a[l];
                        for i in 0..3 {
                            for j in 0..3 {
                                hm[3 * k + i][3 * l + j] += c * h[i][j];
                            }
                        }
                    }
                }
            }
        }
        for p in &self.bending_points {
            let (rx, rxx) = p.shape.gradients(q);
            let (e, g, h) = bending_energy_terms(
                self.measures.curvature,
                self.section.ei,
                &rx,
                &rxx,
                with_hessian,
            );
            u += p.wl * e;
            let a = &p.shape.n_x;
            let b = &p.shape.n_xx;
            for k in 0..NS {
                for i in 0..3 {
                    grad[3 * k + i] += p.wl * (a[k] * g[i] + b[k] * g[3 + i]);
                }
            }
            if let Some(hm) = hess.as_deref_mut() {
                for k in 0..NS {
                    for l in k..NS {
                        let aa = p.wl * a[k] * a[l];
                        let ab = p.wl * a[k] * b[l];
                        let ba = p.wl * b[k] * a[l];
                        let bb = p.wl * b[k] * b[l];
                        for i in 0..3 {
                            for j in 0..3 {
                                hm[3 * k + i][3 * l + j] += aa * h[i][j]
                                    + ab * h[i][3 + j]
                                    + ba * h[3 + i][j]
                                    + bb * h[3 + i][3 + j];
                            }
                        }
                    }
                }
            }
        }
        if let Some(hm) = hess {
            // Mirror the blocks l < k from the computed upper block triangle.
            for k in 0..NS {
                for l in 0..k {
                    for i in 0..3 {
                        for j in 0..3 {
                            hm[3 * k + i][3 * l + j] = hm[3 * l + j][3 * k + i];
                        }
                    }
                }
            }
        }
        u
    }

    /// Static drag (a cable at rest in a moving fluid; docs/method.md §2.8,
    /// §6.8): subtracts the generalized force int N^T f(0, r_x) dx, times
    /// `factor`, from `grad` (= dU/dq) and its derivative from `hess`.
    pub fn add_static_drag(
        &self,
        drag: &crate::loads::AirDrag,
        factor: f64,
        q: &[f64; ND],
        grad: &mut [f64; ND],
        hess: Option<&mut [[f64; ND]; ND]>,
    ) {
        let mut hess = hess;
        for p in &self.axial_points {
            let (rx, _) = p.shape.gradients(q);
            let (f, _, dx) = drag.force(&[0.0; 3], &rx);
            for k in 0..NS {
                for i in 0..3 {
                    grad[3 * k + i] -= factor * p.wl * p.shape.n[k] * f[i];
                }
            }
            if let Some(h) = hess.as_deref_mut() {
                for k in 0..NS {
                    for l in 0..NS {
                        let b = factor * p.wl * p.shape.n[k] * p.shape.n_x[l];
                        for i in 0..3 {
                            for j in 0..3 {
                                h[3 * k + i][3 * l + j] -= b * dx[i][j];
                            }
                        }
                    }
                }
            }
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

    /// Slab action A^e of eq. (10) for unknowns `y = [e_a, v_a, e_b, v_b]`.
    pub fn slab_action(&self, slab: &TimeSlab, y: &[[f64; ND]; 4], g: &[f64; 3]) -> f64 {
        let fg = self.gravity_load(g);
        let mut action = 0.0;
        for tp in &slab.points {
            let (q, qdot) = interpolate_in_time(&tp.shape, y);
            let mq = self.mass_times(&qdot);
            let kinetic = 0.5 * dot_n(&qdot, &mq);
            let strain = self.strain_energy(&q);
            let gravity = dot_n(&fg, &q);
            action += tp.w_dt * (kinetic - strain + gravity);
        }
        action
    }

    /// Gradient of the slab action with respect to `y` (plus the virtual
    /// work of the drag loads, eq. 17) and, if `with_hessian`, the
    /// matrices at the time points from which every block of its Jacobian
    /// follows (see [`SlabDerivatives`] and [`Self::slab_hessian_block`]).
    ///
    /// Drag, per unit length f(r_dot, r_x), integrated with the axial rule
    /// (docs/method.md §2.8, (M11); the rest is (M14) of §3.2):
    ///
    /// ```text
    ///   dW/dy_m   = sum_g w_g dt phi_m sum_s w_s l N_k f
    ///   C_g = sum_s w_s l N_k N_l df/dr_dot,   G_g = sum_s w_s l N_k N_x,l df/dr_x
    ///   block_mn += sum_g w_g dt phi_m (phidot_n C_g + phi_n G_g)
    /// ```
    pub fn slab_derivatives(
        &self,
        slab: &TimeSlab,
        y: &[[f64; ND]; 4],
        loads: &SlabLoads,
        with_hessian: bool,
        out: &mut SlabDerivatives<ND>,
    ) {
        let fg = self.gravity_load(&loads.gravity);
        out.grad = [[0.0; ND]; 4];
        out.action = 0.0;
        out.drag_work = 0.0;
        out.has_drag = !loads.drag.is_empty();
        let np = slab.points.len();
        if out.k_at_points.len() < np {
            out.k_at_points.resize(np, [[0.0; ND]; ND]);
        }
        if out.has_drag && with_hessian && out.c_at_points.len() < np {
            out.c_at_points.resize(np, [[0.0; ND]; ND]);
            out.g_at_points.resize(np, [[0.0; ND]; ND]);
        }
        let mut du = [0.0; ND];
        for (gi, tp) in slab.points.iter().enumerate() {
            let (q, qdot) = interpolate_in_time(&tp.shape, y);
            let mq = self.mass_times(&qdot);
            let hess = if with_hessian {
                Some(&mut out.k_at_points[gi])
            } else {
                None
            };
            let strain = self.strain_energy_derivatives(&q, &mut du, hess);
            out.action += tp.w_dt * (0.5 * dot_n(&qdot, &mq) - strain + dot_n(&fg, &q));
            // Generalized drag force on q at this time point: f_q = sum N_k f.
            let mut fq = [0.0; ND];
            if out.has_drag {
                if with_hessian {
                    out.c_at_points[gi] = [[0.0; ND]; ND];
                    out.g_at_points[gi] = [[0.0; ND]; ND];
                }
                for drag in loads.drag {
                    for p in &self.axial_points {
                        let (rx, _) = p.shape.gradients(&q);
                        let mut rdot = [0.0; 3];
                        for k in 0..NS {
                            for i in 0..3 {
                                rdot[i] += p.shape.n[k] * qdot[3 * k + i];
                            }
                        }
                        let (f, dv, dx) = drag.force(&rdot, &rx);
                        out.drag_work +=
                            tp.w_dt * p.wl * (f[0] * rdot[0] + f[1] * rdot[1] + f[2] * rdot[2]);
                        for k in 0..NS {
                            for i in 0..3 {
                                fq[3 * k + i] += p.wl * p.shape.n[k] * f[i];
                            }
                        }
                        if with_hessian {
                            let (c, g) = (&mut out.c_at_points[gi], &mut out.g_at_points[gi]);
                            for k in 0..NS {
                                for l in 0..NS {
                                    let a = p.wl * p.shape.n[k] * p.shape.n[l];
                                    let b = p.wl * p.shape.n[k] * p.shape.n_x[l];
                                    for i in 0..3 {
                                        for j in 0..3 {
                                            c[3 * k + i][3 * l + j] += a * dv[i][j];
                                            g[3 * k + i][3 * l + j] += b * dx[i][j];
                                        }
                                    }
                                }
                            }
                        }
                    }
                }
            }
            for m in 0..4 {
                let a = tp.w_dt * tp.shape.t_dot[m];
                let b = tp.w_dt * tp.shape.t[m];
                for d in 0..ND {
                    out.grad[m][d] += a * mq[d] - b * (du[d] - fg[d] - fq[d]);
                }
            }
        }
    }

    /// Hessian block d2A^e / dy_m dy_n (ND x ND) from the derivatives
    /// evaluated by [`Self::slab_derivatives`] with `with_hessian = true`:
    /// `C_mn M (x) I_3 - sum_g w_g dt phi_m phi_n K_g`.
    pub fn slab_hessian_block(
        &self,
        slab: &TimeSlab,
        derivs: &SlabDerivatives<ND>,
        m: usize,
        n: usize,
        out: &mut [[f64; ND]; ND],
    ) {
        *out = [[0.0; ND]; ND];
        for (gi, tp) in slab.points.iter().enumerate() {
            let c = -tp.w_dt * tp.shape.t[m] * tp.shape.t[n];
            let k = &derivs.k_at_points[gi];
            for (orow, krow) in out.iter_mut().zip(k.iter()) {
                for (o, kv) in orow.iter_mut().zip(krow.iter()) {
                    *o += c * kv;
                }
            }
        }
        let cm = slab.kinetic[m][n];
        for k in 0..NS {
            for l in 0..NS {
                let v = cm * self.mass[k][l];
                for i in 0..3 {
                    out[3 * k + i][3 * l + i] += v;
                }
            }
        }
        if derivs.has_drag {
            for (gi, tp) in slab.points.iter().enumerate() {
                let a = tp.w_dt * tp.shape.t[m] * tp.shape.t_dot[n];
                let b = tp.w_dt * tp.shape.t[m] * tp.shape.t[n];
                let (c, g) = (&derivs.c_at_points[gi], &derivs.g_at_points[gi]);
                for (orow, (crow, grow)) in out.iter_mut().zip(c.iter().zip(g.iter())) {
                    for (o, (cv, gv)) in orow.iter_mut().zip(crow.iter().zip(grow.iter())) {
                        *o += a * cv + b * gv;
                    }
                }
            }
        }
    }
}

/// Gradient of the slab action and the strain-energy Hessians at the time
/// quadrature points, for one element and one slab.
#[derive(Clone, Debug)]
pub struct SlabDerivatives<const ND: usize> {
    /// A^e without the drag (for diagnostics and tests).
    pub action: f64,
    /// dA^e/dy_m (with the drag's virtual work) for m = e_a, v_a, e_b, v_b.
    pub grad: [[f64; ND]; 4],
    /// d2U/dq2 at q(t_g), one per time Gauss point.
    pub k_at_points: Vec<[[f64; ND]; ND]>,
    /// Drag: whether there is any, int f . r_dot over the slab (its work,
    /// negative in still air), and the matrices C_g, G_g per time point.
    pub has_drag: bool,
    pub drag_work: f64,
    pub c_at_points: Vec<[[f64; ND]; ND]>,
    pub g_at_points: Vec<[[f64; ND]; ND]>,
}

impl<const ND: usize> Default for SlabDerivatives<ND> {
    fn default() -> Self {
        SlabDerivatives {
            action: 0.0,
            grad: [[0.0; ND]; 4],
            k_at_points: Vec::new(),
            has_drag: false,
            drag_work: 0.0,
            c_at_points: Vec::new(),
            g_at_points: Vec::new(),
        }
    }
}

/// The distributed loads an element sees in a slab: gravity (eq. 13) and
/// air drag (eq. 17).
#[derive(Clone, Copy, Debug)]
pub struct SlabLoads<'a> {
    pub gravity: [f64; 3],
    pub drag: &'a [crate::loads::AirDrag],
}

impl SlabLoads<'_> {
    /// Gravity only.
    pub fn gravity(g: [f64; 3]) -> SlabLoads<'static> {
        SlabLoads {
            gravity: g,
            drag: &[],
        }
    }
}

/// One time quadrature point of a slab: the time shape functions and the
/// weight times the slab length.
#[derive(Clone, Copy, Debug)]
pub struct TimePoint {
    pub w_dt: f64,
    pub shape: TimeShape,
}

/// The time direction of a slab (one layer of space-time elements):
/// eq. (6) evaluated at the time Gauss points.
#[derive(Clone, Debug)]
pub struct TimeSlab {
    pub dt: f64,
    pub points: Vec<TimePoint>,
    /// `C_mn = sum_g w_g dt phidot_m phidot_n`: the kinetic part of the
    /// Hessian is C (x) M.
    pub kinetic: [[f64; 4]; 4],
    /// `b_m = sum_g w_g dt phi_m`: a constant force F does work b_m F . y_m.
    pub load: [f64; 4],
}

impl TimeSlab {
    pub fn new(dt: f64, rule: &GaussRule) -> Self {
        let points: Vec<TimePoint> = rule
            .iter()
            .map(|(tau, w)| TimePoint {
                w_dt: w * dt,
                shape: crate::shape::time_hermite(tau, dt),
            })
            .collect();
        let mut kinetic = [[0.0; 4]; 4];
        let mut load = [0.0; 4];
        for p in &points {
            for m in 0..4 {
                load[m] += p.w_dt * p.shape.t[m];
                for n in 0..4 {
                    kinetic[m][n] += p.w_dt * p.shape.t_dot[m] * p.shape.t_dot[n];
                }
            }
        }
        TimeSlab {
            dt,
            points,
            kinetic,
            load,
        }
    }
}

/// q(t) and qdot(t) from the slab unknowns (eq. 6).
fn interpolate_in_time<const ND: usize>(
    shape: &TimeShape,
    y: &[[f64; ND]; 4],
) -> ([f64; ND], [f64; ND]) {
    let mut q = [0.0; ND];
    let mut qdot = [0.0; ND];
    for m in 0..4 {
        let a = shape.t[m];
        let b = shape.t_dot[m];
        for d in 0..ND {
            q[d] += a * y[m][d];
            qdot[d] += b * y[m][d];
        }
    }
    (q, qdot)
}

pub(crate) fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(crate) fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot_n<const N: usize>(a: &[f64; N], b: &[f64; N]) -> f64 {
    a.iter().zip(b.iter()).map(|(x, y)| x * y).sum()
}
