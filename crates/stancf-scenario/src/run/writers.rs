//! The streamed result files of a run (docs/interface.md): history,
//! nodes, stress, reactions, solver diagnostics and ParaView files, each
//! written to its `.partial` name and committed when complete.

use crate::output::{AtomicFile, Dest, Num, TimeGrid};
use stancf::model::SLOT_R_X;
use stancf::observe::{stress_samples, Energies, StressSample};
use stancf::{Model, State};
use std::io::Write;
use std::time::Instant;

/// Stress samples per element in stress.csv (ends included).
pub(crate) const STRESS_POINTS_PER_ELEMENT: usize = 5;

/// The rows of nodes.csv at time t: `t,node,x,y,z,dx_ds,dy_ds,dz_ds`.
pub(crate) fn node_rows(
    w: &mut impl Write,
    t: Num,
    model: &Model,
    state: &State,
) -> std::io::Result<()> {
    for j in 0..model.nodes() {
        let r = model.node_position(&state.e, j);
        let o = model.coordinate(j, SLOT_R_X, 0);
        let d = &state.e[o..o + 3];
        writeln!(
            w,
            "{t},{j},{},{},{},{},{},{}",
            Num(r[0]),
            Num(r[1]),
            Num(r[2]),
            Num(d[0]),
            Num(d[1]),
            Num(d[2])
        )?;
    }
    Ok(())
}

/// The rows of stress.csv at time t: `t,s,axial_stress,curvature,element`.
pub(crate) fn stress_rows(
    w: &mut impl Write,
    t: Num,
    samples: &[StressSample],
) -> std::io::Result<()> {
    for s in samples {
        writeln!(
            w,
            "{t},{},{},{},{}",
            Num(s.s),
            Num(s.axial_stress),
            Num(s.curvature),
            s.element
        )?;
    }
    Ok(())
}

/// The streamed result files of a run.
pub(crate) struct Writers {
    history: AtomicFile,
    nodes: AtomicFile,
    stress: AtomicFile,
    reactions: Option<AtomicFile>,
    /// Per-step solver diagnostics and residual histories (dynamic runs).
    solver: Option<(AtomicFile, AtomicFile)>,
    /// ParaView files (`--vtk`).
    vtk: Option<crate::vtk::VtkWriter>,
    pub(crate) samples: Vec<StressSample>,
    /// Whether history.csv has the `damping_work` column (a cable with
    /// axial damping).
    damping: bool,
    /// How times are written (a dynamic run's: k dt in decimals).
    pub(crate) times: TimeGrid,
}

/// The wall clock the library's Part A / Part B split is timed with.
pub(crate) struct WallClock(pub(crate) Instant);

impl stancf::Clock for WallClock {
    fn seconds(&self) -> f64 {
        self.0.elapsed().as_secs_f64()
    }
}

/// One step's solver diagnostics (solver.csv, convergence.csv).
pub(crate) struct SolverRow<'a> {
    pub(crate) t: f64,
    pub(crate) step: usize,
    pub(crate) report: &'a stancf::solver::NewtonReport,
    pub(crate) residuals: &'a [f64],
    pub(crate) part_a: f64,
    pub(crate) part_b: f64,
    /// Residuals below this are round-off for the rate estimate.
    pub(crate) rate_floor: f64,
}

/// One written state with what the solver says about it.
pub(crate) struct Row<'a> {
    pub(crate) state: &'a State,
    pub(crate) energies: &'a Energies,
    pub(crate) iterations: usize,
    pub(crate) residual: f64,
    pub(crate) increment: f64,
    /// Reactions to write with this row (none at t = 0 of a dynamic run).
    pub(crate) reactions: Option<&'a [(usize, [f64; 3])]>,
    /// Work of moving constraints, of drag and of the axial damping so far.
    pub(crate) constraint_work: f64,
    pub(crate) drag_work: f64,
    pub(crate) damping_work: f64,
}

