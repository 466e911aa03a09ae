//! What of a rod the water wets at a pose (docs/method.md §15.11): each
//! cross-section's wet fraction along the rod, for its added mass (B18)
//! and drag (B19), and each cap's, on jets in the pose; and how fast they
//! change as the rod moves, for the momentum the water keeps.
//!
//! From the rod's lower end (c = q_z >= 0, t along the axis), the centre
//! of the section at t is at z(t) = z_low + c t and the section, a disc of
//! radius a tilted by the axis, reaches a s above and below it (s =
//! sqrt(1 - c^2)). Its part under z = 0 is the disc's segment below the
//! chord at x = -z(t) / (a s) of its half-height:
//!
//! ```text
//!   phi(t) = Phi(x) = 1/2 + (x sqrt(1 - x^2) + asin x) / pi,   x in [-1, 1]      (B22)
//! ```
//!
//! 1 where the whole section is under (t <= t_w = -(z_low + a s) / c), 0
//! where it is out (t >= t_d), the segment between: the added mass and
//! drag of the section at t are phi(t) times the whole section's, as
//! MoorDyn scales its nodes' by their submerged fraction. The wet run [0,
//! t_w] goes by the rod's Gauss rules; the cut band [t_w, t_d] by 6-point
//! Gauss-Legendre on its moving ends (phi is smooth inside; the ends move
//! with the pose, phi is continuous there, so the pieces' sum carries its
//! exact derivatives). A vertical rod's band is empty: its sections are
//! wet up to the waterline t_w = t_d = -z_low / c. A cap is wet in the
//! proportion of a sphere of the rod's diameter about its centre that is
//! under the surface ([`cap_wetness`]).

use super::jet::{Jet, JetVec};
use crate::quadrature::GaussRule;

/// Points of the band's rule.
const BAND_POINTS: usize = 6;

/// A cap: its centre (body axes), its wet fraction and that fraction's
/// rate along the motion.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Cap<const N: usize, const H: usize = N> {
    pub centre: [f64; 3],
    pub wetness: Jet<N, H>,
    pub rate: Jet<N, H>,
}

/// The wet part of a rod at a pose (body axes, from the reference point).
#[derive(Clone, Copy, Debug)]
pub(crate) struct WetPart<const N: usize, const H: usize = N> {
    /// The lower end, the axis upwards and the length.
    low: [f64; 3],
    up: [f64; 3],
    length: f64,
    /// z(t) = z_low + c t, the sections' half-height a s.
    z_low: Jet<N, H>,
    c: Jet<N, H>,
    half_height: Jet<N, H>,
    /// The wet run's end t_w and the cut band's t_d (in [0, L]).
    wet_to: Jet<N, H>,
    dry_from: Jet<N, H>,
    /// The rates of z_low, c and a s along the motion (first-order jets).
    rates: [Jet<N, H>; 3],
    pub caps: [Cap<N, H>; 2],
}

/// A station of the wet side: its point (body axes, on jets: it slides
/// with the band), its weight times its length times its section's wet
/// fraction, and its weight times its length times the rate of that
/// fraction (for the momentum the water keeps).
pub(crate) struct Station<const N: usize, const H: usize = N> {
    pub point: JetVec<N, H>,
    pub weight: Jet<N, H>,
    pub wetting: Jet<N, H>,
}

impl<const N: usize> WetPart<N> {
    /// The same of first order, for the water's virtual work.
    pub fn first_order(&self) -> WetPart<N, 0> {
        let cap = |c: &Cap<N>| Cap {
            centre: c.centre,
            wetness: c.wetness.first_order(),
            rate: c.rate.first_order(),
        };
        WetPart {
            low: self.low,
            up: self.up,
            length: self.length,
            z_low: self.z_low.first_order(),
            c: self.c.first_order(),
            half_height: self.half_height.first_order(),
            wet_to: self.wet_to.first_order(),
            dry_from: self.dry_from.first_order(),
            rates: self.rates.map(Jet::first_order),
            caps: self.caps.each_ref().map(cap),
        }
    }
}

impl<const N: usize, const H: usize> WetPart<N, H> {
    /// The whole rod under water, from `end_a` to `end_b`.
    pub fn all(end_a: [f64; 3], end_b: [f64; 3]) -> Self {
        let step = crate::vec3::sub(end_b, end_a);
        let length = crate::vec3::norm(step);
        let zero = Jet::constant(0.0);
        let cap = |centre| Cap {
            centre,
            wetness: Jet::constant(1.0),
            rate: zero,
        };
        // Every section wholly wet: the band, empty, is never evaluated.
        WetPart {
            low: end_a,
            up: crate::vec3::scale(1.0 / length, step),
            length,
            z_low: Jet::constant(-1.0),
            c: zero,
            half_height: zero,
            wet_to: Jet::constant(length),
            dry_from: Jet::constant(length),
            rates: [zero; 3],
            caps: [cap(end_a), cap(end_b)],
        }
    }

