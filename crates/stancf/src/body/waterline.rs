//! The part of a rod under the still water surface z = 0 (docs/method.md
//! §15.11, (B20)-(B21)): its volume V_w and the first moment of that
//! volume about the surface, I = int_{V_w} z dV, for a solid circular
//! cylinder of radius a and length L at any depth and tilt, exact, on
//! jets in the depth of its lower end z_A and the vertical component of
//! its axis c = q_z (so that the buoyancy's potential -rho g I and the
//! wet length V_w / A carry exact first and second derivatives).
//!
//! A point of the rod is z = z_A + c t + s eta (t in [0, L] along the
//! axis from the lower end, eta in [-a, a] across it in the vertical
//! plane of the axis, s = sqrt(1 - c^2)); the cross-section's chord at
//! eta is 2 sqrt(a^2 - eta^2). Along the axis at a fixed eta, with
//! w = z_A + s eta the height of the lower cap's point,
//!
//! ```text
//!   f(w) = int_0^L min(w + c t, 0) dt = 0                 w >= 0        (dry)
//!                                     = -w^2 / (2 c)      -cL < w < 0   (cut)
//!                                     = w L + c L^2 / 2   w <= -cL      (wet)
//!   g(w) = int_0^L [w + c t < 0] dt   = 0, -w / c, L
//!   I = int f(z_A + s eta) 2 sqrt(a^2 - eta^2) d eta,   V_w = the same with g     (B20)
//! ```
//!
//! Where neither cap is cut by the surface the whole disc is in one
//! piece and, the odd moments vanishing,
//!
//! ```text
//!   I = A (z_A L + c L^2 / 2),  V_w = A L               (under)
//!   I = -(A z_A^2 + I_d s^2) / (2 c),  V_w = -A z_A / c  (piercing)                  (B21)
//! ```
//!
//! (A = pi a^2, I_d = pi a^4 / 4): the piercing rod's heave stiffness
//! rho g A / c and its waterplane moment rho g I_d / c come from the
//! second. Where a cap is cut, the breakpoints eta where w = 0 and
//! w = -cL split the disc, and each polynomial piece integrates against
//! the chord by the circular segment's antiderivatives F_k(eta) =
//! int eta^k sqrt(a^2 - eta^2). The breakpoints move with the pose, and
//! f and g are continuous there, so their motion adds no Leibniz terms to
//! the first derivatives (nor, f being C1, to I's second): the pieces'
//! sum on jets is exact. Where the cut band (-cL < w < 0) is thin beside
//! its distance to the disc's rim (a rod lying near the surface), the
//! antiderivatives' difference loses its digits to the 1/c of its
//! coefficients; there the band is integrated in its own variable
//! v = w / c in [-L, 0], whose integrand has no 1/c, by Gauss-Legendre
//! (its error is far below round-off where the band is that thin).

use super::jet::Jet;

/// The submerged part of a rod: the first moment I = int z dV and the
/// volume V_w of the part under z = 0 (B20).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Submerged<const N: usize> {
    pub first_moment: Jet<N>,
    pub volume: Jet<N>,
}

/// The band (-cL < w < 0) is integrated by Gauss-Legendre in v where it
/// is narrower than this fraction of its distance to the disc's rim.
const THIN_BAND: f64 = 1e-2;

