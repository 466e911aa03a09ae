//! What a system scenario holds (docs/interface.md, "Systems"): its line
//! types, bodies, points, lines and output channels, validated from
//! `[[line_types]]`, `[[bodies]]`, `[[points]]` and `[[lines]]`
//! (`system.rs`, `bodies.rs`) or from a MoorDyn deck (`moordyn.rs`).

use super::analysis::InitialShape;
use super::bodies::SystemBody;
use super::water::Water;
use super::Analysis;
use stancf::motion::CoupledMotion;
use stancf::{ElementType, Grading, Measures};

/// A line type: the section of a line (MoorDyn's LINE TYPES row).
#[derive(Clone, Debug, PartialEq)]
pub struct LineType {
    pub name: String,
    /// Diameter (m): the area pi d^2 / 4 the mass and stiffness are
    /// spread over, and the diameter water sees.
    pub diameter: f64,
    /// Mass per length (kg/m).
    pub mass_per_length: f64,
    /// Axial stiffness EA (N); with a curve, the curve's secant at its
    /// last point (what a damping ratio and a seed take).
    pub ea: f64,
    /// A nonlinear axial law from a tension-strain table (docs/method.md
    /// §2.2a, (M4b)): `ea_curve`, a deck's EA curve file.
    pub ea_curve: Option<std::sync::Arc<stancf::element::AxialCurve>>,
    /// A viscoelastic line's dynamic stiffness (docs/method.md §2.11):
    /// `ea_dynamic` (constant), or `ea_dynamic_alpha` and
    /// `ea_dynamic_beta` (alpha + beta T1); a deck's `EA|EA_D` or
    /// `EA|alphaMBL|vbeta`. `ea` is then the static stiffness and `ba`
    /// the dashpot beside the static spring.
    pub ea_dynamic: Option<stancf::element::DynamicStiffness>,
    /// The dashpot beside the dynamic spring (N s): `ba_dynamic`, a
    /// deck's `BA|BA_D`.
    pub ba_dynamic: f64,
    /// Bending stiffness EI (N m^2); 0 for chain and wire rope.
    pub ei: f64,
    /// Axial damping BA (N s), or minus a damping ratio (MoorDyn's
    /// convention; each line gets BA = zeta l sqrt(EA w) from its element
    /// length l, docs/method.md §2.10, (M36); see
    /// [`SystemScenario::axial_damping`]).
    pub ba: f64,
    /// Normal and axial drag and added mass coefficients (used in water;
    /// keys `cd`, `ca`, `cdax`, `caax`, a deck's Cd, Ca, CdAx, CaAx; the
    /// library's [`stancf::water::hydro::Morison`] under the same names).
    pub cd_normal: f64,
    pub ca_normal: f64,
    pub cd_axial: f64,
    pub ca_axial: f64,
    /// Whether the line carries compression (`compression`, default
    /// true); chains and ropes do not (docs/method.md §2.2, (M4a)), nor
    /// do a MoorDyn deck's lines.
    pub compression: bool,
    /// MoorDyn's VIV lift (docs/method.md §12.7): `viv = { cl, df, cf,
    /// averaging_time }`, a deck's `Cl dF cF` (its averaging time 500
    /// dtM). None: no VIV.
    pub viv: Option<stancf::element::Viv>,
    /// The minimum breaking load (N): `mbl`, or `system.mbl` for a deck's
    /// type. None: not given (no safety factor is reported).
    pub mbl: Option<f64>,
}

impl LineType {
    /// The area pi d^2 / 4 the section is spread over (and that displaces
    /// water).
    pub fn area(&self) -> f64 {
        std::f64::consts::PI * self.diameter * self.diameter / 4.0
    }
}

/// What holds a point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PointType {
    Fixed,
    Free,
    Coupled,
    /// Fixed on body `body` (its index in [`SystemScenario::bodies`]) at
    /// `local` (body axes, from its reference point).
    Body {
        body: usize,
        local: [f64; 3],
    },
}

/// A point of the system.
#[derive(Clone, Debug, PartialEq)]
pub struct SystemPoint {
    pub id: i64,
    pub kind: PointType,
    /// The position at t = 0 (m), global (on a body, where the body's
    /// pose puts the point).
    pub position: [f64; 3],
    pub mass: f64,
    pub force: [f64; 3],
    /// Displaced volume (m^3): buoyancy and added mass in water.
    pub volume: f64,
    /// Drag area CdA (m^2) in water.
    pub drag_area: f64,
    /// Added-mass coefficient Ca on the volume.
    pub ca: f64,
    /// The motion of a coupled point (none: it stays put).
    pub motion: CoupledMotion,
    /// The file a tabulated motion was read from, as the scenario names it.
    pub motion_file: Option<String>,
    /// Damping along the global axes of a free point (MoorDyn-F's
    /// EXTERNAL LOADS; `damping_linear`, `damping_quadratic`).
    pub damping: stancf::damping::AxisDamping,
}