    /// The rod from `end_a` to `end_b` of radius `a` whose end A is at
    /// height `z_a` and whose axis has the vertical component `c`.
    pub fn at(end_a: [f64; 3], end_b: [f64; 3], a: f64, z_a: Jet<N, H>, c: Jet<N, H>) -> Self {
        let mut part = Self::all(end_a, end_b);
        let length = part.length;
        part.caps = [
            Cap {
                wetness: cap_wetness(z_a, a),
                ..part.caps[0]
            },
            Cap {
                wetness: cap_wetness(z_a + c.scale(length), a),
                ..part.caps[1]
            },
        ];
        let (z_low, c) = if c.v < 0.0 {
            part.low = end_b;
            part.up = crate::vec3::scale(-1.0, part.up);
            (z_a + c.scale(length), -c)
        } else {
            (z_a, c)
        };
        let s2 = Jet::constant(1.0) - c * c;
        let s = if s2.v > 0.0 {
            let s = s2.v.sqrt();
            s2.compose(s, 0.5 / s, -0.25 / (s * s2.v))
        } else {
            Jet::constant(0.0)
        };
        let half_height = s.scale(a);
        let clip = |t: Jet<N, H>| {
            if t.v <= 0.0 {
                Jet::constant(0.0)
            } else if t.v >= length {
                Jet::constant(length)
            } else {
                t
            }
        };
        let (wet_to, dry_from) = if c.v > 0.0 {
            let inverse_c = c.compose(1.0 / c.v, -1.0 / (c.v * c.v), 2.0 / c.v.powi(3));
            (
                clip((-half_height - z_low) * inverse_c),
                clip((half_height - z_low) * inverse_c),
            )
        } else {
            // Level: every section at the same height.
            let depth = -z_low.v;
            let all = Jet::constant(length);
            let none = Jet::constant(0.0);
            if depth >= half_height.v {
                (all, all)
            } else if depth <= -half_height.v {
                (none, none)
            } else {
                (none, all)
            }
        };
        WetPart {
            z_low,
            c,
            half_height,
            wet_to,
            dry_from,
            ..part
        }
    }

    /// The same with the rates along the motion of its pose-dependent
    /// numbers, `rate(x)` being d x / dt.
    pub fn with_rates(mut self, rate: impl Fn(&Jet<N, H>) -> Jet<N, H>) -> Self {
        self.rates = [rate(&self.z_low), rate(&self.c), rate(&self.half_height)];
        for cap in &mut self.caps {
            cap.rate = first_order(rate(&cap.wetness));
        }
        self
    }

    /// The point of the axis at t from the lower end.
    pub fn point(&self, t: Jet<N, H>) -> JetVec<N, H> {
        std::array::from_fn(|i| Jet::constant(self.low[i]) + t.scale(self.up[i]))
    }

    /// The side's stations: `rule` ([0, 1] points and weights) on each
    /// of `pieces` equal pieces of the wet run, then the band's rule.
    pub fn stations<'a>(
        &'a self,
        rule: &'a [(f64, f64)],
        pieces: usize,
    ) -> impl Iterator<Item = Station<N, H>> + 'a {
        let zero = Jet::constant(0.0);
        let piece = self.wet_to.scale(1.0 / pieces as f64);
        let runs = if self.wet_to.v > 0.0 { pieces } else { 0 };
        let run = (0..runs).flat_map(move |k| {
            rule.iter().map(move |&(x, w)| Station {
                point: self.point(piece.scale(k as f64 + x)),
                weight: piece.scale(w),
                wetting: zero,
            })
        });
        let width = self.dry_from - self.wet_to;
        let band = GaussRule::shared(BAND_POINTS);
        let cut = if width.v > 0.0 { BAND_POINTS } else { 0 };
        let band = band.points[..cut]
            .iter()
            .zip(&band.weights)
            .map(move |(x, w)| {
                let t = self.wet_to + width.scale(*x);
                let (fraction, rate) = self.section(t);
                let weight = width.scale(*w);
                Station {
                    point: self.point(t),
                    weight: weight * fraction,
                    wetting: first_order(weight * rate),
                }
            });
        run.chain(band)
    }

    /// The wet fraction of the section at t (B22) and its rate along the
    /// motion at that section: x = -(z_low + c t) / (a s),
    /// dx/dt = -(z_low' + c' t) / (a s) - x (a s)' / (a s).
    fn section(&self, t: Jet<N, H>) -> (Jet<N, H>, Jet<N, H>) {
        let hh = self.half_height;
        let inverse = hh.compose(1.0 / hh.v, -1.0 / (hh.v * hh.v), 2.0 / hh.v.powi(3));
        let x = -(self.z_low + self.c * t) * inverse;
        let xv = x.v.clamp(-1.0, 1.0);
        let root = (1.0 - xv * xv).max(0.0).sqrt();
        let pi = std::f64::consts::PI;
        let fraction = x.compose(
            0.5 + (xv * root + xv.asin()) / pi,
            2.0 * root / pi,
            if root > 0.0 {
                -2.0 * xv / (pi * root)
            } else {
                0.0
            },
        );
        let curvature = if root > 0.0 {
            -2.0 * xv / (pi * root)
        } else {
            0.0
        };
        let slope = x.compose(2.0 * root / pi, curvature, 0.0);
        let [z_rate, c_rate, hh_rate] = self.rates;
        let x_rate = -(z_rate + c_rate * t) * inverse - x * hh_rate * inverse;
        (fraction, first_order(slope * x_rate))
    }

    /// The waterline's section of a rod whose band is empty (a vertical
    /// rod) and the rate of the wet run's end there, if the waterline
    /// lies on the rod: the water's momentum goes in or out there.
    pub fn waterline(&self) -> Option<(JetVec<N, H>, Jet<N, H>)> {
        let inside = self.wet_to.v > 0.0 && self.wet_to.v < self.length;
        if !(inside && self.dry_from.v == self.wet_to.v) {
            return None;
        }
        // t_w = -z_low / c: t_w' = -(z_low' + c' t_w) / c.
        let c = self.c;
        let inverse_c = c.compose(1.0 / c.v, -1.0 / (c.v * c.v), 2.0 / c.v.powi(3));
        let [z_rate, c_rate, _] = self.rates;
        let rate = -(z_rate + c_rate * self.wet_to) * inverse_c;
        Some((self.point(self.wet_to), first_order(rate)))
    }
}