/// (B20)-(B21) for a rod of `length` L and `radius` a whose end A is at
/// height `z_a` and whose axis (from A to B) has the vertical component
/// `c`: on jets in whatever z_a and c depend on.
pub(crate) fn submerged<const N: usize>(
    z_a: Jet<N>,
    c: Jet<N>,
    length: f64,
    radius: f64,
) -> Submerged<N> {
    // From the lower end: c >= 0.
    let (z_low, c) = if c.v < 0.0 {
        (z_a + c.scale(length), -c)
    } else {
        (z_a, c)
    };
    let (l, a) = (length, radius);
    let z_high = z_low + c.scale(l);
    let s2 = Jet::constant(1.0) - c * c;
    let area = std::f64::consts::PI * a * a;
    let zero = Jet::constant(0.0);
    let s_v = s2.v.max(0.0).sqrt();
    let cut = s_v > 0.0 && (z_low.v.abs() < a * s_v || z_high.v.abs() < a * s_v);
    if !cut {
        return if z_low.v >= 0.0 {
            Submerged {
                first_moment: zero,
                volume: zero,
            }
        } else if z_high.v <= 0.0 {
            Submerged {
                first_moment: (z_low.scale(l) + c.scale(0.5 * l * l)).scale(area),
                volume: Jet::constant(area * l),
            }
        } else {
            let inverse_c = c.compose(1.0 / c.v, -1.0 / (c.v * c.v), 2.0 / c.v.powi(3));
            let disc_moment = 0.25 * std::f64::consts::PI * a.powi(4);
            Submerged {
                first_moment: (z_low * z_low).scale(area) + s2.scale(disc_moment),
                volume: z_low.scale(area),
            }
            .times(inverse_c.scale(-0.5), inverse_c.scale(-1.0))
        };
    }
    let s = s2.compose(s_v, 0.5 / s_v, -0.25 / (s_v * s2.v));
    let inverse_s = s.compose(1.0 / s_v, -1.0 / (s_v * s_v), 2.0 / s_v.powi(3));
    // Where the lower cap's line leaves the water (w = 0) and where the
    // whole line is under (w = -cL), clipped to the disc.
    let dry_from = clip(-z_low * inverse_s, a);
    let wet_to = clip(-z_high * inverse_s, a);
    let rim = Jet::constant(-a);
    // The wet piece: f = w L + c L^2 / 2 = (z L + c L^2/2) + s L eta.
    let mut first_moment = disc_piece(
        [z_low.scale(l) + c.scale(0.5 * l * l), s.scale(l), zero],
        rim,
        wet_to,
        a,
    );
    let mut volume = disc_piece([Jet::constant(l), zero, zero], rim, wet_to, a);
    let width = dry_from.v - wet_to.v;
    let margin = (a - dry_from.v.abs()).min(a - wet_to.v.abs());
    if width > 0.0 && width < THIN_BAND * margin {
        let band = thin_band(z_low, c, inverse_s, l, a);
        first_moment = first_moment + band.first_moment;
        volume = volume + band.volume;
    } else if width > 0.0 {
        // The cut piece: f = -(z + s eta)^2 / (2c), g = -(z + s eta) / c.
        let inverse_c = c.compose(1.0 / c.v, -1.0 / (c.v * c.v), 2.0 / c.v.powi(3));
        let half = inverse_c.scale(-0.5);
        let f = [
            z_low * z_low * half,
            (z_low * s).scale(2.0) * half,
            s2 * half,
        ];
        let g = [-z_low * inverse_c, -s * inverse_c, zero];
        first_moment = first_moment + disc_piece(f, wet_to, dry_from, a);
        volume = volume + disc_piece(g, wet_to, dry_from, a);
    }
    Submerged {
        first_moment,
        volume,
    }
}

impl<const N: usize> Submerged<N> {
    fn times(self, on_moment: Jet<N>, on_volume: Jet<N>) -> Self {
        Submerged {
            first_moment: self.first_moment * on_moment,
            volume: self.volume * on_volume,
        }
    }
}

/// A breakpoint clipped to the disc [-a, a] (a constant at the rim).
fn clip<const N: usize>(eta: Jet<N>, a: f64) -> Jet<N> {
    if eta.v <= -a {
        Jet::constant(-a)
    } else if eta.v >= a {
        Jet::constant(a)
    } else {
        eta
    }
}

/// int_lo^hi (p0 + p1 eta + p2 eta^2) 2 sqrt(a^2 - eta^2) d eta.
fn disc_piece<const N: usize>(p: [Jet<N>; 3], lo: Jet<N>, hi: Jet<N>, a: f64) -> Jet<N> {
    let mut sum = Jet::constant(0.0);
    for (k, pk) in p.iter().enumerate() {
        if pk.v == 0.0 && pk.g.iter().all(|x| *x == 0.0) {
            continue;
        }
        sum = sum + *pk * (segment(k, hi, a) - segment(k, lo, a)).scale(2.0);
    }
    sum
}

/// F_k(eta) = int eta^k sqrt(a^2 - eta^2) d eta, the circular segment's
/// antiderivatives, on a jet (a constant at the rim, where F_k'' is
/// infinite):
///   F_0 = (eta r + a^2 asin(eta/a)) / 2,  F_1 = -r^3 / 3,
///   F_2 = eta (2 eta^2 - a^2) r / 8 + a^4 asin(eta/a) / 8,  r = sqrt(a^2 - eta^2).
fn segment<const N: usize>(k: usize, eta: Jet<N>, a: f64) -> Jet<N> {
    let e = eta.v.clamp(-a, a);
    let r = (a * a - e * e).max(0.0).sqrt();
    let arc = (e / a).clamp(-1.0, 1.0).asin();
    let value = match k {
        0 => 0.5 * (e * r + a * a * arc),
        1 => -r.powi(3) / 3.0,
        _ => e * (2.0 * e * e - a * a) * r / 8.0 + a.powi(4) * arc / 8.0,
    };
    if r == 0.0 || eta.g.iter().all(|x| *x == 0.0) {
        return Jet::constant(value);
    }
    let slope = e.powi(k as i32) * r;
    let curvature = match k {
        0 => -e / r,
        1 => r - e * e / r,
        _ => 2.0 * e * r - e.powi(3) / r,
    };
    eta.compose(value, slope, curvature)
}

