//! A system whose lines, points and gravity come from a MoorDyn deck
//! (`[system] moordyn = ...`; docs/interface.md, "MoorDyn decks"), with
//! the scenario's motions, meshes, water keys, farm, analysis and output;
//! and the keys that only such a scenario takes.

use super::analysis::{analysis_part, AnalysisKind, InitialShape};
use super::context::Ctx;
use super::motions::motions;
use super::raw::{RawScenario, RawSystem};
use super::system_parts::SystemScenario;
use super::water::water_keys;
use super::ScenarioError;
use std::path::Path;

/// A system whose lines, points and gravity come from the MoorDyn deck at
/// `deck_path` (`system.moordyn`), with the scenario's motions, meshes,
/// water keys, analysis and output.
pub(super) fn deck_system(
    ctx: &Ctx,
    raw: RawScenario,
    (rs, deck_path): (RawSystem, &Path),
    (title, path): (String, &Path),
    host: &super::HostEnvironment,
) -> Result<SystemScenario, ScenarioError> {
    if let Some(key) = [
        (rs.gravity.is_some(), "system.gravity"),
        (!raw.line_types.is_empty(), "line_types"),
        (!raw.bodies.is_empty(), "bodies"),
        (!raw.rod_types.is_empty(), "rod_types"),
        (!raw.rods.is_empty(), "rods"),
        (!raw.points.is_empty(), "points"),
        (!raw.lines.is_empty(), "lines"),
        (!raw.failures.is_empty(), "failures"),
    ]
    .into_iter()
    .find_map(|(present, key)| present.then_some(key))
    {
        return Err(ctx.err(
            key,
            "the MoorDyn deck of system.moordyn gives the line types, points, lines, \
             gravity and failures (its FAILURE section); the scenario adds motions, [[mesh]] (the lines' meshes), \
             [water] (what the deck does not give), [analysis] and [output]",
        ));
    }
    let mut deck = super::moordyn::load_deck(ctx, "system.moordyn", deck_path)?;
    if let Some(values) = &raw.deck {
        super::deck_values::set_deck_values(ctx, values, &mut deck)?;
    }
    let dir = path.parent().unwrap_or(Path::new(""));
    let added = raw.water.map(|w| water_keys(ctx, w, dir)).transpose()?;
    let farm = raw
        .farm
        .map(|f| super::farm::scenario_farm(ctx, f, dir))
        .transpose()?;
    let deck_file = deck_path.display().to_string();
    // A dynamic analysis' duration is the run's length a host would give
    // (a WaterKin file's wave record is resampled over it).
    let dynamic = raw
        .analysis
        .as_ref()
        .is_some_and(|a| a.kind.as_deref().is_none_or(|k| k == "dynamic"));
    let run_length = raw.analysis.as_ref().and_then(|a| a.duration);
    let host = &super::HostEnvironment {
        run_length: host.run_length.or(run_length.filter(|_| dynamic)),
        ..host.clone()
    };
    let mut sc = super::moordyn::deck_scenario(
        &deck,
        &deck_file,
        deck_path,
        title,
        added.map(|w| (ctx, w)),
        host,
        farm,
    )?;
    sc.names = super::names::Names::of_deck(&deck, Some(deck_file.clone()))
        .with_rods(&sc.rods, deck.points.len());
    super::deck_mesh::deck_meshes(ctx, &raw.mesh, &mut sc)?;
    if let Some(mbl) = &rs.mbl {
        breaking_loads(ctx, mbl, &mut sc)?;
    }
    let deck_alone = raw.analysis.is_none();
    let (raw_analysis, step_note) = with_deck_step(raw.analysis, &deck);
    let (mut analysis, measures, initial, notes) = analysis_part(
        ctx,
        raw_analysis,
        (InitialShape::Static, sc.has_free_bodies(), sc.has_clamps()),
    )?;
    if deck_alone {
        // As the deck alone: its step is a coupled run's.
        analysis.time_step = deck.time_step().unwrap_or(0.0);
    }
    sc.notes.extend(step_note);
    if let Some(why) = sc
        .static_only
        .as_ref()
        .filter(|_| analysis.kind == AnalysisKind::Dynamic && !host.sets_waves)
    {
        return Err(ScenarioError(why.clone()));
    }
    let lengths: Vec<f64> = sc.lines.iter().map(|l| l.length).collect();
    motions(ctx, &raw.motions, &mut sc.points, &lengths, path, &analysis)?;
    sc.analysis = analysis;
    sc.measures = measures;
    sc.initial = initial;
    // A scenario's own analysis says what it starts from.
    sc.start_without_equilibrium &= deck_alone;
    sc.notes.extend(notes);
    sc.notes.extend(super::sea_limits::static_waves_note(&sc));
    sc.notes.extend(super::sea_limits::breaking_wave_notes(&sc));
    let again = super::overstretch::overstretched_notes(&sc);
    for note in again.into_iter().chain(super::viv_types::viv_notes(&sc)) {
        // The deck's own notes may hold it already.
        if !sc.notes.contains(&note) {
            sc.notes.push(note);
        }
    }
    sc.output_every = super::output::output_every(ctx, raw.output.as_ref())?;
    sc.output_files = super::output::output_files(ctx, raw.output.as_ref())?;
    super::output::channels_to_write(ctx, &sc.output_files, true, sc.channels.len())?;
    let interval = raw.output.as_ref().is_some_and(|o| o.interval.is_some());
    sc.end_forces = super::output::output_end_forces(
        ctx,
        raw.output.as_ref(),
        sc.analysis.force_tolerance.is_some() || interval,
    )?;
    sc.output_interval = super::output_interval::output_interval(ctx, raw.output.as_ref(), &sc)?;
    sc.statistics_after = super::output::statistics_after(ctx, raw.output.as_ref())?;
    super::output::bodies_to_write(ctx, &sc.output_files, sc.bodies.len())?;
    let statics = sc.analysis.kind == AnalysisKind::Static || sc.initial == InitialShape::Static;
    super::output::stiffness_to_write(ctx, &sc.output_files, sc.has_free_bodies(), statics)?;
    Ok(sc)
}

