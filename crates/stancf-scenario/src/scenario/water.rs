//! The water a system's lines are in (docs/interface.md, "Water"):
//! `[water]` of a scenario, a MoorDyn deck's water options
//! ([`super::moordyn_water`]), or both, merged into one [`Water`] that
//! builds the library's sea (docs/method.md §12).
//!
//! z is up, the still water surface z = 0, the seabed the plane through
//! (0, 0, -depth) (flat, or sloped by `seabed.slope`), or a bed of varying
//! height from a MoorDyn seafloor file (`seabed.file`, a deck's
//! `SeafloorFile`).

use super::context::Ctx;
pub use super::moordyn_seafloor::SeabedFile;
use super::raw::{RawCurrent, RawJonswap, RawSeabed, RawWater, RawWave};
use super::ScenarioError;
use stancf::system::StaticFriction;
use stancf::water::current::{CurrentProfile, CurrentRow, Ramp};
use stancf::water::current_grid::CurrentGrid;
use stancf::water::spectrum::Jonswap;
use stancf::water::waves::AiryWave;
use stancf::water::{Seabed, SeabedContact};
use stancf::ModelError;
use std::path::Path;
use std::sync::Arc;

/// The water around a system: z up, the still surface at z = 0.
#[derive(Clone, Debug, PartialEq)]
pub struct Water {
    /// The seabed plane passes through (0, 0, -depth) (m).
    pub depth: f64,
    /// Density rho_w (kg/m^3).
    pub density: f64,
    pub seabed: SeabedOptions,
    /// A steady current profile (None: none).
    pub current: Option<Current>,
    /// Regular Airy waves as given.
    pub waves: Vec<AiryWave>,
    /// An irregular sea whose components add to the waves.
    pub jonswap: Option<Jonswap>,
    /// The duration (s) of the ramp that starts the waves (0: none).
    pub wave_ramp: f64,
    /// The waves are a host's, set at the nodes through the coupling API
    /// (`water.host_waves`, a deck's `WaveKin 1`; docs/method.md §12.1,
    /// (W2f)-(W2g)).
    pub host_waves: bool,
}

/// The seabed's contact and friction (docs/method.md §12.2).
#[derive(Clone, Debug, PartialEq)]
pub struct SeabedOptions {
    /// MoorDyn's kBot (Pa/m).
    pub stiffness: f64,
    /// MoorDyn's cBot (Pa s/m).
    pub damping: f64,
    /// Coulomb's coefficients along a line's axis and across it.
    pub friction_axial: f64,
    pub friction_transverse: f64,
    /// The velocity (m/s) below which friction is regularized (W43).
    pub slip_velocity: f64,
    /// dz/dx and dz/dy of the bed plane.
    pub slope: [f64; 2],
    /// A bed of varying height in place of the plane (W40a).
    pub bathymetry: Option<SeabedFile>,
    /// What friction holds at a static equilibrium (docs/method.md §12.2):
    /// nothing as laid (MoorDyn's), or the pull from an unstretched lay.
    pub static_friction: StaticFriction,
}

impl SeabedOptions {
    /// MoorDyn's defaults: kBot = 3e6 Pa/m, cBot = 3e5 Pa s/m, no
    /// friction; friction regularized below 1 mm/s; a flat bed.
    pub const MOORDYN: SeabedOptions = SeabedOptions {
        stiffness: 3.0e6,
        damping: 3.0e5,
        friction_axial: 0.0,
        friction_transverse: 0.0,
        slip_velocity: 1.0e-3,
        slope: [0.0, 0.0],
        bathymetry: None,
        static_friction: StaticFriction::AsLaid,
    };
}

/// A current, started by a ramp: a steady profile or a grid in space and
/// time.
#[derive(Clone, Debug, PartialEq)]
pub struct Current {
    pub field: CurrentField,
    /// The ramp's duration (s), 0 for none.
    pub ramp: f64,
    /// Where the rows come from, for `stancf check` (a key or a file).
    pub source: String,
}

/// What a current is made of.
#[derive(Clone, Debug, PartialEq)]
pub enum CurrentField {
    /// A steady profile: rows (z, velocity), linear between rows and
    /// constant beyond the ends (W9).
    Profile(Vec<CurrentRow>),
    /// A grid in x, y, z and t, multilinear, holding its edges (W9a): a
    /// MoorDyn deck's dynamic profile (`Currents 2`) or 4-D grid
    /// (`Currents 5`).
    Grid(Box<CurrentGrid>),
}

