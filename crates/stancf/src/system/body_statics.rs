//! A free body in a system's static solve (docs/method.md §15.8): its
//! centre of mass r_G and its rotation vector theta from the rotation it
//! was given, R = R_0 exp([theta]) (B4), are six unknowns in the border
//! after the points'. Its own rows are the variation of the potential of
//! its constant forces F_j at xi'_j from its centre,
//!
//! ```text
//!   V = - F . r_G - sum_j F_j . R_0 exp([theta]) xi'_j,     F = sum_j F_j      (B15)
//! ```
//!
//! (weight and buoyancy act at the centre of mass, MoorDyn's convention,
//! so they give no moment) and the buoyancy's potential of its rods,
//! -rho g I(r_G, theta) (B20), and in a steady uniform current U the drag
//! of (B10) and of its rods (B19) at rest (at the reference point
//! f = 1/2 rho diag(CdA) w |w|, w = R^T U in body axes, -c from the
//! centre), whose generalized forces are R f on r_G and J_r(theta)^T M_G
//! on theta (M_G the drag's moment about the centre, J_r^T = J_r(-theta));
//! a point P on it at xi' is at
//! y_P = r_G + R_0 exp([theta]) xi' (B11 at rest), the lines' rows there
//! are carried to the body's by (dy_P/dq)^T (B12), and P's rows become
//! y_P - (B11) = 0 (B13), as in a step (§15.7).

use super::body_terms::{BodyPoint, PinHold};
use super::layout::SystemLayout;
use super::{System, SystemStatics};
use crate::body::attach::{offsets, project};
use crate::body::jet::{Jet, JetVec};
use crate::body::BodyWater;
use crate::bordered::BorderedMatrix;
use crate::linear::{AddEntries, Jacobian};

/// A free body of a static solve.
#[derive(Clone, Debug)]
pub(super) struct StaticBody {
    pub index: usize,
    /// The rotation theta is measured from.
    pub rotation: [[f64; 3]; 3],
    /// The centre of mass in body axes, from the reference point.
    pub centre_of_mass: [f64; 3],
    /// Constant forces (global) at their arms from the centre (body axes).
    pub forces: Vec<([f64; 3], [f64; 3])>,
    pub points: Vec<BodyPoint>,
    /// The shortest attached line's length and the farthest point's arm
    /// (the scales of the unknowns, as in a step).
    pub length: f64,
    pub arm: f64,
    /// The stiffness of the lines at its points, the largest diagonal of
    /// their rows there at the last Jacobian (the rows' weights).
    pub stiffness: f64,
    /// [r_G; theta] at the last converged increment.
    pub converged: [f64; 6],
    /// The pin's force on the body at the last evaluation of its rows
    /// (the centre's rows it replaces: what balances the body's other
    /// loads, (B35) at rest).
    pub pin_force: [f64; 3],
    /// The body's water where a steady current drags it (B10), (B19).
    pub drag: Option<BodyWater>,
    /// The body's water where it has rods, whose buoyancy is a potential
    /// of the pose (B20).
    pub rods_water: Option<BodyWater>,
    /// Where everything that loads the body lies on one line through it
    /// (a free rod held at its ends), the line (body axes) and the
    /// stiffness of the spin hold about it ([`spin_axis`]).
    pub spin_hold: Option<([f64; 3], f64)>,
    /// Where the body's assembly turns freely about a vertical line
    /// ([`super::body_holds::yaw_hold`]), the vertical in its axes at
    /// t = 0 and the hold's stiffness.
    pub yaw_hold: Option<([f64; 3], f64)>,
    /// A pin (§15.12): the pinned point from the centre of mass (body
    /// axes) and what holds it (a joint, §15.14).
    pub pin: Option<([f64; 3], PinHold)>,
    /// The holds of a body that floats on its rods alone.
    pub float_hold: Option<super::body_holds::FloatHold>,
    /// A constant moment (global, B27).
    pub moment: [f64; 3],
    /// The stiffness scale of a body that its lines do not give one (a
    /// floating or pinned body without lines): its rows' weights.
    pub own_stiffness: f64,
}

impl StaticBody {
    /// The body's unknowns [r_G; theta] from x.
    pub fn unknowns(&self, layout: &SystemLayout, x: &[f64]) -> [f64; 6] {
        std::array::from_fn(|k| x[self.global(layout, k)])
    }

