//! `stancf check` of a system scenario: the system built as a run builds
//! it (every refusal of `run` is a refusal here), then what it is: lines
//! with the bending stiffness each is simulated with, bodies, points, the
//! degrees of freedom, and for a dynamic analysis each line's stable P2
//! step.

use crate::scenario::{AnalysisKind, InitialShape, PointType, SystemScenario, Water};
use crate::Failure;
use stancf::error::Sig;
use stancf::system::System;
use std::fmt::Write as _;
use std::path::Path;

pub use crate::system_start::{prepare, simulation, Prepared};

/// `check`'s words on line i: its type, length, mesh, ends, bending
/// stiffness, damping, compression and VIV.
fn line_words(sc: &SystemScenario, system: &System, i: usize) -> String {
    let l = &sc.lines[i];
    let t = &sc.line_types[l.line_type];
    let ei = sc.bending_stiffness(i);
    let bending = if t.ei > 0.0 {
        format!("EI {} N m^2", Sig(ei))
    } else {
        format!(
            "EI = 0 taken as {} N m^2 ({:e} w L^3, docs/method.md §11.7)",
            Sig(ei),
            crate::scenario::EI_FACTOR
        )
    };
    format!(
        "type {}, {} m, {} {} elements ({}), ends {}{} and {}{}; {bending}{}{}{}",
        t.name,
        Sig(l.length),
        l.elements,
        l.element_type.name(),
        element_sizes(&system.lines()[i].model),
        end_name(sc, l.ends[0]),
        clamp_words(l.clamps[0]),
        end_name(sc, l.ends[1]),
        clamp_words(l.clamps[1]),
        damping_note(sc, i),
        if t.compression {
            ""
        } else {
            "; no compression (docs/method.md §2.2)"
        },
        crate::scenario::viv_words(t),
    )
}

/// `check`'s words on how the system's constraints are enforced
/// (docs/interface.md `constraint_method`).
fn route_words(sc: &SystemScenario) -> String {
    match sc.analysis.constraint_method {
        stancf::ConstraintMethod::Elimination => {
            "eliminated: the fixed coordinates leave the steps' unknowns (a system's default; \
             docs/method.md §6.4)"
                .into()
        }
        stancf::ConstraintMethod::Multiplier if sc.has_clamps() => {
            "Lagrange multipliers: a line end is clamped in a direction, which only they \
             hold (docs/method.md §6.10)"
                .into()
        }
        stancf::ConstraintMethod::Multiplier => {
            "Lagrange multipliers (analysis.constraint_method; docs/method.md §6.3)".into()
        }
    }
}

/// Validates the system of `sc` as `run` does and returns the report.
pub fn check_system(path: &Path, sc: &SystemScenario) -> Result<String, Failure> {
    let Prepared {
        system, unbalanced, ..
    } = prepare(path, sc)?;
    let mut r = String::new();
    let mut line = |k: &str, v: String| {
        let _ = writeln!(r, "{k:<28}{v}");
    };
    line(
        "scenario",
        format!(
            "{} (a system)",
            crate::echo::clip(&sc.title, crate::echo::MAX_ECHO)
        ),
    );
    for (i, l) in sc.lines.iter().enumerate() {
        line(&format!("line {}", l.id), line_words(sc, &system, i));
    }
    for (k, v) in crate::check_bodies::body_words(sc) {
        line(&k, v);
    }
    for (k, v) in crate::check_bodies::rod_words(sc) {
        line(&k, v);
    }
    for (k, v) in point_words(sc) {
        line(&k, v);
    }
    for f in &sc.failures {
        let text = crate::scenario::describe_failure(f, sc);
        let (k, v) = text.split_once(": ").expect("failure <id>: ...");
        line(
            k,
            format!("{v}, at a new free point of no mass (docs/method.md §11.16)"),
        );
    }
    if let Some(w) = &sc.water {
        for (k, v) in water_words(w) {
            line(k, v);
        }
    }
    line(
        "analysis",
        match (sc.analysis.kind, sc.initial) {
            (AnalysisKind::Static, _) => match &unbalanced {
                None => "static equilibrium from the lines' catenaries".into(),
                Some(why) => format!(
                    "MoorDyn's start, the lines' catenaries between their points as given ({}), \
                     written at t = 0: no static equilibrium ({why}; docs/method.md §13.7)",
                    crate::system_start::relaxation_words(sc.moordyn_relaxation)
                ),
            },
            (AnalysisKind::Dynamic, InitialShape::Static) => format!(
                "dynamic from the static equilibrium, {} s in steps of {} s",
                Sig(sc.analysis.duration),
                Sig(sc.analysis.time_step)
            ),
            (AnalysisKind::Dynamic, InitialShape::Reference) => format!(
                "dynamic from the lines straight between their points, {} s in steps of {} s",
                Sig(sc.analysis.duration),
                Sig(sc.analysis.time_step)
            ),
            (AnalysisKind::Dynamic, InitialShape::Catenary) => format!(
                "dynamic from the lines' catenaries between their points as given (MoorDyn's \
                 start without initial conditions), {} s in steps of {} s",
                Sig(sc.analysis.duration),
                Sig(sc.analysis.time_step)
            ),
        },
    );
    line(
        "degrees of freedom",
        crate::check_bodies::dof_words(sc, &system),
    );
    line("constraints", route_words(sc));
    line("work", work_words(sc));
    if sc.analysis.kind == AnalysisKind::Dynamic {
        if let Some(step) = stable_step(sc, &system) {
            line(
                "stable step (P2)",
                format!("{} s (the stiffest line's)", Sig(step)),
            );
        }
    } else if sc.analysis.time_step > 0.0 {
        // A deck alone: its step (dtM, or MoorDyn's from its CFL) is a
        // coupled run's.
        let stability = match stable_step(sc, &system) {
            Some(step) => format!("P2, stable below {} s", Sig(step)),
            None => "the Galerkin step, stable at any step".to_string(),
        };
        line(
            "coupled step",
            format!(
                "{} s, the step of a coupled run of this deck ({stability})",
                Sig(sc.analysis.time_step)
            ),
        );
    }
    if let Some(words) = moordyn_files_words(sc) {
        line("moordyn files", words);
    }
    for n in &sc.notes {
        let _ = writeln!(r, "note: {n}");
    }
    Ok(r)
}

