//! MoorDyn's per-line output files, `<deck>_Line<n>.out` (docs/interface.md,
//! "Results of a system"): for a line whose `LineOutputs` flags ask for
//! them, the node and segment quantities stancf computes, written as
//! MoorDyn's `Line::Output` writes them (`Time`, then per flag in its
//! order: `p` `Node<i>px py pz` (m), `K` `Node<i>Ku` (1/m), `v` `Node<i>vx
//! vy vz` (m/s), `U` `Node<i>Ux Uy Uz` (m/s), `D` `Node<i>Dx Dy Dz` (N),
//! `V` `Node<i>Vx Vy Vz` (N),
//! `t` `Seg<j>Te` (N), `c` `Seg<j>cx cy cz` (N), `s` `Seg<j>St` (-), `d`
//! `Seg<j>dSt` (-/s), `b`
//! `Node<i>bx by bz` (N); a units row of `(m)` and the like unless
//! `WriteUnits 0`; the widths and numbers of the main file,
//! `super::moordyn_out`). The nodes are the line's (its NumSegs + 1
//! unless a scenario remeshes it), the segments its elements: a segment's
//! tension, damping force, strain and strain rate are the element's at
//! its middle, EA eps, BA eps_dot t, eps and d|r_x|/dt (MoorDyn's are its
//! segment's, the stretch of the chord between its nodes); a node's water
//! velocity is the sea's
//! there; its hydrodynamic, VIV and seabed forces are the consistent
//! nodal forces of the water's drag and fluid inertia (without buoyancy,
//! as MoorDyn's), of the VIV lift and of the contact (MoorDyn writes no
//! units for `V`; stancf writes `(N)`). `c` of a viscoelastic line (its
//! law's damping) is not computed: no columns, which `check` notes.

use super::moordyn_out::{write_time, write_value, TIME_WIDTH, WIDTH};
use crate::output::{AtomicFile, Dest};
use stancf::model::SLOT_R;
use stancf::observe::{
    element_damping_forces, element_strain_rates, hydrodynamic_nodal_forces, node_bending,
    node_water_velocities, seabed_nodal_forces, stress_samples, viv_nodal_forces, StressSample,
};
use stancf::{Model, State};
use std::io::Write;

use crate::moordyn::WRITTEN_LINE_FLAGS as WRITTEN_FLAGS;

/// A written flag's columns: per node (else per segment), the suffixes
/// of their names (`Node<i>px`, `Seg<j>Te`) and their unit, as MoorDyn's
/// `Line::openoutput` writes them.
fn columns(flag: char) -> (bool, &'static [&'static str], &'static str) {
    match flag {
        'p' => (true, &["px", "py", "pz"], "(m)"),
        'K' => (true, &["Ku"], "(1/m)"),
        'v' => (true, &["vx", "vy", "vz"], "(m/s)"),
        'U' => (true, &["Ux", "Uy", "Uz"], "(m/s)"),
        'D' => (true, &["Dx", "Dy", "Dz"], "(N)"),
        'V' => (true, &["Vx", "Vy", "Vz"], "(N)"),
        't' => (false, &["Te"], "(N)"),
        'c' => (false, &["cx", "cy", "cz"], "(N)"),
        's' => (false, &["St"], "(-)"),
        'd' => (false, &["dSt"], "(-/s)"),
        _ => (true, &["bx", "by", "bz"], "(N)"),
    }
}

/// One line's file.
pub(super) struct LineOut {
    file: AtomicFile,
    /// The written flags the line asks for, in MoorDyn's order.
    flags: Vec<char>,
    at_rest: bool,
}

