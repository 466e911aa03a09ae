//! The `OPTIONS` section: `value name [comment]` rows, names compared
//! lower-cased as in `MoorDyn2.cpp`'s `readOptionsLine`.

use super::layout::Section;
use super::{DeckError, DeckOption};

/// An option stancf uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SupportedOption {
    /// `dtM` (old `dt`): the time step (s).
    TimeStep,
    /// `g` (`gravity`): gravitational acceleration (m/s²).
    Gravity,
    /// `WtrDpth`: water depth (m), the seabed at z = −depth.
    WaterDepth,
    /// `WtrDnsty` (`rho`, and `rhoW` of MoorDyn-F and the v1 docs): water
    /// density (kg/m³).
    WaterDensity,
    /// `kBot` (`kb`): seabed stiffness (Pa/m).
    BottomStiffness,
    /// `cBot` (`cb`): seabed damping (Pa·s/m).
    BottomDamping,
    /// `FrictionCoefficient`: seabed friction coefficient.
    FrictionCoefficient,
    /// `FricDamp` (MoorDyn-F `CV`): friction damping (s/m), scaling from no
    /// friction at rest to full friction when sliding.
    FrictionDamping,
    /// `StatDynFricScale` (MoorDyn-F `MC`): static over dynamic friction.
    StaticDynamicFrictionScale,
    /// `dtOut`: interval of the output rows (s), 0 for every step.
    OutputInterval,
    /// `Currents`: MoorDyn-C's current mode; 0 none, 1 the steady profile
    /// of `current_profile.txt` beside the deck (other modes are refused
    /// by the scenario that reads the deck).
    Currents,
    /// `WaveKin`: MoorDyn-C's wave mode; 0 none, 7 the summed components
    /// of `wave_frequencies.txt` beside the deck (other modes are refused
    /// by the scenario that reads the deck).
    WaveKin,
    /// `dtWave`: the interval MoorDyn resamples the elevation record of
    /// `WaveKin 3` at (s), read as MoorDyn reads it, in single precision
    /// ([`SupportedOption::as_moordyn_reads`]); MoorDyn's default 0.25 s.
    WaveTimeStep,
    /// `mu_kT` (MoorDyn-F): the seabed's kinetic friction coefficient
    /// across a line.
    TransverseFriction,
    /// `mu_kA` (MoorDyn-F): the same along a line.
    AxialFriction,
    /// `SeafloorFile`: MoorDyn's 3-D seafloor, a grid of the bed's
    /// heights in the file it names (the option's value is the file's
    /// path, read by the scenario that takes the deck).
    SeafloorFile,
    /// `WaterKin` (MoorDyn-F): the file of its water kinematics (a steady
    /// current profile is read; its wave grids are refused by the
    /// scenario that reads the deck), or `SEASTATE`: the sea of the host's
    /// SeaState module, which stancf takes from the host at MoorDyn's
    /// points as `WaveKin 1` ([`super::Deck::host_sets_waves`]).
    WaterKinFile,
    /// `CFL` without a `dtM`: the Courant number MoorDyn derives its step
    /// from ([`super::Deck::time_step`]); beside a `dtM` it is ignored, as
    /// MoorDyn ignores it.
    Courant,
}

impl SupportedOption {
    /// MoorDyn's usual name for it.
    pub fn name(self) -> &'static str {
        match self {
            SupportedOption::TimeStep => "dtM",
            SupportedOption::Gravity => "g",
            SupportedOption::WaterDepth => "WtrDpth",
            SupportedOption::WaterDensity => "WtrDnsty",
            SupportedOption::BottomStiffness => "kBot",
            SupportedOption::BottomDamping => "cBot",
            SupportedOption::FrictionCoefficient => "FrictionCoefficient",
            SupportedOption::FrictionDamping => "FricDamp",
            SupportedOption::StaticDynamicFrictionScale => "StatDynFricScale",
            SupportedOption::OutputInterval => "dtOut",
            SupportedOption::Currents => "Currents",
            SupportedOption::WaveKin => "WaveKin",
            SupportedOption::WaveTimeStep => "dtWave",
            SupportedOption::TransverseFriction => "mu_kT",
            SupportedOption::AxialFriction => "mu_kA",
            SupportedOption::Courant => "CFL",
            SupportedOption::SeafloorFile => "SeafloorFile",
            SupportedOption::WaterKinFile => "WaterKin",
        }
    }

    /// Whether 0 is allowed (else the value must be positive); negative
    /// values are always refused.
    fn zero_allowed(self) -> bool {
        !matches!(
            self,
            SupportedOption::TimeStep | SupportedOption::WaterDepth | SupportedOption::WaveTimeStep
        )
    }

    /// The value MoorDyn computes with: `dtWave` is read by `stof`, a
    /// float, and widened (0.15 becomes 0.15000000596...); the others as
    /// given.
    pub fn as_moordyn_reads(self, v: f64) -> f64 {
        match self {
            SupportedOption::WaveTimeStep => v as f32 as f64,
            _ => v,
        }
    }
}

