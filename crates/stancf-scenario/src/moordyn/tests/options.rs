//! OPTIONS: what is accepted, refused by name or as not a number, and
//! which value holds when one is given twice.

use super::*;

#[test]
fn ic_generator_options_are_accepted() {
    let deck = parse(OC4).unwrap();
    for name in ["dtIC", "TmaxIC", "CdScaleIC", "threshIC"] {
        let o = deck.options.iter().find(|o| o.name == name).unwrap();
        assert_eq!(o.kind, OptionKind::Ignored, "{name}");
    }
    let old = "5.0 ICDfac\n0.001 ICthresh\n0 ICTmax\n1 writeLog\n0 WaveKin\n0 Currents\n0.001 dtM";
    let deck = parse(&with("0.001 dtM", old)).unwrap();
    assert_eq!(deck.options.len(), 7);
    assert_eq!(deck.option(SupportedOption::TimeStep), Some(0.001));
}

#[test]
fn an_unknown_option_is_refused_naming_its_line() {
    let text = with("0.001 dtM", "0.001 dtM\n3 WtrDpht water depth");
    let e = error(&text);
    assert_eq!(e.line, Some(line_of(&text, "WtrDpht")));
    assert_eq!(
        e.to_string(),
        format!(
            "line {}: unknown option \"WtrDpht\"",
            line_of(&text, "WtrDpht")
        )
    );
}

/// MoorPy's decks name the water depth `depth` or `WtrDepth` (MoorPy's
/// `System.load` reads both beside `WtrDpth`): taken as WtrDpth.
#[test]
fn moorpys_names_for_the_water_depth_are_the_water_depth() {
    for name in ["depth", "WtrDepth", "WtrDpth"] {
        let text = with("0.001 dtM", &format!("0.001 dtM\n600.0 {name} water depth"));
        let deck = parse(&text).unwrap();
        assert_eq!(
            deck.option(SupportedOption::WaterDepth),
            Some(600.0),
            "{name}"
        );
    }
}

#[test]
fn moordyn_f_water_kinematics_name_a_file_or_a_hosts_seastate() {
    let text = with("0.001 dtM", "0.001 dtM\n\"WaterKin.dat\" WaterKin");
    let deck = parse(&text).unwrap();
    let (file, name, _) = deck.option_text(SupportedOption::WaterKinFile).unwrap();
    assert_eq!((file, name), ("WaterKin.dat", "WaterKin"));
    assert!(!deck.host_sets_waves());
    assert_eq!(deck.sea_from_seastate(), None);
    for row in [
        "SEASTATE WaterKin",
        "\"SeaState\"   WaterKin  - the host's sea",
    ] {
        let text = with("0.001 dtM", &format!("0.001 dtM\n{row}"));
        let deck = parse(&text).unwrap();
        assert_eq!(
            deck.sea_from_seastate(),
            Some(("WaterKin", line_of(&text, row))),
            "{row}"
        );
        assert!(deck.host_sets_waves(), "{row}");
    }
}

#[test]
fn an_option_given_twice_under_two_names_takes_the_last_as_moordyn() {
    let text = with("0.001 dtM", "1025 rho\n0.001 dtM\n1000 WtrDnsty");
    let deck = parse(&text).unwrap();
    let density: Vec<_> = deck
        .options
        .iter()
        .filter(|o| o.kind == OptionKind::Supported(SupportedOption::WaterDensity))
        .collect();
    assert_eq!(density.len(), 1);
    assert_eq!(density[0].value, OptionValue::Number(1000.0));
    assert_eq!(density[0].line, line_of(&text, "WtrDnsty"));
    assert_eq!(
        density[0].replaces,
        Some(("rho".to_string(), line_of(&text, "rho")))
    );
}

#[test]
fn a_supported_option_must_be_a_finite_number() {
    let e = error(&with("0.001 dtM", "fast dtM"));
    assert!(e.message.contains("not a finite number"), "{e}");
    let e = error(&with("0.001 dtM", "-1 dtM"));
    assert!(e.message.contains("must be positive"), "{e}");
}

