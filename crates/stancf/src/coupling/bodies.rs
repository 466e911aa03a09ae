//! Coupled bodies in the coupling arrays (docs/method.md §13.6): a
//! floating platform moved by another code, as OpenFAST moves MoorDyn's
//! coupled bodies. In MoorDyn's order the arrays hold the coupled
//! bodies' 6 numbers each (3 for a body pinned to the host, MoorDyn's
//! CoupledPinned), then the coupled points' 3:
//!
//! - x: the reference point's position (m) and the roll, pitch and yaw
//!   (radians) of MoorDyn's convention, R = R_x(roll) R_y(pitch) R_z(yaw)
//!   (docs/method.md §15.1);
//! - xd: the reference point's velocity (m/s) and the angular velocity
//!   w (rad/s, global axes; MoorDyn passes the angles' rates and uses
//!   them as w, the same for the small rotations of a platform);
//! - the forces returned: the lines' force on the body and its moment
//!   about the reference point (global axes), summed over the body's
//!   points, f = sum f_P, m = sum (x_P - r) x f_P.
//!
//! A body pinned at its reference point to a coupled point not on a body
//! (MoorDyn's CoupledPinned: the host moves its reference point, it turns
//! freely about it) takes 3 numbers among the bodies': the pin's position
//! and velocity, and the force its pull on the host (docs/method.md
//! §15.17, (B35)).
//!
//! Inside, every point on a coupled body is a coupled point moving along
//! the body point's position r + R xi and velocity v + w x R xi at the
//! interval's ends, (K1)-(K2) per point, as a coupled point does.

use super::identity::Identity;
use super::{identity_order, CoupledSystem};
use crate::body::pose::{point, rotate, rotation_from_moordyn_angles};
use crate::error::ModelError;
use crate::system::{PointKind, System};
use crate::vec3::{add, cross, sub};

/// A coupled body of the arrays: its index among the system's bodies and
/// its points (their places in the coupled points' list and their body
/// coordinates).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct CoupledBody {
    pub body: usize,
    pub points: Vec<(usize, [f64; 3])>,
    /// A body pinned to the host (CoupledPinned): its pin's place in the
    /// coupled points' list; its 3 numbers move that point.
    pub pin: Option<usize>,
}

impl CoupledBody {
    /// Its numbers in the arrays: 6, or 3 for a body pinned to the host.
    fn width(&self) -> usize {
        if self.pin.is_some() {
            3
        } else {
            6
        }
    }
}

/// The arrays' layout: the coupled bodies, then the coupled points not on
/// a body (places in the coupled points' list, in the arrays' order).
#[derive(Clone, Debug, PartialEq)]
pub(super) struct ArrayLayout {
    pub bodies: Vec<CoupledBody>,
    pub plain: Vec<usize>,
}

impl CoupledSystem {
    /// Orders the coupled bodies of the arrays as `order` (a permutation
    /// of [`Self::coupled_bodies`]; e.g. by the bodies' ids, as MoorDyn
    /// orders its coupled bodies). Their 6 numbers stay first.
    pub fn with_body_order(mut self, order: Vec<usize>) -> Result<Self, ModelError> {
        if self.running.is_some() {
            return Err(ModelError::invalid(
                "body_order",
                "the coupled bodies are ordered before initialize, not after",
            ));
        }
        let mut own: Vec<usize> = self.layout.bodies.iter().map(|b| b.body).collect();
        let mut sorted = order.clone();
        own.sort_unstable();
        sorted.sort_unstable();
        if sorted != own {
            return Err(ModelError::invalid(
                "body_order",
                format!("must list the coupled bodies {own:?} once each, got {order:?}"),
            ));
        }
        let mut bodies = std::mem::take(&mut self.layout.bodies);
        self.layout.bodies = order
            .iter()
            .map(|&b| {
                let k = bodies
                    .iter()
                    .position(|c| c.body == b)
                    .expect("a coupled body");
                bodies.swap_remove(k)
            })
            .collect();
        self.identity = Identity::of(
            &self.digest,
            &identity_order(&self.layout, &self.array_points),
            self.step_halvings,
        );
        Ok(self)
    }
}

/// The pose of a body from its 6 numbers: the reference point and R.
pub(super) fn pose(x: &[f64]) -> ([f64; 3], [[f64; 3]; 3]) {
    let degrees = [x[3], x[4], x[5]].map(f64::to_degrees);
    ([x[0], x[1], x[2]], rotation_from_moordyn_angles(degrees))
}

impl ArrayLayout {
    /// Length of the arrays: 6 per coupled body (3 pinned), 3 per
    /// coupled point.
    pub fn dof(&self) -> usize {
        self.body_start(self.bodies.len()) + 3 * self.plain.len()
    }

    /// Start of body k's numbers and of plain point k's.
    pub(super) fn body_start(&self, k: usize) -> usize {
        self.bodies[..k].iter().map(CoupledBody::width).sum()
    }
    pub(super) fn point_start(&self, k: usize) -> usize {
        self.body_start(self.bodies.len()) + 3 * k
    }