impl LineOut {
    /// Creates `name` for a line of `model` whose `LineOutputs` are
    /// `flags`, with its header (and units) rows.
    pub(super) fn create(
        dest: &Dest,
        name: &str,
        model: &Model,
        flags: &str,
        units: bool,
        at_rest: bool,
    ) -> std::io::Result<Self> {
        let viscoelastic = model.viscoelastic().is_some();
        let flags: Vec<char> = WRITTEN_FLAGS
            .into_iter()
            .filter(|f| flags.contains(*f) && !(*f == 'c' && viscoelastic))
            .collect();
        let nodes = model.nodes();
        let segments = model.cable.elements;
        let mut file = dest.create(name)?;
        let w = file.writer();
        write!(w, "{:>TIME_WIDTH$}", "Time")?;
        for &f in &flags {
            let (per_node, suffixes, _) = columns(f);
            if per_node {
                for i in 0..nodes {
                    for s in suffixes {
                        write!(w, "{:>WIDTH$}", format!("Node{i}{s}"))?;
                    }
                }
            } else {
                for j in 1..=segments {
                    for s in suffixes {
                        write!(w, "{:>WIDTH$}", format!("Seg{j}{s}"))?;
                    }
                }
            }
        }
        writeln!(w)?;
        if units {
            write!(w, "{:>TIME_WIDTH$}", "(s)")?;
            for &f in &flags {
                let (per_node, suffixes, unit) = columns(f);
                let count = suffixes.len() * if per_node { nodes } else { segments };
                for _ in 0..count {
                    write!(w, "{unit:>WIDTH$}")?;
                }
            }
            writeln!(w)?;
        }
        Ok(LineOut {
            file,
            flags,
            at_rest,
        })
    }

    /// The row of time `t`; `seabed` the line's seabed nodal forces where
    /// the run has them (else computed here), `samples` scratch space.
    pub(super) fn write_row(
        &mut self,
        t: f64,
        model: &Model,
        state: &State,
        seabed: Option<&[[f64; 3]]>,
        samples: &mut Vec<StressSample>,
    ) -> std::io::Result<()> {
        let t = if self.at_rest { 0.0 } else { t };
        let w = self.file.writer();
        write_time(w, t)?;
        let mut value = |v: f64| write_value(w, v);
        let nodes = model.nodes();
        // Three samples per element (its ends and its middle), taken once
        // for both `t` and `s`.
        if self.flags.iter().any(|f| matches!(f, 't' | 's')) {
            stress_samples(model, state, 3, samples);
        }
        for &f in &self.flags {
            match f {
                'p' | 'v' => {
                    let of = if f == 'p' { &state.e } else { &state.v };
                    for i in 0..nodes {
                        let o = model.coordinate(i, SLOT_R, 0);
                        for c in 0..3 {
                            value(of[o + c])?;
                        }
                    }
                }
                'K' => {
                    for b in node_bending(model, state) {
                        value(b.curvature)?;
                    }
                }
                'U' | 'D' => {
                    // At rest (a static run): the steady current's.
                    let at = (!self.at_rest).then_some(t);
                    let at_nodes = if f == 'U' {
                        node_water_velocities(model, state, at)
                    } else {
                        hydrodynamic_nodal_forces(model, state, at)
                    };
                    for u in at_nodes {
                        for c in u {
                            value(c)?;
                        }
                    }
                }
                'V' => {
                    for force in viv_nodal_forces(model, state, t) {
                        for c in force {
                            value(c)?;
                        }
                    }
                }
                'd' => {
                    for rate in element_strain_rates(model, state) {
                        value(rate)?;
                    }
                }
                'c' => {
                    let forces = element_damping_forces(model, state).unwrap_or_default();
                    for force in forces {
                        for c in force {
                            value(c)?;
                        }
                    }
                }
                't' | 's' => {
                    // The axial force (EA eps, or the line's law's), or
                    // eps, at each element's middle.
                    for mid in samples.iter().skip(1).step_by(3) {
                        value(if f == 't' {
                            mid.axial_stress * model.material.area
                        } else {
                            mid.axial_strain
                        })?;
                    }
                }
                _ => {
                    let computed;
                    let forces = match seabed {
                        Some(f) => f,
                        None => {
                            computed = seabed_nodal_forces(model, state);
                            &computed
                        }
                    };
                    for force in forces {
                        for c in force {
                            value(*c)?;
                        }
                    }
                }
            }
        }
        writeln!(w)
    }

    pub(super) fn commit(self) -> std::io::Result<()> {
        self.file.commit()
    }
}
