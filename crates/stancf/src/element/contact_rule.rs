//! Where the seabed's push is integrated along an element (docs/method.md
//! §12.2, (W47a)-(W47c)): exactly, on the part of the element that is in
//! the bed.
//!
//! The push per length f_n = d (k P(g) - c S(g) n . r_dot) n (W42) is zero
//! clear of the bed, with kinks where the line touches down (g = 0) and at
//! the contact ramp's edge (g = delta, (W41)). The element's axial Gauss
//! rule spread over a touchdown element integrates the kinks to first
//! order in the element length: where the touchdown falls between two of
//! its points decides how much of the bed's push the element feels.
//! Instead, at coordinates q, the roots of g(xi) = 0 and g(xi) = delta in
//! (0, 1) cut the element into pieces, and each piece in the bed, [a, b],
//! carries a Gauss rule mapped onto it:
//!
//! ```text
//!   int_0^1 f_n l dxi = sum_pieces sum_s (b - a) w_s l f_n(a + (b - a) x_s)  (W47a)
//! ```
//!
//! On a plane bed g is a polynomial of degree NS - 1 in xi (cubic in
//! SAC-2, quintic in SAC-3), and on a piece f_n N_k is one of degree
//! 2 (NS - 1) past the ramp, which the NS points of the mass's rule
//! integrate exactly, and 3 (NS - 1) in it, which m = 5 (SAC-2) or 8
//! (SAC-3) points do; an element wholly in the bed takes the same. The sum
//! being the integral, it does not jump when a piece is born or vanishes,
//! and by Leibniz's rule its derivative is the sum of the derivatives at
//! the mapped points with the pieces held: the boundary terms vanish at a
//! touchdown (f_n = 0) and cancel at the ramp's edge (f_n continuous)
//! (W47b). The exact Jacobian is (W47) at those points.
//!
//! The roots (W47c): g's monomial coefficients come from its values at NS
//! equally spaced points, and its real roots are isolated exactly, the
//! roots of its derivative (found the same way, recursively) cutting
//! [0, 1] into pieces on which it is monotone, each with at most one root,
//! found by Newton's method kept inside its bracket. On a bathymetry
//! grid g is no polynomial along the element, no rule is exact, and
//! pieces born and vanishing would make the sum jump (a grid with a step
//! stalled the static solve): the push stays at the axial rule there.
//! Friction (W44) is no polynomial either: it stays at the axial rule
//! (crate::element::point_force::seabed_parts).

use super::point_force::position;
use super::{CableElement, SpacePoint};
use crate::water::{BedSurface, SeabedContact};

/// Steps at most of a bracketed root's search (Newton's converge in a
/// few; bisections alone would reach 2^-60 of the element).
const MAX_ROOT_STEPS: usize = 60;

/// A root in [0, 1] is found to 4 ulp of 1: Newton's last step, or the
/// bracket, below it.
const ROOT_RESOLUTION: f64 = 4.0 * f64::EPSILON;

impl<const NS: usize, const ND: usize> CableElement<NS, ND> {
    /// Calls `visit` at every point where the seabed's push is integrated
    /// for coordinates `q` (W47a): a rule exact for it on each piece
    /// between the touchdowns and the ramp's edges that is in the bed (on
    /// all of the element if it has none in it).
    pub(super) fn for_each_contact_point(
        &self,
        contact: &SeabedContact,
        q: &[f64; ND],
        mut visit: impl FnMut(&SpacePoint<NS>),
    ) {
        if let BedSurface::Grid(_) = contact.seabed.surface {
            // g is no polynomial along the element: no rule is exact, and
            // pieces born and vanishing would make the sum jump.
            self.axial_points.iter().for_each(visit);
            return;
        }
        let mut splits = [0.0; 2 * MAX_COEFFICIENTS];
        let (gap, found) = self.touchdowns(contact, q, &mut splits);
        let delta = contact.ramp_width();
        let mut start = 0.0;
        for end in splits[..found].iter().copied().chain([1.0]) {
            let span = end - start;
            let g = evaluate(&gap[..NS], 0.5 * (start + end));
            if span > 0.0 && g > 0.0 {
                // Past the ramp the push is of degree 2 (NS - 1): the NS
                // points of the mass's rule take it exactly; in the ramp,
                // of degree 3 (NS - 1): the bed's rule.
                let rule = if g > delta {
                    &self.mass_points
                } else {
                    &self.bed_points
                };
                for p in rule {
                    let xi = start + span * p.xi;
                    visit(&SpacePoint {
                        xi,
                        wl: span * p.wl,
                        shape: if found == 0 {
                            p.shape
                        } else {
                            (self.shape)(xi, self.length)
                        },
                    });
                }
            }
            start = end;
        }
    }