    /// The coupled points' positions (3 each, in the list's order, `n`
    /// points) from the arrays' x.
    pub fn positions(&self, x: &[f64], n: usize) -> Vec<f64> {
        let mut out = vec![0.0; 3 * n];
        for (k, body) in self.bodies.iter().enumerate() {
            let s = self.body_start(k);
            if let Some(place) = body.pin {
                out[3 * place..3 * place + 3].copy_from_slice(&x[s..s + 3]);
                continue;
            }
            let (r, rotation) = pose(&x[s..s + 6]);
            for &(place, local) in &body.points {
                out[3 * place..3 * place + 3].copy_from_slice(&point(r, &rotation, local));
            }
        }
        for (k, &place) in self.plain.iter().enumerate() {
            let s = self.point_start(k);
            out[3 * place..3 * place + 3].copy_from_slice(&x[s..s + 3]);
        }
        out
    }

    /// The coupled points' velocities from the arrays' x and xd.
    pub fn velocities(&self, x: &[f64], xd: &[f64], n: usize) -> Vec<f64> {
        let mut out = vec![0.0; 3 * n];
        for (k, body) in self.bodies.iter().enumerate() {
            let s = self.body_start(k);
            if let Some(place) = body.pin {
                out[3 * place..3 * place + 3].copy_from_slice(&xd[s..s + 3]);
                continue;
            }
            let (_, rotation) = pose(&x[s..s + 6]);
            let (v, w) = (
                [xd[s], xd[s + 1], xd[s + 2]],
                [xd[s + 3], xd[s + 4], xd[s + 5]],
            );
            for &(place, local) in &body.points {
                let arm = rotate(&rotation, local);
                out[3 * place..3 * place + 3].copy_from_slice(&add(v, cross(w, arm)));
            }
        }
        for (k, &place) in self.plain.iter().enumerate() {
            let s = self.point_start(k);
            out[3 * place..3 * place + 3].copy_from_slice(&xd[s..s + 3]);
        }
        out
    }

    /// The arrays' forces: a coupled body's force and moment about its
    /// reference point `reference(k)` from its points' forces and
    /// positions, a coupled point's force.
    pub fn forces(
        &self,
        force: impl Fn(usize) -> [f64; 3],
        position: impl Fn(usize) -> [f64; 3],
        reference: impl Fn(usize) -> [f64; 3],
    ) -> Vec<f64> {
        let mut out = vec![0.0; self.dof()];
        for (k, body) in self.bodies.iter().enumerate() {
            let s = self.body_start(k);
            if let Some(place) = body.pin {
                out[s..s + 3].copy_from_slice(&force(place));
                continue;
            }
            let r = reference(k);
            for &(place, _) in &body.points {
                let f = force(place);
                let m = cross(sub(position(place), r), f);
                for c in 0..3 {
                    out[s + c] += f[c];
                    out[s + 3 + c] += m[c];
                }
            }
        }
        for (k, &place) in self.plain.iter().enumerate() {
            let s = self.point_start(k);
            out[s..s + 3].copy_from_slice(&force(place));
        }
        out
    }

    /// Where the numbers that move coupled point `place` are in the
    /// arrays: its body's 6, or its own 3.
    pub fn array_range(&self, place: usize) -> (usize, usize) {
        for (k, body) in self.bodies.iter().enumerate() {
            if body.pin == Some(place) {
                return (self.body_start(k), 3);
            }
            if body.points.iter().any(|&(p, _)| p == place) {
                return (self.body_start(k), 6);
            }
        }
        let k = self
            .plain
            .iter()
            .position(|&p| p == place)
            .expect("a coupled point");
        (self.point_start(k), 3)
    }

    /// Body k's pose and rates in the arrays' x and xd (None for a body
    /// pinned to the host: a free body, not held).
    pub fn held_end(
        &self,
        x: &[f64],
        xd: Option<&[f64]>,
        k: usize,
    ) -> Option<super::held_loads::HeldEnd> {
        if self.bodies[k].pin.is_some() {
            return None;
        }
        let s = self.body_start(k);
        let (position, rotation) = pose(&x[s..s + 6]);
        Some(super::held_loads::HeldEnd {
            position,
            rotation,
            rates: xd.map(|v| ([v[s], v[s + 1], v[s + 2]], [v[s + 3], v[s + 4], v[s + 5]])),
        })
    }

    /// Adds body k's own push (force, moment about its reference point)
    /// to the arrays' forces `out`.
    pub fn add_push(&self, out: &mut [f64], k: usize, push: &[f64; 6]) {
        let s = self.body_start(k);
        for (o, p) in out[s..s + 6].iter_mut().zip(push) {
            *o += p;
        }
    }

