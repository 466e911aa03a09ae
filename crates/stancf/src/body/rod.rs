//! A rod: a rigid slender cylinder fixed in a body (MoorDyn's ROD TYPES
//! and RODS; docs/method.md §15.10, (B17)-(B19)). A free rod is a body of
//! its own; a rod on a body adds its mass and its water to the body's.
//!
//! Its mass is a solid cylinder's (B17). Fully submerged, the water acts
//! along it as on MoorDyn's rod: buoyancy rho V g at its middle (the side
//! pressure and the caps' together), added mass across it and at its
//! caps, in the kinetic energy (B18), and drag across it and on its caps,
//! as virtual work (B19). With u(s) the velocity of the rod's point s
//! through the water (body axes), u = u_ref + Omega x xi(s), and q its
//! axis, u_q = (u . q), u_p = u - u_q q:
//!
//! ```text
//!   T_a = 1/2 rho Ca A int_0^L |u_p|^2 ds + 1/2 rho CaEnd V_end (u_q(A)^2 + u_q(B)^2)     (B18)
//!   f(s) = -1/2 rho Cd d |u_p| u_p,   f_A,B = -1/2 rho CdEnd A |u_q| u_q q                (B19)
//! ```
//!
//! (A = pi d^2/4, V_end = pi d^3/12, a hemisphere of the rod's diameter,
//! both as MoorDyn takes them; like MoorDyn, both caps carry their added
//! mass and drag, and the side carries none along the axis). T_a's
//! integrand is quadratic in s (u_p is linear): two Gauss points over the
//! rod are exact. The drag's |u_p| u_p goes by three Gauss points on each
//! of the rod's segments, to the rule's error.

use super::flow::Flow;
use super::inertia::RigidInertia;
use super::jet::{cross, dot, Jet, JetVec};
use super::waterline::Submerged;
use super::wet::WetPart;
use crate::error::ModelError;
use crate::vec3::{add, norm, scale, sub};

/// A rod in a body's axes (from its reference point), with its type's
/// numbers (MoorDyn's ROD TYPES: Diam, Mass/m, Cd, Ca, CdEnd, CaEnd) and
/// its segments (MoorDyn's NumSegs: here the drag's quadrature).
#[derive(Clone, Debug, PartialEq)]
pub struct Rod {
    pub end_a: [f64; 3],
    pub end_b: [f64; 3],
    pub diameter: f64,
    pub mass_per_length: f64,
    pub drag_coefficient: f64,
    pub added_mass_coefficient: f64,
    pub end_drag_coefficient: f64,
    pub end_added_mass_coefficient: f64,
    pub segments: usize,
}

/// Two-point Gauss-Legendre on [0, 1].
const PAIR: [(f64, f64); 2] = [
    (0.211_324_865_405_187_1, 0.5),
    (0.788_675_134_594_812_9, 0.5),
];

/// Three-point Gauss-Legendre on [0, 1].
const STATIONS: [(f64, f64); 3] = [
    (0.112_701_665_379_258_3, 5.0 / 18.0),
    (0.5, 8.0 / 18.0),
    (0.887_298_334_620_741_7, 5.0 / 18.0),
];

fn constant<const N: usize, const H: usize>(v: [f64; 3]) -> JetVec<N, H> {
    v.map(Jet::constant)
}

impl Rod {
    /// L = |B - A|.
    pub fn length(&self) -> f64 {
        norm(sub(self.end_b, self.end_a))
    }

    /// The unit axis q = (B - A) / L.
    pub fn axis(&self) -> [f64; 3] {
        scale(1.0 / self.length(), sub(self.end_b, self.end_a))
    }

    /// (A + B) / 2, where its weight and its buoyancy act.
    pub fn middle(&self) -> [f64; 3] {
        scale(0.5, add(self.end_a, self.end_b))
    }

    /// The cross-section's area, pi d^2 / 4.
    pub fn area(&self) -> f64 {
        0.25 * std::f64::consts::PI * self.diameter * self.diameter
    }

    /// The displaced volume A L.
    pub fn volume(&self) -> f64 {
        self.area() * self.length()
    }

    /// (B17): mass w L at the middle; a solid cylinder's moments at its
    /// middle, m d^2/8 about its axis and m (L^2/12 + d^2/16) across it,
    /// I = m (L^2/12 + d^2/16) 1 + m (d^2/8 - L^2/12 - d^2/16) q q^T.
    pub fn inertia(&self) -> RigidInertia {
        let (l, d) = (self.length(), self.diameter);
        let m = self.mass_per_length * l;
        let across = m * (l * l / 12.0 + d * d / 16.0);
        let along = m * d * d / 8.0;
        let q = self.axis();
        RigidInertia {
            mass: m,
            centre_of_mass: self.middle(),
            inertia_at_centre: std::array::from_fn(|i| {
                std::array::from_fn(|j| {
                    (if i == j { across } else { 0.0 }) + (along - across) * q[i] * q[j]
                })
            }),
        }
    }

