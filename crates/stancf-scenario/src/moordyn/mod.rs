//! MoorDyn v2 input files ("decks") read into a neutral, validated
//! [`Deck`]. Only what stancf can represent is accepted: line types with
//! constant coefficients, fixed and free bodies, fixed, free and coupled
//! points and points on bodies, fixed, free and body rods, lines between
//! points and rod ends, the options of
//! [`SupportedOption`] (plus MoorDyn's initial condition, logging and
//! output switches, accepted and ignored) and the output channels of
//! [`Channel`]. Everything else (pinned and coupled rods and bodies,
//! failures, nonlinear or viscoelastic stiffness, VIV, wave files,
//! MoorDyn-F water kinematics, bathymetry files...) is refused by name,
//! naming the line of the file.
//! Turning a deck into a simulation model is not done here.
//!
//! The format follows MoorDyn-C's reader (`MoorDyn2.cpp`,
//! `MoorDyn::ReadInFile`, `findStartOfSection`, `readLineProps`,
//! `readOptionsLine`; `Misc.cpp`, `str::split` and `str::decomposeString`)
//! and its documentation (`docs/inputs.rst`, "The V2 Input File"):
//!
//! - A section starts at a line containing `---` whose upper-cased text
//!   contains one of the section's key phrases (`LINE TYPES`, `POINTS`,
//!   `LINES`, `OPTIONS`, `OUTPUTS` and their synonyms); any other
//!   line containing `---` ends the section before it (the customary
//!   `--- need this line ---` or `--- END ---`). The lines before the
//!   first section are a free-form title.
//! - Table sections (line types, points, lines...) start with a row of
//!   column names and a row of units; options and outputs do not.
//! - Values are separated by blanks; the first word containing `#`
//!   starts a comment running to the end of the line (MoorDyn drops that
//!   whole word). Words after the last column MoorDyn reads are ignored
//!   as MoorDyn ignores them, except in `LINE TYPES`, where MoorDyn
//!   refuses rows of other than 10, 11 or 13 words.

mod bodies;
mod channel_units;
mod channels;
pub mod driver;
mod ends;
pub mod external_loads;
pub mod failures;
mod layout;
mod options;
mod rods;
mod sections;
pub mod syrope_columns;
#[cfg(test)]
mod tests;
mod visco_columns;

use std::fmt;
use std::path::Path;

pub use bodies::{BodyAttachment, DeckBody};
pub use channels::{
    Axis, BodyQuantity, Channel, LineEnd, LineQuantity, PointQuantity, RodQuantity,
};
pub use ends::{LineAttachment, RodEnd};
pub use options::{OptionKind, OptionValue, SupportedOption};
pub use rods::{DeckRod, RodAttachment, RodType};

/// A MoorDyn v2 input file, read and checked.
#[derive(Debug, Clone, PartialEq)]
pub struct Deck {
    /// The free-form lines before the first section (banner lines of
    /// dashes excluded), joined with newlines.
    pub title: String,
    /// `LINE TYPES` (or `LINE DICTIONARY`), in file order.
    pub line_types: Vec<LineType>,
    /// `BODIES` (or `BODY LIST`, `BODY PROPERTIES`); the n-th has id n.
    pub bodies: Vec<DeckBody>,
    /// `ROD TYPES` (or `ROD DICTIONARY`), in file order.
    pub rod_types: Vec<RodType>,
    /// `RODS` (or `ROD LIST`, `ROD PROPERTIES`); the n-th has id n.
    pub rods: Vec<DeckRod>,
    /// `POINTS` (or `POINT LIST`, `POINT PROPERTIES`, `CONNECTION
    /// PROPERTIES`, `NODE PROPERTIES`); the n-th has id n.
    pub points: Vec<DeckPoint>,
    /// `LINES` (or `LINE LIST`, `LINE PROPERTIES`); the n-th has id n.
    pub lines: Vec<DeckLine>,
    /// `OPTIONS` (or `SOLVER OPTIONS`), in file order, each name at most
    /// once.
    pub options: Vec<DeckOption>,
    /// `OUTPUTS` (or `OUTPUT`), in file order.
    pub outputs: Vec<Output>,
    /// MoorDyn-F's `EXTERNAL LOADS`, in file order.
    pub external_loads: Vec<external_loads::DeckExternalLoad>,
    /// `SYROPE IC` rows (docs/method.md §2.12).
    pub syrope_ic: Vec<syrope_columns::SyropeIc>,
    /// MoorDyn-F's `FAILURE` rows (docs/method.md §11.16).
    pub failures: Vec<failures::DeckFailure>,
}

