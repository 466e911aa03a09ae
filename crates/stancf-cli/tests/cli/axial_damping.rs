//! Axial damping from the command line (docs/interface.md; docs/method.md
//! §2.10): `ba` of `[[line_types]]` and MoorDyn decks (a coefficient, or
//! minus a damping ratio converted as MoorDyn converts it), and
//! `[material] axial_damping` of a single cable; the damping's work in
//! history.csv.

use crate::common::{
    expect_input_error, one_rope, pendulum, read_csv, repo_file, run_to, scratch, stancf, text,
    write_scenario,
};

/// A rope of 4 m between two fixed points 4 m apart, falling from straight
/// under gravity (stretching as it sags, ringing axially): `ba` is its
/// line type's.
fn rope(ba: &str, analysis: &str) -> String {
    format!(
        "{}[analysis]\n{analysis}\n",
        one_rope(
            "damped rope",
            &format!("ba = {ba}"),
            ("fixed", [4.0, 0.0, 0.0]),
            (1, 4.0, 12),
            ""
        )
    )
}

const DYNAMIC: &str = "type = \"dynamic\"\ntime_step = 2e-4\nduration = 0.2\n[output]\nevery = 20";

/// The number after `key` in `text` (up to the next space).
fn number_after(text: &str, key: &str) -> f64 {
    let at = text.find(key).unwrap_or_else(|| panic!("{key} in {text}")) + key.len();
    text[at..]
        .split_whitespace()
        .next()
        .unwrap()
        .trim_end_matches([',', ';'])
        .parse()
        .unwrap_or_else(|e| panic!("{key}: {e} in {text}"))
}

/// A damped rope runs dynamically (exit 0): history.csv gains the
/// `damping_work` column, the damping takes energy out (its work never
/// grows, and the energy falls by it: E - E_0 = W_d to 1e-5 of W_d; the
/// P2 step's own energy error here is ~1e-9 of the kinetic energy, 1.3e-10
/// J on the undamped rope, against W_d ~ 4.7e-3 J, 4 % of the kinetic),
/// while the undamped rope keeps its energy and writes no such column.
#[test]
fn a_damped_rope_loses_what_its_damping_dissipates() {
    let d = scratch("damping-rope");
    let mut lost = Vec::new();
    for ba in ["20.0", "0.0"] {
        let sc = write_scenario(&d, &format!("rope-{ba}.toml"), &rope(ba, DYNAMIC));
        let out = d.join(format!("out-{ba}"));
        let o = run_to(&sc, &out);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        let (header, rows) = read_csv(&out.join("history.csv"));
        let total = header.iter().position(|h| h == "total").unwrap();
        let (first, last) = (&rows[0], rows.last().unwrap());
        lost.push(first[total] - last[total]);
        if ba == "0.0" {
            assert_eq!(header.last().unwrap(), "residual", "{header:?}");
            continue;
        }
        assert_eq!(header.last().unwrap(), "damping_work", "{header:?}");
        let w = header.len() - 1;
        for pair in rows.windows(2) {
            assert!(pair[1][w] <= pair[0][w], "damping work never gains");
        }
        let balance = last[total] - first[total] - last[w];
        eprintln!(
            "damped rope: W_d {:.6e} J, balance {balance:.1e} J",
            last[w]
        );
        assert!(balance.abs() < 1e-5 * last[w].abs(), "balance {balance:e}");
    }
    eprintln!(
        "energy lost: damped {:.4e} J, undamped {:.3e} J",
        lost[0], lost[1]
    );
    assert!(lost[0] > 1e3 * lost[1].abs());
}

