//! A MoorDyn driver file's run (docs/interface.md, "MoorDyn driver
//! files"): the deck it names, in the driver's sea, run for its TMax as
//! OpenFAST's `MoorDyn_Driver` runs it: from MoorDyn's initial conditions
//! (stancf's static equilibrium where the deck has MoorDyn generate them;
//! the lines' catenaries between the deck's positions where its `TmaxIC`
//! is 0, docs/method.md §13.7), the coupled objects held where the
//! platform rows' offsets put them (InputsMode 0,
//! [`super::moordyn_driver_platforms`]) or moved by the driver's time
//! series (InputsMode 1, [`super::moordyn_driver_motions`]).

use super::context::Ctx;
use super::system_parts::SystemScenario;
use super::{HostEnvironment, ScenarioError};
use crate::moordyn::driver::parse_driver;
use stancf::error::Sig;
use std::path::Path;

/// The system a driver file runs; `file` names it in messages and `path`
/// resolves the files it names (relative to its folder, as the driver
/// resolves them).
pub(super) fn driver_scenario(
    text: &str,
    file: &str,
    path: &Path,
) -> Result<SystemScenario, ScenarioError> {
    let at =
        |line: usize, message: String| ScenarioError(format!("{file}: line {line}: {message}"));
    let d = parse_driver(text).map_err(|e| ScenarioError(format!("{file}: {e}")))?;
    let dir = path.parent().unwrap_or(Path::new(""));
    let deck_path = dir.join(&d.deck);
    let deck_text = crate::input_file::read_text(&deck_path).map_err(|e| {
        at(
            d.lines[3],
            format!("MDInputFile {:?}: {e} ({})", d.deck, deck_path.display()),
        )
    })?;
    let deck = crate::moordyn::parse(&deck_text)
        .map_err(|e| ScenarioError(format!("{}: {e}", deck_path.display())))?;
    let motions = match d.inputs_mode {
        0 => None,
        _ => Some(super::moordyn_driver_motions::read_inputs(&d, file, dir)?),
    };
    let record = match &motions {
        // The driver trims the run to the motions' record.
        Some(m) => d.t_max.min(m.last_time()),
        None => d.t_max,
    };
    // Whole coupling steps (MoorDyn's driver takes TMax / dtC - 1 of them).
    let duration = (record / d.dt_c + 1e-9).floor().max(1.0) * d.dt_c;
    let initial = if deck.generates_initial_conditions() {
        "static"
    } else {
        "catenary"
    };
    let every = output_every(
        deck.option(crate::moordyn::SupportedOption::OutputInterval),
        d.dt_c,
    );
    let title = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let toml_text = format!(
        "title = {}\n[system]\nmoordyn = {}\n[analysis]\ntype = \"dynamic\"\n\
         time_scheme = \"galerkin\"\nduration = {duration:?}\ntime_step = {:?}\n\
         initial = \"{initial}\"\n[output]\nevery = {every}\n",
        toml_string(&title),
        toml_string(&d.deck),
        d.dt_c,
    );
    let raw = super::raw_scenario(&toml_text, file)?;
    let host = HostEnvironment {
        water_depth: Some(d.water_depth),
        water_density: Some(d.water_density),
        gravity: Some(d.gravity),
        turbines: (d.turbines > 0).then(|| d.platforms.iter().map(|p| [p[0], p[1], 0.0]).collect()),
        sets_waves: false,
        // The driver passes MoorDyn-F its TMax (MoorDyn_Driver.f90).
        run_length: Some(d.t_max),
    };
    let ctx = Ctx { file };
    let mut sc = super::system::system_scenario(&ctx, raw, title, path, &host)
        .map_err(|e| ScenarioError(driver_words(&e.0)))?;
    match motions {
        Some(m) => {
            super::moordyn_driver_motions::apply(&m, &mut sc, file, &d)?;
            super::moordyn_driver_platforms::superseded_note(&d, &mut sc, file);
        }
        None => super::moordyn_driver_platforms::place(&d, &deck, &mut sc, file)?,
    }
    sc.notes.push(format!(
        "{file}: MoorDyn's driver file: {} in g {} m/s^2, water {} kg/m^3, {} m deep; {} s \
         from {} (the deck's TmaxIC {}), stepped by stancf's Galerkin step at the driver's dtC, \
         {} s (MoorDyn steps at the smaller of dtC and dtM); the coupled objects {}",
        deck_path.display(),
        Sig(d.gravity),
        Sig(d.water_density),
        Sig(d.water_depth),
        Sig(duration),
        if initial == "static" {
            "the static equilibrium"
        } else {
            "the lines' catenaries between the deck's positions"
        },
        if initial == "static" { "> 0" } else { "0" },
        Sig(d.dt_c),
        if d.inputs_mode == 0 {
            "held where the deck puts them (InputsMode 0)".to_string()
        } else {
            format!("moved by {} (InputsMode 1)", d.inputs_file)
        }
    ));
    Ok(sc)
}

/// Whether `text` is a MoorDyn driver file.
pub(super) fn is_driver(text: &str) -> bool {
    crate::moordyn::driver::looks_like_driver(text)
}

/// Rows written every `dtOut / dtC` steps (the nearest whole number, at
/// least 1; every step for `dtOut` 0 or absent, as MoorDyn writes every
/// coupling step then).
fn output_every(dt_out: Option<f64>, dt_c: f64) -> usize {
    match dt_out {
        Some(o) if o > 0.0 => ((o / dt_c).round() as usize).max(1),
        _ => 1,
    }
}

/// An error of the generated scenario in the driver's words: its keys
/// are the driver's values.
fn driver_words(message: &str) -> String {
    message
        .replace("analysis.duration", "TMax (analysis.duration)")
        .replace("analysis.time_step", "dtC (analysis.time_step)")
}

/// A TOML basic string of `s`.
fn toml_string(s: &str) -> String {
    toml::Value::String(s.to_string()).to_string()
}