    /// Refuses a rod without length, a diameter that is not positive, a
    /// negative or non-finite mass or coefficient, or no segment.
    pub fn validate(&self, key: &str) -> Result<(), ModelError> {
        if self.end_a.iter().chain(&self.end_b).any(|x| !x.is_finite()) {
            return Err(ModelError::invalid(key, "its ends must be finite"));
        }
        if self.length().is_nan() || self.length() <= 0.0 {
            return Err(ModelError::invalid(
                key,
                "its ends are one point: a rod of zero length has no axis (give it a length, \
                 or use a point)",
            ));
        }
        if !(self.diameter.is_finite() && self.diameter > 0.0) {
            return Err(ModelError::invalid(
                format!("{key}.diameter"),
                format!("{}: must be positive", self.diameter),
            ));
        }
        let named = [
            ("mass_per_length", self.mass_per_length),
            ("drag_coefficient", self.drag_coefficient),
            ("added_mass_coefficient", self.added_mass_coefficient),
            ("end_drag_coefficient", self.end_drag_coefficient),
            (
                "end_added_mass_coefficient",
                self.end_added_mass_coefficient,
            ),
        ];
        for (name, v) in named {
            if !(v.is_finite() && v >= 0.0) {
                return Err(ModelError::invalid(
                    format!("{key}.{name}"),
                    format!("{v}: must be finite and not negative"),
                ));
            }
        }
        if self.segments == 0 {
            return Err(ModelError::invalid(
                format!("{key}.segments"),
                "a rod needs at least one segment",
            ));
        }
        Ok(())
    }

    /// The whole rod under water: what a rod deep under the surface
    /// wets (B18)-(B19).
    #[cfg(test)]
    pub(crate) fn all_wet<const N: usize, const H: usize>(&self) -> WetPart<N, H> {
        WetPart::all(self.end_a, self.end_b)
    }

    /// The rod's part under the surface z = 0 (B20) and what it wets
    /// (B22), from the height of its end A, `z_a`, and the vertical
    /// component of its axis, `c` (global), on jets in the pose.
    pub(crate) fn wet_part<const N: usize>(
        &self,
        z_a: Jet<N>,
        c: Jet<N>,
    ) -> (WetPart<N>, Submerged<N>) {
        let (l, a) = (self.length(), 0.5 * self.diameter);
        let under = super::waterline::submerged(z_a, c, l, a);
        (WetPart::at(self.end_a, self.end_b, a, z_a, c), under)
    }

    /// The volume of the rod under the surface z = 0 (B20)-(B21) when its
    /// end A is at height `z_a` and its axis (from A to B) has the
    /// vertical component `axis_z` (global): V where it is all under, 0
    /// above.
    pub fn submerged_volume(&self, z_a: f64, axis_z: f64) -> f64 {
        let (l, a) = (self.length(), 0.5 * self.diameter);
        let under = super::waterline::submerged::<1>(
            Jet::constant(z_a),
            Jet::constant(axis_z.clamp(-1.0, 1.0)),
            l,
            a,
        );
        under.volume.v.clamp(0.0, self.volume())
    }

    /// A cap's added mass, rho CaEnd V_end (V_end = pi d^3 / 12).
    fn cap_added_mass(&self, density: f64) -> f64 {
        density * self.end_added_mass_coefficient * std::f64::consts::PI * self.diameter.powi(3)
            / 12.0
    }

    /// The rod's added mass's kinetic energy (B18) over its wet part
    /// (B22), from the reference point's velocity through the water `u`
    /// and the rate `omega` (body axes).
    pub(crate) fn added_mass_energy<const N: usize, const H: usize>(
        &self,
        wet: &WetPart<N, H>,
        u: &JetVec<N, H>,
        omega: &JetVec<N, H>,
        density: f64,
    ) -> Jet<N, H> {
        let q = constant(self.axis());
        let mut t = Jet::constant(0.0);
        let side = 0.5 * density * self.added_mass_coefficient * self.area();
        if side != 0.0 {
            // |u_p|^2 is quadratic along the rod: two Gauss points are
            // exact on the wet run.
            for station in wet.stations(&PAIR, 1) {
                let (_, u_p) = split(&point_velocity(u, omega, &station.point), &q);
                t = t + dot(&u_p, &u_p) * station.weight.scale(side);
            }
        }
        let cap = 0.5 * self.cap_added_mass(density);
        if cap != 0.0 {
            for end in wet.caps.iter().filter(|e| e.wetness.v > 0.0) {
                let (u_q, _) = split(&point_velocity(u, omega, &constant(end.centre)), &q);
                t = t + (u_q * u_q * end.wetness).scale(cap);
            }
        }
        t
    }

