//! The streamed result files of a system (docs/interface.md, "Systems"):
//! `lines/<id>/nodes.csv` and `lines/<id>/stress.csv` in the single
//! cable's columns, `lines/<id>/node_loads.csv` (curvature, bending moment
//! and the seabed's force at every node), `points.csv`, `bodies.csv`,
//! `tensions.csv` and `history.csv`.

use super::channel_values::channel_value;
use super::moordyn_body_out::BodyOut;
use super::moordyn_line_out::LineOut;
use super::moordyn_out::MoorDynOut;
use super::moordyn_rod_out::RodOut;
use super::rods::RodFrame;
use super::rows::SystemRow;
use crate::moordyn::Channel;
use crate::output::{AtomicFile, Dest, Num, TimeGrid};
use crate::run::writers::{node_rows, stress_rows, STRESS_POINTS_PER_ELEMENT};
use crate::scenario::{OutputChannel, OutputFiles};
use stancf::observe::{node_bending, seabed_nodal_forces, stress_samples, StressSample};
use stancf::{Model, State};
use std::io::Write;

/// The files of one line (None: left out by `output.files`).
struct LineFiles {
    nodes: Option<AtomicFile>,
    stress: Option<AtomicFile>,
    node_loads: Option<AtomicFile>,
}

/// What a run writes beyond its tables' fixed columns.
pub(super) struct Extras {
    /// ParaView files (`--vtk`).
    pub vtk: bool,
    /// history.csv's `damping_work` column.
    pub damping: bool,
    /// history.csv's `water_work` and `seabed_work` columns.
    pub water: bool,
    /// A dynamic run (a static one writes its equilibrium as the `.out`'s
    /// row of t = 0).
    pub dynamic: bool,
    /// Each rod's node count (NumSegs + 1), for its MoorDyn file.
    pub rod_nodes: Vec<usize>,
}

/// MoorDyn's `.out` files of a deck, `m`: `<deck>.out` of its OUTPUTS
/// and a `<deck>_Line<n>.out` for each line (of `models`) that asks for
/// one (None for the others).
fn moordyn_files(
    dest: &Dest,
    m: &crate::scenario::MoorDynOutFile,
    channels: &[OutputChannel],
    models: &[&Model],
    (dynamic, rod_nodes): (bool, &[usize]),
) -> std::io::Result<MoorDynFiles> {
    let mut line_outs: Vec<Option<LineOut>> = models.iter().map(|_| None).collect();
    for (i, name, flags) in &m.lines {
        let out = LineOut::create(dest, name, models[*i], flags, m.units, !dynamic)?;
        line_outs[*i] = Some(out);
    }
    let main = match &m.main {
        Some(main) => Some(MoorDynOut::create(dest, main, channels, m.units, !dynamic)?),
        None => None,
    };
    let body_outs = m
        .bodies
        .iter()
        .map(|(b, name)| BodyOut::create(dest, name, *b, m.units, !dynamic))
        .collect::<std::io::Result<_>>()?;
    let rod_outs = m
        .rods
        .iter()
        .map(|(k, name, flags)| {
            let nodes = rod_nodes[*k];
            RodOut::create(dest, name, (*k, nodes), flags, m.units, !dynamic)
        })
        .collect::<std::io::Result<_>>()?;
    Ok(MoorDynFiles {
        main,
        line_outs,
        body_outs,
        rod_outs,
    })
}

/// MoorDyn's output files of a deck: the main file, each line's, each
/// body's, each rod's.
struct MoorDynFiles {
    main: Option<MoorDynOut>,
    line_outs: Vec<Option<LineOut>>,
    body_outs: Vec<BodyOut>,
    rod_outs: Vec<RodOut>,
}

impl MoorDynFiles {
    /// None of them, for a system of `lines` lines.
    fn none(lines: usize) -> Self {
        MoorDynFiles {
            main: None,
            line_outs: (0..lines).map(|_| None).collect(),
            body_outs: Vec::new(),
            rod_outs: Vec::new(),
        }
    }
}

