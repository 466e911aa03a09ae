//! Vortex-induced vibration (docs/method.md §12.7, issue 32): MoorDyn's
//! VIV columns `Cl dF cF` and a TOML line type's `viv` table; Thorsen's
//! catenary riser, MoorDyn's VIV validation case, locks in at the
//! published cross-flow frequency; the notes where the lift runs outside
//! what it is validated for; and the refusals.

use crate::common::*;

/// Thorsen's catenary riser in a 0.2 m/s uniform current (the data of
/// MoorDyn's `viv/viv.txt`), `elements` SAC-2 elements, its line type's
/// VIV keys `viv` and the analysis `analysis`.
fn riser(viv: &str, elements: usize, analysis: &str) -> String {
    format!(
        "title = \"catenary riser in a uniform current\"\n\
         [system]\ngravity = [0.0, 0.0, -9.80665]\n\
         [water]\ndepth = 10.0\ndensity = 1000.0\n\
         [water.seabed]\nstiffness = 1.5e5\ndamping = 1.0e4\nfriction_axial = 0.5\n\
         friction_transverse = 0.5\n\
         [water.current]\nprofile = [[-10.0, 0.2, 0.0, 0.0], [0.0, 0.2, 0.0, 0.0]]\n\
         [[line_types]]\nname = \"riser\"\ndiameter = 0.024\nmass_per_length = 0.69\n\
         ea = 6.66e5\nei = 10.5\nba = 160.729\ncd = 1.2\nca = 2.0\ncdax = 0.08\ncaax = 0.08\n\
         compression = false\n{viv}\n\
         {}{}[[lines]]\nid = 1\ntype = \"riser\"\nlength = 23.71\nelements = {elements}\n\
         a = 1\nb = 2\n[analysis]\n{analysis}",
        toml_point(1, "fixed", [-21.0425, 0.0, -10.0]),
        toml_point(2, "fixed", [0.0, 0.0, -1.0]),
    )
}

const VIV: &str = "viv = { cl = 0.7, df = 0.08, cf = 0.18, averaging_time = 0.05 }";

/// The mean frequency (Hz) of a signal's upward crossings of its mean
/// over the samples `(t, x)`, crossing times linearly interpolated.
fn crossing_frequency(samples: &[(f64, f64)]) -> f64 {
    let mean = samples.iter().map(|s| s.1).sum::<f64>() / samples.len() as f64;
    let ups: Vec<f64> = samples
        .windows(2)
        .filter(|w| w[0].1 < mean && w[1].1 >= mean)
        .map(|w| w[0].0 + (mean - w[0].1) * (w[1].0 - w[0].0) / (w[1].1 - w[0].1))
        .collect();
    assert!(ups.len() > 5, "{} crossings", ups.len());
    (ups.len() - 1) as f64 / (ups[ups.len() - 1] - ups[0])
}

/// Thorsen's catenary riser (MoorDyn's VIV validation case, whose test
/// asserts it) locks in at the published cross-flow response frequency
/// of 1.04 Hz, so its top tension swings at twice that, 2.08 Hz. Run 15 s
/// from its static shape with the Galerkin step at dt = 0.02 s (1/33 of
/// the shedding period d / (cF U)) on 50 elements (100 and 200 give the
/// same frequency to 0.1 %), the top tension's mean-crossing
/// frequency over 8-15 s is within 2 % of 2.08 Hz: the published value
/// has three digits, and the cross-flow frequency varies along the riser
/// by up to 3 % (1.045 to 1.075 Hz at its quarter points, MoorDyn 1.026
/// to 1.049). Its midspan moves across the flow by an RMS of 0.05 to 0.5
/// diameters: locked-in flexible cylinders stay below one diameter
/// (MoorDyn 2.7.2: 0.18).
#[test]
fn thorsen_catenary_riser_locks_in_at_the_published_cross_flow_frequency() {
    let d = scratch("viv-riser");
    let analysis = "type = \"dynamic\"\ninitial = \"static\"\ntime_scheme = \"galerkin\"\n\
                    time_step = 0.02\nduration = 15.0\n";
    let sc = write_scenario(&d, "riser.toml", &riser(VIV, 50, analysis));
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let top: Vec<(f64, f64)> = read_tensions(&out.join("tensions.csv"))
        .iter()
        .filter(|r| r[2] == 1.0 && r[0] >= 8.0 - 1e-9)
        .map(|r| (r[0], r[6]))
        .collect();
    let f = crossing_frequency(&top);
    eprintln!("top tension frequency {f:.4} Hz");
    assert!((f / 2.08 - 1.0).abs() < 0.02, "top tension at {f} Hz");
    let (header, rows) = read_csv(&out.join("lines/1/nodes.csv"));
    let col = |n: &str| header.iter().position(|h| h == n).unwrap();
    let ys: Vec<f64> = rows
        .iter()
        .filter(|r| r[col("node")] == 25.0 && r[col("t")] >= 8.0 - 1e-9)
        .map(|r| r[col("y")])
        .collect();
    let mean = ys.iter().sum::<f64>() / ys.len() as f64;
    let rms = (ys.iter().map(|y| (y - mean).powi(2)).sum::<f64>() / ys.len() as f64).sqrt();
    eprintln!("midspan cross-flow RMS {:.3} D", rms / 0.024);
    assert!(
        (0.05..0.5).contains(&(rms / 0.024)),
        "RMS {} D",
        rms / 0.024
    );
}