    /// The penetration g (W40) along the element for coordinates q, the
    /// polynomial of degree NS - 1 (monomial coefficients) through its
    /// values at NS equally spaced points (on a plane bed g is affine in
    /// r, and r a polynomial of that degree in xi), and the roots of
    /// g(xi) = 0 and of g(xi) = delta (the contact ramp's edge, (W41)) in
    /// (0, 1), ascending, into `roots` (W47c), with how many.
    fn touchdowns(
        &self,
        contact: &SeabedContact,
        q: &[f64; ND],
        roots: &mut [f64],
    ) -> ([f64; MAX_COEFFICIENTS], usize) {
        let (n, mut g) = (NS, [0.0; MAX_COEFFICIENTS]);
        for (gj, shape) in g.iter_mut().zip(&self.bed_samples) {
            *gj = contact.seabed.penetration(&position(shape, q));
        }
        let gap = monomials(&g[..n]);
        let delta = contact.ramp_width();
        if lies_outside(&gap[..n], (0.0, delta)) {
            // Wholly clear of the bed, or wholly past the ramp: no
            // root of either (most elements, told apart without a
            // search).
            return (gap, 0);
        }
        let mut p = gap;
        // p and p - delta turn at the same points: found once.
        let (derivative, mut turns) = (derivative(&p[..n]), [0.0; MAX_COEFFICIENTS]);
        let n_turns = real_roots(&derivative[..n - 1], &mut turns);
        let turns = &turns[..n_turns];
        let mut found = monotone_roots(&p[..n], &derivative[..n - 1], turns, roots);
        p[0] -= delta;
        found += monotone_roots(&p[..n], &derivative[..n - 1], turns, &mut roots[found..]);
        roots[..found].sort_by(f64::total_cmp);
        (gap, found)
    }
}

/// Coefficients at most of g(xi): degree 5 (SAC-3).
const MAX_COEFFICIENTS: usize = 6;

/// The monomial coefficients c_0 .. c_d of the polynomial of degree d =
/// values.len() - 1 through `values` at d + 1 equally spaced points of
/// [0, 1] (Newton's divided differences, then expanded).
fn monomials(values: &[f64]) -> [f64; MAX_COEFFICIENTS] {
    let n = values.len();
    let x = |j: usize| j as f64 / (n - 1) as f64;
    let mut dd = [0.0; MAX_COEFFICIENTS];
    dd[..n].copy_from_slice(values);
    for level in 1..n {
        for j in (level..n).rev() {
            dd[j] = (dd[j] - dd[j - 1]) / (x(j) - x(j - level));
        }
    }
    // Horner on the Newton form: p = dd_0 + (xi - x_0)(dd_1 + (xi - x_1)(...)).
    let mut c = [0.0; MAX_COEFFICIENTS];
    for j in (0..n).rev() {
        // c <- c (xi - x_j) + dd_j
        for k in (1..n).rev() {
            c[k] = c[k - 1] - x(j) * c[k];
        }
        c[0] = dd[j] - x(j) * c[0];
    }
    c
}

/// p(xi) for monomial coefficients p.
fn evaluate(p: &[f64], xi: f64) -> f64 {
    p.iter().rev().fold(0.0, |acc, c| acc * xi + c)
}