    pub(super) fn global(&self, layout: &SystemLayout, k: usize) -> usize {
        layout.body_unknown(self.index, 0, k).expect("a free body")
    }

    /// The body's rotation at unknowns q.
    pub fn rotation_at(&self, q: &[f64; 6]) -> [[f64; 3]; 3] {
        crate::vec3::mat3_mul(
            &self.rotation,
            &crate::body::rotation::exp_map([q[3], q[4], q[5]]),
        )
    }

    /// Adds the body's rows (B15), carries its points' rows to them (B12)
    /// and sets its points' rows to their constraints (B13). Call after
    /// the lines and points have added theirs.
    pub fn add(
        &mut self,
        layout: &SystemLayout,
        x: &[f64],
        residual: &mut [f64],
        mut jacobian: Option<&mut BorderedMatrix>,
    ) {
        let q = self.unknowns(layout, x);
        let theta = [q[3], q[4], q[5]];
        let g = |k: usize| layout.body_unknown(self.index, 0, k).expect("a free body");
        for (force, arm) in &self.forces {
            let (p, _) = offsets(&self.rotation, *arm, theta, [0.0; 3]);
            let work = project(*force, &p);
            for c in 0..3 {
                residual[g(c)] -= force[c];
                residual[g(3 + c)] -= work.g[c];
            }
            if let Some(m) = jacobian.as_deref_mut() {
                for j in 0..3 {
                    for i in 0..3 {
                        m.add(g(3 + j), g(3 + i), -work.h[j][i]);
                    }
                }
            }
        }
        if let Some(water) = &self.drag {
            self.add_drag(layout, &q, water, residual, jacobian.as_deref_mut());
        }
        if let Some(water) = &self.rods_water {
            self.add_buoyancy(layout, &q, water, residual, jacobian.as_deref_mut());
        }
        for (a, k) in self.spin_hold.iter().chain(&self.yaw_hold).copied() {
            let along = a[0] * theta[0] + a[1] * theta[1] + a[2] * theta[2];
            for i in 0..3 {
                residual[g(3 + i)] += k * a[i] * along;
                if let Some(m) = jacobian.as_deref_mut() {
                    for j in 0..3 {
                        m.add(g(3 + i), g(3 + j), k * a[i] * a[j]);
                    }
                }
            }
        }
        if self.moment != [0.0; 3] {
            // -Q_theta of (B27) and its derivative in theta.
            let th: JetVec<3> = std::array::from_fn(|i| Jet::variable(theta[i], i));
            let on_theta = crate::body::terms::moment_on_theta(&self.rotation, self.moment, &th);
            for c in 0..3 {
                residual[g(3 + c)] -= on_theta[c].v;
                if let Some(m) = jacobian.as_deref_mut() {
                    for j in 0..3 {
                        m.add(g(3 + c), g(3 + j), -on_theta[c].g[j]);
                    }
                }
            }
        }
        if let Some(hold) = self.float_hold {
            self.add_float_hold(&hold, &q, &g, residual, jacobian.as_deref_mut());
        }
        if jacobian.is_some() {
            self.stiffness = self.own_stiffness;
        }
        for bp in &self.points {
            let y = |c: usize| layout.point_unknown(bp.point, 0, c).expect("border");
            let (p, _) = offsets(&self.rotation, bp.arm, theta, [0.0; 3]);
            let raw: [f64; 3] = std::array::from_fn(|c| residual[y(c)]);
            let moment = project(raw, &p);
            for c in 0..3 {
                residual[g(c)] += raw[c];
                residual[g(3 + c)] += moment.g[c];
            }
            if let Some(m) = jacobian.as_deref_mut() {
                for c in 0..3 {
                    self.stiffness = self.stiffness.max(m.get(y(c), y(c)).abs());
                    m.add_border_row(g(c), y(c), 1.0);
                    for j in 0..3 {
                        m.add_border_row(g(3 + j), y(c), p[c].g[j]);
                    }
                }
                for c in 0..3 {
                    m.clear_border_row(y(c));
                }
                for j in 0..3 {
                    for i in 0..3 {
                        m.add(g(3 + j), g(3 + i), moment.h[j][i]);
                    }
                }
            }
            for c in 0..3 {
                residual[y(c)] = x[y(c)] - (q[c] + p[c].v);
            }
            if let Some(m) = jacobian.as_deref_mut() {
                for c in 0..3 {
                    m.add(y(c), y(c), 1.0);
                    m.add(y(c), g(c), -1.0);
                    for j in 0..3 {
                        m.add(y(c), g(3 + j), -p[c].g[j]);
                    }
                }
            }
        }
        // The rows are dU/dq - f: the pin's force balances the others.
        if let Some(raw) = self.add_pin(layout, x, &q, residual, jacobian) {
            self.pin_force = raw;
        }
    }