/// A row of `LINE TYPES`: `TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx
/// CaAx`, optionally followed by `Cl` or `Cl dF cF` (VIV, docs/method.md
/// §12.7; `Cl` = 0 is VIV off).
#[derive(Debug, Clone, PartialEq)]
pub struct LineType {
    /// 1-based line number in the file.
    pub line: usize,
    /// `TypeName`, matched case-sensitively by the lines, as MoorDyn does.
    pub name: String,
    /// `Diam`: volume-equivalent diameter (m).
    pub diameter: f64,
    /// `Mass/m`: mass per unit length (kg/m).
    pub mass_per_length: f64,
    /// `EA`: axial stiffness (N), a constant (the static one of a
    /// viscoelastic `EA|EA_D` or `EA|alpha|beta`); 0 where the column
    /// names a curve file.
    pub ea: f64,
    /// The dynamic stiffness of MoorDyn's viscoelastic forms (docs/method.md
    /// §2.11): `EA|EA_D` (constant) or `EA|alphaMBL|vbeta` (mean-load).
    pub ea_dynamic: Option<stancf::element::DynamicStiffness>,
    /// `BA|BA_D`: the dashpot beside the dynamic spring (N s); 0 when the
    /// column has one value.
    pub ba_dynamic: f64,
    /// `SYROPE:<file>|alphaMBL|vbeta` (docs/method.md §2.12): the
    /// settings file, alpha and beta (the scenario reads the file).
    pub syrope: Option<syrope_columns::SyropeColumns>,
    /// `EA` as the name of a file of MoorDyn's nonlinear tension-strain
    /// curve (docs/method.md §2.2a), which the scenario reads.
    pub ea_curve_file: Option<String>,
    /// `BA/-zeta` as written: if ≥ 0, the internal axial damping
    /// coefficient BA (N·s); if negative, minus the damping ratio ζ
    /// (fraction of critical) from which MoorDyn sets BA for each line
    /// from its segment length (so `-1.0` is critical damping of the
    /// axial segment mode). See [`LineType::damping_ratio`].
    pub ba: f64,
    /// `EI`: bending stiffness (N·m²), a constant.
    pub ei: f64,
    /// `Cd`: transverse drag coefficient (on d·l).
    pub cd_normal: f64,
    /// `Ca`: transverse added-mass coefficient.
    pub ca_normal: f64,
    /// `CdAx`: tangential drag coefficient (on π·d·l).
    pub cd_axial: f64,
    /// `CaAx`: tangential added-mass coefficient.
    pub ca_axial: f64,
    /// `Cl dF cF`: MoorDyn's VIV lift (docs/method.md §12.7); None where
    /// the columns are absent or `Cl` = 0.
    pub viv: Option<VivColumns>,
}

/// A LINE TYPES row's VIV columns.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VivColumns {
    /// `Cl`: the cross-flow lift coefficient (> 0).
    pub cl: f64,
    /// `dF`: the half-width of the synchronisation range.
    pub range: f64,
    /// `cF`: its centre.
    pub centre: f64,
}

impl VivColumns {
    /// MoorDyn's dF and cF where a row gives Cl alone.
    pub const RANGE: f64 = 0.08;
    pub const CENTRE: f64 = 0.18;
    /// MoorDyn's running mean squares span n_m = 500 of its steps.
    pub const MEAN_SQUARE_STEPS: f64 = 500.0;
}

