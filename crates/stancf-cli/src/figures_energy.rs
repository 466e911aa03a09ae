//! The energy figure of a run (cable or system): the kinetic and strain
//! energies and, in a panel of its own, the energy balance, drawn from
//! `history.csv`.

use crate::figure_data::RunInfo;
use crate::plot::{Lines, Panels, Series, PALETTE};
use crate::results::Table;
use std::io;

/// The range max - min of some values (0 for none).
pub(crate) fn range_of(v: &[f64]) -> f64 {
    let (lo, hi) = v
        .iter()
        .fold((f64::MAX, f64::MIN), |(a, b), &x| (a.min(x), b.max(x)));
    if lo <= hi {
        hi - lo
    } else {
        0.0
    }
}

/// Energies against time from `history.csv`. A dynamic run gets two
/// panels: the kinetic and strain energies (and the change of the gravity
/// potential, V - V(0), where it does not dwarf them: a moored line's
/// potential of -8.4e6 J would flatten both), and below them the energy
/// balance E - E(0) - W, with W the work columns the file has
/// (`constraint_work`, `drag_work`, `damping_work`, `water_work`,
/// `seabed_work`), so that the scheme's energy error reads on its own
/// scale; `system`: a system's results, whose file has no work of its
/// coupled points (the balance's legend says that it shows there). A
/// static run gets its strain energy against the load factor.
pub fn energy_figure(history: &Table, info: &RunInfo, system: bool) -> io::Result<Panels> {
    let f = "history.csv";
    let t = history.column(0);
    let x_label = if info.dynamic { "t (s)" } else { "load factor" };
    let strain = history.column(history.need("strain", f)?);
    let mut top = Lines::new(format!("{}: energies", info.title), x_label, "energy (J)");
    let curve = |label: &str, v: &[f64], k: usize| {
        Series::line(
            label,
            t.iter().copied().zip(v.iter().copied()).collect(),
            PALETTE[k],
        )
    };
    if !info.dynamic {
        top.series.push(curve("strain", &strain, 1));
        return Ok(Panels { panels: vec![top] });
    }
    let kinetic = history.column(history.need("kinetic", f)?);
    let total = history.column(history.need("total", f)?);
    let gravity = history.column(history.need("gravity", f)?);
    top.series.push(curve("kinetic", &kinetic, 0));
    top.series.push(curve("strain", &strain, 1));
    let scale = range_of(&kinetic).max(range_of(&strain));
    let v0 = gravity.first().copied().unwrap_or(0.0);
    let change: Vec<f64> = gravity.iter().map(|g| g - v0).collect();
    if gravity.iter().any(|g| *g != 0.0) {
        if range_of(&change) <= 10.0 * scale {
            top.series
                .push(curve("gravity potential change, V - V(0)", &change, 2));
        } else {
            top.title = format!(
                "{}: energies (gravity potential, from {} J, not shown)",
                info.title,
                crate::plot::tick(v0)
            );
        }
    }
    let works: Vec<&str> = [
        "constraint_work",
        "drag_work",
        "damping_work",
        "water_work",
        "seabed_work",
    ]
    .into_iter()
    .filter(|w| history.col(w).is_some())
    .collect();
    let work_columns: Vec<usize> = works.iter().filter_map(|w| history.col(w)).collect();
    let e0 = total.first().copied().unwrap_or(0.0);
    let balance: Vec<f64> = history
        .rows
        .iter()
        .zip(&total)
        .map(|(row, e)| e - e0 - work_columns.iter().map(|&c| row[c]).sum::<f64>())
        .collect();
    let mut bottom = Lines::new(
        "energy balance: E - E(0) - W (E = kinetic + strain + gravity potential)",
        x_label,
        "E - E(0) - W (J)",
    );
    let what = if works.is_empty() {
        "W = 0: no work written".to_string()
    } else {
        format!("W = {}", works.join(" + "))
    };
    let unwritten = if system {
        "; the work of moving coupled points is not written and shows here"
    } else {
        ""
    };
    let mut s = curve(&format!("{what}{unwritten}"), &balance, 6);
    s.color = PALETTE[6];
    bottom.series.push(s);
    Ok(Panels {
        panels: vec![top, bottom],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn history(text: &str) -> Table {
        let dir = std::env::temp_dir().join(format!(
            "stancf-energy-{}-{}",
            std::process::id(),
            text.len()
        ));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("history.csv"), text).unwrap();
        let t = Table::read(&dir.join("history.csv")).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        t
    }

    /// The energy figure shows the kinetic and strain energies and, in a
    /// panel of its own, the balance E - E(0) - W over the work columns the
    /// file has; a gravity potential that would flatten them (a moored
    /// line's -8.4e6 J) is left out and the title says so, one of their
    /// size is shown as its change from the start.
    #[test]
    fn the_energy_figure_shows_kinetic_strain_and_the_balance_not_a_large_potential() {
        let info = RunInfo {
            title: "moored".into(),
            dynamic: true,
            element_lengths: None,
        };
        let h = history(
            "t,kinetic,strain,gravity,total,iterations,residual,water_work,seabed_work\n\
             0,0,1000,-8.4e6,-8399000,0,0,0,0\n\
             1,500,1010,-8.41e6,-8408490,3,0,-2,-1\n",
        );
        let fig = energy_figure(&h, &info, true).unwrap();
        let top: Vec<&str> = fig.panels[0]
            .series
            .iter()
            .map(|s| s.label.as_str())
            .collect();
        assert_eq!(top, ["kinetic", "strain"]);
        assert!(fig.panels[0]
            .title
            .contains("gravity potential, from -8.4e6 J, not shown"));
        let balance = &fig.panels[1].series;
        assert_eq!(balance.len(), 1);
        assert!(balance[0]
            .label
            .starts_with("W = water_work + seabed_work; the work of moving coupled points"));
        // E(1) - E(0) - W = -9490 - (-3).
        assert_eq!(balance[0].points, vec![(0.0, 0.0), (1.0, -9487.0)]);
        let h = history(
            "t,kinetic,strain,gravity,total,iterations,residual,constraint_work,drag_work\n\
             0,0,0,0,0,0,0,0,0\n1,0.01,0,-0.01,0,2,0,0,0\n",
        );
        let fig = energy_figure(&h, &info, false).unwrap();
        let top: Vec<&str> = fig.panels[0]
            .series
            .iter()
            .map(|s| s.label.as_str())
            .collect();
        assert_eq!(
            top,
            ["kinetic", "strain", "gravity potential change, V - V(0)"]
        );
        assert_eq!(
            fig.panels[1].series[0].label,
            "W = constraint_work + drag_work"
        );
    }
}
