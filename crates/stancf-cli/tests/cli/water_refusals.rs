//! What `[water]` and a deck's water options refuse (docs/interface.md,
//! "Water"): every bad value exits 2 naming its key (or the deck's line,
//! or the current file's line), nothing written; a key both the deck and
//! the scenario give names both.

use crate::common::*;

/// A one-rope system hanging from z = -5 m in water 30 m deep, with
/// `water` (TOML lines) as its `[water]` body and `tables` after it.
fn rope_in_water(water: &str, tables: &str) -> String {
    format!(
        "{}[water]\n{water}\n{tables}",
        one_rope("water", "", ("fixed", [4.0, 0.0, 0.0]), (1, 5.0, 4), "")
    )
}

#[test]
fn every_bad_water_value_is_refused_naming_its_key() {
    let depth = "depth = 30.0\n";
    let cases: Vec<(&str, String, &str)> = vec![
        (
            "no depth",
            rope_in_water("density = 1025.0", ""),
            "water.depth",
        ),
        ("depth", rope_in_water("depth = -1.0", ""), "water.depth"),
        (
            "density",
            rope_in_water("depth = 30.0\ndensity = -1.0", ""),
            "water.density",
        ),
        (
            "wave ramp",
            rope_in_water("depth = 30.0\nwave_ramp = -1.0", ""),
            "water.wave_ramp",
        ),
        (
            "unknown",
            rope_in_water("depth = 30.0\ndepht = 3.0", ""),
            "depht",
        ),
        (
            "stiffness",
            rope_in_water(depth, "[water.seabed]\nstiffness = 0.0"),
            "water.seabed.stiffness",
        ),
        (
            "damping",
            rope_in_water(depth, "[water.seabed]\ndamping = -1.0"),
            "water.seabed.damping",
        ),
        (
            "friction axial",
            rope_in_water(depth, "[water.seabed]\nfriction_axial = -0.1"),
            "water.seabed.friction_axial",
        ),
        (
            "friction transverse",
            rope_in_water(depth, "[water.seabed]\nfriction_transverse = nan"),
            "water.seabed.friction_transverse",
        ),
        (
            "slip velocity",
            rope_in_water(depth, "[water.seabed]\nslip_velocity = 0.0"),
            "water.seabed.slip_velocity",
        ),
        (
            "slope",
            rope_in_water(depth, "[water.seabed]\nslope = [0.1]"),
            "water.seabed.slope",
        ),
        (
            "profile and velocity",
            rope_in_water(
                depth,
                "[water.current]\nprofile = [[0.0, 1.0, 0.0, 0.0]]\nvelocity = [1.0, 0.0, 0.0]",
            ),
            "water.current.velocity",
        ),
        (
            "no profile",
            rope_in_water(depth, "[water.current]\nramp = 1.0"),
            "water.current",
        ),
        (
            "short row",
            rope_in_water(
                depth,
                "[water.current]\nprofile = [[-9.0, 1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]",
            ),
            "water.current.profile[1]",
        ),
        (
            "row out of order",
            rope_in_water(
                depth,
                "[water.current]\nprofile = [[-9.0, 1.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], \
                 [-3.0, 1.0, 0.0, 0.0]]",
            ),
            "water.current.profile[2]",
        ),
        (
            "current ramp",
            rope_in_water(
                depth,
                "[water.current]\nvelocity = [1.0, 0.0, 0.0]\nramp = -2.0",
            ),
            "water.current.ramp",
        ),
        (
            "velocity",
            rope_in_water(depth, "[water.current]\nvelocity = [1.0, 0.0]"),
            "water.current.velocity",
        ),
        (
            "amplitude missing",
            rope_in_water(depth, "[[water.waves]]\nperiod = 8.0"),
            "water.waves[0].amplitude",
        ),
        (
            "amplitude",
            rope_in_water(depth, "[[water.waves]]\namplitude = -1.0\nperiod = 8.0"),
            "water.waves[0].amplitude",
        ),
        (
            "period",
            rope_in_water(
                depth,
                "[[water.waves]]\namplitude = 1.0\nperiod = 8.0\n\
                 [[water.waves]]\namplitude = 1.0\nperiod = 0.0",
            ),
            "water.waves[1].period",
        ),
        (
            "heading",
            rope_in_water(
                depth,
                "[[water.waves]]\namplitude = 1.0\nperiod = 8.0\nheading = inf",
            ),
            "water.waves[0].heading",
        ),
        (
            "phase",
            rope_in_water(
                depth,
                "[[water.waves]]\namplitude = 1.0\nperiod = 8.0\nphase = nan",
            ),
            "water.waves[0].phase",
        ),
        (
            "hs",
            rope_in_water(depth, "[water.jonswap]\ntp = 8.0"),
            "water.jonswap.hs",
        ),
        (
            "tp",
            rope_in_water(depth, "[water.jonswap]\nhs = 2.0\ntp = 0.0"),
            "water.jonswap.tp",
        ),
        (
            "gamma",
            rope_in_water(depth, "[water.jonswap]\nhs = 2.0\ntp = 8.0\ngamma = 8.0"),
            "water.jonswap.gamma",
        ),
        (
            "seed",
            rope_in_water(depth, "[water.jonswap]\nhs = 2.0\ntp = 8.0\nseed = -1"),
            "water.jonswap.seed",
        ),
        (
            "components",
            rope_in_water(depth, "[water.jonswap]\nhs = 2.0\ntp = 8.0\ncomponents = 0"),
            "water.jonswap.components",
        ),
        (
            "gravity",
            rope_in_water(depth, "").replace(
                "[[line_types]]",
                "[system]\ngravity = [0.0, -9.81, 0.0]\n[[line_types]]",
            ),
            "system.gravity",
        ),
        (
            "single cable",
            format!("{IMPACT}[water]\ndepth = 30.0\n"),
            "water",
        ),
    ];
    for (name, scenario, key) in cases {
        expect_input_error(&format!("water-{name}"), &scenario, &[key]);
    }
}

