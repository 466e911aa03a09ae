//! A MoorDyn deck's waves (docs/interface.md, "Water"): `WaveKin 7`, the
//! components of `wave_frequencies.txt` beside the deck, and `WaveKin` 2
//! and 3, MoorDyn's FFT grids of the same file or of the elevation record
//! `wave_elevation.txt`, become the sea's regular waves (their
//! conversions, docs/method.md §12.1 (W2b)-(W2e), are checked against
//! MoorDyn's formulas in the scenario crate's `moordyn_wave*` tests),
//! superposed with a scenario's `[[water.waves]]`; the modes stancf does
//! not map and bad files are refused naming the deck's line, the file and
//! its line.

use crate::common::*;
use std::path::{Path, PathBuf};

/// MoorDyn's wavekin_7 deck in short: a 410 m line from an anchor on a
/// 50 m bed to a vessel point at the surface, `WaveKin 7`.
const DECK: &str = "MoorDyn v2 deck: one line in waves
---------------------- LINE TYPES -----------------------------------
TypeName   Diam    Mass/m     EA         BA/-zeta    EI   Cd     Ca     CdAx    CaAx
(name)     (m)     (kg/m)     (N)        (N-s/-)     (N-m^2) (-) (-)    (-)     (-)
chain2  13.332E-3  1.1        7.51E6     -0.5        0    1.37    1.0      0.64     1.0
---------------------- POINT PROPERTIES -----------------------------
ID    Type      X       Y       Z       Mass   Volume  CdA    Ca
(#)   (-)       (m)     (m)     (m)     (kg)   (m^3)   (m^2)  (-)
1     Fixed     -400    0.0     -50.0    0      0       0      0
2     Vessel    0.0     0.0     0.0     0      0       0      0
---------------------- LINES ----------------------------------------
ID   LineType   AttachA  AttachB  UnstrLen  NumSegs  LineOutputs
(#)   (name)     (#)      (#)       (m)       (-)     (-)
1     chain2      1        2         410       20      -
---------------------- OPTIONS --------------------------------------
0.001         dtM                  time step (s)
50            WtrDpth              water depth (m)
WAVEKIN
------------------------- need this line ----------------------------
";

/// MoorDyn's wavekin_7 components: a still row, two waves (one heading
/// 1.57 rad), one of no amplitude.
const COMPONENTS: &str = "0.0 0.0 0.0\n0.35 1.0 0.0 0.0\n0.4 0.0 1.0 1.57\n0.6 0.0 0.0\n";

fn deck(mode: &str) -> String {
    DECK.replace(
        "WAVEKIN",
        &format!("{mode}             WaveKin              waves"),
    )
}

/// "line n:" of the deck's WaveKin row.
fn wavekin_line() -> String {
    let n = DECK.lines().position(|l| l == "WAVEKIN").unwrap() + 1;
    format!("line {n}:")
}

/// `stancf check` of the deck (alone, and taken by a scenario that adds
/// a wave) lists its two waves (and the scenario's third) and says
/// where they come from and how the models differ; a dynamic run of it
/// in the waves runs.
#[test]
fn a_decks_summed_wave_components_are_its_waves() {
    let d = scratch("deck-waves");
    std::fs::write(d.join("deck.txt"), deck("7")).unwrap();
    std::fs::write(d.join("wave_frequencies.txt"), COMPONENTS).unwrap();
    let o = stancf(&["check", d.join("deck.txt").to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(so.contains("2 regular Airy wave(s)"), "{so}");
    let note = so
        .lines()
        .find(|l| l.contains("WaveKin 7"))
        .unwrap_or_else(|| panic!("{so}"));
    let at = wavekin_line();
    for words in [
        at.as_str(),
        "2 wave component(s) of",
        "wave_frequencies.txt",
        "Wheeler",
        "within 2 m of z = 0",
        "a static run (the deck alone) does not see the waves",
    ] {
        assert!(note.contains(words), "{words}: {note}");
    }
    let sc = write_scenario(
        &d,
        "waves.toml",
        "[system]\nmoordyn = \"deck.txt\"\n[[water.waves]]\namplitude = 0.5\nperiod = 8.0\n\
         [analysis]\ntype = \"dynamic\"\ntime_scheme = \"galerkin\"\ntime_step = 0.05\nduration = 0.5\n",
    );
    let (so, se) = text(&stancf(&["check", sc.to_str().unwrap()]));
    assert!(so.contains("3 regular Airy wave(s)"), "{so}{se}");
    let o = run_quiet(&sc, &d.join("out"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
}

#[test]
fn a_wave_mode_or_file_stancf_does_not_map_is_refused_naming_its_line() {
    for (name, mode, file, needles) in [
        (
            "fft grid nyquist",
            "2",
            Some("0.0 0 0\n0.3 1.0 0\n"),
            vec!["WaveKin 2 reads", "line 2", "Nyquist"],
        ),
        (
            "fft grid uneven",
            "2",
            Some("0.0 0 0\n0.3 1.0 0\n0.3 1.0 0\n"),
            vec!["WaveKin 2 reads", "line 3", "ascending"],
        ),
        (
            "no elevation record",
            "3",
            Some(COMPONENTS),
            vec!["WaveKin 3 reads", "wave_elevation.txt", "cannot read"],
        ),
        (
            "unknown",
            "5",
            Some(COMPONENTS),
            vec!["WaveKin is 5", "0, 1, 2, 3 and 7"],
        ),
        (
            "no file",
            "7",
            None,
            vec!["wave_frequencies.txt", "cannot read"],
        ),
        (
            "short row",
            "7",
            Some("0.0 0 0\n0.3 1.0\n"),
            vec!["line 2", "3 or 4 numbers"],
        ),
        (
            "word",
            "7",
            Some("0.0 0 0\n0.3 x 0\n"),
            vec!["line 2", "\"x\""],
        ),
        (
            "degrees",
            "7",
            Some("0.0 0 0\n0.3 1 0 90\n"),
            vec!["line 2", "radians"],
        ),
        (
            "negative",
            "7",
            Some("0.0 0 0\n-0.3 1 0\n"),
            vec!["line 2", "negative"],
        ),
        (
            "one row",
            "7",
            Some("0.3 1 0\n"),
            vec!["1 row(s)", "2 at least"],
        ),
        (
            "lifted",
            "7",
            Some("0.0 0 0.4\n0.3 1 0\n"),
            vec!["line 1", "lifts the still surface"],
        ),
    ] {
        let mut files = vec![("deck.txt", deck(mode))];
        if let Some(f) = file {
            files.push(("wave_frequencies.txt", f.to_string()));
        }
        let files: Vec<(&str, &str)> = files.iter().map(|(n, c)| (*n, c.as_str())).collect();
        let mut needles = needles;
        let at = format!("deck.txt: {}", wavekin_line());
        needles.push(&at);
        expect_refusal_beside(
            &format!("deck-waves-{name}"),
            "[system]\nmoordyn = \"deck.txt\"\n[analysis]\ntype = \"static\"\n",
            &files,
            &needles,
        );
    }
}

/// One regular wave of amplitude 1.5 m and period 15 s, eta = 1.5 sin(w t)
/// at the origin, given three ways: as MoorDyn's elevation record
/// (`WaveKin 3`, sampled every 0.25 s, a float MoorDyn reads exactly, for
/// one period), as MoorDyn's FFT grid spectrum (`WaveKin 2`: a = -1.5 i at
/// w = 2 pi / 15 on the grid of that spacing, eta = |a| cos(w t + arg a))
/// and as `[[water.waves]]` (phase 90 deg: cos(90 deg - w t)). The line's
/// end tensions over 3 s of the waves are the same in the three runs to
/// round-off: the series (W2d) of the record is that one wave, its
/// amplitude and phase to 1e-15, and nothing else.
#[test]
fn a_regular_wave_given_as_moordyns_record_or_grid_is_the_same_wave_given_in_toml() {
    let d = scratch("deck-wave-record");
    let omega = 2.0 * std::f64::consts::PI / 15.0;
    let record: String = (0..=60)
        .map(|i| {
            let t = 0.25 * i as f64;
            format!("{t} {}\n", 1.5 * (omega * t).sin())
        })
        .collect();
    std::fs::create_dir_all(d.join("record")).unwrap();
    std::fs::create_dir_all(d.join("grid")).unwrap();
    std::fs::write(d.join("record/wave_elevation.txt"), record).unwrap();
    let spectrum = format!("0 0 0\n{omega} 0 -1.5\n{} 0 0\n", 2.0 * omega);
    std::fs::write(d.join("grid/wave_frequencies.txt"), spectrum).unwrap();
    std::fs::write(d.join("record/deck.txt"), deck("3")).unwrap();
    std::fs::write(d.join("grid/deck.txt"), deck("2")).unwrap();
    std::fs::write(d.join("deck.txt"), deck("0")).unwrap();
    let analysis = "[analysis]\ntype = \"dynamic\"\ntime_scheme = \"galerkin\"\n\
                    time_step = 0.1\nduration = 3.0\n";
    let runs = [
        (
            "record",
            "[system]\nmoordyn = \"record/deck.txt\"\n".to_string(),
        ),
        (
            "grid",
            "[system]\nmoordyn = \"grid/deck.txt\"\n".to_string(),
        ),
        (
            "toml",
            "[system]\nmoordyn = \"deck.txt\"\n[[water.waves]]\namplitude = 1.5\n\
             period = 15.0\nphase = 90.0\n"
                .to_string(),
        ),
    ];
    let outputs = wave_runs(&d, &runs, analysis);
    let toml = &outputs[2].1;
    for ((name, _), (_, run)) in runs.iter().zip(&outputs).take(2) {
        let (worst, swing, first) = apart_from(run, toml);
        assert!(
            worst < 1e-9 * first,
            "{name}: {worst} N apart from the TOML wave's (swing {swing} N of {first} N)"
        );
    }
}

/// Checks and runs each of `runs` (a name, its `[system]` and `[water]`
/// keys) with `analysis`, each `check` listing one wave; each run's
/// `check` output and tensions.csv rows.
fn wave_runs(d: &Path, runs: &[(&str, String)], analysis: &str) -> Vec<(String, Vec<Vec<f64>>)> {
    runs.iter()
        .map(|(name, system)| {
            let sc = write_scenario(d, &format!("{name}.toml"), &format!("{system}{analysis}"));
            let (so, se) = text(&stancf(&["check", sc.to_str().unwrap()]));
            assert!(so.contains("1 regular Airy wave(s)"), "{name}: {so}{se}");
            let out = d.join(format!("out-{name}"));
            let o = run_quiet(&sc, &out, &[]);
            assert_eq!(o.status.code(), Some(0), "{name}: {}", text(&o).1);
            (so, read_tensions(&out.join("tensions.csv")))
        })
        .collect()
}

/// How far `run`'s end tensions are from `toml`'s at the same rows (N),
/// with the swing the waves make in `toml`'s (asserted above 100 N: the
/// waves load the line) and its first tension.
fn apart_from(run: &[Vec<f64>], toml: &[Vec<f64>]) -> (f64, f64, f64) {
    let first = toml[0][6];
    let swing = toml
        .iter()
        .map(|r| (r[6] - first).abs())
        .fold(0.0, f64::max);
    assert!(
        swing > 100.0,
        "the waves move the tension by {swing} N only"
    );
    assert_eq!(run.len(), toml.len());
    let worst = run
        .iter()
        .zip(toml)
        .map(|(a, b)| (a[6] - b[6]).abs())
        .fold(0.0, f64::max);
    (worst, swing, first)
}

/// The same wave as MoorDyn-F's elevation record (its WaterKin file's
/// `WaveKinMod 1`, WaveKinFile `eta.txt` beside the deck, a header line
/// and the rows to 15 s, dtWave 0.25 s, WaveDir 30 deg) over a run of
/// one period, 15 s: MoorDyn-F resamples it over the run (60 samples, a
/// transform size already), and its series (W2d) is that one wave of
/// heading 30 deg. The line's end tensions are those of the wave given
/// in TOML to round-off, and `check` says where the wave comes from.
#[test]
fn a_regular_wave_given_as_moordyn_fs_elevation_record_is_the_same_wave_given_in_toml() {
    let d = scratch("deck-waterkin-record");
    let omega = 2.0 * std::f64::consts::PI / 15.0;
    let record: String = std::iter::once("time elevation\n".to_string())
        .chain((0..=60).map(|i| {
            let t = 0.25 * i as f64;
            format!("{t} {}\n", 1.5 * (omega * t).sin())
        }))
        .collect();
    std::fs::write(d.join("eta.txt"), record).unwrap();
    std::fs::write(
        d.join("waterkin.dat"),
        "MoorDyn Waves and Currents input file\nnotes\n--- WAVES ---\n1 WaveKinMod\n\
         \"eta.txt\" WaveKinFile\n0.25 dtWave\n30 WaveDir\n2 - X\n-400, 0, 41\n0 - Y\n0\n\
         2 - Z\n-50, 0, 26\n--- CURRENT ---\n0 CurrentMod\n",
    )
    .unwrap();
    let row = "\"waterkin.dat\"   WaterKin   water kinematics";
    std::fs::write(d.join("record.txt"), DECK.replace("WAVEKIN", row)).unwrap();
    std::fs::write(d.join("still.txt"), deck("0")).unwrap();
    let analysis = "[analysis]\ntype = \"dynamic\"\ntime_scheme = \"galerkin\"\n\
                    time_step = 0.25\nduration = 15.0\n";
    let runs = [
        ("record", "[system]\nmoordyn = \"record.txt\"\n".to_string()),
        (
            "toml",
            "[system]\nmoordyn = \"still.txt\"\n[[water.waves]]\namplitude = 1.5\n\
             period = 15.0\nheading = 30.0\nphase = 90.0\n"
                .to_string(),
        ),
    ];
    let outputs = wave_runs(&d, &runs, analysis);
    let said = &outputs[0].0;
    assert!(
        said.contains("WaveKinMod 1, 1 wave component(s) heading 30 deg")
            && said.contains("over the run's 15 s"),
        "{said}"
    );
    let (worst, swing, first) = apart_from(&outputs[0].1, &outputs[1].1);
    eprintln!("record against TOML: {worst:e} N of a {swing:e} N swing about {first:e} N");
    assert!(
        worst < 1e-9 * first,
        "{worst} N apart (swing {swing} N of {first} N)"
    );
}

/// Lowe and Langley (OMAE 2006)'s flexible jumper, as MoorDyn's tests
/// give it (a 170 m line of 165 kg/m, EA 5e8 N, EI 1.208e5 N m^2, from
/// (-100, 0, -55) to a top held at (0, 0, -5) m): its static end forces
/// are the paper's, top (11.40, 45.71) kN and bottom (11.40, 24.04) kN in
/// magnitude, to their last digit (0.005 kN: the deck's 68 elements
/// are within 0.02 N of 136). Its `WaveKin 1` (the host sets the waves)
/// does not stop the static run, which sees no waves in either code; a
/// dynamic run of the deck is refused naming the option's line.
#[test]
fn lowe_langley_2006_static_forces() {
    let d = scratch("lowe-langley");
    let deck = copy_fixture(&d, "lowe-langley-2006-jumper-moordyn.txt", "line.txt");
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let rows = read_tensions(&out.join("tensions.csv"));
    let kn = |r: &[f64]| [r[3].abs() / 1e3, r[4].abs() / 1e3, r[5].abs() / 1e3];
    let (bottom, top) = (kn(&rows[0]), kn(&rows[1]));
    for (have, paper) in [(top, [11.40, 0.0, 45.71]), (bottom, [11.40, 0.0, 24.04])] {
        for i in 0..3 {
            assert!(
                (have[i] - paper[i]).abs() <= 0.005,
                "{have:?} kN against the paper's {paper:?}"
            );
        }
    }
    let sc = write_scenario(
        &d,
        "dynamic.toml",
        "[system]\nmoordyn = \"line.txt\"\n[analysis]\ntype = \"dynamic\"\ntime_step = 0.1\n\
         duration = 1.0\n",
    );
    refused_by_check_and_run(
        &sc,
        &d.join("never"),
        &["line 30: option WaveKin is 1", "static equilibrium only"],
        &[],
    );
}

/// examples/lazy-wave.toml with its `[water]` table's `wave_ramp` line
/// replaced by `replacement` (its waves, when `waves` is false, left out)
/// and its analysis of type `kind`.
fn lazy_wave_with(dir: &Path, replacement: &str, waves: bool, kind: &str) -> PathBuf {
    let text = std::fs::read_to_string(repo_file("examples/lazy-wave.toml")).unwrap();
    let mut text = text
        .replace("wave_ramp = 10.0\n", &format!("{replacement}\n"))
        .replace("type = \"dynamic\"\n", &format!("type = \"{kind}\"\n"));
    if !waves {
        let at = text.find("[[water.waves]]").unwrap();
        let end = at + text[at..].find("[analysis]").unwrap();
        text.replace_range(at..end, "");
    }
    write_scenario(dir, "lazy-wave.toml", &text)
}

/// A scenario whose host sets the waves (`water.host_waves`, a deck's
/// `WaveKin 1`; docs/method.md (W2f)-(W2g)): `check` says so and its
/// static equilibrium runs (the host's flow is not in statics); a
/// dynamic run from the command line, which has no host, is refused
/// naming the key and pointing to the coupling API, and so are waves of
/// the scenario's own beside the host's.
#[test]
fn a_scenario_whose_host_sets_the_waves_runs_its_equilibrium_and_steps_only_coupled() {
    let d = scratch("host-waves-toml");
    let statics = lazy_wave_with(&d, "host_waves = true", false, "static");
    let o = stancf(&["check", statics.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert!(
        text(&o).0.contains("set by a host at the nodes"),
        "{}",
        text(&o).0
    );
    let o = run_quiet(&statics, &d.join("out"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let dynamic = lazy_wave_with(&d, "host_waves = true", false, "dynamic");
    refused_by_check_and_run(
        &dynamic,
        &d.join("never"),
        &[
            "water.host_waves",
            "static equilibrium only",
            "stancf_wave_kin_set",
        ],
        &[],
    );
    let both = lazy_wave_with(&d, "host_waves = true", true, "static");
    refused_by_check_and_run(
        &both,
        &d.join("never"),
        &["water.waves", "no waves of its own"],
        &[],
    );
}

/// `water.host_waves` given by a scenario beside a deck whose `WaveKin` is
/// 1 is given twice: refused naming both, as the other `[water]` keys a
/// deck gives. A deck with a rod and `WaveKin 1` runs its static
/// equilibrium (the host's flow, which stancf does not take at rods yet,
/// is not in statics).
#[test]
fn a_hosts_waves_given_twice_are_refused_and_a_rod_decks_statics_run() {
    let d = scratch("host-waves-twice");
    copy_fixture(&d, "lowe-langley-2006-jumper-moordyn.txt", "line.txt");
    let sc = write_scenario(
        &d,
        "twice.toml",
        "[system]\nmoordyn = \"line.txt\"\n[water]\nhost_waves = true\n",
    );
    refused_by_check_and_run(
        &sc,
        &d.join("never"),
        &["water.host_waves", "option WaveKin", "give it in one place"],
        &[],
    );
    let rod = std::fs::read_to_string(repo_file("examples/rod-hanging-moordyn.txt"))
        .unwrap()
        .replacen(
            "150           WtrDpth",
            "1             WaveKin\n150           WtrDpth",
            1,
        );
    let deck = write_scenario(&d, "rod.txt", &rod);
    let o = run_quiet(&deck, &d.join("out"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
}

/// OpenFAST's md_waterkin3 (`SEASTATE WaterKin`: MoorDyn-F interpolates
/// the glue code's SeaState sea at its nodes) takes its sea from a host as
/// `WaveKin 1` does: `check` passes and notes it; alone, its statics are
/// those of the same deck in still water (its WaterKin row removed), to
/// the digit; a dynamic run without a host is refused naming the option
/// and pointing to the coupling API.
#[test]
fn openfasts_md_waterkin3_takes_its_seastate_sea_from_a_host() {
    let d = scratch("seastate");
    let deck = copy_fixture(&d, "md-waterkin3-moordyn.dat", "moordyn.dat");
    let o = stancf(&["check", deck.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let said = format!("{}{}", text(&o).0, text(&o).1);
    assert!(said.contains("WaterKin SEASTATE (line 35)"), "{said}");
    assert!(said.contains("set by a host"), "{said}");
    let o = run_quiet(&deck, &d.join("seastate"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let still: String = std::fs::read_to_string(&deck)
        .unwrap()
        .lines()
        .filter(|row| !row.starts_with("SEASTATE WaterKin"))
        .map(|row| format!("{row}\n"))
        .collect();
    let still = write_scenario(&d, "still.dat", &still);
    let o = run_quiet(&still, &d.join("still"), &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let tensions = |run: &str| std::fs::read_to_string(d.join(run).join("tensions.csv")).unwrap();
    assert_eq!(tensions("seastate"), tensions("still"));
    let dynamic = write_scenario(
        &d,
        "dynamic.toml",
        "[system]\nmoordyn = \"moordyn.dat\"\n[analysis]\ntype = \"dynamic\"\n\
         time_step = 0.01\nduration = 1.0\n",
    );
    refused_by_check_and_run(
        &dynamic,
        &d.join("never"),
        &[
            "line 35",
            "SEASTATE",
            "static equilibrium only",
            "stancf_wave_kin_set",
        ],
        &[],
    );
}
