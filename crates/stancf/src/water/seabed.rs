//! Contact of a line with the seabed (docs/method.md §12.2, (W40)-(W46)):
//! a penalty per unit length on the penetration, MoorDyn's kBot and cBot,
//! and Coulomb friction against sliding with separate axial and
//! transverse coefficients, regularized near zero velocity.
//!
//! The seabed is a plane through `point` with upward unit normal `n`
//! (flat: n = e_z, point = (0, 0, -depth)). At a point r of the line's
//! axis with velocity r_dot and tangent r_x, per unit unstretched length:
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

use crate::vec3::{cross, dot, mat3_mul};

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

/// A plane seabed with a penalty contact and friction (MoorDyn's kBot,
/// cBot and friction coefficients).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seabed {
    /// A point of the plane (flat bed: (0, 0, -depth)).
    pub point: [f64; 3],
    /// Upward unit normal (flat bed: (0, 0, 1)).
    pub normal: [f64; 3],
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
            point: [0.0, 0.0, -depth],
            normal: [0.0, 0.0, 1.0],
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
            point,
            normal: normal.map(|c| c / length),
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

    /// The penetration g of (W40) at r.
    pub fn penetration(&self, r: &[f64; 3]) -> f64 {
        let d = [
            self.point[0] - r[0],
            self.point[1] - r[1],
            self.point[2] - r[2],
        ];
        dot(self.normal, d)
    }
}