/// channels.csv of a deck's OUTPUTS with its header, and what fills each
/// column (None: no channels, or left out by `output.files`).
type ChannelsFile = Option<(AtomicFile, Vec<(Channel, bool)>)>;

fn channels_file(
    dest: &Dest,
    channels: &[OutputChannel],
    files: &OutputFiles,
) -> std::io::Result<ChannelsFile> {
    if channels.is_empty() || !files.writes("channels.csv") {
        return Ok(None);
    }
    let mut file = dest.create("channels.csv")?;
    let names: Vec<&str> = channels.iter().map(|c| c.name.as_str()).collect();
    writeln!(file.writer(), "t,{}", names.join(","))?;
    Ok(Some((
        file,
        channels.iter().map(|c| (c.channel, c.computed)).collect(),
    )))
}

/// The files of a system run.
pub(super) struct SystemWriters {
    lines: Vec<LineFiles>,
    line_ids: Vec<i64>,
    point_ids: Vec<i64>,
    body_ids: Vec<i64>,
    points: Option<AtomicFile>,
    /// bodies.csv (None: no bodies, or left out by `output.files`).
    bodies: Option<AtomicFile>,
    tensions: Option<AtomicFile>,
    history: Option<AtomicFile>,
    /// channels.csv of a MoorDyn deck's OUTPUTS (none without).
    channels: ChannelsFile,
    /// MoorDyn's `<deck>.out` of the same channels (beside channels.csv).
    moordyn_out: Option<MoorDynOut>,
    /// MoorDyn's `<deck>_Line<n>.out` of each line that asks for one.
    line_outs: Vec<Option<LineOut>>,
    /// MoorDyn's `<deck>_Body<n>.out`, one per deck body, and
    /// `<deck>_Rod<n>.out` of the rods that ask for one.
    body_outs: Vec<BodyOut>,
    rod_outs: Vec<RodOut>,
    /// ParaView files (`--vtk`): one polyline per line.
    vtk: Option<crate::vtk::VtkWriter>,
    samples: Vec<StressSample>,
    /// Whether history.csv has the `damping_work` column.
    damping: bool,
    /// Whether history.csv has the `water_work` and `seabed_work` columns.
    water: bool,
    /// How times are written (a dynamic run's: k dt in decimals).
    pub(super) times: TimeGrid,
    /// The scenario's rods, for `Rod<n>` channels ([`super::rods::frames`]).
    pub(super) rods: Vec<RodFrame>,
    /// The bodies and rods as ParaView draws them (with `--vtk`).
    pub(super) parts: Option<super::vtk_parts::BodyParts>,
    /// The design statistics of the moments written.
    pub(super) statistics: super::statistics::Statistics,
}

