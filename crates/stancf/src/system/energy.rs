//! The energy balance of a system (docs/method.md §8, (M29), and §11.15):
//! its energies (the lines' and the free points'), the work of everything
//! that is not a potential, and the run's watchdog on them.

use super::{SystemSimulation, SystemStatics, Topology};
use crate::integrator::{energy_resolution, EnergyWatch, ENERGY_GROWTH_RATIO};
use crate::observe::{energies, Energies};
use crate::vec3::{dot, norm};

/// Adds the energies of the free points of `topology` at the positions
/// and velocities `state(p)` to `en`: the kinetic energy 1/2 (m + m_a)
/// |v|^2 of the point and the water it entrains (W35), the potential
/// -(m g + B) . x of its weight and buoyancy (a constant load, (W33)) in
/// `gravity`, and -F . x of its given force in `load_potential`.
pub(super) fn add_point_energies(
    topology: &Topology,
    state: impl Fn(usize) -> ([f64; 3], [f64; 3]),
    en: &mut Energies,
) {
    let g = topology.gravity();
    for (p, point) in topology.points().iter().enumerate() {
        if !point.is_free() {
            continue;
        }
        let (x, v) = state(p);
        en.kinetic += 0.5 * topology.point_inertia(p) * dot(v, v);
        let buoyancy = point.water.as_ref().map_or([0.0; 3], |w| w.buoyancy(&g));
        en.gravity -= (0..3)
            .map(|k| (point.mass * g[k] + buoyancy[k]) * x[k])
            .sum::<f64>();
        en.load_potential -= dot(point.force, x);
    }
}

impl SystemStatics {
    /// The energies of the equilibrium at the last converged increment:
    /// every line's strain and gravity energy ([`energies`]), with the
    /// model the scenario gave it, the free points' potentials
    /// ([`add_point_energies`], at rest) and the free bodies' (the
    /// potential of their constant forces, as [`crate::body::FreeBody::energies`]).
    pub fn energies(&self) -> Energies {
        let mut en = Energies::default();
        for (i, l) in self.system().lines().iter().enumerate() {
            let e = energies(&l.model, self.line_state(i));
            en.kinetic += e.kinetic;
            en.strain += e.strain;
            en.gravity += e.gravity;
            en.load_potential += e.load_potential;
        }
        let at_rest = |p| (self.point_position(p), [0.0; 3]);
        add_point_energies(self.system(), at_rest, &mut en);
        en.gravity += self.body_potential();
        en
    }
}

impl SystemSimulation {
    /// The system's energies: every line's ([`crate::Simulation::energies`]),
    /// the free points' ([`add_point_energies`]) and the free bodies'
    /// (kinetic (B9), and the potential of their weight and buoyancy).
    pub fn energies(&self) -> Energies {
        let mut en = Energies::default();
        for l in &self.lines {
            let e = l.energies();
            en.kinetic += e.kinetic;
            en.strain += e.strain;
            en.gravity += e.gravity;
            en.load_potential += e.load_potential;
        }
        add_point_energies(&self.topology, |p| self.point_state(p), &mut en);
        for body in &self.bodies {
            let (kinetic, potential) = body.body.energies();
            en.kinetic += kinetic;
            en.gravity += potential;
        }
        en
    }

    /// Work done on the system by everything that is not a potential:
    /// on the lines, their moving attachments (fixed and coupled points),
    /// drag, axial damping, the seabed and the water
    /// ([`crate::Simulation::external_work`]); on the free points, the
    /// water's drag and inertia (W34), their damping (B42) and the bed's
    /// push (W42p); on the free bodies, their drag
    /// (B10). `energies().mechanical() - external_work()` stays at its
    /// start value up to the scheme's error (in a current with added mass
    /// the body's kinetic energy (B9) is not the conserved quantity,
    /// docs/method.md §15.6).
    pub fn external_work(&self) -> f64 {
        self.lines.iter().map(|l| l.external_work()).sum::<f64>()
            + self.point_water_work
            + self.point_bed_work
            + self.body_water_work()
            + self.pin_work()
    }

    /// The work of the pins a host's motion moves on their bodies so far
    /// (§15.17: each step's mean pin force times the pinned point's
    /// displacement).
    fn pin_work(&self) -> f64 {
        self.bodies
            .iter()
            .filter_map(|b| b.pin)
            .map(|p| p.work)
            .sum()
    }

    /// The work of the free bodies' drag so far (B10), and of their
    /// constant moments (B27).
    pub(super) fn body_water_work(&self) -> f64 {
        self.bodies
            .iter()
            .map(|b| b.body.water_work() + b.body.moment_work())
            .sum()
    }

    /// The energy watchdog of a run from the current state (docs/method.md
    /// §8, (M29)): the lines' energy units summed, and the free points'
    /// loads over the longest line as theirs.
    pub(crate) fn energy_watch(&self) -> EnergyWatch {
        let longest = self
            .lines
            .iter()
            .map(|l| l.model().cable.length)
            .fold(0.0, f64::max);
        let g = self.topology.gravity();
        let points: f64 = self
            .topology
            .points()
            .iter()
            .filter(|p| p.is_free())
            .map(|p| (p.mass * norm(g) + norm(p.force)) * longest)
            .sum();
        let resolution = self
            .lines
            .iter()
            .map(|l| energy_resolution(l.model()))
            .sum::<f64>()
            + energy_resolution_of(points);
        EnergyWatch::with_resolution(resolution, self.energies(), ENERGY_GROWTH_RATIO)
    }
}

/// The round-off of an energy of magnitude `energy` (J), as
/// [`energy_resolution`] takes a model's.
fn energy_resolution_of(energy: f64) -> f64 {
    crate::integrator::ENERGY_ROUND_OFF * energy
}
