//! Undoing a system's last step (docs/method.md §11.15): each line keeps
//! what returns it to the start of its last step (the single cable's
//! undo, §8); the system keeps the rest, taken before the step: its
//! points', bodies' and clamps' states, its end forces and carried
//! momenta, the work on its points, its failures and its clock. The
//! energy watchdog's halving of a Galerkin step (`run.rs`) takes it.

use super::body_clamps::ClampStepEnd;
use super::body_terms::StepBody;
use super::end_forces::{EndForce, ForcesAtTime};
use super::failures::Failures;
use super::simulation::SystemSimulation;
use super::step_equations::PointMotion;

/// The state of a system but its lines' before a step.
#[derive(Clone)]
pub(super) struct SystemUndo {
    points: Vec<PointMotion>,
    bodies: Vec<StepBody>,
    body_momentum: Vec<[f64; 6]>,
    point_momentum: Vec<[f64; 3]>,
    clamp_ends: Vec<ClampStepEnd>,
    clamp_moments: Vec<[f64; 3]>,
    end_forces: Vec<[EndForce; 2]>,
    forces_at_time: ForcesAtTime,
    point_water_work: f64,
    point_bed_work: f64,
    failures: Failures,
    steps: usize,
    t: f64,
}

impl SystemSimulation {
    /// What [`Self::undo`] returns to: the system now, before a step.
    pub(super) fn undo_point(&self) -> SystemUndo {
        SystemUndo {
            points: self.points.clone(),
            bodies: self.bodies.clone(),
            body_momentum: self.body_momentum.clone(),
            point_momentum: self.point_momentum.clone(),
            clamp_ends: self.clamp_ends.clone(),
            clamp_moments: self.clamp_moments.clone(),
            end_forces: self.end_forces.clone(),
            forces_at_time: self.forces_at_time.clone(),
            point_water_work: self.point_water_work,
            point_bed_work: self.point_bed_work,
            failures: self.failures.clone(),
            steps: self.steps,
            t: self.t,
        }
    }

    /// Returns to `undo`, taken just before the last step. Refused (false,
    /// nothing changed) where that step was taken in parts (its Newton
    /// halvings, §11.13: the lines keep one step's undo) or released line
    /// ends (§11.16: the unknowns changed).
    pub(super) fn undo(&mut self, undo: SystemUndo) -> bool {
        if self.steps != undo.steps + 1
            || self.failures.releases.len() != undo.failures.releases.len()
        {
            return false;
        }
        for line in &mut self.lines {
            line.undo_last_step();
        }
        self.points = undo.points;
        self.bodies = undo.bodies;
        self.body_momentum = undo.body_momentum;
        self.point_momentum = undo.point_momentum;
        self.clamp_ends = undo.clamp_ends;
        self.clamp_moments = undo.clamp_moments;
        self.end_forces = undo.end_forces;
        self.forces_at_time = undo.forces_at_time;
        self.point_water_work = undo.point_water_work;
        self.point_bed_work = undo.point_bed_work;
        self.failures = undo.failures;
        self.steps = undo.steps;
        self.t = undo.t;
        self.drop_last_step_record();
        // The clamps' frames turned back with their bodies.
        for clamp in self.topology.body_clamps() {
            let body = self.bodies.iter().find(|b| b.index == clamp.body);
            let rotation = body.expect("a clamp's body is free").body.rotation();
            self.lines[clamp.line].set_direction_hold(clamp.hold, clamp.local.turned(&rotation));
        }
        self.workspace.factors_valid = false;
        true
    }
}

#[cfg(test)]
mod tests {
    use crate::system::{End, Line, Point, System, SystemSimulation};
    use crate::{
        Cable, ElementType, Load, Material, Model, ModelOptions, StepSettings, TimeScheme,
    };

    /// Two ropes (EA 100 N, 10 g/m) from fixed anchors to a free point of
    /// 0.2 kg, straight, in gravity: they fall and swing.
    fn two_ropes() -> SystemSimulation {
        let rope = Material {
            youngs_modulus: 1e7,
            density: 1000.0,
            area: 1e-5,
            second_moment: 1e-12,
            axial_damping: 0.0,
        };
        let hub = [0.0, 0.0, -1.0];
        let anchors = [[2.0, 0.0, 0.0], [-1.0, 1.7, 0.0]];
        let lines: Vec<Line> = anchors
            .iter()
            .enumerate()
            .map(|(i, a)| {
                let d: [f64; 3] = std::array::from_fn(|c| hub[c] - a[c]);
                let length = d.iter().map(|x| x * x).sum::<f64>().sqrt();
                let cable = Cable::straight(length, 4, ElementType::Sac2)
                    .with_origin(*a)
                    .with_direction(d);
                let gravity = Load::Gravity {
                    acceleration: [0.0, 0.0, -9.81],
                };
                let model = Model::new(cable, rope, ModelOptions::default(), vec![gravity]);
                Line {
                    model: model.expect("model"),
                    ends: [End::Point(i), End::Point(2)],
                }
            })
            .collect();
        let points = vec![
            Point::fixed(anchors[0]),
            Point::fixed(anchors[1]),
            Point::free(hub, 0.2),
        ];
        let system = System::new(lines, points, [0.0, 0.0, -9.81]).expect("system");
        let states = system
            .lines()
            .iter()
            .map(|l| l.model.initial_state())
            .collect();
        let settings = StepSettings {
            time_step: 2e-3,
            time_scheme: TimeScheme::Galerkin,
            ..StepSettings::default()
        };
        SystemSimulation::new(system, states, settings).expect("simulation")
    }

    fn snapshot(sim: &SystemSimulation) -> Vec<f64> {
        let mut out = vec![sim.time()];
        for line in sim.lines() {
            out.extend(&line.state().e);
            out.extend(&line.state().v);
        }
        for p in 0..sim.topology().points().len() {
            let (x, v) = sim.point_state(p);
            out.extend(x.iter().chain(&v));
            out.extend(sim.point_force(p));
        }
        out.push(sim.energies().mechanical() - sim.external_work());
        out
    }

    /// An undone step leaves the system as it was before it, to the bit,
    /// and the step taken again reaches the same state (to Newton's
    /// tolerance: the kept factors are dropped, so its iterates differ).
    #[test]
    fn an_undone_step_returns_the_system_to_where_it_was() {
        let mut sim = two_ropes();
        for _ in 0..5 {
            sim.step().expect("step");
        }
        let before = snapshot(&sim);
        let undo = sim.undo_point();
        sim.step().expect("step");
        let after = snapshot(&sim);
        assert!(sim.undo(undo));
        assert_eq!(snapshot(&sim), before);
        sim.step().expect("step again");
        let again = snapshot(&sim);
        let worst = after
            .iter()
            .zip(&again)
            .map(|(a, b)| (a - b).abs() / a.abs().max(1.0))
            .fold(0.0, f64::max);
        assert!(worst < 1e-9, "{worst:e}");
        // A step taken in parts cannot be undone by one step's undo.
        let undo = sim.undo_point();
        sim.step().expect("step");
        sim.step().expect("step");
        assert!(!sim.undo(undo));
    }
}