impl LineType {
    /// ζ when `BA/-zeta` is negative (a damping ratio), `None` when it is
    /// a damping coefficient.
    pub fn damping_ratio(&self) -> Option<f64> {
        (self.ba < 0.0).then_some(-self.ba)
    }
}

/// How a point moves.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Attachment {
    /// `Fixed`, `Fix` or `Anchor`: held at its position.
    Fixed,
    /// `Free`, `Point`, `Connect` or `Con`: moves under the forces on it.
    Free,
    /// `Coupled`, `Cpld`, `Vessel`, `Ves` or `Fairlead`: moved by the
    /// caller (the vessel).
    Coupled,
    /// `Body<n>`: fixed on body n (its id, from 1), `X Y Z` in the body's
    /// axes from its reference point.
    Body(usize),
    /// `Turbine<n>` (a FAST.Farm deck's farm-level moorings): fixed on
    /// turbine n's platform (n from 1, as the FAST.Farm input lists the
    /// turbines), `X Y Z` from the turbine's reference position, which
    /// the farm gives (MoorDyn's docs: "it acts similarly to a BodyN
    /// attachment").
    Turbine(usize),
}

/// A row of `POINTS`: `ID Attachment X Y Z Mass Volume CdA Ca` (a
/// 12-column form with `FX FY FZ` after `Volume` is accepted when the
/// forces are zero).
#[derive(Debug, Clone, PartialEq)]
pub struct DeckPoint {
    /// 1-based line number in the file.
    pub line: usize,
    /// `ID`, 1, 2, 3... in order.
    pub id: usize,
    /// `Attachment` (MoorDyn also calls the column `Type`).
    pub attachment: Attachment,
    /// `X Y Z` (m), global frame, z up from the still water line; on a
    /// body, in the body's axes from its reference point.
    pub position: [f64; 3],
    /// `Mass` (kg), a clump weight.
    pub mass: f64,
    /// `Volume` (m³), buoyancy.
    pub volume: f64,
    /// `CdA`: drag coefficient times area (m²).
    pub cda: f64,
    /// `Ca`: added-mass coefficient (on `Volume`).
    pub ca: f64,
    /// `FX FY FZ` (N) of the old 12-column rows (MoorDyn's `pointF`, a
    /// constant force on a free point); 0 without them.
    pub force: [f64; 3],
}

/// The `LineOutputs` flags whose quantities stancf writes to
/// `<deck>_Line<n>.out`, in MoorDyn's order (`Line::Output`): node
/// positions, curvatures, velocities, the water's velocities, the
/// hydrodynamic and VIV forces, segment tensions, internal damping
/// forces, strains and strain rates, the seabed's nodal forces (`c` not
/// for a viscoelastic line, [`uncomputed_line_flags`]).
pub const WRITTEN_LINE_FLAGS: [char; 11] = ['p', 'K', 'v', 'U', 'D', 'V', 't', 'c', 's', 'd', 'b'];

/// The flags MoorDyn knows whose quantities stancf does not compute for a
/// line (`viscoelastic`: of a viscoelastic type): a viscoelastic line's
/// internal damping force (its law's).
pub fn uncomputed_line_flags(viscoelastic: bool) -> Vec<(char, &'static str)> {
    if viscoelastic {
        vec![('c', "the internal damping force of a viscoelastic line")]
    } else {
        Vec::new()
    }
}