/// A deck of one wire between two fixed points in 150 m of water with
/// `options` added to its OPTIONS and `points` as its third point row
/// (or none).
fn wire_deck(options: &str, point: &str) -> String {
    let deck = std::fs::read_to_string(repo_file("examples/midwater-bridle-moordyn.txt")).unwrap();
    let outputs = "------------------------------- OUTPUTS";
    deck.lines()
        .map(|l| match l {
            l if l.starts_with("3   Free") => format!("{point}\n"),
            l if l.starts_with(outputs) && !options.is_empty() => format!("{options}\n{l}\n"),
            l => format!("{l}\n"),
        })
        .collect()
}

/// The deck beside a scenario that takes it and adds `water` to its
/// `[water]` (none if empty) and `analysis` to its `[analysis]`.
fn deck_scenario(water: &str, analysis: &str) -> String {
    let water = if water.is_empty() {
        String::new()
    } else {
        format!("[water]\n{water}\n")
    };
    format!("[system]\nmoordyn = \"deck.txt\"\n{water}[analysis]\n{analysis}\n")
}

/// The 1-based number of the first line of `text` containing `needle`.
fn line_of(text: &str, needle: &str) -> usize {
    text.lines().position(|l| l.contains(needle)).unwrap() + 1
}

const FREE_POINT: &str = "3   Free      30.0     0.0      -95.0    2000    0.5     0.0    0.0";