impl Current {
    /// The rows of a steady profile (None for a grid).
    pub fn profile(&self) -> Option<&[CurrentRow]> {
        match &self.field {
            CurrentField::Profile(rows) => Some(rows),
            CurrentField::Grid(_) => None,
        }
    }

    /// The largest speed (m/s) of its rows or nodes.
    pub fn fastest(&self) -> f64 {
        let speed = |v: &[f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        match &self.field {
            CurrentField::Profile(rows) => {
                rows.iter().map(|r| speed(&r.velocity)).fold(0.0, f64::max)
            }
            CurrentField::Grid(g) => g.velocities().iter().map(speed).fold(0.0, f64::max),
        }
    }
}

/// The water's keys as one source gives them: a value for each key the
/// source sets, None for a key it leaves out. A deck and a scenario's
/// `[water]` each give one; [`merge`] puts them together.
#[derive(Clone, Debug, Default)]
pub(super) struct WaterKeys {
    pub(super) depth: Option<f64>,
    pub(super) density: Option<f64>,
    pub(super) stiffness: Option<f64>,
    pub(super) damping: Option<f64>,
    pub(super) friction_axial: Option<f64>,
    pub(super) friction_transverse: Option<f64>,
    pub(super) slip_velocity: Option<f64>,
    pub(super) slope: Option<[f64; 2]>,
    pub(super) bathymetry: Option<SeabedFile>,
    pub(super) static_friction: Option<StaticFriction>,
    pub(super) current: Option<Current>,
    pub(super) waves: Vec<AiryWave>,
    pub(super) jonswap: Option<Jonswap>,
    pub(super) wave_ramp: Option<f64>,
    pub(super) host_waves: Option<bool>,
}

impl WaterKeys {
    /// The keys of `[water]` a key of the scenario names, each with
    /// whether it is set: the pairs a deck's option may collide with.
    pub(super) fn given(&self) -> [(&'static str, bool); 9] {
        [
            ("water.depth", self.depth.is_some()),
            ("water.density", self.density.is_some()),
            ("water.seabed.stiffness", self.stiffness.is_some()),
            ("water.seabed.damping", self.damping.is_some()),
            ("water.seabed.friction_axial", self.friction_axial.is_some()),
            (
                "water.seabed.friction_transverse",
                self.friction_transverse.is_some(),
            ),
            ("water.current", self.current.is_some()),
            ("water.seabed.file", self.bathymetry.is_some()),
            ("water.host_waves", self.host_waves.is_some()),
        ]
    }

    /// The water these keys describe, with the defaults of the keys left
    /// out (density 1025 kg/m^3, [`SeabedOptions::MOORDYN`], no current,
    /// no waves); None without a depth.
    pub(super) fn water(self) -> Option<Water> {
        let d = SeabedOptions::MOORDYN;
        Some(Water {
            depth: self.depth?,
            density: self.density.unwrap_or(1025.0),
            seabed: SeabedOptions {
                stiffness: self.stiffness.unwrap_or(d.stiffness),
                damping: self.damping.unwrap_or(d.damping),
                friction_axial: self.friction_axial.unwrap_or(d.friction_axial),
                friction_transverse: self.friction_transverse.unwrap_or(d.friction_transverse),
                slip_velocity: self.slip_velocity.unwrap_or(d.slip_velocity),
                slope: self.slope.unwrap_or(d.slope),
                bathymetry: self.bathymetry,
                static_friction: self.static_friction.unwrap_or(d.static_friction),
            },
            current: self.current,
            waves: self.waves,
            jonswap: self.jonswap,
            wave_ramp: self.wave_ramp.unwrap_or(0.0),
            host_waves: self.host_waves.unwrap_or(false),
        })
    }

    /// These keys with those of `other` added (a key set by both is for
    /// the caller to refuse first).
    pub(super) fn or(self, other: WaterKeys) -> WaterKeys {
        let mut waves = self.waves;
        waves.extend(other.waves);
        WaterKeys {
            depth: self.depth.or(other.depth),
            density: self.density.or(other.density),
            stiffness: self.stiffness.or(other.stiffness),
            damping: self.damping.or(other.damping),
            friction_axial: self.friction_axial.or(other.friction_axial),
            friction_transverse: self.friction_transverse.or(other.friction_transverse),
            slip_velocity: self.slip_velocity.or(other.slip_velocity),
            slope: self.slope.or(other.slope),
            bathymetry: self.bathymetry.or(other.bathymetry),
            static_friction: self.static_friction.or(other.static_friction),
            current: self.current.or(other.current),
            waves,
            jonswap: self.jonswap.or(other.jonswap),
            wave_ramp: self.wave_ramp.or(other.wave_ramp),
            host_waves: self.host_waves.or(other.host_waves),
        }
    }
}

impl Water {
    /// The seabed's height z (m) under (x, y).
    pub fn bed_height(&self, x: f64, y: f64) -> f64 {
        let b = &self.seabed;
        match &b.bathymetry {
            Some(file) => file.grid.height(x, y).height,
            None => -self.depth + b.slope[0] * x + b.slope[1] * y,
        }
    }