impl SystemWriters {
    pub(super) fn create(
        dest: Dest,
        (line_ids, point_ids, body_ids): (&[i64], &[i64], &[i64]),
        (channels, moordyn_out, models): (
            &[OutputChannel],
            Option<&crate::scenario::MoorDynOutFile>,
            &[&Model],
        ),
        files: &OutputFiles,
        extras: Extras,
    ) -> std::io::Result<Self> {
        // A chosen file with its header line (None where left out).
        let table = |path: &str, name: &str, header: &str| -> std::io::Result<_> {
            if !files.writes(name) {
                return Ok(None);
            }
            let mut file = dest.create(path)?;
            writeln!(file.writer(), "{header}")?;
            Ok(Some(file))
        };
        let mut lines = Vec::with_capacity(line_ids.len());
        for id in line_ids {
            let sub = format!("lines/{id}");
            if ["nodes.csv", "stress.csv", "node_loads.csv"]
                .iter()
                .any(|n| files.writes(n))
            {
                std::fs::create_dir_all(dest.dir.join(&sub))?;
            }
            lines.push(LineFiles {
                nodes: table(
                    &format!("{sub}/nodes.csv"),
                    "nodes.csv",
                    "t,node,x,y,z,dx_ds,dy_ds,dz_ds",
                )?,
                stress: table(
                    &format!("{sub}/stress.csv"),
                    "stress.csv",
                    "t,s,axial_stress,curvature,element",
                )?,
                node_loads: table(
                    &format!("{sub}/node_loads.csv"),
                    "node_loads.csv",
                    "t,node,s,curvature,bending_moment,seabed_fx,seabed_fy,seabed_fz",
                )?,
            });
        }
        let points = table(
            "points.csv",
            "points.csv",
            "t,point,x,y,z,vx,vy,vz,fx,fy,fz",
        )?;
        let bodies = if body_ids.is_empty() {
            None
        } else {
            table("bodies.csv", "bodies.csv", super::bodies::HEADER)?
        };
        let tensions = table(
            "tensions.csv",
            "tensions.csv",
            "t,line,end,fx,fy,fz,tension",
        )?;
        let history = table(
            "history.csv",
            "history.csv",
            &format!(
                "t,kinetic,strain,gravity,total,iterations,residual{}{}",
                if extras.damping { ",damping_work" } else { "" },
                if extras.water {
                    ",water_work,seabed_work"
                } else {
                    ""
                }
            ),
        )?;
        let md = match moordyn_out.filter(|_| files.writes("moordyn.out")) {
            Some(m) => {
                let how = (extras.dynamic, &extras.rod_nodes[..]);
                moordyn_files(&dest, m, channels, models, how)?
            }
            None => MoorDynFiles::none(line_ids.len()),
        };
        let channels = channels_file(&dest, channels, files)?;
        Ok(SystemWriters {
            vtk: if extras.vtk {
                Some(crate::vtk::VtkWriter::create(dest.dir)?)
            } else {
                None
            },
            channels,
            moordyn_out: md.main,
            line_outs: md.line_outs,
            body_outs: md.body_outs,
            rod_outs: md.rod_outs,
            lines,
            line_ids: line_ids.to_vec(),
            point_ids: point_ids.to_vec(),
            body_ids: body_ids.to_vec(),
            points,
            bodies,
            tensions,
            history,
            samples: Vec::new(),
            damping: extras.damping,
            water: extras.water,
            times: TimeGrid::default(),
            rods: Vec::new(),
            parts: None,
            statistics: Default::default(),
        })
    }

    /// A point the run added (a line failure's, docs/method.md §11.16):
    /// its rows in points.csv under `id` from the next moment written.
    pub(super) fn add_point(&mut self, id: i64) {
        self.point_ids.push(id);
    }

    /// Writes one moment: its state ([`Self::write_state`]) and its row of
    /// history.csv ([`Self::write_step`]).
    pub(super) fn write(&mut self, row: &SystemRow) -> std::io::Result<()> {
        self.write_state(row)?;
        self.write_step(row)
    }

    /// Writes the state of one moment: every table but history.csv, and
    /// the design statistics. Refuses non-finite values (none may reach a
    /// file): the lines', the points', the bodies', the line ends', the
    /// channels', in this order.
    pub(super) fn write_state(&mut self, row: &SystemRow) -> std::io::Result<()> {
        let t = self.times.time(row.t);
        self.write_lines(row, t)?;
        self.write_points(row, t)?;
        super::bodies::check_finite(&row.bodies, &self.body_ids)
            .map_err(|what| non_finite(&what, row.t))?;
        if let Some(bodies) = self.bodies.as_mut() {
            super::bodies::write_rows(bodies.writer(), t, &self.body_ids, &row.bodies)?;
        }
        for out in &mut self.body_outs {
            out.write_row(t, &row.bodies[out.body])?;
        }
        for out in &mut self.rod_outs {
            out.write_row(t, &self.rods[out.rod].nodes(row))?;
        }
        self.write_tensions(row, t)?;
        if let Some(vtk) = self.vtk.as_mut() {
            vtk.write_lines(t, &row.lines, Some(&self.line_ids))?;
            if let Some(parts) = &self.parts {
                vtk.write_segments(t, &parts.segments(&self.rods, row))?;
            }
        }
        if let Some((file, channels)) = self.channels.as_mut() {
            // None where not computed (the note says why).
            let values = channels
                .iter()
                .map(|(c, computed)| computed.then(|| channel_value(c, row, &self.rods)))
                .collect::<Vec<_>>();
            if values.iter().flatten().any(|v| !v.is_finite()) {
                return Err(non_finite("output channel", row.t));
            }
            let w = file.writer();
            write!(w, "{}", Num(t))?;
            for v in &values {
                match v {
                    Some(v) => write!(w, ",{}", Num(*v))?,
                    None => write!(w, ",")?,
                }
            }
            writeln!(w)?;
            if let Some(out) = self.moordyn_out.as_mut() {
                out.write_row(t, &values)?;
            }
        }
        self.statistics.add(t, row);
        Ok(())
    }

