//! Contact of a line with the seabed (docs/method.md §12.2, (W40)-(W46)):
//! a penalty per unit length on the penetration, MoorDyn's kBot and cBot,
//! and Coulomb friction against sliding with separate axial and
//! transverse coefficients, regularized near zero velocity.
//!
//! The seabed is a plane through `point` with upward unit normal `n`
//! (flat: n = e_z, point = (0, 0, -depth)), or a bathymetry grid
//! ([`super::bathymetry`]), whose local tangent plane gives g and n at
//! each point with their derivatives (W40b)-(W40c). At a point r of the
//! line's axis with velocity r_dot and tangent r_x, per unit unstretched
//! length:
//!
//! ```text
//!   g = n . (p0 - r)                     penetration (> 0 in the bed)    (W40)
//!   P(g) = 0, g^2 / (2 delta), g - delta/2   for g <= 0, < delta, >= delta
//!   S(g) = P'(g) in [0, 1]               contact fraction (C0 ramp)       (W41)
//!   N = d (k P(g) - c S(g) n . r_dot)    normal force (MoorDyn: (kBot pen
//!                                        - cBot v_n) d)                   (W42)
//!   f_n = N n
//! ```
//!
//! The ramp width delta = 1e-3 d makes the force C1 in r (Newton sees a
//! continuous tangent); beyond delta it is MoorDyn's k d g shifted by
//! k d delta/2, a penetration error of delta/2 = 5e-4 d.
//!
//! Friction resists sliding along the bed, in the directions of the line's
//! axis projected on the bed, a = P_n r_x / |P_n r_x| (P_n = I - n n^T),
//! and across it, b = n x a, with the elastic normal force N_e = d k P(g):
//!
//! ```text
//!   v_a = a . r_dot,  v_b = b . r_dot,  phi(v) = v / sqrt(v^2 + v_s^2)   (W43)
//!   f_f = -N_e (mu_a phi(v_a) a + mu_b phi(v_b) b)                       (W44)
//! ```
//!
//! phi is Coulomb's sign(v) regularized below the slip velocity v_s: at
//! |v| = v_s the friction is 1/sqrt(2) of Coulomb's, at 10 v_s 99.5 %.
//! The force's derivatives, for the slab's Jacobian (the matrices C_g,
//! G_g of (M14) and the position part N_k N_l df/dr):
//!
//! ```text
//!   df/dr     = -n n^T d (k P' - c S' n . r_dot) - u (dN_e/dr)^T,
//!               dN_e/dr = -d k P' n,  u = mu_a phi_a a + mu_b phi_b b     (W45)
//!   df/dr_dot = -d c S n n^T - N_e (mu_a phi'_a a a^T + mu_b phi'_b b b^T)
//!   df/dr_x   = -N_e sum_{e = a, b} mu_e (phi'_e e r_dot^T + phi_e I) De,
//!               Da = (I - a a^T) P_n / |P_n r_x|,  Db = [n]x Da          (W46)
//! ```
//!
//! On a bathymetry, g and n depend on r through (W40c): in (W45) the
//! normal force's -n (dg/dr = -n on a plane) becomes dg/dr, the normal's
//! turn adds N dn/dr and -d c S n (r_dot^T dn/dr), and friction's
//! directions turn with n:
//!
//! ```text
//!   da/dr = (I - a a^T) / |P_n r_x| (-(n . r_x) I - n r_x^T) dn/dr,
//!   db/dr = [n]x da/dr - [a]x dn/dr,
//!   df_f/dr += -N_e sum_e mu_e (phi'_e e (r_dot^T de/dr) + phi_e de/dr)  (W46a)
//! ```

use super::bathymetry::{Bathymetry, BedPoint};
use crate::vec3::{cross, dot, mat3_mul};
use std::sync::Arc;

/// Force per unit length at a point and its derivatives with respect to
/// the position r, the tangent r_x and the velocity r_dot (rows: force
/// components).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ForceAtPoint {
    pub force: [f64; 3],
    pub d_r: [[f64; 3]; 3],
    pub d_rx: [[f64; 3]; 3],
    pub d_rdot: [[f64; 3]; 3],
}

