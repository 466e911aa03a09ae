//! The water's terms of a free body in a system's static solve
//! (docs/method.md §15.8, §15.11): the steady current's drag at rest
//! (B10), (B19) and its rods' buoyancy as a potential of the pose (B20),
//! the step's terms ([`crate::body::terms::Context`]) at zero rates, on
//! jets in the pose [r_G; theta].

use super::body_statics::StaticBody;
use super::layout::SystemLayout;
use crate::body::jet::{Jet, JetVec};
use crate::body::terms::{Context, NV};
use crate::body::BodyWater;
use crate::bordered::BorderedMatrix;
use crate::linear::AddEntries;

/// Where the static unknowns [r_G; theta] sit among the terms' variables
/// ([`crate::body::terms::NV`]: r_G at 9..12, theta at 3..6).
const POSE: [usize; 6] = [9, 10, 11, 3, 4, 5];

/// The terms' variables at pose q = [r_G; theta], at rest: jets in the
/// pose.
fn at_rest(q: &[f64; 6]) -> [JetVec<NV>; 4] {
    let mut v = [[Jet::constant(0.0); 3]; 4];
    for (k, &j) in POSE.iter().enumerate() {
        v[j / 3][j % 3] = Jet::variable(q[k], j);
    }
    v
}

impl StaticBody {
    /// The terms of a body in `water` at pose q = [r_G; theta], at rest.
    pub(super) fn context<'a>(&'a self, water: &'a BodyWater) -> Context<'a> {
        Context {
            mass: 0.0,
            inertia_at_centre: &[[0.0; 3]; 3],
            centre_of_mass: self.centre_of_mass,
            rotation_a: &self.rotation,
            loads: &[],
            water: Some(water),
            // Statics sees the steady current alone (§15.8).
            time: crate::body::flow::FlowTime::Steady,
        }
    }

    /// The current's drag at rest (B10), (B19) in the rows, -Q, and its
    /// derivatives in the pose: the step's drag ([`Context::drag`]) at
    /// v_G = 0, theta_dot = 0, on jets.
    pub(super) fn add_drag(
        &self,
        layout: &SystemLayout,
        q: &[f64; 6],
        water: &BodyWater,
        residual: &mut [f64],
        jacobian: Option<&mut BorderedMatrix>,
    ) {
        let g = |k: usize| layout.body_unknown(self.index, 0, k).expect("a free body");
        let (on_centre, on_theta) = self
            .context(water)
            .drag(&at_rest(q))
            .expect("a body in water");
        for c in 0..3 {
            residual[g(c)] -= on_centre[c].v;
            residual[g(3 + c)] -= on_theta[c].v;
        }
        if let Some(m) = jacobian {
            for c in 0..3 {
                for (k, j) in POSE.iter().enumerate() {
                    m.add(g(c), g(k), -on_centre[c].g[*j]);
                    m.add(g(3 + c), g(k), -on_theta[c].g[*j]);
                }
            }
        }
    }

    /// The rods' buoyancy (B20) in the rows, dU_b/dq, and its Hessian.
    pub(super) fn add_buoyancy(
        &self,
        layout: &SystemLayout,
        q: &[f64; 6],
        water: &BodyWater,
        residual: &mut [f64],
        jacobian: Option<&mut BorderedMatrix>,
    ) {
        let g = |k: usize| layout.body_unknown(self.index, 0, k).expect("a free body");
        let u = self.context(water).buoyancy_potential(&at_rest(q));
        for (k, &j) in POSE.iter().enumerate() {
            residual[g(k)] += u.g[j];
        }
        if let Some(m) = jacobian {
            for (k, &j) in POSE.iter().enumerate() {
                for (l, &i) in POSE.iter().enumerate() {
                    m.add(g(k), g(l), u.h[j][i]);
                }
            }
        }
    }

    /// The rods' buoyancy's potential -rho g I (B20) at pose q.
    pub(super) fn buoyancy_potential(&self, q: &[f64; 6]) -> f64 {
        self.rods_water
            .as_ref()
            .map_or(0.0, |w| self.context(w).buoyancy_potential(&at_rest(q)).v)
    }
}