/// A row of `LINES`: `ID LineType AttachA AttachB UnstrLen NumSegs
/// Outputs`.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckLine {
    /// 1-based line number in the file.
    pub line: usize,
    /// `ID`, 1, 2, 3... in order.
    pub id: usize,
    /// `LineType`, as written.
    pub line_type: String,
    /// Index of the line type in [`Deck::line_types`].
    pub type_index: usize,
    /// `AttachA`: the point or rod end at end A (node 0, the anchor end).
    pub end_a: LineAttachment,
    /// `AttachB`: the point or rod end at end B (node `segments`, the
    /// fairlead end).
    pub end_b: LineAttachment,
    /// `UnstrLen` (m), > 0.
    pub unstretched_length: f64,
    /// `NumSegs`, ≥ 1; the line has `segments + 1` nodes.
    pub segments: usize,
    /// `Outputs` (`LineOutputs`): MoorDyn's per-line output file flags as
    /// written, e.g. `p`, `pt`, `-` (none).
    pub outputs: String,
}

impl DeckLine {
    /// Whether MoorDyn would write a file for this line: one of the flag
    /// letters `pvUDVKctsd` is present (as `MoorDyn2.cpp` tests).
    pub fn wants_line_file(&self) -> bool {
        self.outputs.chars().any(|c| "pvUDVKctsd".contains(c))
    }
}

/// A row of `OPTIONS`: `value name [comment]`.
#[derive(Debug, Clone, PartialEq)]
pub struct DeckOption {
    /// 1-based line number in the file.
    pub line: usize,
    /// The name as written, e.g. `WtrDnsty`.
    pub name: String,
    /// The value, a number for every supported option.
    pub value: OptionValue,
    /// What stancf does with it.
    pub kind: OptionKind,
    /// The same option given before under this name at this line, which
    /// this one replaces (MoorDyn reads its options in order: the last
    /// one holds).
    pub replaces: Option<(String, usize)>,
}

/// A word of `OUTPUTS`.
#[derive(Debug, Clone, PartialEq)]
pub struct Output {
    /// 1-based line number in the file.
    pub line: usize,
    /// The channel name as written, e.g. `FairTen1`.
    pub name: String,
    /// What it measures.
    pub channel: Channel,
    /// Why it is not a channel MoorDyn knows, for a
    /// [`Channel::Unrecognized`] (MoorDyn warns and skips it).
    pub unrecognized: Option<String>,
}

impl Deck {
    /// The option `which` if the deck sets it: its name as written and
    /// its line.
    pub fn option_at(&self, which: SupportedOption) -> Option<(&str, usize)> {
        self.options
            .iter()
            .find(|o| o.kind == OptionKind::Supported(which))
            .map(|o| (o.name.as_str(), o.line))
    }

    /// The text of an option whose value is a word or a path
    /// (`SeafloorFile`, `WaterKin`), with its name as written and its line.
    pub fn option_text(&self, which: SupportedOption) -> Option<(&str, &str, usize)> {
        self.options.iter().find_map(|o| match (o.kind, &o.value) {
            (OptionKind::Supported(s), OptionValue::Text(t)) if s == which => {
                Some((t.as_str(), o.name.as_str(), o.line))
            }
            _ => None,
        })
    }

    /// Whether MoorDyn generates initial conditions for this deck before
    /// it runs: its `TmaxIC` (`ICTmax`), the last given, is positive, or
    /// absent (MoorDyn's default is positive). With `TmaxIC 0` MoorDyn
    /// starts from the deck's positions, each line in its catenary.
    pub fn generates_initial_conditions(&self) -> bool {
        self.initial_conditions_time().is_some()
    }

    /// MoorDyn's time for its initial conditions, the last `TmaxIC`
    /// (`ICTmax`) given: None where it is 0 or below (none generated),
    /// NaN where it is not given (MoorDyn's default) or not a number.
    pub fn initial_conditions_time(&self) -> Option<f64> {
        let given = self.options.iter().rev().find(|o| {
            o.name.eq_ignore_ascii_case("tmaxic") || o.name.eq_ignore_ascii_case("ictmax")
        });
        match given.map(|o| &o.value) {
            Some(OptionValue::Number(v)) if *v <= 0.0 => None,
            Some(OptionValue::Number(v)) => Some(*v),
            _ => Some(f64::NAN),
        }
    }

