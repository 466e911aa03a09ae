//! Building a [`Simulation`], and the checks it shares with
//! [`step_unknowns`], which counts a step's unknowns without building one.

use super::{Simulation, StepSettings, Undo};
use crate::assembly::{AssemblyScratch, Scales, SlabLayout, StepStart};
use crate::band::BandLu;
use crate::constraints::ConstraintMethod;
use crate::element::TimeSlab;
use crate::error::ModelError;
use crate::loads::{EndMoment, MomentAngle};
use crate::model::{Model, State, SLOT_R_X};
use crate::quadrature::GaussRule;
use crate::solver::NewtonWorkspace;

impl Simulation {
    /// Prepares a simulation from `initial` (which must have the model's
    /// size; its constrained coordinates are set to their prescribed values
    /// and rates at `initial.t`).
    pub fn new(model: Model, initial: State, settings: StepSettings) -> Result<Self, ModelError> {
        Self::build(model, initial, settings, true)
    }

    /// A line of a system (see [`crate::system`]): everything of a
    /// simulation; its own linear solver where the line is solved apart
    /// (`own_solver`: a system without free points, docs/method.md
    /// §11.14), none where the system's step solves all lines together.
    pub(crate) fn line_of_system(
        model: Model,
        initial: State,
        settings: StepSettings,
        own_solver: bool,
    ) -> Result<Self, ModelError> {
        Self::build(model, initial, settings, own_solver)
    }

    /// This line of a system rebuilt on `model` (the same line with
    /// other constraints: an end released from its point, or the planar
    /// reduction lifted when the system's lines join, docs/method.md
    /// §11.16) at its current state, carrying what a run accumulates: the
    /// steps, the work counters, the predictor's rates and the Galerkin
    /// momentum, except at node `released`, whose momentum restarts as
    /// M v (the reaction's impulse it held is gone with the point).
    pub(crate) fn rebuilt(
        &self,
        model: Model,
        settings: StepSettings,
        own_solver: bool,
        released: Option<usize>,
    ) -> Result<Self, ModelError> {
        let mut next = Self::build(model, self.state.clone(), settings, own_solver)?;
        next.steps = self.steps;
        next.constraint_work = self.constraint_work;
        next.drag_work = self.drag_work;
        next.damping_work = self.damping_work;
        next.seabed_work = self.seabed_work;
        next.water_work = self.water_work;
        next.acceleration.clone_from(&self.acceleration);
        next.last_slopes.clone_from(&self.last_slopes);
        next.last_dt = self.last_dt;
        next.clock.clone_from(&self.clock);
        if next.moment_angles.len() == self.moment_angles.len() {
            next.moment_angles.clone_from(&self.moment_angles);
        }
        let dpn = self.model.dofs_per_node();
        for (g, p) in next.momentum.iter_mut().enumerate() {
            if released != Some(g / dpn) {
                *p = self.momentum[g];
            }
        }
        next.previous.momentum.clone_from(&next.momentum);
        Ok(next)
    }

    /// Restarts the carried Galerkin momentum at `node` as M v of the
    /// current state (a junction split by a release, docs/method.md
    /// §11.16: the line's share of a junction's momentum is its own end
    /// momentum, which differs from M v by its share of the junction's
    /// internal impulse; once apart, each part carries M v).
    pub(crate) fn restart_momentum_at(&mut self, node: usize) {
        let mut mv = vec![0.0; self.model.dofs()];
        self.model.momentum(&self.state.e, &self.state.v, &mut mv);
        let dpn = self.model.dofs_per_node();
        let node_coordinates = node * dpn..(node + 1) * dpn;
        self.momentum[node_coordinates.clone()].copy_from_slice(&mv[node_coordinates.clone()]);
        self.previous.momentum[node_coordinates.clone()].copy_from_slice(&mv[node_coordinates]);
    }