/// The seabed as one line of diameter `diameter` touches it.
#[derive(Clone, Copy, Debug, PartialEq)]
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
        let slide = (rdot, self.seabed.slip_velocity);
        self.force_with(r, rx, rdot, slide, Sliding::Velocity, derivatives)
    }

    /// The contact force on a line at rest whose point at `r` has slid by
    /// `slide` = r - r_0 from where the static solve started (W48):
    /// friction resists that displacement as it resists a velocity in
    /// (W43)-(W44), regularized below u_s = [`Self::static_slip`], so a
    /// line pulled along the bed from its seed carries Coulomb's friction
    /// once it has moved by a few u_s. The derivatives in r include the
    /// slide's (d slide / dr = I); d_rdot is zero.
    pub fn static_force(&self, r: &[f64; 3], rx: &[f64; 3], slide: &[f64; 3]) -> ForceAtPoint {
        let slide = (slide, self.static_slip());
        let mut out = self.force_with(r, rx, &[0.0; 3], slide, Sliding::Position, true);
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
        r: &[f64; 3],
        rx: &[f64; 3],
        rdot: &[f64; 3],
        (slide, slip): (&[f64; 3], f64),
        sliding: Sliding,
        derivatives: bool,
    ) -> ForceAtPoint {
        let bed = &self.seabed;
        let n = bed.normal;
        let d = self.diameter;
        let (p, s, ds) = smoothed_penetration(bed.penetration(r), self.ramp_width());
        let mut out = ForceAtPoint::default();
        if s == 0.0 {
            return out;
        }
        let vn = dot(n, rdot);
        let normal = d * (bed.stiffness * p - bed.damping * s * vn);
        out.force = n.map(|c| normal * c);
        if derivatives {
            let nn = outer(&n, &n);
            let stiffness = -d * (bed.stiffness * s - bed.damping * ds * vn);
            add_scaled(&mut out.d_r, stiffness, &nn);
            add_scaled(&mut out.d_rdot, -d * bed.damping * s, &nn);
        }
        if bed.has_friction() {
            let normal = (d * bed.stiffness * p, d * bed.stiffness * s);
            let slide = (slide, slip);
            self.add_friction(normal, rx, slide, derivatives.then_some(sliding), &mut out);
        }
        out
    }

    /// Adds the friction (W43)-(W44) on the sliding `rdot` (a velocity,
    /// or in statics a displacement, regularized below `vs`) with elastic
    /// normal force `ne` (and its derivative along -n, `dne`) and, given
    /// what the sliding is (`derivatives`), its derivatives (W45)-(W46),
    /// the sliding's into d_r or d_rdot.
    fn add_friction(
        &self,
        (ne, dne): (f64, f64),
        rx: &[f64; 3],
        (rdot, vs): (&[f64; 3], f64),
        derivatives: Option<Sliding>,
        out: &mut ForceAtPoint,
    ) {
        let bed = &self.seabed;
        let n = bed.normal;
        // P_n r_x: the tangent's part along the bed.
        let rn = dot(n, rx);
        let pt = [rx[0] - rn * n[0], rx[1] - rn * n[1], rx[2] - rn * n[2]];
        let len = dot(pt, pt).sqrt();
        if len == 0.0 || ne == 0.0 && dne == 0.0 {
            return;
        }
        let a = pt.map(|c| c / len);
        let b = cross(n, a);
        // Da = (I - a a^T) P_n / |P_n r_x|, Db = [n]x Da: only for the
        // derivatives.
        let directions = derivatives.map(|sliding| {
            let pn: [[f64; 3]; 3] = std::array::from_fn(|i| {
                std::array::from_fn(|j| f64::from(u8::from(i == j)) - n[i] * n[j])
            });
            let ia: [[f64; 3]; 3] = std::array::from_fn(|i| {
                std::array::from_fn(|j| (f64::from(u8::from(i == j)) - a[i] * a[j]) / len)
            });
            let da = mat3_mul(&ia, &pn);
            let nx = [[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]];
            (sliding, da, mat3_mul(&nx, &da))
        });
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
            let Some((sliding, da, db)) = &directions else {
                continue;
            };
            let de = if axial { da } else { db };
            let by_sliding = match sliding {
                Sliding::Position => &mut out.d_r,
                Sliding::Velocity => &mut out.d_rdot,
            };
            add_scaled(by_sliding, -ne * mu * dphi, &outer(&e, &e));
            // d(phi e)/dr_x = phi' e (r_dot^T De) + phi De.
            let rdot_de: [f64; 3] =
                std::array::from_fn(|j| (0..3).map(|k| rdot[k] * de[k][j]).sum());
            add_scaled(&mut out.d_rx, -ne * mu * dphi, &outer(&e, &rdot_de));
            add_scaled(&mut out.d_rx, -ne * mu * phi, de);
        }
        if directions.is_some() {
            // -u (dN_e/dr)^T with dN_e/dr = -dne n.
            add_scaled(&mut out.d_r, dne, &outer(&u, &n));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bed() -> SeabedContact {
        SeabedContact {
            seabed: Seabed::plane([0.3, 0.0, -50.0], [0.1, -0.2, 1.0], 3e6, 3e5)
                .with_friction(0.6, 1.0, 0.05),
            diameter: 0.08,
        }
    }

    /// Central differences of `force` in argument `which` (r, r_x, r_dot)
    /// against the analytic derivative, to 1e-6 of the largest derivative
    /// (step h: round-off eps |f| / h and truncation h^2 f''' are both
    /// below 1e-9 of it for these magnitudes; P is quadratic in the ramp).
    fn check(c: &SeabedContact, args: [[f64; 3]; 3], which: usize, h: f64) {
        let f0 = c.force(&args[0], &args[1], &args[2]);
        let analytic = [f0.d_r, f0.d_rx, f0.d_rdot][which];
        let scale = [f0.d_r, f0.d_rx, f0.d_rdot]
            .iter()
            .flatten()
            .flatten()
            .fold(0.0f64, |m, x| m.max(x.abs()));
        for j in 0..3 {
            let (mut plus, mut minus) = (args, args);
            plus[which][j] += h;
            minus[which][j] -= h;
            let fp = c.force(&plus[0], &plus[1], &plus[2]).force;
            let fm = c.force(&minus[0], &minus[1], &minus[2]).force;
            for i in 0..3 {
                let fd = (fp[i] - fm[i]) / (2.0 * h);
                assert!(
                    (fd - analytic[i][j]).abs() <= 1e-6 * scale + 1e-9,
                    "arg {which} d f{i}/d x{j}: fd {fd} analytic {}",
                    analytic[i][j]
                );
            }
        }
    }

    #[test]
    fn the_contact_force_derivatives_match_finite_differences() {
        let c = bed();
        let n = c.seabed.normal;
        let rx = [0.8, 0.5, -0.1];
        let v = [0.03, -0.02, -0.01];
        // Deep in the bed, in the ramp, and clear of it.
        for below in [0.01, 0.3 * c.ramp_width(), -0.01] {
            let along = [0.4, 0.9, 0.0];
            let along_n = dot(along, n);
            let r: [f64; 3] = std::array::from_fn(|i| {
                c.seabed.point[i] + along[i] - along_n * n[i] - below * n[i]
            });
            assert!((c.seabed.penetration(&r) - below).abs() < 1e-12);
            let h = if below.abs() < c.ramp_width() {
                1e-8
            } else {
                1e-6
            };
            for which in 0..3 {
                check(&c, [r, rx, v], which, h);
            }
        }
    }

    /// A residual's contact force (no derivatives) is the full one's to
    /// the bit, with friction along and across the line, in and past the
    /// ramp, sliding slower and faster than the slip velocity; its
    /// derivatives are zero.
    #[test]
    fn the_force_without_derivatives_is_the_full_forces_to_the_bit() {
        let c = bed();
        let n = c.seabed.normal;
        for below in [0.01, 0.3 * c.ramp_width(), -0.01] {
            for v in [[0.03, -0.02, -0.01], [2.0, 1.5, -0.3], [-1e-4, 3e-4, 0.0]] {
                let r: [f64; 3] = std::array::from_fn(|i| c.seabed.point[i] - below * n[i]);
                let rx = [0.8, 0.5, -0.1];
                let full = c.force(&r, &rx, &v);
                let lean = c.force_at(&r, &rx, &v, false);
                assert_eq!(lean.force, full.force, "below {below}, v {v:?}");
                assert_eq!((lean.d_r, lean.d_rx, lean.d_rdot), Default::default());
            }
        }
    }

    #[test]
    fn a_line_resting_in_the_bed_feels_its_weight_back_without_friction_at_rest() {
        let c = SeabedContact {
            seabed: Seabed::flat(100.0, 3e6, 3e5).with_friction(0.5, 1.0, 1e-3),
            diameter: 0.1,
        };
        let g = 2e-3;
        let f = c.force(&[5.0, 2.0, -100.0 - g], &[1.0, 0.0, 0.0], &[0.0; 3]);
        let expected = 3e6 * 0.1 * (g - 0.5 * c.ramp_width());
        // The penetration 100 + g - 100 is exact to eps 100 / g = 1e-11.
        assert!((f.force[2] - expected).abs() <= 1e-10 * expected);
        assert_eq!((f.force[0], f.force[1]), (0.0, 0.0));
    }

    #[test]
    fn sliding_friction_is_coulombs_well_above_the_slip_velocity() {
        let c = SeabedContact {
            seabed: Seabed::flat(100.0, 3e6, 0.0).with_friction(0.5, 1.0, 1e-3),
            diameter: 0.1,
        };
        let r = [0.0, 0.0, -100.01];
        let ne = 3e6 * 0.1 * (0.01 - 0.5 * c.ramp_width());
        // Axial (along x) and transverse (along y) sliding at 1 m/s.
        let fa = c.force(&r, &[2.0, 0.0, 0.3], &[1.0, 0.0, 0.0]).force;
        let ft = c.force(&r, &[2.0, 0.0, 0.3], &[0.0, -1.0, 0.0]).force;
        let coulomb = |mu: f64| mu * ne / (1.0f64 + 1e-6).sqrt();
        assert!((fa[0] + coulomb(0.5)).abs() <= 1e-12 * ne);
        assert!((ft[1] - coulomb(1.0)).abs() <= 1e-12 * ne);
    }

    /// Static friction (W48): the slide r - r_0 stands where the velocity
    /// was, so the derivative in r of the force with r_0 held is the
    /// velocity-free derivative plus the sliding's; against central
    /// differences as above, in the bed and in the ramp.
    #[test]
    fn the_static_contact_force_derivatives_match_finite_differences() {
        let c = bed();
        let n = c.seabed.normal;
        let rx = [0.8, 0.5, -0.1];
        for below in [0.01, 0.3 * c.ramp_width()] {
            let along = [0.4, 0.9, 0.0];
            let along_n = dot(along, n);
            let r: [f64; 3] = std::array::from_fn(|i| {
                c.seabed.point[i] + along[i] - along_n * n[i] - below * n[i]
            });
            // Slid by a few u_s (where phi bends) from r_0.
            let r0: [f64; 3] =
                std::array::from_fn(|i| r[i] - [2.0, -1.0, 0.5][i] * c.static_slip());
            let force = |r: &[f64; 3], rx: &[f64; 3]| {
                c.static_force(r, rx, &std::array::from_fn(|i| r[i] - r0[i]))
            };
            let f0 = force(&r, &rx);
            assert_eq!(f0.d_rdot, [[0.0; 3]; 3]);
            let scale = [f0.d_r, f0.d_rx]
                .iter()
                .flatten()
                .flatten()
                .fold(0.0f64, |m, x| m.max(x.abs()));
            // h = 1e-7: round-off eps |r| / h stays below 1e-7 at |r| ~ 50 m
            // and truncation (h / u_s)^2 below 1e-5 across the slide's
            // regularization (u_s = 8e-5 m).
            let h = 1e-7;
            for j in 0..3 {
                for (which, analytic) in [(0, f0.d_r), (1, f0.d_rx)] {
                    let (mut rp, mut rm, mut xp, mut xm) = (r, r, rx, rx);
                    if which == 0 {
                        rp[j] += h;
                        rm[j] -= h;
                    } else {
                        xp[j] += h;
                        xm[j] -= h;
                    }
                    let (fp, fm) = (force(&rp, &xp).force, force(&rm, &xm).force);
                    for i in 0..3 {
                        let fd = (fp[i] - fm[i]) / (2.0 * h);
                        assert!(
                            (fd - analytic[i][j]).abs() <= 1e-6 * scale,
                            "arg {which} d f{i}/d x{j}: fd {fd} analytic {}",
                            analytic[i][j]
                        );
                    }
                }
            }
            // Slid far: Coulomb's friction against the slide, no damping.
            let far = c.static_force(&r, &[1.0, 0.0, 0.0], &[1.0, 0.0, 0.0]);
            assert!(far.force[0] < 0.0);
        }
    }
}