/// A rate with its value and first derivatives (its second would need
/// the pose's third derivatives: the water's virtual work, where rates
/// enter, takes none).
fn first_order<const N: usize, const H: usize>(mut x: Jet<N, H>) -> Jet<N, H> {
    x.h = [[0.0; H]; H];
    x
}

/// How much of a cap at height `z` is under water: the fraction of a
/// sphere of radius `a` about the cap's centre that lies under z = 0,
/// (1 + zeta)^2 (2 - zeta) / 4 with zeta = -z / a in [-1, 1]: 1 a radius
/// down, 0 a radius up, and C1 in between, so that a cap's added mass
/// fades in and out with the pose (a cap switched on or off at once would
/// kick the body's velocity and its energy).
pub(crate) fn cap_wetness<const N: usize, const H: usize>(z: Jet<N, H>, a: f64) -> Jet<N, H> {
    let zeta = -z.v / a;
    if zeta >= 1.0 {
        return Jet::constant(1.0);
    }
    if zeta <= -1.0 {
        return Jet::constant(0.0);
    }
    let f = (1.0 + zeta).powi(2) * (2.0 - zeta) / 4.0;
    let df = 0.75 * (1.0 - zeta * zeta);
    let d2f = -1.5 * zeta;
    // d/dz = -1/a d/dzeta.
    z.compose(f, -df / a, d2f / (a * a))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The sections' wet area summed along the rod is the volume under
    /// the surface (Cavalieri: A int phi dt = V_w, with V_w of (B20)),
    /// for a rod level at the surface (phi the same everywhere: exact),
    /// upright (no band: exact), tilted through it (the whole band on the
    /// rod: phi - 1/2 is odd about the band's middle, so the symmetric
    /// rule is exact) and with its lower cap cut (the band cut off at the
    /// cap: the 6-point rule against phi's sqrt-like end, to 1e-3).
    #[test]
    fn the_sections_wet_area_adds_up_to_the_submerged_volume() {
        let (l, a) = (3.0, 0.4);
        let area = std::f64::consts::PI * a * a;
        for (z_a, c, tolerance) in [
            (-0.1, 0.0, 1e-12),
            (-1.0, 1.0, 1e-12),
            (-0.6, 0.5, 1e-12),
            (-0.2, 0.5, 1e-3),
        ] {
            let (z, cc) = (Jet::<1>::constant(z_a), Jet::<1>::constant(c));
            let part = WetPart::at([0.0; 3], [0.0, 0.0, l], a, z, cc);
            let summed: f64 = part.stations(&[(0.5, 1.0)], 1).map(|s| s.weight.v).sum();
            let volume = crate::body::waterline::submerged(z, cc, l, a).volume.v;
            eprintln!(
                "z_A {z_a}, c {c}: A sum phi against V_w: {:.1e}",
                (area * summed - volume).abs() / volume
            );
            assert!(
                (area * summed - volume).abs() < tolerance * volume,
                "{} {volume}",
                area * summed
            );
        }
    }
}
