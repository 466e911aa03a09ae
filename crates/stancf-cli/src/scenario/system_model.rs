//! The library's system from a [`SystemScenario`]: every line a cable
//! model of its line type's section, every point a library point, and
//! the lines' start shapes (docs/method.md §11.6).

use super::system::{LineType, PointType, SystemScenario};
use stancf::system::{End, Line, Point, PointKind, System};
use stancf::{Cable, Load, Material, Model, ModelError, ModelOptions};

/// The factor c in the bending stiffness EI = c w L^3 a line of EI = 0
/// is given (docs/method.md §11.7): bending then changes the tensions of
/// a line of weight w L under tension T by about c w L / T, 1e-7 at
/// T = w L.
pub const EI_FACTOR: f64 = 1e-7;

impl SystemScenario {
    /// The bending stiffness line i is simulated with: its type's EI, or
    /// for EI = 0 (chain, wire rope) c w L^3 with c = [`EI_FACTOR`] and w
    /// its weight per length (in a system without gravity, c EA L^2 /
    /// 1000).
    pub fn bending_stiffness(&self, line: usize) -> f64 {
        let l = &self.lines[line];
        let t = &self.line_types[l.line_type];
        if t.ei > 0.0 {
            return t.ei;
        }
        let g = self.gravity.iter().map(|g| g * g).sum::<f64>().sqrt();
        let w = t.mass_per_length * g;
        let reference_tension = if w > 0.0 { w * l.length } else { 1e-3 * t.ea };
        EI_FACTOR * reference_tension * l.length * l.length
    }

    /// The library's system: the lines' models (their reference shapes
    /// straight between their end points) and the points.
    pub fn system(&self) -> Result<System, ModelError> {
        let points: Vec<Point> = self.points.iter().map(library_point).collect();
        let lines = self
            .lines
            .iter()
            .enumerate()
            .map(|(i, l)| {
                let model = self
                    .line_model(i, &points)
                    .map_err(|e| e.under(&format!("lines[{i}]")))?;
                let ends = l.ends.map(|e| e.map_or(End::Loose, End::Point));
                Ok(Line { model, ends })
            })
            .collect::<Result<Vec<_>, ModelError>>()?;
        System::new(lines, points, self.gravity)
    }

    /// Line i's cable model: its type's section over the area pi d^2 / 4,
    /// its reference straight from end A toward end B (from a loose end A
    /// down along gravity to B), under gravity. The start shapes are the
    /// library's ([`stancf::system::straight_states`],
    /// [`stancf::system::catenary_states`]).
    fn line_model(&self, i: usize, points: &[Point]) -> Result<Model, ModelError> {
        let l = &self.lines[i];
        let t = &self.line_types[l.line_type];
        let at = |e: Option<usize>| e.map(|p| points[p].state_at(0.0).0);
        let down = if self.gravity == [0.0; 3] {
            [0.0, 0.0, -1.0]
        } else {
            self.gravity
        };
        let (origin, direction) = match (at(l.ends[0]), at(l.ends[1])) {
            (Some(a), Some(b)) => (a, std::array::from_fn(|k| b[k] - a[k])),
            (Some(a), None) => (a, down),
            (None, Some(b)) => {
                let n = down.iter().map(|c| c * c).sum::<f64>().sqrt();
                (std::array::from_fn(|k| b[k] - l.length * down[k] / n), down)
            }
            (None, None) => unreachable!("a line has an attached end (checked on reading)"),
        };
        let direction = if direction == [0.0; 3] {
            down
        } else {
            direction
        };
        let cable = Cable::straight(l.length, l.elements, l.element_type)
            .with_origin(origin)
            .with_direction(direction);
        let material = section_material(t, self.bending_stiffness(i));
        let options = ModelOptions {
            measures: self.measures,
            space_points: self.analysis.space_points,
        };
        let gravity = if self.gravity == [0.0; 3] {
            vec![]
        } else {
            vec![Load::Gravity {
                acceleration: self.gravity,
            }]
        };
        Model::new(cable, material, options, gravity)
    }
}

fn library_point(p: &super::system::SystemPoint) -> Point {
    match p.kind {
        PointType::Fixed => Point::fixed(p.position),
        PointType::Coupled => Point::coupled(p.position, p.motion),
        PointType::Free => Point {
            kind: PointKind::Free,
            position: p.position,
            mass: p.mass,
            force: p.force,
        },
    }
}

/// The material of a line type's section: A = pi d^2 / 4, E = EA / A,
/// rho = m / A, I = EI / E.
fn section_material(t: &LineType, ei: f64) -> Material {
    let area = std::f64::consts::PI * t.diameter * t.diameter / 4.0;
    let youngs_modulus = t.ea / area;
    Material {
        youngs_modulus,
        density: t.mass_per_length / area,
        area,
        second_moment: ei / youngs_modulus,
    }
}