    /// The rod's drag (B19) over its wet part (B22) and the momentum the
    /// water keeps as the rod's added mass changes (B23): their resultant
    /// force and their moment about the body's centre of mass `centre`
    /// (body axes). `flow` gives the sea's flow at a point of the rod
    /// (body axes; None in still water or a uniform current, which `u`
    /// holds): the drag then acts on the velocity through the moving
    /// water, and the fluid's inertia and the caps' dynamic pressure join
    /// it (B32)-(B33):
    ///
    /// ```text
    ///   f_I(s) = rho (1 + Ca) A a_p,   f_I,A|B = rho CaEnd V_end a_q q,
    ///   f_p,A = rho A p_d q,   f_p,B = -rho A p_d q
    /// ```
    pub(crate) fn drag<const N: usize, const H: usize>(
        &self,
        wet: &WetPart<N, H>,
        u: &JetVec<N, H>,
        omega: &JetVec<N, H>,
        density: f64,
        centre: [f64; 3],
        flow: &dyn Fn(&JetVec<N, H>) -> Option<Flow<N, H>>,
    ) -> (JetVec<N, H>, JetVec<N, H>) {
        let q = constant(self.axis());
        let mut force = constant::<N, H>([0.0; 3]);
        let mut moment = constant::<N, H>([0.0; 3]);
        let mut add_at = |xi: &JetVec<N, H>, f: JetVec<N, H>| {
            let arm: JetVec<N, H> = std::array::from_fn(|i| xi[i] - Jet::constant(centre[i]));
            let m = cross(&arm, &f);
            for i in 0..3 {
                force[i] = force[i] + f[i];
                moment[i] = moment[i] + m[i];
            }
        };
        let side = -0.5 * density * self.drag_coefficient * self.diameter;
        let side_mass = -0.5 * density * self.added_mass_coefficient * self.area();
        let side_inertia = density * (1.0 + self.added_mass_coefficient) * self.area();
        for station in wet.stations(&STATIONS, self.segments) {
            let moving = point_velocity(u, omega, &station.point);
            let (_, u_p) = split(&moving, &q);
            let sea = flow(&station.point);
            let (_, through_p) = match &sea {
                Some(s) => split(&std::array::from_fn(|i| moving[i] - s.velocity[i]), &q),
                None => (Jet::constant(0.0), u_p),
            };
            let mut f = constant::<N, H>([0.0; 3]);
            if side != 0.0 {
                let speed = super::jet::norm(&through_p);
                f = through_p.map(|c| (c * speed * station.weight).scale(side));
            }
            if let Some(s) = &sea {
                let (_, a_p) = split(&s.acceleration, &q);
                for i in 0..3 {
                    f[i] = f[i] + (a_p[i] * station.weight).scale(side_inertia);
                }
            }
            if side_mass != 0.0 && station.wetting.v != 0.0 {
                let rate = absolute(station.wetting);
                for i in 0..3 {
                    f[i] = f[i] + (u_p[i] * rate).scale(side_mass);
                }
            }
            add_at(&station.point, f);
        }
        if let (true, Some((xi, rate))) = (side_mass != 0.0, wet.waterline()) {
            let (_, u_p) = split(&point_velocity(u, omega, &xi), &q);
            let rate = absolute(rate);
            add_at(&xi, u_p.map(|c| (c * rate).scale(side_mass)));
        }
        let cap = -0.5 * density * self.end_drag_coefficient * self.area();
        let cap_mass = -0.5 * self.cap_added_mass(density);
        let cap_inertia = 2.0 * cap_mass.abs();
        for (k, end) in wet.caps.iter().enumerate() {
            if end.wetness.v == 0.0 && end.rate.v == 0.0 {
                continue;
            }
            let centre = constant(end.centre);
            let moving = point_velocity(u, omega, &centre);
            let (u_q, _) = split(&moving, &q);
            let sea = flow(&centre);
            let through_q = match &sea {
                Some(s) => split(&std::array::from_fn(|i| moving[i] - s.velocity[i]), &q).0,
                None => u_q,
            };
            let mut along = through_q * absolute(through_q) * end.wetness.scale(cap)
                + u_q * absolute(end.rate).scale(cap_mass);
            if let Some(s) = &sea {
                // The pressure pushes on the cap's face, inward: along q
                // at end A, against it at end B.
                let inward = if k == 0 { 1.0 } else { -1.0 };
                let a_q = dot(&s.acceleration, &q);
                along = along
                    + (a_q.scale(cap_inertia) + s.pressure.scale(inward * density * self.area()))
                        * end.wetness;
            }
            add_at(&centre, q.map(|c| c * along));
        }
        (force, moment)
    }
}