    /// Writes a step's row of history.csv (its energies, Newton's
    /// iterations and residual, the works so far). Refuses non-finite
    /// values: the energies, the residual, the works.
    pub(super) fn write_step(&mut self, row: &SystemRow) -> std::io::Result<()> {
        let [kinetic, strain, gravity] = row.energies;
        if ![kinetic, strain, gravity, row.residual]
            .iter()
            .all(|v| v.is_finite())
        {
            return Err(non_finite("energy or residual", row.t));
        }
        self.write_history(row, self.times.time(row.t))
    }

    /// Each line's nodes.csv, stress.csv and node_loads.csv rows at the
    /// written time `t`.
    fn write_lines(&mut self, row: &SystemRow, t: f64) -> std::io::Result<()> {
        let bad = |what: String| non_finite(&what, row.t);
        let t = Num(t);
        for (i, (model, state)) in row.lines.iter().enumerate() {
            if !state.e.iter().all(|v| v.is_finite()) {
                return Err(bad(format!("position of line {}", self.line_ids[i])));
            }
            let files = &mut self.lines[i];
            if let Some(stress) = files.stress.as_mut() {
                stress_samples(model, state, STRESS_POINTS_PER_ELEMENT, &mut self.samples);
                if !self
                    .samples
                    .iter()
                    .all(|s| s.axial_stress.is_finite() && s.curvature.is_finite())
                {
                    return Err(bad(format!("stress of line {}", self.line_ids[i])));
                }
                stress_rows(stress.writer(), t, &self.samples)?;
            }
            if let Some(nodes) = files.nodes.as_mut() {
                node_rows(nodes.writer(), t, model, state)?;
            }
            if let Some(node_loads) = files.node_loads.as_mut() {
                let computed;
                let bed = match &row.seabed {
                    Some(forces) => &forces[i],
                    None => {
                        computed = seabed_nodal_forces(model, state);
                        &computed
                    }
                };
                node_load_rows(node_loads.writer(), t, model, state, bed)
                    .map_err(|_| bad(format!("node loads of line {}", self.line_ids[i])))?;
            }
            if let Some(out) = self.line_outs[i].as_mut() {
                let bed = row.seabed.as_ref().map(|f| f[i].as_slice());
                out.write_row(t.0, model, state, bed, &mut self.samples)?;
            }
        }
        Ok(())
    }

    /// The rows of points.csv at the written time `t`.
    fn write_points(&mut self, row: &SystemRow, t: f64) -> std::io::Result<()> {
        let t = Num(t);
        for (p, (x, v, f)) in row.points.iter().enumerate() {
            if ![x, v, f].iter().all(|a| a.iter().all(|c| c.is_finite())) {
                let what = format!("state of point {}", self.point_ids[p]);
                return Err(non_finite(&what, row.t));
            }
            let Some(points) = self.points.as_mut() else {
                continue;
            };
            writeln!(
                points.writer(),
                "{t},{},{},{},{},{},{},{},{},{},{}",
                self.point_ids[p],
                Num(x[0]),
                Num(x[1]),
                Num(x[2]),
                Num(v[0]),
                Num(v[1]),
                Num(v[2]),
                Num(f[0]),
                Num(f[1]),
                Num(f[2])
            )?;
        }
        Ok(())
    }