/// What stancf does with an option.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OptionKind {
    /// Used by stancf.
    Supported(SupportedOption),
    /// Accepted and ignored: MoorDyn's initial condition generator
    /// (`dtIC`, `TmaxIC`, `CdScaleIC`, `threshIC`, `ICgenDynamic`,
    /// `fileIC` and their old names), logging and output switches
    /// (`writeLog`, `WriteUnits`, `disableOutput`, `disableOutTime`,
    /// `OutSwitch`, `Echo`), and the settings that are inert as given
    /// (`inertialF 0`, `UnifyCurrentGrid`, `inertialF_rampT`).
    Ignored,
}

/// An option's value as written.
#[derive(Debug, Clone, PartialEq)]
pub enum OptionValue {
    /// A finite number.
    Number(f64),
    /// Anything else (e.g. the file of `fileIC`).
    Text(String),
}

/// How a name is treated.
enum Class {
    Known(OptionKind),
    /// Accepted and ignored only when the value is 0.
    IgnoredIfZero(&'static str),
    /// `tScheme`: accepted and unused (stancf steps with its own scheme,
    /// noted by the scenario) if MoorDyn knows the name.
    Scheme,
}

/// Whether MoorDyn knows time scheme `name` (`create_time_scheme` in its
/// Time.cpp): Euler, LEuler, Heun, RK2, RK4, AB2-4, LAB2-4, and the
/// implicit BEuler<n>, Midpoint<n>, ACA<n>, Wilson<n> with n iterations.
fn moordyn_scheme(name: &str) -> bool {
    let lower = name.to_ascii_lowercase();
    let fixed = [
        "euler", "leuler", "heun", "rk2", "rk4", "ab2", "ab3", "ab4", "lab2", "lab3", "lab4",
    ];
    let iterated = ["beuler", "midpoint", "aca", "wilson"];
    fixed.contains(&lower.as_str())
        || iterated.iter().any(|p| {
            lower
                .strip_prefix(p)
                .is_some_and(|n| !n.is_empty() && n.parse::<u32>().is_ok())
        })
}

fn classify(lower: &str) -> Option<Class> {
    use SupportedOption as S;
    let s = |o| Some(Class::Known(OptionKind::Supported(o)));
    match lower {
        "dtm" | "dt" => s(S::TimeStep),
        "g" | "gravity" => s(S::Gravity),
        // MoorPy's names for it too (`System.load`: "depth", "wtrdepth");
        // MoorDyn 2.7 warns of them and ignores them (a note says so).
        "wtrdpth" | "depth" | "wtrdepth" => s(S::WaterDepth),
        "rho" | "wtrdnsty" | "rhow" => s(S::WaterDensity),
        "kbot" | "kb" => s(S::BottomStiffness),
        "cbot" | "cb" => s(S::BottomDamping),
        "frictioncoefficient" => s(S::FrictionCoefficient),
        "fricdamp" | "cv" => s(S::FrictionDamping),
        "statdynfricscale" | "mc" => s(S::StaticDynamicFrictionScale),
        "dtout" => s(S::OutputInterval),
        "currents" => s(S::Currents),
        "dtic" | "icdt" | "tmaxic" | "ictmax" | "cdscaleic" | "icdfac" | "threshic"
        | "icthresh" | "gendynamicic" | "icgendynamic" | "fileic" | "icfile" | "writelog"
        | "writeunits" | "disableoutput" | "disableouttime" | "outswitch" | "echo"
        | "unifycurrentgrid" | "inertialf_rampt" => Some(Class::Known(OptionKind::Ignored)),
        "wavekin" => s(S::WaveKin),
        "dtwave" => s(S::WaveTimeStep),
        "inertialf" => Some(Class::IgnoredIfZero(
            "MoorDyn-F's inertial coupled forces are not supported",
        )),
        "cfl" => s(S::Courant),
        "tscheme" => Some(Class::Scheme),
        "seafloorfile" => s(S::SeafloorFile),
        "waterkin" => s(S::WaterKinFile),
        "mu_kt" => s(S::TransverseFriction),
        "mu_ka" => s(S::AxialFriction),
        _ => None,
    }
}

/// The options, each name (synonyms included) at most once.
pub(crate) fn read(s: &Section) -> Result<Vec<DeckOption>, DeckError> {
    let mut out: Vec<DeckOption> = Vec::new();
    // MoorDyn derives dtM from cfl only without a dtM; with one, it
    // ignores cfl (MoorDyn2.cpp, `Init`).
    let gives_dtm = s.rows.iter().any(|r| {
        r.words
            .get(1)
            .is_some_and(|n| matches!(n.to_ascii_lowercase().as_str(), "dtm" | "dt"))
    });
    for row in &s.rows {
        if row.words.len() < 2 {
            return Err(DeckError::at(
                row.line,
                format!(
                    "an option row is \"value name\"; this one has only \"{}\"",
                    row.words[0]
                ),
            ));
        }
        let (text, name) = (row.words[0], row.words[1]);
        let lower = name.to_ascii_lowercase();
        let number = text.parse::<f64>().ok().filter(|v| v.is_finite());
        let class = if lower == "cfl" && gives_dtm {
            Some(Class::Known(OptionKind::Ignored))
        } else {
            classify(&lower)
        };
        let kind = match class {
            None => {
                return Err(DeckError::at(
                    row.line,
                    format!("unknown option \"{name}\""),
                ))
            }
            Some(Class::IgnoredIfZero(why)) if number != Some(0.0) => {
                return Err(DeckError::at(
                    row.line,
                    format!("option {name} is {text}: {why} (only 0 is accepted)"),
                ))
            }
            Some(Class::IgnoredIfZero(_)) => OptionKind::Ignored,
            Some(Class::Scheme) if !moordyn_scheme(text) => {
                return Err(DeckError::at(
                    row.line,
                    format!(
                        "option {name} is \"{text}\", a time scheme MoorDyn does not know \
                         (MoorDyn refuses it too; its schemes: Euler, LEuler, Heun, RK2, RK4, \
                         AB2-AB4, LAB2-LAB4, BEuler<n>, Midpoint<n>, ACA<n>, Wilson<n>)"
                    ),
                ))
            }
            Some(Class::Scheme) => OptionKind::Ignored,
            Some(Class::Known(k)) => k,
        };
        let value = match (kind, number) {
            (OptionKind::Supported(SupportedOption::SeafloorFile), _) => {
                OptionValue::Text(text.to_string())
            }
            (OptionKind::Supported(SupportedOption::WaterKinFile), _) => {
                let path = text.trim_matches('"');
                OptionValue::Text(path.to_string())
            }
            (OptionKind::Supported(o), Some(v)) => supported_value(o, v, name, row.line)?,
            (OptionKind::Supported(_), None) => {
                return Err(DeckError::at(
                    row.line,
                    format!("option {name} is \"{text}\", which is not a finite number"),
                ))
            }
            (OptionKind::Ignored, Some(v)) => OptionValue::Number(v),
            (OptionKind::Ignored, None) => OptionValue::Text(text.to_string()),
        };
        let same = |o: &&DeckOption| {
            o.name.eq_ignore_ascii_case(name)
                || matches!(kind, OptionKind::Supported(_)) && o.kind == kind
        };
        // Given again: MoorDyn reads the options in order, so the last
        // holds (a note says so).
        let replaces = out.iter().position(|o| same(&o)).map(|i| {
            let first = out.remove(i);
            (first.name, first.line)
        });
        out.push(DeckOption {
            line: row.line,
            name: name.to_string(),
            value,
            kind,
            replaces,
        });
    }
    Ok(out)
}

fn supported_value(
    o: SupportedOption,
    v: f64,
    name: &str,
    line: usize,
) -> Result<OptionValue, DeckError> {
    if v < 0.0 || (v == 0.0 && !o.zero_allowed()) {
        let bound = if o.zero_allowed() {
            "zero or positive"
        } else {
            "positive"
        };
        return Err(DeckError::at(
            line,
            format!("option {name} is {v}; it must be {bound}"),
        ));
    }
    Ok(OptionValue::Number(v))
}