/// The roots in (0, 1) where p changes sign, ascending, into `roots`;
/// returns how many (a root p only touches may count twice: a split
/// between two pieces on the same side, which changes no exact sum).
/// Exact isolation: a line's or a quadratic's in closed form; above, the
/// roots of p' cut [0, 1] into pieces on which p is monotone
/// ([`monotone_roots`]).
fn real_roots(p: &[f64], roots: &mut [f64]) -> usize {
    let degree = p.iter().rposition(|&c| c != 0.0).unwrap_or(0);
    match degree {
        0 => 0,
        1 => {
            let root = -p[0] / p[1];
            let inside = root > 0.0 && root < 1.0 && !roots.is_empty();
            if inside {
                roots[0] = root;
            }
            usize::from(inside)
        }
        2 => quadratic_roots(p, roots),
        _ => {
            let p = &p[..=degree];
            let dp = derivative(p);
            let mut turns = [0.0; MAX_COEFFICIENTS];
            let n_turns = real_roots(&dp[..degree], &mut turns);
            monotone_roots(p, &dp[..degree], &turns[..n_turns], roots)
        }
    }
}

/// p' of p (monomial coefficients; one fewer).
fn derivative(p: &[f64]) -> [f64; MAX_COEFFICIENTS] {
    let mut dp = [0.0; MAX_COEFFICIENTS];
    for k in 1..p.len() {
        dp[k - 1] = k as f64 * p[k];
    }
    dp
}

/// The real roots in (0, 1) of c0 + c1 xi + c2 xi^2, ascending, in the
/// form that loses no digits to cancellation (q = -(c1 + sign(c1)
/// sqrt(disc)) / 2, the roots q / c2 and c0 / q); a double root is none.
fn quadratic_roots(p: &[f64], roots: &mut [f64]) -> usize {
    let (c0, c1, c2) = (p[0], p[1], p[2]);
    let disc = c1 * c1 - 4.0 * c0 * c2;
    if disc <= 0.0 {
        return 0;
    }
    let q = -0.5 * (c1 + c1.signum() * disc.sqrt());
    let (mut r1, mut r2) = (q / c2, if q != 0.0 { c0 / q } else { -q / c2 });
    if r1 > r2 {
        std::mem::swap(&mut r1, &mut r2);
    }
    let mut found = 0;
    for r in [r1, r2] {
        if r > 0.0 && r < 1.0 && found < roots.len() {
            roots[found] = r;
            found += 1;
        }
    }
    found
}

/// The roots in (0, 1) where p (derivative dp) changes sign, ascending,
/// into `roots`, given the points `turns` (ascending) where dp does:
/// between two of them p is monotone, and a piece whose ends differ in
/// sign holds one root.
fn monotone_roots(p: &[f64], dp: &[f64], turns: &[f64], roots: &mut [f64]) -> usize {
    if one_signed(p) {
        return 0;
    }
    let mut found = 0;
    let (mut a, mut pa) = (0.0, evaluate(p, 0.0));
    for b in turns.iter().copied().chain([1.0]) {
        let pb = evaluate(p, b);
        if (pa > 0.0) != (pb > 0.0) && found < roots.len() {
            roots[found] = bracketed_root(p, dp, (a, pa), (b, pb));
            found += 1;
        }
        (a, pa) = (b, pb);
    }
    found
}

/// Whether p keeps one sign on [0, 1] ([`lies_outside`] of (0, 0)).
fn one_signed(p: &[f64]) -> bool {
    lies_outside(p, (0.0, 0.0))
}

/// Whether p lies below `low` or above `high` on all of [0, 1], by its
/// Bernstein coefficients b_i = sum_{k <= i} C(i, k) / C(n, k) c_k,
/// between which p lies there (the convex hull of its control points).
fn lies_outside(p: &[f64], (low, high): (f64, f64)) -> bool {
    let n = p.len() - 1;
    let (mut above, mut below) = (true, true);
    for i in 0..=n {
        let b: f64 = (0..=i).map(|k| BERNSTEIN[n][i][k] * p[k]).sum();
        above &= b > high;
        below &= b < low;
    }
    above || below
}