/// The MoorDyn files a run of `sc` writes, if any.
fn moordyn_files_words(sc: &SystemScenario) -> Option<String> {
    let out = sc
        .moordyn_out
        .as_ref()
        .filter(|_| sc.output_files.writes("moordyn.out"))?;
    Some(format!(
        "{}, as MoorDyn writes them (docs/interface.md, \"Results of a system\")",
        out.names().join(", ")
    ))
}

/// One line per point: what holds it (a coupled point's motion, a free
/// point's mass, a body point's body and body coordinates) and where it
/// is at t = 0.
fn point_words(sc: &SystemScenario) -> Vec<(String, String)> {
    sc.points
        .iter()
        .map(|p| {
            let kind = match p.kind {
                PointType::Fixed => "fixed".to_string(),
                PointType::Body { body, local } => format!(
                    "on {} body {} at [{}, {}, {}] m in its axes,",
                    sc.bodies[body].type_word(),
                    sc.bodies[body].id,
                    Sig(local[0]),
                    Sig(local[1]),
                    Sig(local[2])
                ),
                PointType::Coupled => match (&p.motion_file, p.motion.table()) {
                    (Some(file), Some(table)) => {
                        let (first, last) = table.span();
                        format!(
                            "coupled, moving along the table {file} ({} rows, t = {} to {} s)",
                            table.len(),
                            Sig(first),
                            Sig(last)
                        )
                    }
                    _ if p.motion.moves() => "coupled, moving".to_string(),
                    _ => "coupled, at rest".to_string(),
                },
                PointType::Free => format!("free, mass {} kg", Sig(p.mass)),
            };
            (
                format!("point {}", p.id),
                format!(
                    "{kind} at [{}, {}, {}] m",
                    Sig(p.position[0]),
                    Sig(p.position[1]),
                    Sig(p.position[2])
                ),
            )
        })
        .collect()
}

/// The elements and steps of a system against the bounds `run` applies
/// ([`crate::work_bounds`]).
fn work_words(sc: &SystemScenario) -> String {
    use crate::scenario::MAX_STEPS;
    use crate::work_bounds::{system_work, MAX_SYSTEM_ELEMENTS};
    let work = system_work(sc);
    let steps = match sc.analysis.kind {
        AnalysisKind::Dynamic => format!(
            "; {} steps (a run takes {:e} without --allow-large)",
            Sig(work.steps),
            MAX_STEPS as f64
        ),
        AnalysisKind::Static => String::new(),
    };
    format!(
        "{} elements in all (a run takes {MAX_SYSTEM_ELEMENTS} without --allow-large){steps}",
        work.elements
    )
}