    /// Body k's reference point in the arrays' x.
    pub fn reference(&self, x: &[f64], k: usize) -> [f64; 3] {
        let s = self.body_start(k);
        [x[s], x[s + 1], x[s + 2]]
    }
}

/// The coupling arrays' layout of `system` whose coupled points are
/// `coupled` (system order): its coupled bodies in body order, their
/// points' places in `coupled`, then the other coupled points.
pub(super) fn array_layout(system: &System, coupled: &[usize]) -> ArrayLayout {
    let place = |p: usize| {
        coupled
            .iter()
            .position(|&q| q == p)
            .expect("a coupled point")
    };
    let coupled_body_points: Vec<usize> = (0..system.bodies().len())
        .filter(|&b| system.bodies()[b].kind == crate::system::BodyKind::Coupled)
        .flat_map(|b| {
            system
                .body_points(b)
                .iter()
                .map(|&(p, _)| p)
                .collect::<Vec<_>>()
        })
        .collect();
    let bodies: Vec<CoupledBody> = (0..system.bodies().len())
        .filter_map(|b| {
            if system.bodies()[b].kind == crate::system::BodyKind::Coupled {
                let points = system.body_points(b);
                let points = points.iter().map(|&(p, local)| (place(p), local));
                return Some(CoupledBody {
                    body: b,
                    points: points.collect(),
                    pin: None,
                });
            }
            host_pin(system, b, &coupled_body_points).map(|p| CoupledBody {
                body: b,
                points: Vec::new(),
                pin: Some(place(p)),
            })
        })
        .collect();
    let on_body: Vec<usize> = bodies
        .iter()
        .flat_map(|b| b.points.iter().map(|&(k, _)| k).chain(b.pin))
        .collect();
    let plain = (0..coupled.len())
        .filter(|k| !on_body.contains(k))
        .collect();
    ArrayLayout { bodies, plain }
}

/// The coupled point free body b is pinned to at its reference point, if
/// that point is on no coupled body (`on_bodies`; MoorDyn's CoupledPinned
/// body: the host moves its reference point; docs/method.md §15.17).
fn host_pin(system: &System, b: usize, on_bodies: &[usize]) -> Option<usize> {
    let body = &system.bodies()[b];
    let pin = body.pin.filter(|pin| pin.local == [0.0; 3])?;
    let point = &system.points()[pin.point];
    let coupled = matches!(point.kind, PointKind::Coupled(_)) && !on_bodies.contains(&pin.point);
    (body.kind == crate::system::BodyKind::Free && coupled).then_some(pin.point)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A body's points where its pose puts them and moving with it, and
    /// its points' forces summed into a force and a moment about the
    /// reference point (a couple of two opposite forces: no force, their
    /// moment).
    #[test]
    fn a_coupled_bodys_numbers_move_its_points_and_sum_their_forces() {
        let layout = ArrayLayout {
            bodies: vec![CoupledBody {
                body: 0,
                points: vec![(0, [1.0, 0.0, 0.0]), (2, [-1.0, 0.0, 0.0])],
                pin: None,
            }],
            plain: vec![1],
        };
        assert_eq!(layout.dof(), 9);
        let yaw = std::f64::consts::FRAC_PI_2;
        let x = [10.0, 0.0, -5.0, 0.0, 0.0, yaw, 7.0, 8.0, 9.0];
        let p = layout.positions(&x, 3);
        let expect = [10.0, 1.0, -5.0, 7.0, 8.0, 9.0, 10.0, -1.0, -5.0];
        for (a, b) in p.iter().zip(expect) {
            assert!((a - b).abs() < 1e-14, "{p:?}");
        }
        let xd = [0.5, 0.0, 0.0, 0.0, 0.0, 2.0, 1.0, 1.0, 1.0];
        let v = layout.velocities(&x, &xd, 3);
        // w x arm: 2 z x (0, 1, 0) = (-2, 0, 0); at the other point (2, 0, 0).
        let expect = [-1.5, 0.0, 0.0, 1.0, 1.0, 1.0, 2.5, 0.0, 0.0];
        for (a, b) in v.iter().zip(expect) {
            assert!((a - b).abs() < 1e-14, "{v:?}");
        }
        let pos = |k: usize| [p[3 * k], p[3 * k + 1], p[3 * k + 2]];
        let f = |k: usize| match k {
            0 => [3.0, 0.0, 0.0],
            2 => [-3.0, 0.0, 0.0],
            _ => [0.0, 0.0, 4.0],
        };
        let out = layout.forces(f, pos, |_| [10.0, 0.0, -5.0]);
        // (0, 1, 0) x (3, 0, 0) + (0, -1, 0) x (-3, 0, 0) = (0, 0, -6).
        let expect = [0.0, 0.0, 0.0, 0.0, 0.0, -6.0, 0.0, 0.0, 4.0];
        for (a, b) in out.iter().zip(expect) {
            assert!((a - b).abs() < 1e-13, "{out:?}");
        }
    }
}
