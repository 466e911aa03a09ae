//! The time loop of a run (docs/method.md §11.15, issue 29): a system
//! steps as a single cable does, the step count rounded up and the last
//! step shortened to land on the duration; and every time in a result
//! file is the decimal product of k and the step as written.

use crate::common::*;

/// The time column of a CSV file as written (its first field per row).
fn written_times(path: &std::path::Path) -> Vec<String> {
    let text = std::fs::read_to_string(path).unwrap();
    text.lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap().to_string())
        .collect()
}

/// Checks the run in `out` ended at 0.001 s after 4 steps of 0.0003 s,
/// the last one shortened to 0.0001 s, every step in history.csv.
fn ends_at_a_millisecond(out: &std::path::Path) {
    let summary = read_json(&out.join("summary.json"));
    assert_eq!(summary["steps"], 4, "{summary}");
    assert_eq!(summary["t_final"].as_f64(), Some(0.001), "{summary}");
    assert_eq!(
        written_times(&out.join("history.csv")),
        ["0", "0.0003", "0.0006", "0.0009", "0.001"]
    );
}

/// A rope between a fixed point and a coupled one, 4 m in 8 elements.
fn rope_system(analysis: &str) -> String {
    let mut sc = one_rope("rope", "", ("coupled", [3.9, 0.0, 0.0]), (1, 4.0, 8), "");
    sc.push_str(&format!("[analysis]\n{analysis}\n"));
    sc
}

#[test]
fn a_system_ends_on_its_duration_with_a_shortened_last_step() {
    let d = scratch("time-loop-toml");
    let sc = write_scenario(
        &d,
        "rope.toml",
        &rope_system("type = \"dynamic\"\ntime_step = 0.0003\nduration = 0.001"),
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    ends_at_a_millisecond(&out);
}

#[test]
fn a_moordyn_deck_system_ends_on_its_duration_with_a_shortened_last_step() {
    // A deck gives dtM (and no duration stancf reads: TMax is MoorDyn's
    // driver's); the scenario taking it gives the step and the duration.
    let d = scratch("time-loop-deck");
    let deck = rope_deck("").replace("1.0e-4 dtM", "3.0e-4 dtM");
    std::fs::write(d.join("deck.txt"), deck).unwrap();
    let sc = write_scenario(
        &d,
        "deck.toml",
        "title = \"rope deck\"\n[system]\nmoordyn = \"deck.txt\"\n[analysis]\n\
         type = \"dynamic\"\ntime_step = 0.0003\nduration = 0.001\n",
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    ends_at_a_millisecond(&out);
}

#[test]
fn every_time_a_system_writes_is_k_times_the_step_in_decimals() {
    let d = scratch("time-loop-system-decimals");
    let sc = write_scenario(
        &d,
        "rope.toml",
        // Galerkin steps of 1 ms (P2 at 10 ms, 30 times its stable
        // step, grows, and the energy watchdog stops it at the third).
        &rope_system(
            "type = \"dynamic\"\ntime_scheme = \"galerkin\"\ntime_step = 0.001\nduration = 0.015",
        ),
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let steps: Vec<String> = (0..=15).map(|k| format!("{}", k as f64 / 1000.0)).collect();
    assert_eq!(written_times(&out.join("history.csv")), steps);
    for file in ["points.csv", "tensions.csv", "lines/1/nodes.csv"] {
        for t in written_times(&out.join(file)) {
            assert!(steps.contains(&t), "{file}: {t}");
        }
    }
}

#[test]
fn every_time_a_single_cable_writes_is_k_times_the_step_in_decimals() {
    let d = scratch("time-loop-cable-decimals");
    let sc = write_scenario(&d, "pendulum.toml", &pendulum("pendulum", 0.001, 0.015, 1));
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let steps: Vec<String> = (0..=15).map(|k| format!("{}", k as f64 / 1000.0)).collect();
    assert_eq!(written_times(&out.join("history.csv")), steps);
    for file in ["nodes.csv", "stress.csv", "reactions.csv", "solver.csv"] {
        for t in written_times(&out.join(file)) {
            assert!(steps.contains(&t), "{file}: {t}");
        }
    }
}