    /// The library's water: the sea of this depth under gravity of
    /// magnitude `gravity` (m/s^2), the regular waves and the JONSWAP
    /// components superposed and started by the wave ramp, the current
    /// by its ramp. Errors name the `[water]` key.
    pub fn library(&self, gravity: f64) -> Result<stancf::water::Water, ModelError> {
        let mut waves = self.waves.clone();
        if let Some(j) = &self.jonswap {
            waves.extend(j.waves().map_err(|e| e.under("water.jonswap"))?);
        }
        let mut sea = stancf::water::kinematics::Sea::new(self.depth, gravity, &waves)
            .map_err(|e| e.under("water"))?
            .with_wave_ramp(Ramp::new(self.wave_ramp).map_err(|e| e.under("water.wave_ramp"))?);
        if let Some(c) = &self.current {
            let ramp = Ramp::new(c.ramp).map_err(|e| e.under("water.current"))?;
            sea = match &c.field {
                CurrentField::Profile(rows) => {
                    let profile =
                        CurrentProfile::new(rows).map_err(|e| e.under("water.current"))?;
                    sea.with_current(profile, ramp)
                }
                CurrentField::Grid(grid) => sea.with_current_grid((**grid).clone(), ramp),
            };
        }
        if self.host_waves {
            sea = sea.with_host_waves().map_err(|e| e.under("water"))?;
        }
        Ok(stancf::water::Water {
            density: self.density,
            sea,
        })
    }