/// The scenario's `[analysis]` with the deck's step (its dtM, or
/// MoorDyn's step from its CFL) as `time_step` where a dynamic analysis
/// gives none, and a note saying so: the step a coupled run of the deck
/// takes.
fn with_deck_step(
    raw: Option<super::raw::RawAnalysis>,
    deck: &crate::moordyn::Deck,
) -> (Option<super::raw::RawAnalysis>, Option<String>) {
    // No [analysis]: the deck's own analysis, static, as the deck alone
    // (super::moordyn::deck_scenario).
    let Some(mut a) = raw else {
        let statics = super::raw::RawAnalysis {
            kind: Some("static".into()),
            ..Default::default()
        };
        return (Some(statics), None);
    };
    // A missing type is a dynamic analysis (scenario/analysis.rs).
    let dynamic = a.kind.as_deref().unwrap_or("dynamic") == "dynamic";
    match (dynamic, a.time_step, deck.time_step()) {
        (true, None, Some(dt)) => {
            a.time_step = Some(dt);
            let note = format!(
                "analysis.time_step: the deck's step, {} s (MoorDyn's dtM, or its step from \
                 its CFL; stancf's step is not bound by it: a larger time_step may do, \
                 within the stable step `check` shows)",
                stancf::error::Sig(dt)
            );
            (Some(a), Some(note))
        }
        _ => (Some(a), None),
    }
}

/// The keys only a scenario that takes a deck has, refused in a TOML
/// system naming the key: `[farm]`, `[[mesh]]`.
pub(super) fn refuse_deck_keys(ctx: &Ctx, raw: &RawScenario) -> Result<(), ScenarioError> {
    if raw.deck.is_some() {
        return Err(ctx.err(
            "deck",
            "sets values of a MoorDyn deck (system.moordyn); a TOML system's [[line_types]], \
             [[lines]] and [[points]] hold their own",
        ));
    }
    if raw.farm.is_some() {
        return Err(ctx.err(
            "farm",
            "gives the turbines of a FAST.Farm deck's Turbine<n> points (system.moordyn); a \
             TOML system's points give their own positions",
        ));
    }
    if !raw.mesh.is_empty() {
        return Err(ctx.err(
            "mesh",
            "gives the mesh of a MoorDyn deck's lines (system.moordyn); a [[lines]] entry takes \
             its own elements and grading",
        ));
    }
    Ok(())
}

/// `system.mbl = { <type name> = N, ... }`: the minimum breaking loads
/// of the deck's line types (a MoorDyn deck gives none), each positive
/// and naming one of its types.
fn breaking_loads(
    ctx: &Ctx,
    mbl: &toml::Table,
    sc: &mut SystemScenario,
) -> Result<(), ScenarioError> {
    for (name, value) in mbl {
        let key = format!("system.mbl.{name}");
        let v = ctx.positive(&key, super::deck_values::number(ctx, &key, value)?)?;
        let names = sc.line_types.iter().map(|t| t.name.as_str());
        let k = super::deck_values::type_named(ctx, &key, name, names)?;
        sc.line_types[k].mbl = Some(v);
    }
    Ok(())
}