    /// Whether the deck's waves are a host's: `WaveKin 1`, MoorDyn's
    /// external wave kinematics, which the host sets at the nodes while it
    /// steps the system (docs/method.md §12.1, (W2f)-(W2g)), or MoorDyn-F's
    /// `SEASTATE WaterKin` ([`Deck::sea_from_seastate`]).
    pub fn host_sets_waves(&self) -> bool {
        self.option(SupportedOption::WaveKin) == Some(1.0) || self.sea_from_seastate().is_some()
    }

    /// The option's name and line where a MoorDyn-F deck's `WaterKin` is
    /// `SEASTATE`: its water's kinematics (waves and current) are those of
    /// the glue code's SeaState module, which MoorDyn-F interpolates on
    /// SeaState's grid at its nodes. stancf takes them from the host as
    /// `WaveKin 1`'s, at MoorDyn's points (docs/method.md (W2f)-(W2h)).
    pub fn sea_from_seastate(&self) -> Option<(&str, usize)> {
        self.option_text(SupportedOption::WaterKinFile)
            .filter(|(value, _, _)| value.eq_ignore_ascii_case("seastate"))
            .map(|(_, name, line)| (name, line))
    }

    /// The value of a supported option, if the deck sets it.
    pub fn option(&self, which: SupportedOption) -> Option<f64> {
        self.options.iter().find_map(|o| match (o.kind, &o.value) {
            (OptionKind::Supported(s), OptionValue::Number(v)) if s == which => Some(*v),
            _ => None,
        })
    }

    /// The time step MoorDyn takes (`MoorDyn::Init`): `dtM` if given;
    /// else `CFL` (MoorDyn's 0.5 when not given) times the shortest
    /// natural period of a line's segment, 2 pi sqrt(m_s / k_s) with
    /// m_s = w L / N and k_s = EA N / L (MoorDyn's `NatFreqCFL` of a line;
    /// points, rods and bodies take their lines'): CFL 2 pi (L / N)
    /// sqrt(w / EA). None for a deck without lines.
    pub fn time_step(&self) -> Option<f64> {
        if let Some(dt) = self.option(SupportedOption::TimeStep) {
            return Some(dt);
        }
        let cfl = self.option(SupportedOption::Courant).unwrap_or(0.5);
        self.lines
            .iter()
            .map(|l| {
                let t = self.line_type_of(l);
                let segment = l.unstretched_length / l.segments as f64;
                cfl * 2.0 * std::f64::consts::PI * segment * (t.mass_per_length / t.ea).sqrt()
            })
            .reduce(f64::min)
    }

    /// The line type of a line.
    pub fn line_type_of(&self, line: &DeckLine) -> &LineType {
        &self.line_types[line.type_index]
    }

    /// The type of a rod.
    pub fn rod_type_of(&self, rod: &DeckRod) -> &RodType {
        &self.rod_types[rod.type_index]
    }

    /// The point with this id (ids start at 1).
    pub fn point(&self, id: usize) -> Option<&DeckPoint> {
        id.checked_sub(1).and_then(|i| self.points.get(i))
    }
}

/// Why a deck was refused.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DeckError {
    /// 1-based line number in the file, when the problem has one.
    pub line: Option<usize>,
    /// What is wrong, in words.
    pub message: String,
}

impl DeckError {
    /// An error at deck line `line`; the pieces of the deck it quotes are
    /// cut to [`crate::echo::MAX_ECHO`] characters.
    pub(crate) fn at(line: usize, message: impl Into<String>) -> DeckError {
        DeckError {
            line: Some(line),
            message: crate::echo::clip_quoted(&message.into()),
        }
    }

    /// An error of the whole deck (its quoted pieces cut as in [`Self::at`]).
    pub(crate) fn whole(message: impl Into<String>) -> DeckError {
        DeckError {
            line: None,
            message: crate::echo::clip_quoted(&message.into()),
        }
    }
}