    /// The springs of [`super::body_holds::FloatHold`] in the rows.
    fn add_float_hold(
        &self,
        hold: &super::body_holds::FloatHold,
        q: &[f64; 6],
        g: &impl Fn(usize) -> usize,
        residual: &mut [f64],
        mut jacobian: Option<&mut BorderedMatrix>,
    ) {
        let a = hold.vertical;
        let along = a[0] * q[3] + a[1] * q[4] + a[2] * q[5];
        for c in 0..2 {
            residual[g(c)] += hold.translation * (q[c] - hold.at[c]);
            if let Some(m) = jacobian.as_deref_mut() {
                m.add(g(c), g(c), hold.translation);
            }
        }
        for i in 0..3 {
            residual[g(3 + i)] += hold.rotation * a[i] * along;
            if let Some(m) = jacobian.as_deref_mut() {
                for j in 0..3 {
                    m.add(g(3 + i), g(3 + j), hold.rotation * a[i] * a[j]);
                }
            }
        }
    }

    /// The weights of the body's unknowns: its centre like a point of
    /// the shortest line's length L, its rotation by its farthest arm.
    pub fn unknown_weights(&self) -> [f64; 6] {
        std::array::from_fn(|k| if k < 3 { 1.0 } else { self.arm } / self.length)
    }

    /// The weights of the body's rows: the displacement a row's force (or
    /// moment) would cause on the lines' stiffness at its points, as a
    /// fraction of L.
    pub fn row_weights(&self) -> [f64; 6] {
        let k = self.stiffness.max(f64::MIN_POSITIVE);
        std::array::from_fn(|i| {
            if i < 3 && self.pin.is_some() {
                // The pin's rows are positions.
                1.0 / self.length
            } else if i < 3 {
                1.0 / (k * self.length)
            } else {
                1.0 / (k * self.arm * self.length)
            }
        })
    }
}

impl SystemStatics {
    /// The potential of the free bodies' constant forces at the last
    /// converged increment, -sum_j F_j . x_j (weight and buoyancy at the
    /// centre of mass, loads at their points).
    pub(super) fn body_potential(&self) -> f64 {
        let eq = &self.equations;
        eq.bodies
            .iter()
            .map(|body| {
                let q = body.converged;
                let rotation = body.rotation_at(&q);
                body.buoyancy_potential(&q)
                    + body
                        .forces
                        .iter()
                        .map(|(f, arm)| {
                            let at = crate::body::pose::point([q[0], q[1], q[2]], &rotation, *arm);
                            -crate::vec3::dot(*f, at)
                        })
                        .sum::<f64>()
            })
            .sum()
    }

    /// Free body b's pose at the last converged increment: its reference
    /// point and its rotation (body axes to global); None for a fixed body.
    /// The force of body b's pin on it at the equilibrium (global): what
    /// balances its weight, buoyancy, the current's drag and its lines'
    /// pull. None if b is not a pinned free body.
    pub fn pin_force(&self, b: usize) -> Option<[f64; 3]> {
        let body = self.equations.bodies.iter().find(|s| s.index == b)?;
        body.pin.map(|_| body.pin_force)
    }

    pub fn body_pose(&self, b: usize) -> Option<([f64; 3], [[f64; 3]; 3])> {
        let eq = &self.equations;
        let body = eq.bodies.iter().find(|s| s.index == b)?;
        let q = body.converged;
        let rotation = body.rotation_at(&q);
        let arm = crate::body::pose::rotate(&rotation, body.centre_of_mass);
        Some((crate::vec3::sub([q[0], q[1], q[2]], arm), rotation))
    }

    /// The system with its free bodies where the last converged increment
    /// put them (and their points with them): the system a dynamic run
    /// from this equilibrium starts from, with [`Self::line_states`].
    pub fn system_at_equilibrium(&self) -> System {
        let mut system = self.equations.system.clone();
        for body in &self.equations.bodies {
            let (position, rotation) = self.body_pose(body.index).expect("a free body");
            system.set_body_pose(body.index, position, rotation);
        }
        system
    }
}