/// The seabed's surface: a plane, or a bathymetry grid (W40a).
#[derive(Clone, Debug, PartialEq)]
pub enum BedSurface {
    /// The plane through `point` with upward unit normal `normal` (flat
    /// bed: (0, 0, -depth) and (0, 0, 1)).
    Plane { point: [f64; 3], normal: [f64; 3] },
    /// A bed of varying height, contact on its local tangent plane
    /// (W40b).
    Grid(Arc<Bathymetry>),
}

/// A seabed with a penalty contact and friction (MoorDyn's kBot, cBot and
/// friction coefficients).
#[derive(Clone, Debug, PartialEq)]
pub struct Seabed {
    pub surface: BedSurface,
    /// kBot (Pa/m): normal force per unit length per metre of penetration
    /// per metre of diameter.
    pub stiffness: f64,
    /// cBot (Pa s/m): the same per unit penetration velocity.
    pub damping: f64,
    /// Friction coefficients along the line's axis and across it.
    pub friction_axial: f64,
    pub friction_transverse: f64,
    /// Slip velocity v_s (m/s) below which friction is regularized (W43).
    pub slip_velocity: f64,
}

impl Seabed {
    /// A flat seabed at z = -depth.
    pub fn flat(depth: f64, stiffness: f64, damping: f64) -> Self {
        Seabed {
            surface: BedSurface::Plane {
                point: [0.0, 0.0, -depth],
                normal: [0.0, 0.0, 1.0],
            },
            stiffness,
            damping,
            friction_axial: 0.0,
            friction_transverse: 0.0,
            slip_velocity: 1e-3,
        }
    }

    /// A sloped bed: the plane through `point` with upward normal along
    /// `normal` (any length; made a unit vector here).
    pub fn plane(point: [f64; 3], normal: [f64; 3], stiffness: f64, damping: f64) -> Self {
        let length = dot(normal, normal).sqrt();
        Seabed {
            surface: BedSurface::Plane {
                point,
                normal: normal.map(|c| c / length),
            },
            ..Seabed::flat(0.0, stiffness, damping)
        }
    }

    /// A bed of varying height (W40a)-(W40c).
    pub fn on_grid(bathymetry: Arc<Bathymetry>, stiffness: f64, damping: f64) -> Self {
        Seabed {
            surface: BedSurface::Grid(bathymetry),
            ..Seabed::flat(0.0, stiffness, damping)
        }
    }

    /// The same bed with Coulomb friction.
    pub fn with_friction(mut self, axial: f64, transverse: f64, slip_velocity: f64) -> Self {
        self.friction_axial = axial;
        self.friction_transverse = transverse;
        self.slip_velocity = slip_velocity;
        self
    }

    /// Whether either friction coefficient is nonzero.
    pub fn has_friction(&self) -> bool {
        self.friction_axial != 0.0 || self.friction_transverse != 0.0
    }

    /// The contact geometry at r: (W40) on a plane, (W40b)-(W40c) on a
    /// grid.
    pub fn contact_point(&self, r: &[f64; 3]) -> BedPoint {
        match &self.surface {
            BedSurface::Plane { normal, .. } => BedPoint {
                penetration: self.penetration(r),
                normal: *normal,
                d_penetration: normal.map(|c| -c),
                d_normal: [[0.0; 3]; 3],
            },
            BedSurface::Grid(b) => b.contact_point(r),
        }
    }

    /// The penetration g of (W40) (or (W40b)) at r.
    pub fn penetration(&self, r: &[f64; 3]) -> f64 {
        match &self.surface {
            BedSurface::Plane { point, normal } => {
                let d = [point[0] - r[0], point[1] - r[1], point[2] - r[2]];
                dot(*normal, d)
            }
            BedSurface::Grid(b) => b.contact_point(r).penetration,
        }
    }

    /// The bed's upward unit normal at (above) r.
    pub fn normal_at(&self, r: &[f64; 3]) -> [f64; 3] {
        match &self.surface {
            BedSurface::Plane { normal, .. } => *normal,
            BedSurface::Grid(b) => b.contact_point(r).normal,
        }
    }

