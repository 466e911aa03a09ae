use super::*;

/// A WaterKin file's lines with `mode` as WaveKinMod and `types` as the
/// grid's X, Y, Z types.
fn settings(mode: &str, file: &str, types: [&str; 3]) -> String {
    format!(
        "MoorDyn Waves and Currents input file\nnotes\n--- WAVES ---\n{mode} WaveKinMod\n\
         {file} WaveKinFile\n0.5 dtWave\n30 WaveDir\n{} - X\n-24, 150, 100\n{} - Y\n-5, 5, 3\n\
         {} - Z\n-600, 0, 61\n--- CURRENT ---\n0 CurrentMod\n",
        types[0], types[1], types[2]
    )
}

fn read(text: &str) -> Result<Option<RecordWaves>, String> {
    read_wave_settings(&text.lines().collect::<Vec<_>>())
}

#[test]
fn the_record_settings_are_read_and_the_hybrid_method_is_refused_by_line() {
    let s = read(&settings("1", "\"waves/eta.txt\"", ["2", "1", "2"])).unwrap();
    assert_eq!(
        s,
        Some(RecordWaves {
            file: "waves/eta.txt".into(),
            dt: 0.5,
            heading_deg: 30.0
        })
    );
    assert_eq!(read(&settings("0", "\"\"", ["2", "2", "2"])).unwrap(), None);
    let e = read(&settings("2", "\"\"", ["2", "2", "2"])).unwrap_err();
    assert!(
        e.starts_with("line 4: WaveKinMod 2: the hybrid method"),
        "{e}"
    );
    let e = read(&settings("1", "\"\"", ["2", "2", "2"])).unwrap_err();
    assert!(
        e.starts_with("line 5: WaveKinMod 1 needs a WaveKinFile"),
        "{e}"
    );
    let e = read(&settings("1", "eta.txt", ["2", "3", "2"])).unwrap_err();
    assert!(e.starts_with("line 10: the Y grid's type is 3"), "{e}");
}

/// WaveKinFile as Fortran's list-directed read takes it: quoted (double
/// or single, spaces kept) or its first word.
#[test]
fn a_quoted_file_name_keeps_its_spaces() {
    assert_eq!(
        quoted_or_first_word("\"my eta.txt\" WaveKinFile"),
        "my eta.txt"
    );
    assert_eq!(quoted_or_first_word("  'eta.txt'   WaveKinFile"), "eta.txt");
    assert_eq!(quoted_or_first_word("eta.txt WaveKinFile"), "eta.txt");
}

/// MoorDyn-F's transform sizes: the next number whose prime factors are
/// at most 23.
#[test]
fn transform_sizes_have_no_prime_factor_above_23() {
    assert_eq!(small_factors_at_least(200), 200);
    assert_eq!(small_factors_at_least(401), 405); // 3^4 5
    assert_eq!(small_factors_at_least(29), 30);
    assert_eq!(small_factors_at_least(47 * 53), 2496); // 2491 to 2495 have 29 to 499; 2^6 3 13
}

/// As MoorDyn-F samples a record: header lines skipped, linear between
/// the rows, still water at the record's last time and after it, padded
/// to an even transform size.
#[test]
fn a_record_is_sampled_as_moordyn_f_samples_it() {
    let text = "elevation record\nt eta\n(s) (m)\n0 0\n1.0 2.0\n2.0, 0.0, 9\n";
    let (samples, t_last) = record_samples(text, 0.5, Some(3.25)).unwrap();
    assert_eq!(t_last, 2.0);
    // ceil(3.25 / 0.5) = 7 samples, 8 even, 2 PSF(4) = 8.
    assert_eq!(samples, [0.0, 1.0, 2.0, 1.0, 0.0, 0.0, 0.0, 0.0]);
    // Without a run length: over the record, to its last time.
    let (samples, _) = record_samples(text, 0.5, None).unwrap();
    assert_eq!(samples, [0.0, 1.0, 2.0, 1.0]);
    let late = "0.5 0\n1 1\n";
    let e = record_samples(late, 0.5, None).unwrap_err();
    assert!(e.contains("line 1: the record starts at 0.5 s"), "{e}");
    // One row: no pair of rows about any sample, a still sea.
    let (samples, _) = record_samples("t eta\n0 1.5\n", 0.5, Some(2.0)).unwrap();
    assert_eq!(samples, [0.0; 4]);
    let broken = "0 0\n1 1\nend\n";
    let e = record_samples(broken, 0.5, None).unwrap_err();
    assert!(e.starts_with("line 3: \"end\""), "{e}");
}

/// A regular wave given as an elevation record over whole periods is the
/// same wave: amplitude, period, heading (WaveDir) and phase, to
/// round-off.
#[test]
fn a_regular_wave_given_as_a_record_is_that_wave() {
    let (a, period, phase_deg): (f64, f64, f64) = (1.5, 10.0, 40.0);
    let mut text = String::from("t eta\n");
    for i in 0..=400 {
        let t = 0.5 * f64::from(i);
        let theta = 2.0 * std::f64::consts::PI * t / period - phase_deg.to_radians();
        text += &format!("{t} {:.17e}\n", a * theta.cos());
    }
    let (samples, _) = record_samples(&text, 0.5, Some(200.0)).unwrap();
    assert_eq!(samples.len(), 400);
    let series = record_series(&samples, 0.5, 30.0, f64::INFINITY);
    assert_eq!(series.waves.len(), 1, "{:?}", series.waves);
    let w = &series.waves[0];
    assert!((w.amplitude - a).abs() < 1e-12, "{w:?}");
    assert!((w.period - period).abs() < 1e-12, "{w:?}");
    assert!((w.phase_deg - phase_deg).abs() < 1e-9, "{w:?}");
    assert_eq!(w.heading_deg, 30.0);
}