/// The stiffness scale of a body without lines, for its rows' weights:
/// its net weight over its size (the farthest of its pin, its rods' ends
/// and its centre of mass from one another; 1 m for a point-like body).
fn own_stiffness(body: &super::Body, net: [f64; 3]) -> f64 {
    let mut size = 0.0f64;
    let c = body.inertia.centre_of_mass;
    if let Some(pin) = body.pin {
        size = size.max(crate::vec3::norm(crate::vec3::sub(pin.local, c)));
    }
    if let Some(w) = &body.water {
        for r in &w.rods {
            size = size.max(r.length());
        }
    }
    let size = if size > 0.0 { size } else { 1.0 };
    crate::vec3::norm(net) / size
}

/// The free bodies of `system` as a static solve holds them: their
/// weight and buoyancy at the centre of mass, their points' arms from it,
/// and the scales of §15.8.
pub(super) fn static_bodies(system: &System) -> Vec<StaticBody> {
    system
        .free_bodies_children_first()
        .into_iter()
        .map(|b| {
            let body = &system.bodies()[b];
            let c = body.inertia.centre_of_mass;
            let (volume, density) = body
                .water
                .as_ref()
                .map_or((0.0, 0.0), |w| (w.volume, w.density));
            let g = system.gravity();
            let net = g.map(|gc| (body.inertia.mass - density * volume) * gc);
            let mut length = f64::INFINITY;
            let mut arm = 0.0f64;
            let points: Vec<BodyPoint> = system
                .points()
                .iter()
                .enumerate()
                .filter(|(_, pt)| pt.body() == Some(b))
                .map(|(p, pt)| {
                    let super::PointKind::Body { local, .. } = pt.kind else {
                        unreachable!("a point on a body")
                    };
                    for (li, _) in system.attachments(p) {
                        length = length.min(system.lines()[li].model.cable.length);
                    }
                    let arm_p = crate::vec3::sub(local, c);
                    arm = arm.max(crate::vec3::norm(arm_p));
                    BodyPoint {
                        point: p,
                        arm: arm_p,
                    }
                })
                .collect();
            let length = if length.is_finite() { length } else { 1.0 };
            StaticBody {
                index: b,
                rotation: body.rotation,
                centre_of_mass: c,
                forces: std::iter::once((net, [0.0; 3]))
                    .chain(
                        body.loads
                            .iter()
                            .map(|&(f, at)| (f, crate::vec3::sub(at, c))),
                    )
                    .collect(),
                points,
                length,
                arm: if arm > 0.0 { arm } else { length },
                stiffness: 0.0,
                converged: [0.0; 6],
                pin_force: [0.0; 3],
                drag: body
                    .water
                    .as_ref()
                    .filter(|w| {
                        w.current != [0.0; 3]
                            && (w.drag_areas != [0.0; 3]
                                || w.rods.iter().any(|r| {
                                    r.drag_coefficient != 0.0 || r.end_drag_coefficient != 0.0
                                }))
                    })
                    .cloned(),
                rods_water: body.water.as_ref().filter(|w| !w.rods.is_empty()).cloned(),
                pin: body.pin.map(|pin| {
                    let hold = match system.joint_point(b) {
                        Some(p) => PinHold::Point(p),
                        // A host's motion holds it where it is at t = 0.
                        None => PinHold::Fixed(system.points()[pin.point].state_at(0.0).0),
                    };
                    (crate::vec3::sub(pin.local, c), hold)
                }),
                float_hold: super::body_holds::float_hold(system, b),
                moment: body.moment,
                own_stiffness: own_stiffness(body, net),
                // A connector's spin is held by its own row (§15.20).
                spin_hold: super::body_holds::spin_axis(
                    body,
                    &super::body_holds::points_local(system, b),
                )
                .filter(|_| !body.connector)
                .map(|a| {
                    let weight = crate::vec3::norm(net).max(f64::MIN_POSITIVE);
                    (a, weight * length)
                }),
                yaw_hold: super::body_holds::yaw_hold(system, b)
                    .filter(|_| !body.connector)
                    .map(|a| {
                        let weight = crate::vec3::norm(net).max(f64::MIN_POSITIVE);
                        (a, weight * length)
                    }),
            }
        })
        .collect()
}