    /// The seabed as a line of diameter `diameter` touches it: the plane
    /// z = -depth + sx x + sy y (upward normal (-sx, -sy, 1)) or the
    /// bathymetry, with the contact's stiffness and damping and the
    /// friction.
    pub fn seabed_contact(&self, diameter: f64) -> SeabedContact {
        let b = &self.seabed;
        let [sx, sy] = b.slope;
        let bed = match &b.bathymetry {
            Some(file) => Seabed::on_grid(file.grid.clone(), b.stiffness, b.damping),
            None => Seabed::plane(
                [0.0, 0.0, -self.depth],
                [-sx, -sy, 1.0],
                b.stiffness,
                b.damping,
            ),
        }
        .with_friction(b.friction_axial, b.friction_transverse, b.slip_velocity);
        SeabedContact {
            seabed: bed,
            diameter,
        }
    }
}

/// `[water]` of a scenario, each key checked (the message names it).
/// Files it names (`seabed.file`) are relative to `dir`, the scenario's
/// folder.
pub(super) fn water_keys(ctx: &Ctx, raw: RawWater, dir: &Path) -> Result<WaterKeys, ScenarioError> {
    let positive = |k: &str, v: Option<f64>| v.map(|v| ctx.positive(k, v)).transpose();
    let non_negative = |k: &str, v: Option<f64>| v.map(|v| ctx.non_negative(k, v)).transpose();
    let mut keys = WaterKeys {
        depth: positive("water.depth", raw.depth)?,
        // 0: water without weight, drag or inertia (MoorDyn's WtrDnsty 0
        // leaves the water out; the seabed stays).
        density: non_negative("water.density", raw.density)?,
        wave_ramp: non_negative("water.wave_ramp", raw.wave_ramp)?,
        host_waves: raw.host_waves,
        ..WaterKeys::default()
    };
    if let Some(s) = raw.seabed {
        seabed_keys(ctx, s, &mut keys, dir)?;
    }
    keys.current = raw.current.map(|c| current(ctx, c)).transpose()?;
    keys.waves = raw
        .waves
        .iter()
        .enumerate()
        .map(|(i, w)| wave(ctx, i, w))
        .collect::<Result<_, _>>()?;
    keys.jonswap = raw.jonswap.map(|j| jonswap(ctx, j)).transpose()?;
    Ok(keys)
}

/// `[water.seabed]`: stiffness and slip velocity > 0; damping and
/// friction >= 0; slope two finite numbers.
fn seabed_keys(
    ctx: &Ctx,
    s: RawSeabed,
    keys: &mut WaterKeys,
    dir: &Path,
) -> Result<(), ScenarioError> {
    let positive = |k: &str, v: Option<f64>| v.map(|v| ctx.positive(k, v)).transpose();
    let non_negative = |k: &str, v: Option<f64>| v.map(|v| ctx.non_negative(k, v)).transpose();
    keys.stiffness = positive("water.seabed.stiffness", s.stiffness)?;
    keys.damping = non_negative("water.seabed.damping", s.damping)?;
    keys.friction_axial = non_negative("water.seabed.friction_axial", s.friction_axial)?;
    keys.friction_transverse =
        non_negative("water.seabed.friction_transverse", s.friction_transverse)?;
    keys.slip_velocity = positive("water.seabed.slip_velocity", s.slip_velocity)?;
    keys.static_friction = s
        .static_friction
        .map(|name| {
            StaticFriction::from_name(&name).ok_or_else(|| {
                ctx.err(
                    "water.seabed.static_friction",
                    format!(
                        "\"{name}\" is not a policy: \"as_laid\" (friction holds nothing at \
                         the equilibrium, MoorDyn's) or \"pulled\" (each anchored line pulled \
                         out along the bed from an unstretched lay, the closed form's)"
                    ),
                )
            })
        })
        .transpose()?;
    keys.slope = match s.slope {
        None => None,
        Some(v) if v.len() != 2 => {
            return Err(ctx.err(
                "water.seabed.slope",
                format!("the slope is [dz/dx, dz/dy], 2 numbers, got {}", v.len()),
            ))
        }
        Some(v) => Some([
            ctx.finite("water.seabed.slope", v[0])?,
            ctx.finite("water.seabed.slope", v[1])?,
        ]),
    };
    if let Some(name) = s.file {
        if keys.slope.is_some() {
            return Err(ctx.err(
                "water.seabed.slope",
                "the bed of water.seabed.file has its own shape: give a slope or a file, not both",
            ));
        }
        let path = dir.join(&name);
        let read = |e: String| ctx.err("water.seabed.file", format!("{}: {e}", path.display()));
        let text = crate::input_file::read_text(&path).map_err(read)?;
        let grid = super::moordyn_seafloor::read_seafloor(&text).map_err(read)?;
        keys.bathymetry = Some(SeabedFile {
            grid: Arc::new(grid),
            source: format!("{} (water.seabed.file)", path.display()),
        });
    }
    Ok(())
}

/// `[water.current]`: `profile` (rows [z, ux, uy, uz], z strictly
/// monotone) or `velocity` (uniform), one of them; `ramp` >= 0.
fn current(ctx: &Ctx, c: RawCurrent) -> Result<Current, ScenarioError> {
    let ramp = match c.ramp {
        Some(r) => ctx.non_negative("water.current.ramp", r)?,
        None => 0.0,
    };
    let (rows, source) = match (c.profile, c.velocity) {
        (Some(_), Some(_)) => {
            return Err(ctx.err(
                "water.current.velocity",
                "give a profile or a uniform velocity, not both",
            ))
        }
        (None, None) => {
            return Err(ctx.err(
                "water.current",
                "needs a profile ([[z, ux, uy, uz], ...]) or a velocity ([ux, uy, uz])",
            ))
        }
        (None, Some(v)) => {
            let velocity = ctx.vector("water.current.velocity", &v)?;
            (
                vec![CurrentRow { z: 0.0, velocity }],
                "water.current.velocity".to_string(),
            )
        }
        (Some(p), None) => (profile(ctx, &p)?, "water.current.profile".to_string()),
    };
    Ok(Current {
        field: CurrentField::Profile(rows),
        ramp,
        source,
    })
}

/// The rows of `water.current.profile`: each [z, ux, uy, uz], finite, z
/// strictly increasing or strictly decreasing.
fn profile(ctx: &Ctx, p: &[Vec<f64>]) -> Result<Vec<CurrentRow>, ScenarioError> {
    let key = "water.current.profile";
    if p.is_empty() {
        return Err(ctx.err(key, "a profile needs at least one row [z, ux, uy, uz]"));
    }
    let mut rows = Vec::with_capacity(p.len());
    for (i, r) in p.iter().enumerate() {
        if r.len() != 4 {
            return Err(ctx.err(
                &format!("{key}[{i}]"),
                format!("a row is [z, ux, uy, uz], 4 numbers, got {}", r.len()),
            ));
        }
        for v in r {
            ctx.finite(&format!("{key}[{i}]"), *v)?;
        }
        rows.push(CurrentRow {
            z: r[0],
            velocity: [r[1], r[2], r[3]],
        });
    }
    CurrentProfile::new(&rows).map_err(|e| {
        let at = e.key.trim_start_matches("rows").trim_end_matches(".z");
        ctx.err(&format!("{key}{at}"), e.message)
    })?;
    Ok(rows)
}

/// One `[[water.waves]]` entry: amplitude >= 0 and period > 0 required;
/// heading and phase in degrees, finite, default 0.
fn wave(ctx: &Ctx, i: usize, w: &RawWave) -> Result<AiryWave, ScenarioError> {
    let key = |k: &str| format!("water.waves[{i}].{k}");
    Ok(AiryWave {
        amplitude: ctx.non_negative(
            &key("amplitude"),
            ctx.required(&key("amplitude"), w.amplitude)?,
        )?,
        period: ctx.required_positive(&key("period"), w.period)?,
        heading_deg: ctx.finite(&key("heading"), w.heading.unwrap_or(0.0))?,
        phase_deg: ctx.finite(&key("phase"), w.phase.unwrap_or(0.0))?,
    })
}

/// The most components a JONSWAP sea may have (each is evaluated at every
/// Gauss point of every step).
const MAX_COMPONENTS: i64 = 10_000;

/// `[water.jonswap]`: hs >= 0 and tp > 0 required; gamma in [1, 7]
/// (default 3.3), heading (degrees, default 0), seed (integer >= 0,
/// default 0), components (1..=10000, default 100).
fn jonswap(ctx: &Ctx, j: RawJonswap) -> Result<Jonswap, ScenarioError> {
    let gamma = ctx.finite("water.jonswap.gamma", j.gamma.unwrap_or(3.3))?;
    if !(1.0..=7.0).contains(&gamma) {
        return Err(ctx.err(
            "water.jonswap.gamma",
            format!("must be within [1, 7] (1 is Pierson-Moskowitz), got {gamma}"),
        ));
    }
    let seed = j.seed.unwrap_or(0);
    if seed < 0 {
        return Err(ctx.err(
            "water.jonswap.seed",
            format!("must be an integer >= 0, got {seed}"),
        ));
    }
    Ok(Jonswap {
        hs: ctx.non_negative("water.jonswap.hs", ctx.required("water.jonswap.hs", j.hs)?)?,
        tp: ctx.required_positive("water.jonswap.tp", j.tp)?,
        gamma,
        heading_deg: ctx.finite("water.jonswap.heading", j.heading.unwrap_or(0.0))?,
        seed: seed as u64,
        components: ctx.count(
            "water.jonswap.components",
            j.components.unwrap_or(100),
            1,
            MAX_COMPONENTS,
        )?,
    })
}

/// The water of a system without a deck: `[water]` (its depth required)
/// under `gravity`, which must point along -z (the key named:
/// `system.gravity`); files it names relative to `dir`.
pub(super) fn scenario_water(
    ctx: &Ctx,
    raw: Option<RawWater>,
    gravity: [f64; 3],
    dir: &Path,
) -> Result<Option<Water>, ScenarioError> {
    let Some(raw) = raw else { return Ok(None) };
    check_gravity(ctx, gravity)?;
    let keys = water_keys(ctx, raw, dir)?;
    match keys.water() {
        Some(w) => Ok(Some(w)),
        None => Err(ctx.err(
            "water.depth",
            "required key is missing (the seabed is at z = -depth)",
        )),
    }
}

/// Water needs gravity along -z (its surface is the plane z = 0).
pub(super) fn check_gravity(ctx: &Ctx, gravity: [f64; 3]) -> Result<(), ScenarioError> {
    // No gravity at all (MoorDyn's g = 0) leaves the water's surface where
    // it is; waves then are refused by the sea (they need g).
    if gravity[0] == 0.0 && gravity[1] == 0.0 && gravity[2] <= 0.0 {
        return Ok(());
    }
    Err(ctx.err(
        "system.gravity",
        format!(
            "[water] needs gravity along -z (z is up, the still surface z = 0), got \
             [{}, {}, {}]",
            gravity[0], gravity[1], gravity[2]
        ),
    ))
}
