//! FAST.Farm's farm-level MoorDyn decks (docs/interface.md, "MoorDyn
//! decks"): points on `Turbine<n>` are on turbine n's platform, at X, Y,
//! Z from the turbine's position, which the FAST.Farm input gives.
//! OpenFAST's regression deck glue-codes/fast-farm/MD_Shared (two
//! turbines 1600 m apart, a shared line through two buoys, four anchor
//! lines).

use crate::common::*;
use std::path::Path;

/// The FAST.Farm input's lines stancf reads (the rest of r-test's
/// FAST.Farm.fstf is wind and wakes).
const FSTF: &str = "------- FAST.Farm for OpenFAST INPUT FILE -------------------------------------------------
Two turbines with shared moorings
--- SHARED MOORING SYSTEM --- [used only for Mod_SharedMoor>0]
\"SharedMooring2.dat\" SharedMoorFile  - Name of file containing shared mooring system input parameters (quoted string)
0.05              DT_Mooring         - Time step for farm-level mooring coupling with each turbine (s)
--- WIND TURBINES ---
2                 NumTurbines        - Number of wind turbines (-) [>=1]
WT_X     WT_Y  WT_Z     WT_FASTInFile                          X0_High  Y0_High  Z0_High  dX_High  dY_High  dZ_High
(m)      (m)   (m)      (string)                               (m)      (m)      (m)      (m)      (m)      (m)
   0.000 0     0.000    \"IEA-15-240-RWT-UMaineSemi_T1.fst\"     -180     -180     -2       15       15       15
1600.000 0     0.000    \"IEA-15-240-RWT-UMaineSemi_T2.fst\"     1420     -180     -2       15       15       15
--- WAKE DYNAMICS ---
";

/// The deck with each `Turbine<n>` point written as a coupled point at
/// the turbine's position (0, 0, 0) or (1600, 0, 0) plus its X, Y, Z.
fn with_coupled_points(deck: &str) -> String {
    deck.lines()
        .map(|l| {
            let w: Vec<&str> = l.split_whitespace().collect();
            match w.get(1).and_then(|a| a.strip_prefix("Turbine")) {
                Some(n) => {
                    let dx = if n == "1" { 0.0 } else { 1600.0 };
                    let x: f64 = w[2].parse().unwrap();
                    format!("{} Coupled {} {} {} 0 0 0 0", w[0], x + dx, w[3], w[4])
                }
                None => l.to_string(),
            }
        })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}

/// The tension column of a static run of `scenario`.
fn tensions(scenario: &Path, out: &Path) -> Vec<f64> {
    let o = run_quiet(scenario, out, &[]);
    assert!(o.status.success(), "{}", text(&o).1);
    read_tensions(&out.join("tensions.csv"))
        .iter()
        .map(|r| r[6])
        .collect()
}

/// The deck beside its FAST.Farm input finds its turbines there, and its
/// equilibrium is the same deck's with the turbines' points held as
/// coupled points where the turbines put them: the same numbers in
/// (0 + x and 1600 + x are exact; an unturned platform adds exact zeros),
/// the same solve, the same tensions to round-off (1e-12). MoorDyn 2.7's
/// initial conditions on the coupled-point deck end within 7e-6 of these
/// (issue 31's note).
#[test]
fn a_fast_farm_deck_finds_its_turbines_beside_it_and_holds_their_points_where_they_put_them() {
    let dir = scratch("fast_farm_beside");
    let deck = copy_fixture(&dir, "fast-farm-shared-mooring.dat", "SharedMooring2.dat");
    write_scenario(&dir, "FAST.Farm.fstf", FSTF);
    let deck_text = std::fs::read_to_string(&deck).unwrap();
    let coupled = write_scenario(&dir, "coupled.dat", &with_coupled_points(&deck_text));
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (stdout, stderr) = text(&o);
    assert!(o.status.success(), "{stderr}");
    let said = stdout.clone() + &stderr;
    for needle in [
        "on 2 turbines' platforms at (0, 0, 0), (1600, 0, 0)",
        "FAST.Farm.fstf, the FAST.Farm input beside the deck",
    ] {
        assert!(said.contains(needle), "{needle}\n{said}");
    }
    let (farm, held) = (
        tensions(&deck, &dir.join("out-farm")),
        tensions(&coupled, &dir.join("out-coupled")),
    );
    assert_eq!(farm.len(), 14);
    for (a, b) in farm.iter().zip(&held) {
        assert!((a - b).abs() <= 1e-12 * b, "{a} N against {b} N");
    }
    // Each turbine is a coupled body in bodies.csv, holding its lines.
    let (header, rows) = read_csv(&dir.join("out-farm/bodies.csv"));
    assert_eq!(header[1], "body");
    assert_eq!(rows.len(), 2);
    assert_eq!((rows[0][2], rows[1][2]), (0.0, 1600.0));
    assert!(rows.iter().all(|r| r[14].abs() > 1e6), "{rows:?}");
}