#[cfg(test)]
pub(super) mod tests {
    use crate::body::RigidInertia;
    use crate::linear::Jacobian;
    use crate::statics::StaticEquations;
    use crate::system::{Body, BodyKind, End, Line, Point, System, SystemStatics};
    use crate::{Cable, ElementType, Load, Material, Model, ModelOptions, StaticSettings};

    /// The static rows' Jacobian with a free body (its own forces' moment,
    /// its points' rows carried to it, their constraints, the current's
    /// drag on it and on its rod) against central differences, away from
    /// the equilibrium and with the body turned.
    #[test]
    fn the_static_jacobian_with_a_free_body_is_the_derivative_of_its_rows() {
        let g = [0.0, 0.0, -9.81];
        let rotation = crate::body::pose::rotation_from_moordyn_angles([10.0, -20.0, 30.0]);
        let mut body = Body::new(
            BodyKind::Free,
            [0.0, 0.0, -10.0],
            rotation,
            RigidInertia::principal(400.0, [0.1, 0.0, -1.0], [50.0, 60.0, 70.0]),
        );
        body.loads.push(([30.0, -20.0, 500.0], [0.5, 0.5, 0.2]));
        // A current's drag with different areas on the body's axes.
        body.water = Some(crate::body::BodyWater {
            density: 1025.0,
            volume: 0.05,
            drag_areas: [1.0, 2.0, 0.5],
            current: [0.8, -0.3, 0.1],
            rods: Vec::new(),
            ..crate::body::BodyWater::default()
        });
        // And a rod's drag across it and on its caps (B19).
        body.rods.push(crate::body::rod::sample());
        let (lines, points) = two_lines_to(&body, |k, local| [0.5 * k as f64, 2.0 * local[1], 0.0]);
        let system = System::with_bodies(lines, points, vec![body], g).unwrap();
        let (worst, size) = static_jacobian_error(system);
        eprintln!("static Jacobian against differences: {worst:.1e} of {size:.1e}");
        assert!(worst < 1e-6 * size, "{worst:e} of {size:e}");
    }

    /// The same with both lines clamped at the body along their chords
    /// (docs/method.md §15.19) and a connector (§15.20) joining a third
    /// line to a fourth: the holds' rows, their multipliers in the lines'
    /// and the bodies' rows, the connector's held spin; every unknown
    /// moved off the seed (the multipliers not zero).
    #[test]
    fn the_static_jacobian_with_clamps_at_bodies_is_the_derivative_of_its_rows() {
        let g = [0.0, 0.0, -9.81];
        let rotation = crate::body::pose::rotation_from_moordyn_angles([10.0, -20.0, 30.0]);
        let body = Body::new(
            BodyKind::Free,
            [0.0, 0.0, -10.0],
            rotation,
            RigidInertia::principal(400.0, [0.1, 0.0, -1.0], [50.0, 60.0, 70.0]),
        );
        let (lines, mut points) =
            two_lines_to(&body, |k, local| [0.5 * k as f64, 2.0 * local[1], 0.0]);
        let mut lines: Vec<Line> = lines
            .into_iter()
            .map(|l| {
                let chord = l.model.cable.direction;
                l.clamped(1, chord).unwrap()
            })
            .collect();
        // A connector at (5, 0, -5) joining a line from a fixed point to a
        // line to another, both clamped along x + z.
        let joint = [5.0, 0.0, -5.0];
        let axis = [1.0, 0.0, 0.2];
        for (k, (a, b)) in [([0.0, 0.0, -6.0], joint), (joint, [10.0, 0.0, -3.5])]
            .into_iter()
            .enumerate()
        {
            let material = Material {
                youngs_modulus: 1e9,
                density: 2000.0,
                area: 1e-3,
                second_moment: 1e-7,
                axial_damping: 0.0,
            };
            let cable = Cable::straight(
                crate::vec3::norm(crate::vec3::sub(b, a)),
                4,
                ElementType::Sac2,
            )
            .with_origin(a)
            .with_direction(crate::vec3::sub(b, a));
            let loads = vec![Load::Gravity { acceleration: g }];
            let model = Model::new(cable, material, ModelOptions::default(), loads).unwrap();
            let ends = if k == 0 {
                [End::Point(4), End::Point(5)]
            } else {
                [End::Point(5), End::Point(6)]
            };
            lines.push(Line { model, ends }.clamped(1 - k, axis).unwrap());
        }
        points.push(Point::fixed([0.0, 0.0, -6.0]));
        points.push(Point::on_body(1, [0.0; 3]));
        points.push(Point::fixed([10.0, 0.0, -3.5]));
        let bodies = vec![body, Body::connector(joint, axis)];
        let system = System::with_bodies(lines, points, bodies, g).unwrap();
        let (worst, size) = static_jacobian_error(system);
        eprintln!("static Jacobian with clamps against differences: {worst:.1e} of {size:.1e}");
        assert!(worst < 1e-6 * size, "{worst:e} of {size:e}");
    }

