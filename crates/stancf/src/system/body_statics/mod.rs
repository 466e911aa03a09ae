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

mod build;
#[cfg(test)]
pub(super) mod tests;

use super::layout::SystemLayout;
use super::{System, SystemStatics};
use crate::body::attach::{offsets, project};
use crate::body::jet::{Jet, JetVec};
use crate::body::BodyWater;
use crate::bordered::BorderedMatrix;
use crate::linear::{AddEntries, Jacobian};
pub(super) use build::static_bodies;

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
    /// The body's water where a steady current drags it (B10), (B19), or
    /// where it carries a body-fixed external force (B43).
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
    /// The centre of mass a body nothing holds or loads is held at
    /// ([`super::body_holds::rest_hold`]).
    pub rest_hold: Option<[f64; 3]>,
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

    /// The body without anything of its own, its rows its lines' alone
    /// (the points' pull and the clamps' reactions), theta measured from
    /// `rotation`: no weight, buoyancy, water, loads, moment, pin or
    /// holds (the mooring stiffness's body, §15.9).
    pub fn bare(&self, rotation: [[f64; 3]; 3]) -> StaticBody {
        StaticBody {
            rotation,
            forces: Vec::new(),
            drag: None,
            rods_water: None,
            spin_hold: None,
            yaw_hold: None,
            pin: None,
            float_hold: None,
            rest_hold: None,
            moment: [0.0; 3],
            ..self.clone()
        }
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
        if let Some(at) = self.rest_hold {
            // k (r_G - r_G0) and k theta, k = 1: zero at the given pose.
            for k in 0..6 {
                residual[g(k)] += if k < 3 { q[k] - at[k] } else { q[k] };
                if let Some(m) = jacobian.as_deref_mut() {
                    m.add(g(k), g(k), 1.0);
                }
            }
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