impl SystemPoint {
    /// The id a point made after `points` takes: one more than their
    /// largest (1 if there are none).
    pub fn next_id(points: &[SystemPoint]) -> i64 {
        points
            .iter()
            .map(|p| p.id)
            .max()
            .unwrap_or(0)
            .saturating_add(1)
    }

    /// A point of `kind` made at `position` (a rod's end, a pin's), with
    /// nothing of its own: no mass, force, water or motion.
    pub fn made(id: i64, kind: PointType, position: [f64; 3]) -> Self {
        SystemPoint {
            id,
            kind,
            position,
            mass: 0.0,
            force: [0.0; 3],
            volume: 0.0,
            drag_area: 0.0,
            ca: 0.0,
            motion: CoupledMotion::NONE,
            motion_file: None,
            damping: Default::default(),
        }
    }
}

/// An output channel of a MoorDyn deck, written to channels.csv.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputChannel {
    /// The name as the deck writes it (MoorDyn's).
    pub name: String,
    pub channel: crate::moordyn::Channel,
    /// Whether stancf computes it; a channel it does not has its column
    /// in channels.csv left empty (and a note says why).
    pub computed: bool,
}

/// A line of the system.
#[derive(Clone, Debug, PartialEq)]
pub struct SystemLine {
    pub id: i64,
    /// Index into the line types.
    pub line_type: usize,
    /// Unstretched length (m).
    pub length: f64,
    pub elements: usize,
    pub element_type: ElementType,
    /// The points (indices) ends A and B attach to; None: loose.
    pub ends: [Option<usize>; 2],
    /// How the elements divide the length (docs/method.md §1.6).
    pub grading: Grading,
    /// Ends A and B clamped in a direction (as given; the library
    /// normalizes it): r_x held parallel to it (docs/method.md §6.10).
    pub clamps: [Option<[f64; 3]>; 2],
    /// A Syrope line's largest mean tension before the run (N; `tmax0`,
    /// a deck's SYROPE IC; docs/method.md §2.12).
    pub tmax0: Option<f64>,
}

impl SystemLine {
    /// Whether an end is clamped in a direction (docs/method.md §6.10):
    /// only the multiplier route holds it.
    pub fn clamped(&self) -> bool {
        self.clamps.iter().any(Option::is_some)
    }
}

/// A validated system scenario.
#[derive(Clone, Debug)]
pub struct SystemScenario {
    pub title: String,
    pub line_types: Vec<LineType>,
    /// Rigid bodies (docs/method.md §15); a free rod's body among them.
    pub bodies: Vec<SystemBody>,
    /// Rods (docs/method.md §15.10): free (a body of `bodies`), on a body,
    /// fixed, or (a deck's, of zero length) a free point.
    pub rods: Vec<super::rod_parts::SystemRod>,
    pub points: Vec<SystemPoint>,
    pub lines: Vec<SystemLine>,
    /// Acceleration of gravity (m/s^2), default [0, 0, -9.81] (z up).
    pub gravity: [f64; 3],
    pub analysis: Analysis,
    pub measures: Measures,
    pub initial: InitialShape,
    pub output_every: usize,
    /// `output.interval` (s): the result tables written at its multiples,
    /// between the steps (docs/method.md §6.5a); None: at the steps.
    pub output_interval: Option<f64>,
    /// The result files written (`output.files`; all by default).
    pub output_files: super::OutputFiles,
    /// The end forces written: step means or estimates at t.
    pub end_forces: super::output::EndForces,
    /// `output.statistics_after` (s): the design statistics of summary.json
    /// take the written moments from this time on (after a transient).
    pub statistics_after: f64,
    pub notes: Vec<String>,
    /// The water the lines are in (None: air).
    pub water: Option<Water>,
    /// Output channels (from a MoorDyn deck).
    pub channels: Vec<OutputChannel>,
    /// Why the scenario runs statically only (a deck's `WaveKin 1`): a
    /// dynamic or coupled run of it is refused with this.
    pub static_only: Option<String>,
    /// MoorDyn's main output file of a deck with OUTPUTS (None without).
    pub moordyn_out: Option<Box<MoorDynOutFile>>,
    /// Where its values were written (TOML keys or a deck's lines).
    pub names: super::names::Names,
    /// Line failures (docs/method.md §11.16).
    pub failures: Vec<SystemFailure>,
    /// A deck alone: where it has no static equilibrium (a line longer
    /// than its path, (C20); a body or rod that floats on no line and
    /// sinks) its run writes MoorDyn's start, the deck's positions with
    /// each line in its catenary, as MoorDyn's `Init` leaves it with
    /// `TmaxIC 0`, and as its initial conditions start from otherwise,
    /// without settling (docs/method.md §13.7).
    pub start_without_equilibrium: bool,
    /// The deck's `TmaxIC` where MoorDyn generates initial conditions
    /// for it (None: TmaxIC 0, or a scenario; NaN: not given, MoorDyn's
    /// default): what the note of a start without equilibrium says.
    pub moordyn_relaxation: Option<f64>,
}