impl Writers {
    pub(crate) fn create(
        dest: Dest,
        with_reactions: bool,
        with_solver: bool,
        with_vtk: bool,
        with_damping: bool,
    ) -> std::io::Result<Self> {
        let mut w = Writers {
            history: dest.create("history.csv")?,
            nodes: dest.create("nodes.csv")?,
            stress: dest.create("stress.csv")?,
            reactions: if with_reactions {
                Some(dest.create("reactions.csv")?)
            } else {
                None
            },
            solver: if with_solver {
                Some((dest.create("solver.csv")?, dest.create("convergence.csv")?))
            } else {
                None
            },
            vtk: if with_vtk {
                Some(crate::vtk::VtkWriter::create(dest.dir)?)
            } else {
                None
            },
            samples: Vec::new(),
            damping: with_damping,
            times: TimeGrid::default(),
        };
        writeln!(
            w.history.writer(),
            "t,kinetic,strain,gravity,total,iterations,residual,increment,load_potential,constraint_work,drag_work{}",
            if with_damping { ",damping_work" } else { "" }
        )?;
        if let Some((solver, conv)) = w.solver.as_mut() {
            writeln!(
                solver.writer(),
                "t,step,iterations,factorizations,residual,increment,convergence_rate,part_a_s,part_b_s"
            )?;
            writeln!(conv.writer(), "t,step,evaluation,residual")?;
        }
        writeln!(w.nodes.writer(), "t,node,x,y,z,dx_ds,dy_ds,dz_ds")?;
        writeln!(w.stress.writer(), "t,s,axial_stress,curvature,element")?;
        if let Some(r) = w.reactions.as_mut() {
            writeln!(r.writer(), "t,node,fx,fy,fz")?;
        }
        Ok(w)
    }

    /// One written step. Refuses non-finite values (none may reach a file).
    pub(crate) fn write(&mut self, model: &Model, row: &Row) -> std::io::Result<()> {
        let (state, en) = (row.state, row.energies);
        stress_samples(model, state, STRESS_POINTS_PER_ELEMENT, &mut self.samples);
        let finite = state.e.iter().all(|v| v.is_finite())
            && [
                en.kinetic,
                en.strain,
                en.gravity,
                en.load_potential,
                row.residual,
                row.increment,
            ]
            .iter()
            .all(|v| v.is_finite())
            && self
                .samples
                .iter()
                .all(|s| s.axial_stress.is_finite() && s.curvature.is_finite())
            && row
                .reactions
                .unwrap_or(&[])
                .iter()
                .all(|(_, f)| f.iter().all(|v| v.is_finite()));
        if !finite {
            return Err(std::io::Error::new(
                std::io::ErrorKind::InvalidData,
                format!("non-finite result at t = {}", state.t),
            ));
        }
        let t = Num(self.times.time(state.t));
        write!(
            self.history.writer(),
            "{t},{},{},{},{},{},{},{},{},{},{}",
            Num(en.kinetic),
            Num(en.strain),
            Num(en.gravity),
            Num(en.total()),
            row.iterations,
            Num(row.residual),
            Num(row.increment),
            Num(en.load_potential),
            Num(row.constraint_work),
            Num(row.drag_work)
        )?;
        if self.damping {
            write!(self.history.writer(), ",{}", Num(row.damping_work))?;
        }
        writeln!(self.history.writer())?;
        node_rows(self.nodes.writer(), t, model, state)?;
        stress_rows(self.stress.writer(), t, &self.samples)?;
        if let Some(vtk) = self.vtk.as_mut() {
            vtk.write_lines(self.times.time(state.t), &[(model, state)], None)?;
        }
        if let (Some(file), Some(reactions)) = (self.reactions.as_mut(), row.reactions) {
            let w = file.writer();
            for (node, f) in reactions {
                writeln!(w, "{t},{node},{},{},{}", Num(f[0]), Num(f[1]), Num(f[2]))?;
            }
        }
        Ok(())
    }

    /// One step's solver diagnostics.
    pub(crate) fn write_solver(&mut self, row: &SolverRow) -> std::io::Result<()> {
        let Some((solver, conv)) = self.solver.as_mut() else {
            return Ok(());
        };
        let rate = stancf::convergence_rate(row.residuals, row.rate_floor)
            .map(|r| Num(r).to_string())
            .unwrap_or_default();
        let t = Num(self.times.time(row.t));
        let (r, inc) = (row.report.residual, row.report.increment);
        writeln!(
            solver.writer(),
            "{t},{},{},{},{},{},{rate},{},{}",
            row.step,
            row.report.iterations,
            row.report.factorizations,
            Num(if r.is_finite() { r } else { 0.0 }),
            Num(if inc.is_finite() { inc } else { 0.0 }),
            Num(row.part_a),
            Num(row.part_b)
        )?;
        let w = conv.writer();
        for (k, r) in row
            .residuals
            .iter()
            .enumerate()
            .filter(|(_, r)| r.is_finite())
        {
            writeln!(w, "{t},{},{k},{}", row.step, Num(*r))?;
        }
        Ok(())
    }

    pub(crate) fn commit(self) -> std::io::Result<()> {
        if let Some((solver, conv)) = self.solver {
            solver.commit()?;
            conv.commit()?;
        }
        self.history.commit()?;
        self.nodes.commit()?;
        self.stress.commit()?;
        if let Some(r) = self.reactions {
            r.commit()?;
        }
        if let Some(v) = self.vtk {
            v.commit()?;
        }
        Ok(())
    }
}