/// MoorDyn derives its step from CFL only when the deck gives no dtM
/// (MoorDyn2.cpp, `Init`): with a dtM, CFL is accepted and unused;
/// without one, dtM = CFL 2 pi (L / N) sqrt(w / EA), CFL times the
/// natural period of the line's segment (MoorDyn's `NatFreqCFL`): here 11
/// m of 20 kg/m at EA 1e8 N, 0.0309 s; with neither, MoorDyn's CFL of 0.5.
#[test]
fn cfl_is_ignored_beside_a_dtm_and_sets_moordyns_step_without_one() {
    let text = with("0.001 dtM", "0.5 CFL\n0.001 dtM");
    let deck = parse(&text).unwrap();
    let cfl = deck.options.iter().find(|o| o.name == "CFL").unwrap();
    assert_eq!(cfl.kind, OptionKind::Ignored);
    assert_eq!(deck.time_step(), Some(0.001));
    let period = 2.0 * std::f64::consts::PI * 11.0 * (20.0f64 / 1e8).sqrt();
    for (options, cfl) in [("0.25 CFL", 0.25), ("0 writeLog", 0.5)] {
        let deck = parse(&with("0.001 dtM", options)).unwrap();
        assert_eq!(deck.option(SupportedOption::TimeStep), None);
        let dt = deck.time_step().unwrap();
        assert!(
            (dt - cfl * period).abs() < 1e-15,
            "{options}: {dt} {}",
            cfl * period
        );
    }
}

/// tScheme names MoorDyn's integrator: accepted when MoorDyn knows the
/// name (stancf steps with its own; the scenario notes it), refused
/// naming its line when it does not, as MoorDyn refuses it.
#[test]
fn a_moordyn_time_scheme_is_accepted_and_an_unknown_one_refused() {
    for name in [
        "RK4",
        "rk2",
        "Euler",
        "LEuler",
        "Heun",
        "AB3",
        "LAB2",
        "BEuler5",
        "Midpoint2",
        "ACA10",
        "wilson3",
    ] {
        let deck = parse(&with("0.001 dtM", &format!("0.001 dtM\n{name} tScheme"))).unwrap();
        let o = deck.options.iter().find(|o| o.name == "tScheme").unwrap();
        assert_eq!(o.kind, OptionKind::Ignored, "{name}");
    }
    for name in ["RK5", "BEuler", "Newmark", "ACAx"] {
        let text = with("0.001 dtM", &format!("0.001 dtM\n{name} tScheme"));
        let e = error(&text);
        assert_eq!(e.line, Some(line_of(&text, "tScheme")), "{name}");
        assert!(
            e.message.contains("a time scheme MoorDyn does not know"),
            "{e}"
        );
    }
}

#[test]
fn moordyn_fs_separate_friction_coefficients_are_read() {
    let deck = parse(&with("0.001 dtM", "0.001 dtM\n0.3 mu_kT\n0.6 mu_kA")).unwrap();
    assert_eq!(deck.option(SupportedOption::TransverseFriction), Some(0.3));
    assert_eq!(deck.option(SupportedOption::AxialFriction), Some(0.6));
}

/// `SeafloorFile`'s value is a path, kept as written for the scenario to
/// find and read.
#[test]
fn a_seafloor_file_option_keeps_its_path() {
    let text = with(
        "0.001 dtM",
        "0.001 dtM\nMooring/3D_seafloor/bed.txt SeafloorFile 3D seafloor file path",
    );
    let deck = parse(&text).unwrap();
    let found = deck.option_text(SupportedOption::SeafloorFile).unwrap();
    let line = line_of(&text, "SeafloorFile");
    assert_eq!(found, ("Mooring/3D_seafloor/bed.txt", "SeafloorFile", line));
}
