//! A MoorDyn deck's waves (docs/interface.md, "Water"): `WaveKin 7`, the
//! components of `wave_frequencies.txt` beside the deck, become the sea's
//! regular waves (their conversion, docs/method.md §12.1 (W2b), is
//! checked against MoorDyn's formula in the scenario crate's
//! `moordyn_waves` tests), superposed with a scenario's `[[water.waves]]`;
//! the modes stancf does not map and bad files are refused naming the
//! deck's line, the file and its line.

use crate::common::*;

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
            "external",
            "1",
            Some(COMPONENTS),
            vec!["WaveKin is 1", "externally driven"],
        ),
        (
            "fft grid",
            "2",
            Some(COMPONENTS),
            vec!["WaveKin is 2", "WaveKin 7 sums"],
        ),
        (
            "elevation grid",
            "3",
            Some(COMPONENTS),
            vec!["WaveKin is 3"],
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