/// The cut band in its own variable v = w / c in [-L, 0] (eta =
/// (c v - z) / s): I_band = -(c^2 / (2 s)) int v^2 chord dv and
/// V_band = -(c / s) int v chord dv, by 8-point Gauss-Legendre.
fn thin_band<const N: usize>(
    z_low: Jet<N>,
    c: Jet<N>,
    inverse_s: Jet<N>,
    l: f64,
    a: f64,
) -> Submerged<N> {
    let rule = crate::quadrature::GaussRule::shared(8);
    let (mut moment, mut volume) = (Jet::constant(0.0), Jet::constant(0.0));
    for (x, w) in rule.points.iter().zip(&rule.weights) {
        let v = -l * (1.0 - x);
        let eta = (c.scale(v) - z_low) * inverse_s;
        let inside = Jet::constant(a * a) - eta * eta;
        let r = inside.v.max(0.0).sqrt();
        let chord = inside
            .compose(r, 0.5 / r, -0.25 / (r * inside.v))
            .scale(2.0 * w * l);
        moment = moment + chord.scale(v * v);
        volume = volume + chord.scale(v);
    }
    Submerged {
        first_moment: (c * c * inverse_s).scale(-0.5) * moment,
        volume: -(c * inverse_s) * volume,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const L: f64 = 3.0;
    const A: f64 = 0.4;
    /// The brute force's samples along and across the rod.
    const SAMPLES: (usize, usize) = (2000, 2000);

    /// I and V_w by brute force: the cylinder sampled by Gauss points
    /// along, across and around (its disc in polar coordinates), each
    /// point's z tested against the surface, for rods at moderate tilt
    /// and depth where the samples resolve the cut well enough.
    fn sampled(z_a: f64, c: f64) -> (f64, f64) {
        let s = (1.0 - c * c).sqrt();
        let (along, across) = SAMPLES;
        let (mut moment, mut volume) = (0.0, 0.0);
        for i in 0..along {
            let t = (i as f64 + 0.5) / along as f64 * L;
            for j in 0..across {
                let eta = -A + (j as f64 + 0.5) / across as f64 * 2.0 * A;
                let chord = 2.0 * (A * A - eta * eta).sqrt();
                let z = z_a + c * t + s * eta;
                if z < 0.0 {
                    let dv = chord * (L / along as f64) * (2.0 * A / across as f64);
                    moment += z * dv;
                    volume += dv;
                }
            }
        }
        (moment, volume)
    }

    fn at(z_a: f64, c: f64) -> Submerged<2> {
        submerged(Jet::variable(z_a, 0), Jet::variable(c, 1), L, A)
    }

    /// (B20) against the sampled cylinder, for a rod under, piercing with
    /// no cap cut, with its lower or its upper cap cut, lying nearly flat
    /// across the surface, and tilted the other way (end A higher).
    #[test]
    fn the_submerged_volume_and_moment_are_the_cylinders() {
        for (z_a, c) in [
            (-4.0, 0.6),
            (-1.0, 0.8),
            (-0.1, 0.6),
            (-1.6, 0.6),
            (-0.05, 0.02),
            (-0.05, 1e-4),
            (0.9, -0.5),
        ] {
            let exact = at(z_a, c);
            let (moment, volume) = sampled(z_a, c);
            // The samples place the cut to half a cell: across, a strip
            // of half a cell's width along the whole rod, and along, a
            // cross-section of half a cell's length.
            let (along, across) = SAMPLES;
            let bound = 0.5 * (2.0 * A / across as f64) * 2.0 * A * L
                + 0.5 * (L / along as f64) * std::f64::consts::PI * A * A;
            assert!(
                (exact.volume.v - volume).abs() < bound,
                "V at {z_a}, {c}: {} vs {volume}",
                exact.volume.v
            );
            assert!(
                (exact.first_moment.v - moment).abs() < bound * (L + 2.0 * A),
                "I at {z_a}, {c}: {} vs {moment}",
                exact.first_moment.v
            );
        }
    }

    /// dI/dz_A = V_w (the buoyancy is rho g V_w, B20), and the jets'
    /// first and second derivatives are differences of their values
    /// (relative to the largest derivative), in every regime and across the switch to the thin band.
    #[test]
    fn the_submerged_parts_jets_are_exact() {
        let mut worst = 0.0f64;
        for (z_a, c) in [
            (-4.0, 0.6),
            (-1.0, 0.8),
            (-1.0, 1.0 - 1e-9),
            (-0.1, 0.6),
            (-1.6, 0.6),
            (-0.05, 0.02),
            (-0.05, 1e-4),
            (-0.05, 3e-3),
            (0.9, -0.5),
        ] {
            let exact = at(z_a, c);
            assert!(
                (exact.first_moment.g[0] - exact.volume.v).abs() < 1e-10,
                "dI/dz vs V at {z_a}, {c}"
            );
            // Fourth-order differences, the step well inside the band's
            // width c L / s (so that its truncation, (h / c)^4, and its
            // round-off, eps / h, both stay far below the tolerance).
            let h = 1e-4 * (100.0 * c.abs()).min(1.0);
            for j in 0..2 {
                let d = |steps: f64| {
                    let (z, cc) = if j == 0 {
                        (z_a + steps * h, c)
                    } else {
                        (z_a, c + steps * h)
                    };
                    at(z, cc)
                };
                let (p1, m1, p2, m2) = (d(1.0), d(-1.0), d(2.0), d(-2.0));
                let stencil = |f: &dyn Fn(&Submerged<2>) -> f64| {
                    (8.0 * (f(&p1) - f(&m1)) - (f(&p2) - f(&m2))) / (12.0 * h)
                };
                for part in 0..2 {
                    let pick = |s: &Submerged<2>| if part == 0 { s.first_moment } else { s.volume };
                    let e = pick(&exact);
                    let size =
                        e.g.iter()
                            .chain(e.h.iter().flatten())
                            .fold(1.0f64, |m, x| m.max(x.abs()));
                    let mut here = (stencil(&|s| pick(s).v) - e.g[j]).abs() / size;
                    for k in 0..2 {
                        here = here.max((stencil(&|s| pick(s).g[k]) - e.h[k][j]).abs() / size);
                    }
                    worst = worst.max(here);
                }
            }
        }
        eprintln!("the waterline jets against differences: {worst:.1e}");
        assert!(worst < 1e-7, "{worst:e}");
    }

    /// A floating vertical cylinder's hydrostatic stiffness, the naval
    /// architect's: in heave rho g A_wp, and in heel about a point at
    /// height z_G on its axis rho g (I_wp + V (z_B - z_G)) (I_wp = pi a^4
    /// / 4 the waterplane's second moment, V = A h the displaced volume,
    /// z_B = -h/2 its centroid): the buoyancy's potential -rho g I of
    /// (B21) turned about that point, on jets in the heel phi, and in its
    /// depth.
    #[test]
    fn a_floating_cylinders_stiffness_is_the_naval_architects() {
        let (rho, g) = (1025.0, 9.81);
        let (draft, z_g) = (1.8, -0.4);
        // End A is at -draft; the pivot is l above it along the axis.
        let l = z_g + draft;
        let phi = Jet::<2>::variable(0.0, 0);
        let heave = Jet::<2>::variable(0.0, 1);
        let cos = phi.compose(1.0, 0.0, -1.0);
        let z_a = heave + Jet::constant(z_g) - cos.scale(l);
        let u = submerged(z_a, cos, L, A).first_moment.scale(-rho * g);
        let area = std::f64::consts::PI * A * A;
        let volume = area * draft;
        let want_heel =
            rho * g * (0.25 * std::f64::consts::PI * A.powi(4) + volume * (-0.5 * draft - z_g));
        assert!(
            (u.h[0][0] - want_heel).abs() < 1e-12 * want_heel.abs(),
            "{} {want_heel}",
            u.h[0][0]
        );
        assert!((u.h[1][1] - rho * g * area).abs() < 1e-12 * rho * g * area);
        // Upright, the heel neither lifts nor sinks it (the waterplane's
        // centroid is on the axis): no heave-heel coupling.
        assert!(u.h[0][1].abs() < 1e-9 * rho * g * area);
        // And the buoyancy is rho g V.
        assert!((-u.g[1] - rho * g * volume).abs() < 1e-12 * rho * g * volume);
    }
}