/// C(i, k) / C(n, k), the monomials' Bernstein coefficients on [0, 1],
/// for n < MAX_COEFFICIENTS.
const BERNSTEIN: [[[f64; MAX_COEFFICIENTS]; MAX_COEFFICIENTS]; MAX_COEFFICIENTS] = {
    const fn choose(n: usize, k: usize) -> u64 {
        let mut c = 1u64;
        let mut j = 0;
        while j < k {
            c = c * (n - j) as u64 / (j as u64 + 1);
            j += 1;
        }
        c
    }
    let mut table = [[[0.0; MAX_COEFFICIENTS]; MAX_COEFFICIENTS]; MAX_COEFFICIENTS];
    let mut n = 0;
    while n < MAX_COEFFICIENTS {
        let mut i = 0;
        while i <= n {
            let mut k = 0;
            while k <= i {
                table[n][i][k] = choose(i, k) as f64 / choose(n, k) as f64;
                k += 1;
            }
            i += 1;
        }
        n += 1;
    }
    table
};

/// The root of p between a and b, where p is monotone and changes sign:
/// Newton's steps from the secant's point, a bisection wherever a step
/// would leave the bracket, which shrinks about the root at each
/// evaluation; to the resolution of f64 in [0, 1].
fn bracketed_root(p: &[f64], dp: &[f64], (mut a, pa): (f64, f64), (mut b, pb): (f64, f64)) -> f64 {
    let above_a = pa > 0.0;
    // p's round-off: where |p| is below it, x is as much a root as any
    // (near a double root, as at an anchor lying on the bed, Newton's
    // steps would only halve the distance).
    let noise = 8.0 * f64::EPSILON * p.iter().map(|c| c.abs()).sum::<f64>();
    let mut x = a - pa * (b - a) / (pb - pa);
    if !(x > a && x < b) {
        x = 0.5 * (a + b);
    }
    for _ in 0..MAX_ROOT_STEPS {
        let px = evaluate(p, x);
        if px.abs() <= noise {
            return x;
        }
        if (px > 0.0) == above_a {
            a = x;
        } else {
            b = x;
        }
        let step = px / evaluate(dp, x);
        if step.abs() <= ROOT_RESOLUTION {
            return (x - step).clamp(a, b);
        }
        x = if x - step > a && x - step < b {
            x - step
        } else {
            0.5 * (a + b)
        };
        if b - a <= ROOT_RESOLUTION {
            return x;
        }
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The interpolant through a polynomial's values is that polynomial:
    /// (xi - 0.2)(xi - 0.5)(xi - 0.9) = -0.09 + 0.73 xi - 1.6 xi^2 + xi^3.
    /// Its roots to 1e-12: a root's search stops where |p| is within its
    /// round-off, 8 eps sum |c_k| = 6e-15, over a slope of 0.1 to 0.3.
    #[test]
    fn a_cubic_is_its_own_interpolant_and_its_roots_are_found() {
        let p = |x: f64| (x - 0.2) * (x - 0.5) * (x - 0.9);
        let values: Vec<f64> = (0..4).map(|j| p(j as f64 / 3.0)).collect();
        let c = monomials(&values);
        for (got, want) in c.iter().zip([-0.09, 0.73, -1.6, 1.0]) {
            assert!((got - want).abs() < 1e-14, "{c:?}");
        }
        let mut roots = [0.0; MAX_COEFFICIENTS];
        let found = real_roots(&c[..4], &mut roots);
        assert_eq!(found, 3);
        for (got, want) in roots.iter().zip([0.2, 0.5, 0.9]) {
            assert!((got - want).abs() < 1e-12, "{roots:?}");
        }
    }

    /// A narrow dip between two equally spaced points of the same sign
    /// is found: (xi - 0.41)(xi - 0.43), positive at 0, 1/3, 2/3 and 1,
    /// held as a quintic's coefficients.
    #[test]
    fn a_narrow_dip_between_the_sampled_points_is_found() {
        let p = [0.41 * 0.43, -(0.41 + 0.43), 1.0, 0.0, 0.0, 0.0];
        let mut roots = [0.0; MAX_COEFFICIENTS];
        assert_eq!(real_roots(&p, &mut roots), 2);
        assert!((roots[0] - 0.41).abs() < 1e-14 && (roots[1] - 0.43).abs() < 1e-14);
    }
}