    /// Two lines (10.5 m, 6 SAC-2, EA 1e6 N, 2 kg/m, under gravity) from
    /// fixed points at `anchor(k, local)` to body 0's points `local`,
    /// [0, -1, 0] and [0, 1, 0.3]: the lines and points 0-3 (anchor,
    /// body point, anchor, body point).
    pub(in crate::system) fn two_lines_to(
        body: &Body,
        anchor: impl Fn(usize, [f64; 3]) -> [f64; 3],
    ) -> (Vec<Line>, Vec<Point>) {
        let g = [0.0, 0.0, -9.81];
        let mut points = Vec::new();
        let mut lines = Vec::new();
        for (k, local) in [[0.0, -1.0, 0.0], [0.0, 1.0, 0.3]].into_iter().enumerate() {
            let anchor = anchor(k, local);
            let end = body.point(local);
            points.push(Point::fixed(anchor));
            points.push(Point::on_body(0, local));
            let material = Material {
                youngs_modulus: 1e9,
                density: 2000.0,
                area: 1e-3,
                second_moment: 1e-9,
                axial_damping: 0.0,
            };
            let cable = Cable::straight(10.5, 6, ElementType::Sac2)
                .with_origin(anchor)
                .with_direction(crate::vec3::sub(end, anchor));
            let loads = vec![Load::Gravity { acceleration: g }];
            let model = Model::new(cable, material, ModelOptions::default(), loads).unwrap();
            lines.push(Line {
                model,
                ends: [End::Point(2 * k), End::Point(2 * k + 1)],
            });
        }
        (lines, points)
    }

    /// The largest difference between the static rows' Jacobian of
    /// `system` and their central differences (steps 1e-6), and the
    /// largest entry, away from the seed: every free body turned and moved
    /// a little.
    pub(in crate::system) fn static_jacobian_error(system: System) -> (f64, f64) {
        let seeds = crate::system::catenary_states(&system);
        let mut statics = SystemStatics::new(system, seeds, StaticSettings::default()).unwrap();
        let eq = &mut statics.equations;
        eq.homotopy = 0.0;
        let mut x = statics.newton.x.clone();
        for b in 0..eq.layout.body_base.len() {
            for k in 0..6 {
                if let Some(i) = eq.layout.body_unknown(b, 0, k) {
                    x[i] += 0.05 * (k as f64 + 1.0) / (b as f64 + 1.0);
                }
            }
        }
        // The multipliers (and everything else) a little off the seed.
        let scale = x.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (i, v) in x.iter_mut().enumerate() {
            *v += 1e-4 * scale * (i as f64).sin();
        }
        let n = x.len();
        let mut jac = crate::bordered::BorderedMatrix::new(&eq.layout.shapes, eq.layout.border);
        let mut r = vec![0.0; n];
        eq.evaluate(&x, &mut r, Some(&mut jac));
        let h = 1e-6;
        let mut worst = 0.0f64;
        let mut size = 0.0f64;
        for c in 0..n {
            let (mut xp, mut xm) = (x.clone(), x.clone());
            xp[c] += h;
            xm[c] -= h;
            let (mut rp, mut rm) = (vec![0.0; n], vec![0.0; n]);
            eq.evaluate(&xp, &mut rp, None);
            eq.evaluate(&xm, &mut rm, None);
            for i in 0..n {
                let fd = (rp[i] - rm[i]) / (2.0 * h);
                let a = jac.get(i, c);
                size = size.max(a.abs());
                worst = worst.max((fd - a).abs());
            }
        }
        (worst, size)
    }
}