/// A scenario that takes the deck gives the turbines itself, as numbers
/// or as the FAST.Farm input: the same equilibrium.
#[test]
fn a_scenario_gives_a_fast_farm_decks_turbines_by_position_or_by_its_input() {
    let dir = scratch("fast_farm_scenario");
    copy_fixture(&dir, "fast-farm-shared-mooring.dat", "farm.dat");
    write_scenario(&dir, "layout.fstf", FSTF);
    let by = |name: &str, farm: &str| {
        let sc = write_scenario(
            &dir,
            &format!("{name}.toml"),
            &format!(
                "[system]\nmoordyn = \"farm.dat\"\n[farm]\n{farm}\n[analysis]\ntype = \"static\"\n"
            ),
        );
        tensions(&sc, &dir.join(format!("out-{name}")))
    };
    let given = by("given", "turbines = [[0.0, 0.0, 0.0], [1600.0, 0.0, 0.0]]");
    let read = by("read", "fast_farm = \"layout.fstf\"");
    assert_eq!(given, read);
}

/// Without the turbines' positions, with too few, or with a mass on a
/// turbine's point, the deck is refused naming the line; `[farm]` in a
/// TOML system is refused naming the key.
#[test]
fn a_fast_farm_deck_without_its_turbines_is_refused_by_line() {
    let deck = std::fs::read_to_string(repo_file(
        "crates/stancf-cli/tests/fixtures/fast-farm-shared-mooring.dat",
    ))
    .unwrap();
    expect_refusal_beside(
        "fast_farm_no_turbines",
        "[system]\nmoordyn = \"farm.dat\"\n",
        &[("farm.dat", &deck)],
        &["line 21: point 1 is on turbine 1", "[farm] turbines"],
    );
    expect_refusal_beside(
        "fast_farm_one_turbine",
        "[system]\nmoordyn = \"farm.dat\"\n[farm]\nturbines = [[0.0, 0.0, 0.0]]\n",
        &[("farm.dat", &deck)],
        &["a point is on turbine 2, and farm.turbines gives 1 turbines"],
    );
    let heavy = deck.replacen(
        "1    Turbine1    -58.0      0.0    -14.00      0.00",
        "1    Turbine1    -58.0      0.0    -14.00      5.00",
        1,
    );
    expect_refusal_beside(
        "fast_farm_heavy_point",
        "[system]\nmoordyn = \"farm.dat\"\n",
        &[("farm.dat", &heavy)],
        &["line 21", "point 1 is on turbine 1 with Mass 5"],
    );
    expect_input_error(
        "fast_farm_toml_system",
        "[farm]\nturbines = [[0.0, 0.0, 0.0]]\n[[points]]\nid = 1\ntype = \"fixed\"\n\
         position = [0.0, 0.0, 0.0]\n",
        &["farm", "FAST.Farm deck's Turbine<n> points"],
    );
}