    /// The rows of tensions.csv at the written time `t`.
    fn write_tensions(&mut self, row: &SystemRow, t: f64) -> std::io::Result<()> {
        let t = Num(t);
        for (i, ends) in row.ends.iter().enumerate() {
            for (name, end) in ["A", "B"].iter().zip(ends) {
                let Some(e) = end else { continue };
                if !e.force.iter().all(|c| c.is_finite()) {
                    let what = format!("end force of line {}", self.line_ids[i]);
                    return Err(non_finite(&what, row.t));
                }
                let Some(tensions) = self.tensions.as_mut() else {
                    continue;
                };
                writeln!(
                    tensions.writer(),
                    "{t},{},{name},{},{},{},{}",
                    self.line_ids[i],
                    Num(e.force[0]),
                    Num(e.force[1]),
                    Num(e.force[2]),
                    Num(e.tension())
                )?;
            }
        }
        Ok(())
    }

    /// The row of history.csv at the written time `t` (the energies were
    /// checked finite).
    fn write_history(&mut self, row: &SystemRow, t: f64) -> std::io::Result<()> {
        if !(row.damping_work.is_finite()
            && row.water_work.is_finite()
            && row.seabed_work.is_finite())
        {
            return Err(non_finite("damping, water or seabed work", row.t));
        }
        let Some(history) = self.history.as_mut() else {
            return Ok(());
        };
        let [kinetic, strain, gravity] = row.energies;
        write!(
            history.writer(),
            "{},{},{},{},{},{},{}",
            Num(t),
            Num(kinetic),
            Num(strain),
            Num(gravity),
            Num(kinetic + strain + gravity),
            row.iterations,
            Num(row.residual)
        )?;
        if self.damping {
            write!(history.writer(), ",{}", Num(row.damping_work))?;
        }
        if self.water {
            let (w, b) = (Num(row.water_work), Num(row.seabed_work));
            write!(history.writer(), ",{w},{b}")?;
        }
        writeln!(history.writer())?;
        Ok(())
    }

    pub(super) fn commit(self) -> std::io::Result<()> {
        let files = self
            .lines
            .into_iter()
            .flat_map(|l| [l.nodes, l.stress, l.node_loads]);
        let tables = [
            self.points,
            self.bodies,
            self.tensions,
            self.history,
            self.channels.map(|(f, _)| f),
        ];
        for file in files.chain(tables).flatten() {
            file.commit()?;
        }
        if let Some(out) = self.moordyn_out {
            out.commit()?;
        }
        for out in self.line_outs.into_iter().flatten() {
            out.commit()?;
        }
        for out in self.body_outs {
            out.commit()?;
        }
        for out in self.rod_outs {
            out.commit()?;
        }
        if let Some(vtk) = self.vtk {
            vtk.commit()?;
        }
        Ok(())
    }
}

/// The error of a non-finite value `what` at time `t` (none may reach a
/// file).
fn non_finite(what: &str, t: f64) -> std::io::Error {
    std::io::Error::new(
        std::io::ErrorKind::InvalidData,
        format!("non-finite {what} at t = {t}"),
    )
}

/// The rows of `node_loads.csv` at time `t`: per node its material
/// coordinate, curvature, bending moment EI kappa and the seabed's
/// consistent nodal force `bed`, friction included (docs/interface.md).
/// A non-finite value is an error (InvalidData, for the caller to name).
fn node_load_rows(
    w: &mut impl Write,
    t: Num,
    model: &Model,
    state: &State,
    bed: &[[f64; 3]],
) -> std::io::Result<()> {
    let bending = node_bending(model, state);
    for (j, (b, f)) in bending.iter().zip(bed).enumerate() {
        let values = [b.s, b.curvature, b.bending_moment, f[0], f[1], f[2]];
        if !values.iter().all(|v| v.is_finite()) {
            return Err(std::io::Error::from(std::io::ErrorKind::InvalidData));
        }
        let [s, k, m, fx, fy, fz] = values.map(Num);
        writeln!(w, "{t},{j},{s},{k},{m},{fx},{fy},{fz}")?;
    }
    Ok(())
}