/// The seabed's shape: its plane, or its grid and file.
fn bed_shape(w: &Water) -> String {
    let b = &w.seabed;
    match &b.bathymetry {
        None => format!(
            "through z = {} m, slope [{}, {}]",
            Sig(-w.depth),
            Sig(b.slope[0]),
            Sig(b.slope[1])
        ),
        Some(file) => {
            let [xs, ys] = file.grid.axes();
            let (lo, hi) = file.grid.height_range();
            format!(
                "a bathymetry of {} x {} nodes, z from {} to {} m, from {}",
                xs.len(),
                ys.len(),
                Sig(lo),
                Sig(hi),
                file.source
            )
        }
    }
}

/// The water as `check` reports it: depth, density and seabed; the
/// current's rows and ramp; the waves, the JONSWAP sea and their ramp.
fn water_words(w: &Water) -> Vec<(&'static str, String)> {
    let b = &w.seabed;
    let mut out = vec![
        (
            "water",
            format!(
                "depth {} m, density {} kg/m^3 (still surface z = 0)",
                Sig(w.depth),
                Sig(w.density)
            ),
        ),
        (
            "seabed",
            format!(
                "{}; kBot {} Pa/m, cBot {} Pa s/m, friction {} axial and {} transverse, \
                 regularized below {} m/s{}",
                bed_shape(w),
                Sig(b.stiffness),
                Sig(b.damping),
                Sig(b.friction_axial),
                Sig(b.friction_transverse),
                Sig(b.slip_velocity),
                static_friction_note(b)
            ),
        ),
    ];
    if let Some(c) = &w.current {
        let speed = |v: [f64; 3]| Sig((v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt());
        let what = match &c.field {
            crate::scenario::CurrentField::Profile(rows) => {
                let (first, last) = (rows[0], rows[rows.len() - 1]);
                format!(
                    "{} rows, z = {} m: {} m/s to z = {} m: {} m/s",
                    rows.len(),
                    Sig(first.z),
                    speed(first.velocity),
                    Sig(last.z),
                    speed(last.velocity)
                )
            }
            crate::scenario::CurrentField::Grid(g) => {
                let [x, y, z, t] = g.axes().clone().map(|a| (a.len(), a[0], a[a.len() - 1]));
                format!(
                    "a grid of {} x {} x {} points (x {} to {} m, y {} to {} m, z {} to {} m) at {} \
                     times from {} to {} s, up to {} m/s",
                    x.0,
                    y.0,
                    z.0,
                    Sig(x.1),
                    Sig(x.2),
                    Sig(y.1),
                    Sig(y.2),
                    Sig(z.1),
                    Sig(z.2),
                    t.0,
                    Sig(t.1),
                    Sig(t.2),
                    Sig(c.fastest())
                )
            }
        };
        out.push((
            "current",
            format!("{what}{}, from {}", ramp_words(c.ramp), c.source),
        ));
    }
    if !w.waves.is_empty() || w.jonswap.is_some() {
        let jonswap = w.jonswap.map_or(String::new(), |j| {
            format!(
                " and a JONSWAP sea of {} components (Hs {} m, Tp {} s, gamma {}, heading {} \
                 deg, seed {})",
                j.components,
                Sig(j.hs),
                Sig(j.tp),
                Sig(j.gamma),
                Sig(j.heading_deg),
                j.seed
            )
        });
        out.push((
            "waves",
            format!(
                "{} regular Airy wave(s){jonswap}{}",
                w.waves.len(),
                ramp_words(w.wave_ramp)
            ),
        ));
    }
    if w.host_waves {
        out.push((
            "waves",
            "set by a host at the nodes and points through the coupling API (MoorDyn's \
             WaveKin 1, docs/method.md (W2f)-(W2g)); still water until it sets them"
                .to_string(),
        ));
    }
    out
}

fn ramp_words(ramp: f64) -> String {
    if ramp > 0.0 {
        format!(", ramped over {} s", Sig(ramp))
    } else {
        String::new()
    }
}

/// The axial damping line i gets, as `check` reports it: nothing without
/// damping; BA (N s), and for a damping ratio (a negative `ba`) the ratio
/// and the element length it was converted with (docs/method.md §2.10,
/// (M36)); a static analysis does not use it.
fn damping_note(sc: &SystemScenario, i: usize) -> String {
    let l = &sc.lines[i];
    let t = &sc.line_types[l.line_type];
    if let Some(dynamic) = &t.ea_dynamic {
        return visco_note(sc, i, dynamic);
    }
    if t.ba == 0.0 {
        return String::new();
    }
    let ba = sc.axial_damping(i);
    let from = if t.ba < 0.0 {
        format!(
            " (damping ratio {} on {} m elements: zeta l sqrt(EA w), MoorDyn's, docs/method.md \
             §2.10)",
            Sig(-t.ba),
            Sig(l.length / l.elements as f64)
        )
    } else {
        String::new()
    };
    let unused = if sc.analysis.kind == AnalysisKind::Static {
        ", unused in statics"
    } else {
        ""
    };
    format!("; axial damping BA {} N s{from}{unused}", Sig(ba))
}

/// A viscoelastic line's law as `check` reports it (docs/method.md §2.11).
fn visco_note(
    sc: &SystemScenario,
    i: usize,
    dynamic: &stancf::element::DynamicStiffness,
) -> String {
    let t = &sc.line_types[sc.lines[i].line_type];
    let k2 = match *dynamic {
        stancf::element::DynamicStiffness::Syrope { ref curves, .. } => {
            let (lo, hi) = curves.tension_range();
            return format!(
                "; Syrope (docs/method.md §2.12): the working curve ({:?}, k1 {}, k2 {}) of \
                 Tmax0 {} N below Tmax, the original curve ({} to {} N) above, dynamic stiffness \
                 {} N + {} x the spring's tension, BA {} N s, BA_D {} N s; statics take the \
                 working curve",
                curves.form,
                Sig(curves.k1),
                Sig(curves.k2),
                Sig(sc.lines[i].tmax0.unwrap_or(f64::NAN)),
                Sig(lo),
                Sig(hi),
                Sig(curves.alpha),
                Sig(curves.beta),
                Sig(sc.axial_damping(i)),
                Sig(t.ba_dynamic)
            );
        }
        stancf::element::DynamicStiffness::Constant(k2) => format!("dynamic EA_D {} N", Sig(k2)),
        stancf::element::DynamicStiffness::MeanLoad { alpha, beta } => format!(
            "dynamic stiffness {} N + {} x the static spring's tension",
            Sig(alpha),
            Sig(beta)
        ),
    };
    format!(
        "; viscoelastic (docs/method.md §2.11): static EA {} N, {k2}, BA {} N s beside the \
         static spring, BA_D {} N s beside the dynamic one; statics take the static EA",
        Sig(t.ea),
        Sig(sc.axial_damping(i)),
        Sig(t.ba_dynamic)
    )
}

/// The largest P2 step every line is stable with (None for the Galerkin
/// step or a quadrature without a limit): the core's
/// [`stancf::system::stable_step`] (docs/method.md §4.6) with the
/// scenario's time quadrature.
pub fn stable_step(sc: &SystemScenario, system: &System) -> Option<f64> {
    let a = &sc.analysis;
    stancf::system::stable_step(system, a.time_scheme, a.time_points, a.time_layers)
}

/// "l m long" on a uniform mesh; a graded or sectioned one's shortest and
/// longest elements and its grading (docs/method.md §1.6).
fn element_sizes(model: &stancf::Model) -> String {
    match model.cable.grading {
        stancf::Grading::Sections(ref s) => format!(
            "{} m to {} m long, in {} sections",
            Sig(model.shortest_element_length()),
            Sig(model.longest_element_length()),
            s.len()
        ),
        stancf::Grading::Geometric { toward, ratio } if !model.cable.grading.is_uniform() => {
            format!(
                "{} m to {} m long, graded toward {} with ratio {}",
                Sig(model.shortest_element_length()),
                Sig(model.longest_element_length()),
                toward.name(),
                Sig(ratio)
            )
        }
        _ => format!("{} m long", Sig(model.element_length(0))),
    }
}

fn end_name(sc: &SystemScenario, end: Option<usize>) -> String {
    match end {
        Some(p) => format!("point {}", sc.points[p].id),
        None => "loose".into(),
    }
}

/// ", clamped along [dx, dy, dz]" (the unit direction) for a clamped end.
fn clamp_words(clamp: Option<[f64; 3]>) -> String {
    let Some(d) = clamp else {
        return String::new();
    };
    let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    format!(
        " (clamped along [{}, {}, {}])",
        Sig(d[0] / n),
        Sig(d[1] / n),
        Sig(d[2] / n)
    )
}

/// What friction holds at a static equilibrium, said where there is
/// friction (docs/method.md §12.2).
fn static_friction_note(b: &crate::scenario::SeabedOptions) -> &'static str {
    if b.friction_axial == 0.0 && b.friction_transverse == 0.0 {
        return "";
    }
    match b.static_friction {
        stancf::system::StaticFriction::Pulled => {
            "; at a static equilibrium each anchored line is pulled out along the bed from an \
             unstretched lay, friction holding it towards its anchor (static_friction = \
             \"pulled\", docs/method.md §12.2)"
        }
        _ => {
            "; at a static equilibrium friction holds nothing, the lines laid as they rest \
             (MoorDyn's; static_friction = \"as_laid\", docs/method.md §12.2)"
        }
    }
}