    /// The height z of a horizontal plane bed; None for a sloped plane or
    /// a grid.
    pub fn horizontal_height(&self) -> Option<f64> {
        match &self.surface {
            BedSurface::Plane { point, normal } if *normal == [0.0, 0.0, 1.0] => Some(point[2]),
            _ => None,
        }
    }
}

/// The seabed as one line of diameter `diameter` touches it.
#[derive(Clone, Debug, PartialEq)]
pub struct SeabedContact {
    pub seabed: Seabed,
    /// The line's hydrodynamic diameter d (m).
    pub diameter: f64,
}

/// What friction resists: the velocity (dynamics) or the displacement
/// from the seed (statics), where its derivative goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sliding {
    Velocity,
    Position,
}

/// Which part of the contact force: the whole, the normal push with its
/// damping (W42), or the friction (W44). The element integrates the
/// first exactly where it is in the bed and the second at its axial rule
/// (docs/method.md §12.2, (W47a)).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Part {
    Whole,
    Normal,
    Friction,
}

/// P(g), P'(g) = S(g) and P''(g) = S'(g) of (W40)-(W41).
fn smoothed_penetration(g: f64, delta: f64) -> (f64, f64, f64) {
    if g <= 0.0 {
        (0.0, 0.0, 0.0)
    } else if g < delta {
        (0.5 * g * g / delta, g / delta, 1.0 / delta)
    } else {
        (g - 0.5 * delta, 1.0, 0.0)
    }
}

/// phi(v) of (W43) and its derivative.
fn regularized_sign(v: f64, vs: f64) -> (f64, f64) {
    let s = (v * v + vs * vs).sqrt();
    (v / s, vs * vs / (s * s * s))
}

fn outer(a: &[f64; 3], b: &[f64; 3]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i] * b[j]))
}

fn add_scaled(m: &mut [[f64; 3]; 3], s: f64, a: &[[f64; 3]; 3]) {
    for (mr, ar) in m.iter_mut().zip(a) {
        for (x, y) in mr.iter_mut().zip(ar) {
            *x += s * y;
        }
    }
}

impl SeabedContact {
    /// The ramp width delta of (W41): 1e-3 of the diameter.
    pub fn ramp_width(&self) -> f64 {
        1e-3 * self.diameter
    }

    /// The displacement scale u_s of static friction (W48): 1e-3 of the
    /// diameter, the contact ramp's width.
    pub fn static_slip(&self) -> f64 {
        1e-3 * self.diameter
    }

    /// The contact force per unit length (W42)-(W44) and its derivatives
    /// (W45)-(W46) at position r, tangent r_x, velocity r_dot. Zero, with
    /// zero derivatives, clear of the bed.
    pub fn force(&self, r: &[f64; 3], rx: &[f64; 3], rdot: &[f64; 3]) -> ForceAtPoint {
        self.force_at(r, rx, rdot, true)
    }

    /// [`Self::force`], its derivatives only when `derivatives` (else
    /// zero): a residual without a Jacobian skips them, with the same
    /// force to the bit.
    pub(crate) fn force_at(
        &self,
        r: &[f64; 3],
        rx: &[f64; 3],
        rdot: &[f64; 3],
        derivatives: bool,
    ) -> ForceAtPoint {
        self.part_at(Part::Whole, r, rx, rdot, derivatives)
    }

    /// [`Self::force_at`]'s `part`.
    pub(crate) fn part_at(
        &self,
        part: Part,
        r: &[f64; 3],
        rx: &[f64; 3],
        rdot: &[f64; 3],
        derivatives: bool,
    ) -> ForceAtPoint {
        let slide = (rdot, self.seabed.slip_velocity);
        self.force_with(part, (r, rx, rdot), slide, Sliding::Velocity, derivatives)
    }

    /// The contact force on a line at rest whose point at `r` has slid by
    /// `slide` = r - r_0 from where the static solve started (W48):
    /// friction resists that displacement as it resists a velocity in
    /// (W43)-(W44), regularized below u_s = [`Self::static_slip`], so a
    /// line pulled along the bed from its seed carries Coulomb's friction
    /// once it has moved by a few u_s. The derivatives in r include the
    /// slide's (d slide / dr = I); d_rdot is zero.
    pub fn static_force(&self, r: &[f64; 3], rx: &[f64; 3], slide: &[f64; 3]) -> ForceAtPoint {
        self.static_part(Part::Whole, r, rx, slide)
    }