/// A negative `ba` is minus a damping ratio: `check` reports the BA each
/// line gets, zeta l sqrt(EA w) with its element length l, as MoorDyn
/// does (c = zeta (L / N) sqrt(E rho), BA = c A, by hand here), and the
/// run goes (exit 0).
#[test]
fn a_damping_ratio_in_a_line_type_becomes_moordyns_coefficient() {
    let d = scratch("damping-ratio-toml");
    let sc = write_scenario(&d, "ratio.toml", &rope("-0.5", DYNAMIC));
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let area = std::f64::consts::PI * 0.01 * 0.01 / 4.0;
    let (e, rho) = (2.0e4 / area, 0.08 / area);
    let by_hand = 0.5 * (4.0 / 12.0) * (e * rho).sqrt() * area;
    let ba = number_after(&so, "axial damping BA ");
    assert!(
        (ba / by_hand - 1.0).abs() < 1e-5,
        "{ba} against {by_hand}: {so}"
    );
    assert!(so.contains("damping ratio 0.5"), "{so}");
    let o = run_to(&sc, &d.join("out"));
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
}

/// The shipped midwater deck's wire has BA/-zeta = -0.8: `check` reports
/// MoorDyn's coefficient for each line from its own segment length
/// (UnstrLen / NumSegs: 46 m / 20 and 68 m / 24), and the deck runs.
#[test]
fn a_decks_negative_ba_is_converted_per_line_as_moordyn_does() {
    let deck = repo_file("examples/midwater-bridle-moordyn.txt");
    let o = stancf(&["check", deck.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    let area = std::f64::consts::PI * 0.05 * 0.05 / 4.0;
    let (e, rho) = (2.0e8 / area, 12.0 / area);
    for (id, length, segments) in [(1, 46.0, 20.0), (2, 68.0, 24.0)] {
        let row = so
            .lines()
            .find(|l| l.starts_with(&format!("line {id} ")))
            .unwrap_or_else(|| panic!("line {id}: {so}"));
        let by_hand = 0.8 * (length / segments) * (e * rho).sqrt() * area;
        let ba = number_after(row, "axial damping BA ");
        assert!(
            (ba / by_hand - 1.0).abs() < 1e-5,
            "line {id}: {ba} against {by_hand}"
        );
        assert!(row.contains("unused in statics"), "{row}");
    }
    let d = scratch("damping-deck");
    let o = run_to(&deck, &d.join("out"));
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
}

/// A single cable with `[material] axial_damping`: `check` reports it,
/// the run writes the damping's work in history.csv and summary.json, and
/// the energy falls by it (to 1e-6 of the largest kinetic energy, the
/// P2 step's energy error being ~1e-8 of it here); a negative value is
/// refused naming the key (a damping ratio is for line types).
#[test]
fn a_cables_axial_damping_is_read_reported_and_accounted() {
    let d = scratch("damping-cable");
    let damped = pendulum("damped", 1e-4, 0.05, 10).replace(
        "second_moment = 9.15e-12",
        "second_moment = 9.15e-12\naxial_damping = 0.05",
    );
    let sc = write_scenario(&d, "damped.toml", &damped);
    let o = stancf(&["check", sc.to_str().unwrap()]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(so.contains("axial damping BA"), "{so}");
    let out = d.join("out");
    let o = run_to(&sc, &out);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (header, rows) = read_csv(&out.join("history.csv"));
    assert_eq!(header.last().unwrap(), "damping_work");
    let (total, w) = (4, header.len() - 1);
    let (first, last) = (&rows[0], rows.last().unwrap());
    let kinetic = rows.iter().fold(0.0f64, |m, r| m.max(r[1]));
    let balance = last[total] - first[total] - last[w];
    eprintln!(
        "damped pendulum: W_d = {:.4e} J, largest kinetic energy {kinetic:.4e} J, balance \
         {balance:.1e} J",
        last[w]
    );
    assert!(last[w] < -1e-6 * kinetic, "the damping dissipates");
    assert!(balance.abs() < 1e-6 * kinetic, "{balance:e}");
    let s: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert_eq!(s["energy"]["damping_work"].as_f64().unwrap(), last[w]);

    expect_input_error(
        "damping-negative",
        &pendulum("negative", 1e-4, 0.01, 1).replace(
            "second_moment = 9.15e-12",
            "second_moment = 9.15e-12\naxial_damping = -0.5",
        ),
        &["material.axial_damping", ">= 0", "line_types"],
    );
}