/// A deck's `Cl` column alone takes MoorDyn's dF 0.08 and cF 0.18 and an
/// averaging time of 500 dtM; `check` says so. With P2, without a steady
/// current, or with a step longer than 1/30 of the shedding period,
/// `check` notes that VIV is not validated there.
#[test]
fn a_decks_cl_column_turns_the_lift_on_with_moordyns_defaults_and_notes_its_steps() {
    let d = scratch("viv-deck");
    std::fs::write(d.join("deck.txt"), riser_deck("0.7", "0.0001")).unwrap();
    let sc = write_scenario(
        &d,
        "run.toml",
        "[system]\nmoordyn = \"deck.txt\"\n[analysis]\ntype = \"dynamic\"\nduration = 1.0\n\
         time_step = 0.05\n",
    );
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (stdout, stderr) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    assert!(
        stdout.contains("VIV lift Cl 0.7, shedding at f d / |v_n| = cF 0.18 +- dF 0.08, running RMS over 0.05 s"),
        "{stdout}"
    );
    assert!(
        stdout.contains("validated with the Galerkin step, not with P2"),
        "{stdout}"
    );
    assert!(
        stdout.contains("validated in a steady current; this water has none"),
        "{stdout}"
    );
    // In a current, the step is judged against the shedding period.
    let current = "[water.current]\nprofile = [[-10.0, 0.2, 0.0, 0.0], [0.0, 0.2, 0.0, 0.0]]\n";
    let text_with = std::fs::read_to_string(&sc).unwrap() + current;
    std::fs::write(&sc, text_with).unwrap();
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (stdout, stderr) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    assert!(
        stdout.contains(
            "the step 0.05 s is 0.075 of the VIV shedding period d / (cF U) = 0.666667 s"
        ),
        "{stdout}"
    );
    // Cl = 0 is MoorDyn's VIV off.
    std::fs::write(d.join("deck.txt"), riser_deck("0.0", "0.0001")).unwrap();
    let o = stancf(&["check", d.join("deck.txt").to_str().unwrap()]);
    let (stdout, stderr) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    assert!(
        !stdout.contains("VIV") && !stderr.contains("VIV"),
        "{stdout}{stderr}"
    );
}

/// The riser as a MoorDyn deck with `Cl` = `cl` (one VIV column) and
/// `dtM` = `dtm`.
fn riser_deck(cl: &str, dtm: &str) -> String {
    format!(
        "riser\n---- LINE TYPES ----\n\
         TypeName Diam Mass/m EA BA/-zeta EI Cd Ca CdAx CaAx Cl\n(-) (m) (kg/m) (N) (N-s) (N-m^2) (-) (-) (-) (-) (-)\n\
         cable 0.024 0.69 6.66e5 -1 10.5 1.2 2.0 0.08 0.08 {cl}\n\
         ---- POINTS ----\nID Attachment X Y Z M V CdA CA\n(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)\n\
         1 Fixed -21.0425 0 -10 0 0 0 0\n2 Fixed 0 0 -1 0 0 0 0\n\
         ---- LINES ----\nID LineType AttachA AttachB UnstrLen NumSegs Outputs\n(-) (-) (-) (-) (m) (-) (-)\n\
         1 cable 1 2 23.71 40 -\n\
         ---- OPTIONS ----\n{dtm} dtM\n10 WtrDpth\n1000 WtrDnsty\n\
         ---- OUTPUTS ----\nFairTen1\nEND\n"
    )
}

/// Bad VIV input is refused naming the key or the row: a TOML `viv`
/// without its averaging time or with dF not below cF, in air; a deck's
/// dF not below cF.
#[test]
fn bad_viv_input_is_refused_by_key_and_row() {
    let steady = "type = \"static\"\n";
    expect_input_error(
        "viv-no-averaging",
        &riser("viv = { cl = 0.7 }", 10, steady),
        &["line_types[0].viv.averaging_time", "500 of its steps"],
    );
    expect_input_error(
        "viv-range",
        &riser(
            "viv = { cl = 0.7, df = 0.2, cf = 0.18, averaging_time = 0.05 }",
            10,
            steady,
        ),
        &["line_types[0].viv", "dF must be >= 0 and below cF"],
    );
    let in_air = riser(VIV, 10, steady)
        .replace("[water]\ndepth = 10.0\ndensity = 1000.0\n", "")
        .replace("[water.seabed]\nstiffness = 1.5e5\ndamping = 1.0e4\nfriction_axial = 0.5\nfriction_transverse = 0.5\n", "")
        .replace("[water.current]\nprofile = [[-10.0, 0.2, 0.0, 0.0], [0.0, 0.2, 0.0, 0.0]]\n", "");
    expect_input_error("viv-air", &in_air, &["line_types[0].viv", "acts in water"]);
    let d = scratch("viv-deck-range");
    let deck = riser_deck("0.7 0.2 0.18", "0.0001").replace("CaAx Cl\n", "CaAx Cl dF cF\n");
    let path = d.join("deck.txt");
    std::fs::write(&path, deck).unwrap();
    refused_by_check_and_run(
        &path,
        &d.join("never"),
        &["deck.txt", "line 5", "dF < cF"],
        &[],
    );
}