    /// [`Self::static_force`]'s `part`.
    pub(crate) fn static_part(
        &self,
        part: Part,
        r: &[f64; 3],
        rx: &[f64; 3],
        slide: &[f64; 3],
    ) -> ForceAtPoint {
        let slide = (slide, self.static_slip());
        let at_rest = (r, rx, &[0.0; 3]);
        let mut out = self.force_with(part, at_rest, slide, Sliding::Position, true);
        out.d_rdot = [[0.0; 3]; 3];
        out
    }

    /// (W42)-(W46) with the normal damping on `rdot` and the friction on
    /// `slide` regularized below `slip` (a velocity in dynamics, a
    /// displacement in statics); the friction's derivative in `slide`
    /// goes into d_r or d_rdot as `sliding` says; the derivatives only
    /// when `derivatives`.
    fn force_with(
        &self,
        part: Part,
        (r, rx, rdot): (&[f64; 3], &[f64; 3], &[f64; 3]),
        (slide, slip): (&[f64; 3], f64),
        sliding: Sliding,
        derivatives: bool,
    ) -> ForceAtPoint {
        let bed = &self.seabed;
        let at = bed.contact_point(r);
        let n = at.normal;
        let d = self.diameter;
        let (p, s, ds) = smoothed_penetration(at.penetration, self.ramp_width());
        let mut out = ForceAtPoint::default();
        if s == 0.0 {
            return out;
        }
        let vn = dot(n, rdot);
        let normal = d * (bed.stiffness * p - bed.damping * s * vn);
        if part != Part::Friction {
            out.force = n.map(|c| normal * c);
        }
        if derivatives && part != Part::Friction {
            // dN/dr = d (k S - c S' v_n) dg/dr - d c S r_dot^T dn/dr and
            // df/dr = n dN/dr + N dn/dr ((W45), (W46a)).
            let by_depth = d * (bed.stiffness * s - bed.damping * ds * vn);
            let dn = &at.d_normal;
            let d_normal_force: [f64; 3] = std::array::from_fn(|j| {
                let turn: f64 = (0..3).map(|i| rdot[i] * dn[i][j]).sum();
                by_depth * at.d_penetration[j] - d * bed.damping * s * turn
            });
            add_scaled(&mut out.d_r, 1.0, &outer(&n, &d_normal_force));
            add_scaled(&mut out.d_r, normal, dn);
            add_scaled(&mut out.d_rdot, -d * bed.damping * s, &outer(&n, &n));
        }
        if bed.has_friction() && part != Part::Normal {
            let normal = (d * bed.stiffness * p, d * bed.stiffness * s);
            let slide = (slide, slip);
            self.add_friction(
                &at,
                normal,
                rx,
                slide,
                derivatives.then_some(sliding),
                &mut out,
            );
        }
        out
    }