#[test]
fn a_water_key_both_the_deck_and_the_scenario_give_is_refused_naming_both() {
    let current = "header\nheader\nheader\n-150.0 0.1 0.0 0.0\n0.0 0.3 0.0 0.0\n";
    for (water, options, key, option) in [
        ("density = 1000.0", "", "water.density", "WtrDnsty"),
        ("depth = 100.0", "", "water.depth", "WtrDpth"),
        (
            "[water.seabed]\nstiffness = 1.0e6",
            "1.0e6 kBot",
            "water.seabed.stiffness",
            "kBot",
        ),
        (
            "[water.seabed]\ndamping = 1.0e5",
            "1.0e5 cBot",
            "water.seabed.damping",
            "cBot",
        ),
        (
            "[water.seabed]\nfriction_transverse = 0.3",
            "0.5 FrictionCoefficient",
            "water.seabed.friction_transverse",
            "FrictionCoefficient",
        ),
        (
            "[water.current]\nvelocity = [0.2, 0.0, 0.0]",
            "1 Currents",
            "water.current",
            "Currents",
        ),
    ] {
        expect_input_error_beside(
            &format!("water-both-{key}"),
            &deck_scenario(water, "type = \"static\""),
            &[
                ("deck.txt", &wire_deck(options, FREE_POINT)),
                ("current_profile.txt", current),
            ],
            &[key, option, "deck.txt"],
        );
    }
}

#[test]
fn a_decks_current_mode_or_file_stancf_does_not_map_is_refused_naming_its_line() {
    let good = "header\nheader\nheader\n-150.0 0.1 0.0 0.0\n0.0 0.3 0.0 0.0\n";
    for (name, options, file, needles) in [
        (
            "dynamic grid without its file",
            "2 Currents",
            good,
            vec![
                "Currents 2 reads",
                "current_profile_dynamic.txt",
                "cannot read",
            ],
        ),
        (
            "4d grid without its file",
            "5 Currents",
            good,
            vec!["Currents 5 reads", "current_profile_4d.txt", "cannot read"],
        ),
        (
            "node mode",
            "3 Currents",
            good,
            vec!["Currents is 3", "not implemented by MoorDyn either"],
        ),
        (
            "short row",
            "1 Currents",
            "h\nh\nh\n-150.0\n",
            vec!["line 4", "at least 2 numbers"],
        ),
        (
            "word",
            "1 Currents",
            "h\nh\nh\n-150.0 0.1 x 0.0\n",
            vec!["line 4", "\"x\""],
        ),
        (
            "order",
            "1 Currents",
            "h\nh\nh\n-150.0 0.1 0 0\n0.0 0.1 0 0\n-3.0 0.1 0 0\n",
            vec!["line 6", "strictly increasing"],
        ),
        ("no rows", "1 Currents", "h\nh\nh\n\n", vec!["no rows"]),
        (
            "waves",
            "5 WaveKin",
            good,
            vec!["WaveKin is 5", "[[water.waves]]"],
        ),
    ] {
        let deck = wire_deck(options, FREE_POINT);
        let option_line = format!("deck.txt: line {}:", line_of(&deck, options));
        let mut needles = needles;
        needles.push(&option_line);
        expect_refusal_beside(
            &format!("water-deck-{name}"),
            &deck_scenario("", "type = \"static\""),
            &[("deck.txt", &deck), ("current_profile.txt", file)],
            &needles,
        );
    }
    expect_refusal_beside(
        "water-deck-no-file",
        &deck_scenario("", "type = \"static\""),
        &[("deck.txt", &wire_deck("1 Currents", FREE_POINT))],
        &["current_profile.txt", "cannot read"],
    );
}

/// A free point's volume, drag (CdA) and added mass (Ca) are the
/// library's point in water (docs/method.md §12.6): the deck runs its
/// statics and its dynamics with them.
#[test]
fn a_free_point_with_drag_and_added_mass_runs_static_and_dynamic() {
    let dynamic = "type = \"dynamic\"\ntime_step = 2.0e-4\nduration = 4.0e-4";
    let with_drag = "3   Free      30.0     0.0      -95.0    2000    0.5     1.0    0.8";
    let d = scratch("water-point-runs");
    std::fs::write(d.join("deck.txt"), wire_deck("", with_drag)).unwrap();
    for analysis in [dynamic, "type = \"static\""] {
        let sc = write_scenario(&d, "deck.toml", &deck_scenario("", analysis));
        let out = d.join("out");
        let _ = std::fs::remove_dir_all(&out);
        let o = run_quiet(&sc, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{analysis}: {}", text(&o).1);
    }
}
