//! The energy watchdog of a run (docs/method.md §8, (M29)): the model's
//! energy unit, the round-off of energy balances, and [`EnergyWatch`].

use crate::model::Model;
use crate::observe::Energies;

/// The model's own energy unit (J), never zero (`E_model` of docs/method.md
/// §8, (M29)): the energies of deformations and motions of order one of
/// this cable,
///
/// ```text
///   E_model = E A L + E I / L + m |g| L + sum |F| L + sum |M|
/// ```
///
/// (twice the strain energy of a unit axial strain over the length L and
/// of a bend to curvature 1 / L; the work of the weight m g and of the
/// point forces over a displacement L; that of the end moments over one
/// radian). E A > 0, so it is positive whatever the loads.
pub fn model_energy_scale(model: &Model) -> f64 {
    let m = &model.material;
    let l = model.cable.length;
    let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let weight = m.density * m.area * l * norm(model.gravity);
    let forces: f64 = model.point_forces().map(|(_, f)| norm(f)).sum();
    let moments: f64 = model.end_moments().map(|(_, mo)| norm(mo)).sum();
    m.youngs_modulus * m.area * l
        + m.youngs_modulus * m.second_moment / l
        + (weight + forces) * l
        + moments
}

/// Relative size of the round-off in an energy evaluation and in the
/// energy balance of a step (a sum of many terms, each rounded to eps of
/// its size): changes of the energy below this times the magnitudes
/// involved are not resolved.
const ROUND_OFF: f64 = ENERGY_ROUND_OFF;

/// [`ROUND_OFF`] for other energy units (a system's free points).
pub const ENERGY_ROUND_OFF: f64 = 1e3 * f64::EPSILON;

/// Energy changes of this model below this are round-off (J):
/// `1e3 eps E_model` ([`model_energy_scale`]). A cable at rest, or nearly,
/// has energies of O(eps^2 E_model): positions and slopes rounded to eps
/// give strains of O(eps), so 1/2 E A L eps^2; this is eps^-1 ~ 4.5e15 times
/// more, yet still nothing physical (for the paper's 4 m PVC cable 9e-9 J,
/// the energy of a strain of 7e-7).
pub fn energy_resolution(model: &Model) -> f64 {
    ROUND_OFF * model_energy_scale(model)
}

/// Watches the mechanical energy of a run for growth without a source
/// (docs/method.md §8, (M29)).
///
/// The cable under gravity, constant point forces and end moments
/// conserves E = T + U + V_g + V_F; P2 keeps it within a bounded
/// oscillation when the step is stable. Moving constraints and drag add
/// their work W. A rise of E - W by more than `ratio` times the energy
/// scale of the motion so far (the largest T + U seen, plus the largest
/// change of the potentials and the largest |W|) can only come from an
/// unstable step, provided it is also above the round-off of the energy
/// balance: `1e3 eps` times the magnitudes summed (the energies, |W|) and
/// the model's own energy unit ([`energy_resolution`]). Without that unit a
/// cable at rest, whose energy scale is itself round-off (1e-28 J), trips
/// on its own round-off. An unstable mode grows geometrically (P2 beyond
/// its limit: by up to 3 + 2 sqrt(2) per step in amplitude, docs/method.md
/// §4.5), so from round-off, O(eps^2 E_model), it passes the floor
/// within ln(1e3 / eps) / ln(rho^2) steps: about 20 at rho = 3.
#[derive(Clone, Debug)]
pub struct EnergyWatch {
    pub ratio: f64,
    pub(super) initial: Energies,
    scale: f64,
    resolution: f64,
}

impl EnergyWatch {
    pub fn new(model: &Model, initial: Energies, ratio: f64) -> Self {
        Self::with_resolution(energy_resolution(model), initial, ratio)
    }

    /// The watch with the energy unit's round-off `resolution` (J) given:
    /// a system's, its lines' summed ([`energy_resolution`]).
    pub fn with_resolution(resolution: f64, initial: Energies, ratio: f64) -> Self {
        EnergyWatch {
            ratio,
            initial,
            scale: initial.kinetic.abs() + initial.strain.abs(),
            resolution,
        }
    }

    /// The energies the watch started from.
    pub fn initial(&self) -> &Energies {
        &self.initial
    }

    /// The energy scale of the motion so far.
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Records a state's energies and the work of the constraints and the
    /// drag so far; Err(drift) if the energy grew without a source.
    pub fn check(&mut self, en: &Energies, external_work: f64) -> Result<(), f64> {
        let potential_change = (en.gravity - self.initial.gravity).abs()
            + (en.load_potential - self.initial.load_potential).abs();
        self.scale = self
            .scale
            .max(en.kinetic.abs() + en.strain.abs() + potential_change + external_work.abs());
        let drift = en.mechanical() - self.initial.mechanical() - external_work;
        let floor = ROUND_OFF * (en.magnitude() + self.initial.magnitude() + external_work.abs())
            + self.resolution;
        if drift > self.ratio * self.scale && drift > floor {
            Err(drift)
        } else {
            Ok(())
        }
    }
}

/// Default `ratio` of [`EnergyWatch`].
pub const ENERGY_GROWTH_RATIO: f64 = 0.1;