/// MoorDyn's output files a deck asks for: `<deck>.out` of its OUTPUTS
/// (`run/system/moordyn_out.rs`) and `<deck>_Line<n>.out` of each line
/// with `LineOutputs` flags (`run/system/moordyn_line_out.rs`).
#[derive(Clone, Debug, PartialEq)]
pub struct MoorDynOutFile {
    /// `<deck file stem>.out`, MoorDyn's `_basename + ".out"` (None: the
    /// deck has no OUTPUTS).
    pub main: Option<String>,
    /// Each line's file and flags: (line index, `<stem>_Line<id>.out`,
    /// the flags as written).
    pub lines: Vec<(usize, String, String)>,
    /// Each of the deck's bodies' files: (body index, `<stem>_Body<id>.out`).
    pub bodies: Vec<(usize, String)>,
    /// Each rod's file and flags: (rod index, `<stem>_Rod<id>.out`, the
    /// flags as written).
    pub rods: Vec<(usize, String, String)>,
    /// Whether the units rows are written (MoorDyn's `WriteUnits`, 1
    /// unless the deck says 0).
    pub units: bool,
}

impl MoorDynOutFile {
    /// Every file name it writes.
    pub fn names(&self) -> Vec<String> {
        self.main
            .iter()
            .cloned()
            .chain(self.lines.iter().map(|(_, name, _)| name.clone()))
            .chain(self.bodies.iter().map(|(_, name)| name.clone()))
            .chain(self.rods.iter().map(|(_, name, _)| name.clone()))
            .collect()
    }
}

impl SystemScenario {
    /// Whether the system has a free body.
    pub fn has_free_bodies(&self) -> bool {
        self.bodies.iter().any(SystemBody::is_free)
    }

    /// Whether a line end is clamped in a direction (docs/method.md
    /// §6.10): only the multiplier route holds it.
    pub fn has_clamps(&self) -> bool {
        self.lines.iter().any(SystemLine::clamped)
    }

    /// Whether point p moves with the system's unknowns: a free point or
    /// a point on a free body.
    pub fn point_moves(&self, p: usize) -> bool {
        match self.points[p].kind {
            PointType::Free => true,
            PointType::Body { body, .. } => self.bodies[body].is_free(),
            PointType::Fixed | PointType::Coupled => false,
        }
    }

    /// Whether point p is held where it is: a fixed point or a point on
    /// a fixed body.
    pub fn point_is_fixed(&self, p: usize) -> bool {
        match self.points[p].kind {
            PointType::Fixed => true,
            PointType::Body { body, .. } => self.bodies[body].kind == super::BodyType::Fixed,
            PointType::Free | PointType::Coupled => false,
        }
    }

    /// Whether point p is moved by a coupling code: a coupled point or a
    /// point on a coupled body.
    pub fn point_is_coupled(&self, p: usize) -> bool {
        match self.points[p].kind {
            PointType::Coupled => true,
            PointType::Body { body, .. } => self.bodies[body].is_coupled(),
            PointType::Fixed | PointType::Free => false,
        }
    }
}

/// A failure of a system: the ends of `lines` (indices) let go of `point`
/// (index) at `time` (s) or when one of their tensions reaches `tension`
/// (N), whichever comes first.
#[derive(Clone, Debug, PartialEq)]
pub struct SystemFailure {
    /// Its id (a deck's FailureID; TOML `id`, default its place from 1).
    pub id: i64,
    pub point: usize,
    pub lines: Vec<usize>,
    pub time: Option<f64>,
    pub tension: Option<f64>,
    /// The point as the input names it: `point 3`, a deck's `R1A`.
    pub place: String,
}

impl SystemFailure {
    /// The library's failure.
    pub fn to_library(&self) -> stancf::system::LineFailure {
        stancf::system::LineFailure {
            point: self.point,
            lines: self.lines.clone(),
            time: self.time,
            tension: self.tension,
        }
    }
}