    fn build(
        model: Model,
        initial: State,
        settings: StepSettings,
        own_solver: bool,
    ) -> Result<Self, ModelError> {
        let mut model = model;
        let dt = settings.time_step;
        let time_rule = check_settings(&settings)?;
        check_initial_state(&model, &initial)?;
        model
            .constraints
            .check_direction_route(settings.constraint_method)?;
        let n = model.dofs();
        let mut initial = initial;
        model.apply_constraints(&mut initial);
        // A line without its internal state starts at rest.
        model.check_internal_state(&initial.internal)?;
        if model.has_internal_state() && settings.time_layers != 1 {
            return Err(ModelError::invalid(
                "analysis.time_layers",
                format!(
                    "a viscoelastic or VIV line is stepped with one time layer per step (got \
                     {}): its internal state is collocated over one slab (docs/method.md §2.11, \
                     §12.7)",
                    settings.time_layers
                ),
            ));
        }
        if initial.internal.is_empty() {
            initial.internal = model.rest_internal_state(&initial.e);
        }
        check_end_moments(&model, &initial.e)?;
        if settings.planar_reduction {
            model.reduce_to_plane(&initial);
        }
        let layers = settings.time_layers;
        let scheme = settings.time_scheme.layout(layers);
        let layout = SlabLayout::new(&model, scheme, settings.constraint_method);
        let h = dt / layers as f64;
        let slab = TimeSlab::new(h, &time_rule);
        let scales = Scales::new(&model, &layout, h);
        let (kl, ku) = layout.bandwidths();
        let workspace = if own_solver {
            NewtonWorkspace::new(layout.size(), kl, ku, settings.newton.max_iterations)
        } else {
            // No factors: only `spare`, the buffer of the end values' rows.
            NewtonWorkspace::new(layout.size(), 0, 0, 1)
        };
        let scratch = AssemblyScratch::new(&model, &layout);
        let mut start = StepStart::new(&model, layout.time_nodes());
        start.set(&model, initial.t, &initial.e, &initial.v, h);
        start.set_internal(&initial.internal);
        let moment_angles = moment_angles(&model, &initial.e);
        let reactions: Vec<(usize, [f64; 3])> = model
            .constraints
            .position_nodes
            .iter()
            .map(|&nd| (nd, [0.0; 3]))
            .collect();
        let mut momentum = vec![0.0; n];
        model.momentum(&initial.e, &initial.v, &mut momentum);
        let mass_lu = if settings.time_scheme.carries_momentum() {
            Some(constrained_mass_lu(&model, &initial.e)?)
        } else {
            None
        };
        let previous = Undo {
            momentum: vec![0.0; n],
            state: initial.clone(),
            acceleration: vec![0.0; n],
            constraint_work: 0.0,
            drag_work: 0.0,
            damping_work: 0.0,
            seabed_work: 0.0,
            water_work: 0.0,
            moment_angles: moment_angles.clone(),
            reactions: reactions.clone(),
        };
        Ok(Simulation {
            x: vec![0.0; layout.size()],
            x_predicted: vec![0.0; layout.size()],
            acceleration: vec![0.0; n],
            last_slopes: vec![0.0; 2 * n],
            last_dt: None,
            guide: None,
            model,
            settings,
            time_rule,
            layout,
            slab,
            scales,
            state: initial,
            start,
            workspace,
            scratch,
            steps: 0,
            reactions,
            constraint_work: 0.0,
            drag_work: 0.0,
            damping_work: 0.0,
            seabed_work: 0.0,
            water_work: 0.0,
            moment_angles,
            previous,
            clock: None,
            momentum,
            mass_lu,
            rhs: vec![0.0; n],
            mass_v: vec![0.0; n],
        })
    }
}

/// The unwrapped angles of the end moments (docs/method.md §2.7, (M8)),
/// started at coordinates `e` from the reference shape.
fn moment_angles(model: &Model, e: &[f64]) -> Vec<MomentAngle> {
    let reference = model.reference_coordinates();
    let mut moment_angles = Vec::new();
    for (node, m) in model.end_moments() {
        let Some(moment) = EndMoment::from_vector(&m) else {
            continue;
        };
        let o = model.coordinate(node, SLOT_R_X, 0);
        let r0 = [reference[o], reference[o + 1], reference[o + 2]];
        let rx = [e[o], e[o + 1], e[o + 2]];
        moment_angles.push(MomentAngle::new(moment, node, r0, &rx));
    }
    moment_angles
}

/// The Galerkin step's factors of the mass matrix at coordinates `e`
/// (with the entrained water's, (W31)), with the rows of constrained
/// coordinates replaced by identity rows, so that v_b = M^-1 p_b takes the
/// prescribed constrained rates (docs/method.md §5.1, (M22)).
fn constrained_mass_lu(model: &Model, e: &[f64]) -> Result<BandLu, ModelError> {
    let bw = 2 * model.dofs_per_node() - 1;
    let mut lu = BandLu::new(model.dofs(), bw, bw);
    super::entrained::factorize_constrained_mass(&mut lu, model, e)
        .map_err(|_| ModelError::invalid("material", "the mass matrix is singular"))?;
    Ok(lu)
}