/// |x| on a jet (its derivative the sign, zero at zero).
fn absolute<const N: usize, const H: usize>(x: Jet<N, H>) -> Jet<N, H> {
    x.compose(x.v.abs(), x.v.signum(), 0.0)
}

/// u + Omega x xi.
fn point_velocity<const N: usize, const H: usize>(
    u: &JetVec<N, H>,
    omega: &JetVec<N, H>,
    xi: &JetVec<N, H>,
) -> JetVec<N, H> {
    let turn = cross(omega, xi);
    std::array::from_fn(|i| u[i] + turn[i])
}

/// (u . q, u - (u . q) q).
fn split<const N: usize, const H: usize>(
    u: &JetVec<N, H>,
    q: &JetVec<N, H>,
) -> (Jet<N, H>, JetVec<N, H>) {
    let along = dot(u, q);
    (along, std::array::from_fn(|i| u[i] - along * q[i]))
}

/// A rod of every coefficient, off a body's axes (for tests).
#[cfg(test)]
pub(crate) fn sample() -> Rod {
    Rod {
        end_a: [0.2, -0.3, -0.5],
        end_b: [0.9, 0.4, -1.8],
        diameter: 0.3,
        mass_per_length: 40.0,
        drag_coefficient: 1.2,
        added_mass_coefficient: 1.0,
        end_drag_coefficient: 0.8,
        end_added_mass_coefficient: 0.5,
        segments: 3,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rod() -> Rod {
        Rod {
            end_a: [0.3, -0.2, 0.1],
            end_b: [1.1, 0.4, -0.5],
            diameter: 0.2,
            mass_per_length: 30.0,
            drag_coefficient: 1.2,
            added_mass_coefficient: 1.0,
            end_drag_coefficient: 0.6,
            end_added_mass_coefficient: 0.5,
            segments: 4,
        }
    }

    /// (B17) is the solid cylinder's inertia: against the integral of
    /// (|x|^2 1 - x x^T) dm over a cylinder sampled finely (rings of
    /// points across, Gauss along), to the sampling's error.
    #[test]
    fn a_rods_inertia_is_a_solid_cylinders() {
        let r = rod();
        let i = r.inertia();
        assert!((i.mass - 30.0 * r.length()).abs() < 1e-12);
        let q = r.axis();
        // Two unit vectors across the axis.
        let e1 = crate::vec3::normalized(crate::vec3::cross(q, [0.0, 0.0, 1.0]));
        let e2 = crate::vec3::cross(q, e1);
        let (l, radius) = (r.length(), 0.5 * r.diameter);
        let rule = crate::quadrature::GaussRule::new(6).unwrap();
        let (rings, spokes) = (200usize, 64usize);
        let density = r.mass_per_length / (std::f64::consts::PI * radius * radius);
        let mut sampled = [[0.0; 3]; 3];
        for (x, w) in rule.points.iter().zip(&rule.weights) {
            let along = (x - 0.5) * l;
            for k in 0..rings {
                // Midpoint rule in the radius, exact enough for rho^3.
                let rho = (k as f64 + 0.5) / rings as f64 * radius;
                let dr = radius / rings as f64;
                for j in 0..spokes {
                    let phi = 2.0 * std::f64::consts::PI * j as f64 / spokes as f64;
                    let p: [f64; 3] = std::array::from_fn(|c| {
                        along * q[c] + rho * (phi.cos() * e1[c] + phi.sin() * e2[c])
                    });
                    let dm =
                        density * w * l * rho * dr * 2.0 * std::f64::consts::PI / spokes as f64;
                    let pp = crate::vec3::dot(p, p);
                    for a in 0..3 {
                        for b in 0..3 {
                            sampled[a][b] += dm * (if a == b { pp } else { 0.0 } - p[a] * p[b]);
                        }
                    }
                }
            }
        }
        for a in 0..3 {
            for b in 0..3 {
                let e = (sampled[a][b] - i.inertia_at_centre[a][b]).abs();
                assert!(
                    e < 1e-5 * i.inertia_at_centre[0][0].abs().max(1.0),
                    "{a}{b}: {e:e}"
                );
            }
        }
    }

    /// (B18) for a rod moving across itself, along itself and turning
    /// about its middle: 1/2 rho Ca A L v^2, 1/2 rho CaEnd 2 V_end v^2
    /// and 1/2 rho Ca A w^2 L^3/12.
    #[test]
    fn a_rods_added_mass_is_moordyns_in_each_motion() {
        let mut r = rod();
        r.end_a = [-0.5, 0.0, 0.0];
        r.end_b = [0.5, 0.0, 0.0];
        let (rho, v, w) = (1025.0, 0.7, 0.9);
        let z = constant::<1, 1>([0.0; 3]);
        let (a, l) = (r.area(), r.length());
        let across = r.added_mass_energy(&r.all_wet(), &constant([0.0, v, 0.0]), &z, rho);
        let want = 0.5 * rho * 1.0 * a * l * v * v;
        assert!((across.v - want).abs() < 1e-12 * want);
        let along = r.added_mass_energy(&r.all_wet(), &constant([v, 0.0, 0.0]), &z, rho);
        let v_end = std::f64::consts::PI * 0.2f64.powi(3) / 12.0;
        let want = 0.5 * rho * 0.5 * 2.0 * v_end * v * v;
        assert!((along.v - want).abs() < 1e-12 * want);
        let turning = r.added_mass_energy(&r.all_wet(), &z, &constant([0.0, 0.0, w]), rho);
        let want = 0.5 * rho * 1.0 * a * w * w * l.powi(3) / 12.0;
        assert!((turning.v - want).abs() < 1e-12 * want);
    }

    /// The drag (B19) of a rod moving across itself at v is
    /// 1/2 rho Cd d L v^2 against the motion with no moment about its
    /// middle; turning at w about its middle, the drag's moment is
    /// -2 int_0^(L/2) 1/2 rho Cd d (w s)^2 s ds = -rho Cd d w^2 L^4/64,
    /// which the rule meets to its error (|s| s^2 has a kink at s = 0,
    /// the segments' ends; with an even count of segments it is exact).
    #[test]
    fn a_rods_drag_is_the_integral_of_its_sections_drag() {
        let mut r = rod();
        r.end_a = [-0.5, 0.0, 0.0];
        r.end_b = [0.5, 0.0, 0.0];
        let (rho, v, w) = (1025.0, 0.7, 0.9);
        let z = constant::<1, 1>([0.0; 3]);
        let middle = r.middle();
        let (f, m) = r.drag(
            &r.all_wet(),
            &constant([0.0, v, 0.0]),
            &z,
            rho,
            middle,
            &|_| None,
        );
        let want = -0.5 * rho * 1.2 * 0.2 * 1.0 * v * v;
        assert!((f[1].v - want).abs() < 1e-12 * want.abs());
        assert!(f[0].v.abs() < 1e-12 && m.iter().all(|c| c.v.abs() < 1e-12));
        let (f, m) = r.drag(
            &r.all_wet(),
            &z,
            &constant([0.0, 0.0, w]),
            rho,
            middle,
            &|_| None,
        );
        let want = -rho * 1.2 * 0.2 * w * w / 64.0;
        assert!(f.iter().all(|c| c.v.abs() < 1e-12), "{:?}", f.map(|c| c.v));
        assert!(
            (m[2].v - want).abs() < 1e-12 * want.abs(),
            "{} {want}",
            m[2].v
        );
        // Along its axis both caps drag: 2 x 1/2 rho CdEnd A v^2.
        let (f, _) = r.drag(
            &r.all_wet(),
            &constant([v, 0.0, 0.0]),
            &z,
            rho,
            middle,
            &|_| None,
        );
        let want = -rho * 0.6 * r.area() * v * v;
        assert!((f[0].v - want).abs() < 1e-12 * want.abs());
    }

    /// A rod standing half out of the water has half its volume under;
    /// level and half under, half; deep, all; above, none; upside down,
    /// the same (its end A is then the upper end).
    #[test]
    fn a_rods_submerged_volume_is_its_part_under_the_surface() {
        let r = rod();
        let (l, v) = (r.length(), r.volume());
        for (z_a, c, want) in [
            (-0.5 * l, 1.0, 0.5),
            (0.0, 0.0, 0.5),
            (-10.0, 0.3, 1.0),
            (1.0, 0.3, 0.0),
            (0.5 * l, -1.0, 0.5),
        ] {
            let got = r.submerged_volume(z_a, c) / v;
            assert!((got - want).abs() < 1e-12, "{z_a} {c}: {got}");
        }
    }
}