    /// Adds the friction (W43)-(W44) on the sliding `rdot` (a velocity,
    /// or in statics a displacement, regularized below `vs`) with elastic
    /// normal force `ne` (and its derivative in the penetration, `dne`)
    /// at the bed's point `at` and, given what the sliding is
    /// (`derivatives`), its derivatives (W45)-(W46a), the sliding's into
    /// d_r or d_rdot.
    fn add_friction(
        &self,
        at: &BedPoint,
        (ne, dne): (f64, f64),
        rx: &[f64; 3],
        (rdot, vs): (&[f64; 3], f64),
        derivatives: Option<Sliding>,
        out: &mut ForceAtPoint,
    ) {
        let bed = &self.seabed;
        let n = at.normal;
        // P_n r_x: the tangent's part along the bed.
        let rn = dot(n, rx);
        let pt = [rx[0] - rn * n[0], rx[1] - rn * n[1], rx[2] - rn * n[2]];
        let len = dot(pt, pt).sqrt();
        if len == 0.0 || ne == 0.0 && dne == 0.0 {
            return;
        }
        let a = pt.map(|c| c / len);
        let b = cross(n, a);
        let directions = derivatives.map(|sliding| (sliding, Turns::of(at, a, rx, len)));
        let mut u = [0.0; 3];
        for (e, mu, axial) in [
            (a, bed.friction_axial, true),
            (b, bed.friction_transverse, false),
        ] {
            if mu == 0.0 {
                continue;
            }
            let (phi, dphi) = regularized_sign(dot(e, rdot), vs);
            for i in 0..3 {
                u[i] += mu * phi * e[i];
                out.force[i] -= ne * mu * phi * e[i];
            }
            let Some((sliding, turns)) = &directions else {
                continue;
            };
            let by_sliding = match sliding {
                Sliding::Position => &mut out.d_r,
                Sliding::Velocity => &mut out.d_rdot,
            };
            add_scaled(by_sliding, -ne * mu * dphi, &outer(&e, &e));
            // d(phi e)/dq = phi' e (r_dot^T De) + phi De, for q = r_x and,
            // on a bathymetry, q = r.
            let (de_rx, de_r) = turns.of_direction(axial);
            for (target, de) in [(&mut out.d_rx, Some(de_rx)), (&mut out.d_r, de_r)] {
                let Some(de) = de else { continue };
                let rdot_de: [f64; 3] =
                    std::array::from_fn(|j| (0..3).map(|k| rdot[k] * de[k][j]).sum());
                add_scaled(target, -ne * mu * dphi, &outer(&e, &rdot_de));
                add_scaled(target, -ne * mu * phi, de);
            }
        }
        if directions.is_some() {
            // -u (dN_e/dr)^T with dN_e/dr = dne dg/dr.
            add_scaled(&mut out.d_r, -dne, &outer(&u, &at.d_penetration));
        }
    }
}

type Mat3 = [[f64; 3]; 3];

/// How friction's directions a and b turn: with the tangent r_x (W46),
/// and on a bathymetry with the position r through the normal (W46a).
struct Turns {
    da_rx: [[f64; 3]; 3],
    db_rx: [[f64; 3]; 3],
    /// (da/dr, db/dr), None on a plane.
    by_position: Option<[Mat3; 2]>,
}

impl Turns {
    /// At the bed's point `at`, direction a = P_n r_x / `len`.
    fn of(at: &BedPoint, a: [f64; 3], rx: &[f64; 3], len: f64) -> Turns {
        let n = at.normal;
        let identity = |i: usize, j: usize| f64::from(u8::from(i == j));
        let pn: [[f64; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| identity(i, j) - n[i] * n[j]));
        let ia: [[f64; 3]; 3] =
            std::array::from_fn(|i| std::array::from_fn(|j| (identity(i, j) - a[i] * a[j]) / len));
        let nx = skew(n);
        let da_rx = mat3_mul(&ia, &pn);
        let db_rx = mat3_mul(&nx, &da_rx);
        let curved = at.d_normal.iter().flatten().any(|c| *c != 0.0);
        let by_position = curved.then(|| {
            // d(P_n r_x)/dn = -(n . r_x) I - n r_x^T.
            let rn = dot(n, *rx);
            let dw_dn: [[f64; 3]; 3] = std::array::from_fn(|i| {
                std::array::from_fn(|k| -rn * identity(i, k) - n[i] * rx[k])
            });
            let da_r = mat3_mul(&ia, &mat3_mul(&dw_dn, &at.d_normal));
            let mut db_r = mat3_mul(&nx, &da_r);
            add_scaled(&mut db_r, -1.0, &mat3_mul(&skew(a), &at.d_normal));
            [da_r, db_r]
        });
        Turns {
            da_rx,
            db_rx,
            by_position,
        }
    }

    /// (de/dr_x, de/dr) of direction a (`axial`) or b.
    fn of_direction(&self, axial: bool) -> (&[[f64; 3]; 3], Option<&[[f64; 3]; 3]>) {
        match (axial, &self.by_position) {
            (true, p) => (&self.da_rx, p.as_ref().map(|[da, _]| da)),
            (false, p) => (&self.db_rx, p.as_ref().map(|[_, db]| db)),
        }
    }
}

/// [v]x, the matrix of v x.
fn skew(v: [f64; 3]) -> [[f64; 3]; 3] {
    [[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]]
}

#[cfg(test)]
#[path = "seabed_tests.rs"]
mod tests;