/// The checks of [`Simulation::new`] on the settings alone; the time
/// quadrature they ask for.
fn check_settings(settings: &StepSettings) -> Result<GaussRule, ModelError> {
    let dt = settings.time_step;
    if !dt.is_finite() || dt <= 0.0 {
        return Err(ModelError::invalid(
            "analysis.time_step",
            format!("must be > 0, got {dt}"),
        ));
    }
    if settings.time_layers == 0 {
        return Err(ModelError::invalid(
            "analysis.time_layers",
            "must be at least 1, got 0",
        ));
    }
    let time_rule = GaussRule::new(settings.time_points)
        .map_err(|e| ModelError::invalid("analysis.quadrature", e.message))?;
    let tol = settings.newton.tolerance;
    if !tol.is_finite() || tol <= 0.0 {
        return Err(ModelError::invalid(
            "analysis.tolerance",
            format!("must be > 0, got {tol}"),
        ));
    }
    if settings.newton.max_iterations == 0 {
        return Err(ModelError::invalid(
            "analysis.max_iterations",
            "must be at least 1",
        ));
    }
    let layers = settings.time_layers;
    if !settings.time_scheme.layers_allowed() && layers != 1 {
        return Err(ModelError::invalid(
            "analysis.time_layers",
            format!(
                "the Galerkin step takes one layer per step (got {layers}): joining \
                 layers by C1 interior nodes inside a Galerkin step is unstable \
                 (docs/method.md §5.4)"
            ),
        ));
    }
    Ok(time_rule)
}

/// The initial state has the model's size and is finite.
fn check_initial_state(model: &Model, initial: &State) -> Result<(), ModelError> {
    let n = model.dofs();
    if initial.e.len() != n || initial.v.len() != n {
        return Err(ModelError::invalid(
            "initial_state",
            format!(
                "expected {n} coordinates, got {} and {}",
                initial.e.len(),
                initial.v.len()
            ),
        ));
    }
    if initial
        .e
        .iter()
        .chain(initial.v.iter())
        .any(|v| !v.is_finite())
        || !initial.t.is_finite()
    {
        return Err(ModelError::invalid("initial_state", "must be finite"));
    }
    Ok(())
}

/// An end moment must bend the cable at coordinates `e`: a moment about
/// the end's own tangent is a torsion, which a cable cannot carry.
fn check_end_moments(model: &Model, e: &[f64]) -> Result<(), ModelError> {
    for (i, (node, m)) in model.end_moments().enumerate() {
        let Some(moment) = EndMoment::from_vector(&m) else {
            continue;
        };
        let o = model.coordinate(node, SLOT_R_X, 0);
        if !moment.acts_on(&[e[o], e[o + 1], e[o + 2]]) {
            return Err(ModelError::invalid(
                format!("loads[{i}].moment"),
                "the moment is about the cable's own tangent (a torsion, which a cable cannot carry)",
            ));
        }
    }
    Ok(())
}

/// The unknowns of the system every step of a [`Simulation`] of `model`
/// from `initial` with `settings` solves, and whether the planar reduction
/// applies ([`Simulation::unknowns_per_step`], [`Simulation::is_planar`]),
/// after the same checks as [`Simulation::new`] but without building it:
/// no copy of the model, no matrices, O(nodes) time and the memory of one
/// state (`stancf check` on a large mesh). The count is the numbering of
/// [`SlabLayout::new`]: every coordinate has one unknown per slot (2 per
/// time layer with P2, 3 with the Galerkin step) unless it is eliminated
/// (held by the planar reduction, or constrained with elimination), and a
/// constrained coordinate with multipliers has one multiplier per slot too.
pub fn step_unknowns(
    model: &Model,
    initial: &State,
    settings: &StepSettings,
) -> Result<(usize, bool), ModelError> {
    check_settings(settings)?;
    check_initial_state(model, initial)?;
    let mut state = initial.clone();
    model.apply_constraints(&mut state);
    check_end_moments(model, &state.e)?;
    // Model::reduce_to_plane holds the z coordinates, g = 2 mod 3.
    let reduces = settings.planar_reduction && model.planar_coordinates(&state).is_some();
    let planar = reduces || model.constraints.has_inactive();
    let slots = settings.time_scheme.slots(settings.time_layers);
    let elimination = settings.constraint_method == ConstraintMethod::Elimination;
    let held = |g: usize| model.constraints.is_inactive(g) || (reduces && g % 3 == 2);
    let mut size = 0;
    for g in 0..model.dofs() {
        let inactive = held(g);
        let constrained = model.constraints.is_constrained(g) && !inactive;
        if !(inactive || (elimination && constrained)) {
            size += slots;
        }
        if constrained && !elimination {
            size += slots;
        }
    }
    Ok((size, planar))
}
