//! A free point's own contact with the seabed (docs/method.md §12.2,
//! (W42p)). A line's push (W42) acts at its Gauss points, so a free point
//! at the end of lines that reach the bed at an angle (a clump weight on
//! a sloped bed, a pendulum's bob on the bed) had nothing under it: it
//! sank until the Gauss points beside it were deep enough to carry it
//! through a kink in its lines, a state Newton cannot find (MoorDyn's
//! seafloor.txt, 10 kg on a neutrally buoyant rope of EA 1e9 N). MoorDyn
//! holds such a point through its lines' end nodes, each with the push
//! of half its segment; stancf gives the point that push itself,
//!
//! ```text
//!   f_p = sum_i (l_i / 2) d_i (k P(g) - c S(g) n . r_dot) n            (W42p)
//! ```
//!
//! over the lines i attached at the point whose line type has a seabed
//! (d_i its diameter, l_i its end element's length), with P and S of
//! (W41) at the point's penetration g (W40) (the ramp delta = 1e-3 of
//! the widest d_i) and n the bed's normal there. It is frictionless: the
//! friction near the point is its lines' (W44) at their Gauss points.
//! It enters the point's rows as its water's force does (§12.6, (W34)):
//! virtual work at the slab's time points with its exact derivatives in
//! both schemes, and - f_p at rest in statics.

use super::{End, Line};
use crate::water::seabed::Part;
use crate::water::{PointForce, PointInWater, SeabedContact};

/// The seabed under a free point: (W42p) as the contact of the widest
/// attached line times a contact length.
#[derive(Clone, Debug, PartialEq)]
pub struct PointBed {
    /// The bed as the widest attached line on it touches it (its diameter
    /// sets the ramp of (W41)).
    contact: SeabedContact,
    /// sum_i l_i d_i / (2 d): the length of the widest line whose push
    /// equals the point's (m).
    length: f64,
}

impl PointBed {
    /// The bed under free point p of `lines`: None where no line attached
    /// there has a seabed.
    pub(super) fn of(lines: &[Line], p: usize) -> Option<PointBed> {
        let mut contact: Option<&SeabedContact> = None;
        let mut width = 0.0;
        for line in lines {
            for (end, at) in line.ends.iter().enumerate() {
                if *at != End::Point(p) {
                    continue;
                }
                let model = &line.model;
                let Some(bed) = &model.seabed else { continue };
                let element = if end == 0 {
                    0
                } else {
                    model.cable.elements - 1
                };
                width += 0.5 * model.element_length(element) * bed.diameter;
                if contact.is_none_or(|c| bed.diameter > c.diameter) {
                    contact = Some(bed);
                }
            }
        }
        let contact = contact?.clone();
        let length = width / contact.diameter;
        Some(PointBed { contact, length })
    }

    /// The push (W42p) on the point at r moving at r_dot, with its
    /// derivatives; zero clear of the bed.
    pub fn force(&self, r: &[f64; 3], rdot: &[f64; 3]) -> PointForce {
        let f = self.contact.part_at(Part::Normal, r, &[0.0; 3], rdot, true);
        self.scaled(f.force, f.d_r, f.d_rdot)
    }

    /// The push (W42p) on the point at rest at r, with its derivative.
    pub fn static_force(&self, r: &[f64; 3]) -> PointForce {
        let f = self
            .contact
            .static_part(Part::Normal, r, &[0.0; 3], &[0.0; 3]);
        self.scaled(f.force, f.d_r, [[0.0; 3]; 3])
    }

    fn scaled(&self, force: [f64; 3], d_r: [[f64; 3]; 3], d_rdot: [[f64; 3]; 3]) -> PointForce {
        let l = self.length;
        PointForce {
            force: force.map(|c| l * c),
            d_r: d_r.map(|row| row.map(|c| l * c)),
            d_rdot: d_rdot.map(|row| row.map(|c| l * c)),
        }
    }
}

/// The steady force f on a free point at rest at r (its static rows
/// hold minus it): the steady current's drag on it in water (§12.6) and
/// the bed's push (W42p), with their derivative in r.
pub fn steady_point_force(
    water: Option<&PointInWater>,
    bed: Option<&PointBed>,
    r: &[f64; 3],
) -> PointForce {
    let mut f = water.map_or_else(PointForce::default, |w| w.static_force(r));
    if let Some(bed) = bed {
        add_force(&mut f, &bed.static_force(r));
    }
    f
}

/// f += g, the force and its derivatives.
pub(super) fn add_force(f: &mut PointForce, g: &PointForce) {
    for i in 0..3 {
        f.force[i] += g.force[i];
        for j in 0..3 {
            f.d_r[i][j] += g.d_r[i][j];
            f.d_rdot[i][j] += g.d_rdot[i][j];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::water::Seabed;

    fn bed_of_slope() -> PointBed {
        let normal = [-0.2, 0.3, 1.0];
        let n = crate::vec3::norm(normal);
        let seabed = Seabed::plane([1.0, -2.0, -30.0], normal.map(|c| c / n), 3e6, 3e5);
        PointBed {
            contact: SeabedContact {
                seabed,
                diameter: 0.1,
            },
            length: 0.8,
        }
    }

    /// (W42p) past the ramp: k l d (g - delta/2) along n, less the
    /// damping c l d v_n; its derivatives match central differences.
    #[test]
    fn a_points_push_is_its_lines_half_elements_push_with_exact_derivatives() {
        let bed = bed_of_slope();
        let n = bed.contact.seabed.normal_at(&[0.0; 3]);
        let r = [2.0, -1.0, -30.5];
        let rdot = [0.3, -0.2, -0.1];
        let g = bed.contact.seabed.penetration(&r);
        assert!(g > 1e-4);
        let f = bed.force(&r, &rdot);
        let vn = crate::vec3::dot(n, rdot);
        let expected = 0.8 * 0.1 * (3e6 * (g - 0.5e-4) - 3e5 * vn);
        for c in 0..3 {
            assert!((f.force[c] - expected * n[c]).abs() <= 1e-9 * expected.abs());
        }
        let (dr, dv) =
            crate::water::point::derivative_errors(|r, v| bed.force(r, v), &r, &rdot, 1e-7);
        assert!(dr <= 1e-6 * 3e6 * 0.08, "d f / d r off by {dr}");
        assert!(dv <= 1e-6 * 3e5 * 0.08, "d f / d rdot off by {dv}");
        let s = bed.static_force(&r);
        assert!((s.force[2] - 0.8 * 0.1 * 3e6 * (g - 0.5e-4) * n[2]).abs() < 1e-6);
        assert_eq!(s.d_rdot, [[0.0; 3]; 3]);
        let above = [2.0, -1.0, -20.0];
        assert_eq!(bed.force(&above, &rdot), PointForce::default());
    }
}
