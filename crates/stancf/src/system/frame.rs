//! The frame of a system's step (docs/method.md §11.3): its unknowns'
//! layout and indices, their scales, the bordered solver's workspace and
//! the Galerkin step's mass matrix, built with the simulation and again
//! when a release changes the unknowns (§11.16).

use super::body_terms::StepBody;
use super::layout::SystemLayout;
use super::mass::SystemMass;
use super::step_equations::system_scales;
use super::Topology;
use crate::bordered::BorderedLu;
use crate::error::ModelError;
use crate::integrator::{Simulation, StepSettings};
use crate::solver::NewtonWorkspace;

/// What a system's step is laid out on (its unknowns, their indices
/// and scales, the bordered solver's workspace and the Galerkin step's
/// mass matrix): built with the simulation and again when a line end is
/// released and the unknowns change (docs/method.md §11.16).
pub(super) struct Frame {
    pub layout: SystemLayout,
    pub point_index: Vec<Vec<usize>>,
    pub workspace: NewtonWorkspace<BorderedLu>,
    pub unknown_scale: Vec<f64>,
    pub equation_scale: Vec<f64>,
    pub mass: Option<SystemMass>,
}

impl Frame {
    pub fn new(
        topology: &Topology,
        lines: &[Simulation],
        bodies: &[StepBody],
        settings: &StepSettings,
    ) -> Result<Self, ModelError> {
        let models: Vec<_> = lines.iter().map(|l| l.model()).collect();
        let scheme = settings.time_scheme.layout(settings.time_layers);
        let layout = SystemLayout::new(topology, &models, scheme, settings.constraint_method);
        let point_index = (0..topology.points().len())
            .map(|p| match layout.point_base[p] {
                Some(_) => (0..3 * layout.slots)
                    .map(|k| layout.point_unknown(p, k / 3, k % 3).expect("free"))
                    .collect(),
                None => Vec::new(),
            })
            .collect();
        let lu = BorderedLu::new(&layout.shapes, layout.border);
        let workspace =
            NewtonWorkspace::with_factors(lu, layout.size, settings.newton.max_iterations);
        let (unknown_scale, equation_scale) =
            system_scales(topology, lines, &layout, bodies, settings.time_step);
        let joined = topology.has_free_points() || topology.has_free_bodies();
        let mass = if joined && settings.time_scheme.carries_momentum() {
            Some(SystemMass::new(topology, &models, bodies)?)
        } else {
            None
        };
        Ok(Frame {
            layout,
            point_index,
            workspace,
            unknown_scale,
            equation_scale,
            mass,
        })
    }

    /// Zeroed buffers of each line's unknowns (its local x and residual).
    pub fn line_buffers(&self) -> Vec<Vec<f64>> {
        self.layout
            .lines
            .iter()
            .map(|l| vec![0.0; l.size()])
            .collect()
    }
}