impl fmt::Display for DeckError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.line {
            Some(n) => write!(f, "line {n}: {}", self.message),
            None => f.write_str(&self.message),
        }
    }
}

impl std::error::Error for DeckError {}

/// Reads and checks a MoorDyn v2 deck.
pub fn parse(text: &str) -> Result<Deck, DeckError> {
    let layout = layout::split(text)?;
    let mut line_types = Vec::new();
    let mut bodies = Vec::new();
    let mut rod_types = Vec::new();
    let mut rod_rows = None;
    let mut points = Vec::new();
    let mut raw_lines = Vec::new();
    let mut options = Vec::new();
    let mut raw_outputs = Vec::new();
    let mut external_rows = None;
    let mut syrope_ic = Vec::new();
    let mut failure_rows = None;
    for section in &layout.sections {
        use layout::SectionKind as K;
        match section.kind {
            K::LineTypes => line_types = sections::line_types(section)?,
            K::Bodies => bodies = bodies::bodies(section)?,
            K::RodTypes => rod_types = rods::rod_types(section)?,
            // Read once the types are (ROD TYPES may follow RODS).
            K::Rods => rod_rows = Some(section),
            K::Points => points = sections::points(section)?,
            K::Lines => raw_lines = sections::lines(section)?,
            K::Options => options = options::read(section)?,
            K::Outputs => raw_outputs = channels::words(section)?,
            // Read once the points and bodies are.
            K::ExternalLoads => external_rows = Some(section),
            K::SyropeIc => syrope_ic = syrope_columns::syrope_ic(section)?,
            // Read once the lines are.
            K::Failure => failure_rows = Some(section),
            other => sections::refuse_rows(section, other)?,
        }
    }
    let rods = match rod_rows {
        Some(section) => rods::rods(section, &rod_types)?,
        None => Vec::new(),
    };
    bodies::check_body_points(&points, &bodies)?;
    let external_loads = match external_rows {
        Some(section) => external_loads::external_loads(section, &points, &bodies)?,
        None => Vec::new(),
    };
    bodies::check_turbine_points(&points)?;
    let lines = sections::link_lines(raw_lines, &line_types, &points)?;
    if lines.is_empty() && bodies.is_empty() && rods.is_empty() {
        return Err(DeckError::whole(
            "the deck defines no lines, bodies or rods: nothing moves (a system holds lines, \
             bodies or rods, with the points they hold)",
        ));
    }
    rods::check_rods(&rods, bodies.len(), &lines)?;
    let failures = match failure_rows {
        Some(section) => failures::failures(section, (points.len(), rods.len()), &lines)?,
        None => Vec::new(),
    };
    let outputs = channels::resolve(raw_outputs, &lines, &points, (&bodies, &rods))?;
    Ok(Deck {
        title: layout.title,
        line_types,
        bodies,
        rod_types,
        rods,
        points,
        lines,
        options,
        outputs,
        external_loads,
        syrope_ic,
        failures,
    })
}

/// Reads and checks the MoorDyn v2 deck in a file. A file that cannot be
/// read is an error without a line, naming the file.
pub fn load(path: &Path) -> Result<Deck, DeckError> {
    let text = crate::input_file::read_text(path)
        .map_err(|e| DeckError::whole(format!("{}: {e}", path.display())))?;
    // An error of the whole deck names the deck (one at a line is named
    // with its line by the caller).
    parse(&text).map_err(|e| match e.line {
        Some(_) => e,
        None => DeckError::whole(format!("{}: {}", path.display(), e.message)),
    })
}

/// Whether a text looks like a MoorDyn deck rather than a TOML scenario:
/// some line starts with `---` and names a MoorDyn section (`LINE
/// TYPES`, `POINTS`, `LINES`, `OPTIONS`...).
pub fn looks_like_moordyn(text: &str) -> bool {
    layout::deck_lines(text)
        .any(|l| l.trim_start().starts_with("---") && layout::SectionKind::of_header(l).is_some())
}
