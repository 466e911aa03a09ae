//! MoorDyn's main output file (docs/interface.md, "Results of a system"):
//! a deck's OUTPUTS are also written as `<deck>.out`, the file MoorDyn
//! writes, read here as MHKiT's `read_moordyn` reads it (whitespace
//! separated, the first row the names, the second skipped as the units,
//! the first column the index) and checked against channels.csv.

use crate::common::*;
use std::path::Path;

/// The rope deck's OUTPUTS: three tensions and forces, a node's height,
/// and `N4Px`, a name MoorDyn does not know (it skips it; so does the
/// .out, while channels.csv keeps an empty column).
const OUTPUTS: &str = "FairTen1\nAnchTen1\nPoint2FX\nL1N2PZ\nN4Px\n";

/// `rope.txt` (beside it in `d`) run for `duration` s of 0.01 s steps, its
/// coupled point swung.
fn swing(d: &Path, duration: f64) -> std::path::PathBuf {
    write_scenario(
        d,
        "swing.toml",
        &format!(
            "[system]\nmoordyn = \"rope.txt\"\n[[motions]]\npoint = 2\n\
             amplitude = [0.05, 0.0, 0.02]\nperiod = 0.5\n[analysis]\ntype = \"dynamic\"\n\
             time_scheme = \"galerkin\"\ntime_step = 0.01\nduration = {duration}\n"
        ),
    )
}

/// The rows of a `.out` file: its words, row by row.
fn words(path: &Path) -> Vec<Vec<String>> {
    std::fs::read_to_string(path)
        .unwrap_or_else(|e| panic!("{path:?}: {e}"))
        .lines()
        .map(|l| l.split_whitespace().map(String::from).collect())
        .collect()
}

/// A dynamic run of the rope, its coupled point swung: `rope.out` beside
/// channels.csv has MoorDyn's header and units rows, its column widths
/// (10, then 20 per channel), and the same numbers as channels.csv to
/// the 8 digits it writes (7 after the point: |error| <= 5e-8 |v|; the
/// time to 4 decimals); the run again into the same folder replaces it
/// (the layout knows the file by its summary).
#[test]
fn a_decks_outputs_are_also_moordyns_out_file() {
    let d = scratch("moordyn-out");
    std::fs::write(d.join("rope.txt"), rope_deck(OUTPUTS)).unwrap();
    let sc = swing(&d, 0.3);
    let out = d.join("out");
    for _ in 0..2 {
        let o = run_quiet(&sc, &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    }
    let table = words(&out.join("rope.out"));
    assert_eq!(
        table[0],
        ["Time", "FairTen1", "AnchTen1", "Point2FX", "L1N2PZ"]
    );
    assert_eq!(table[1], ["(s)", "N", "N", "N", "m"]);
    let text = std::fs::read_to_string(out.join("rope.out")).unwrap();
    assert!(text.lines().all(|l| l.len() == 10 + 4 * 20), "{text}");
    let (header, rows) = read_csv_with_blanks(&out.join("channels.csv"));
    assert_eq!(header[5], "N4Px");
    assert_eq!(rows.len(), table.len() - 2);
    assert_eq!(rows.len(), 31);
    for (row, written) in rows.iter().zip(&table[2..]) {
        let t: f64 = written[0].parse().unwrap();
        assert!((t - row[0]).abs() <= 5e-5, "{t} against {}", row[0]);
        for c in 1..5 {
            let v: f64 = written[c].parse().unwrap();
            assert!(
                (v - row[c]).abs() <= 5e-8 * row[c].abs(),
                "{}: {v} against {}",
                header[c],
                row[c]
            );
        }
    }
    let swing = rows.iter().map(|r| r[1]).fold(f64::NEG_INFINITY, f64::max)
        - rows.iter().map(|r| r[1]).fold(f64::INFINITY, f64::min);
    assert!(swing > 1.0, "the fairlead tension moves by {swing} N only");
    let summary = read_json(&out.join("summary.json"));
    assert_eq!(summary["moordyn_out"], serde_json::json!(["rope.out"]));
}

/// `WriteUnits 0` leaves out the units row as MoorDyn does, and a static
/// run (a deck alone) writes its equilibrium as MoorDyn's row of t = 0.
#[test]
fn without_units_and_at_rest_the_out_file_is_moordyns_too() {
    let d = scratch("moordyn-out-static");
    let deck = rope_deck(OUTPUTS).replace("50 WtrDpth\n", "50 WtrDpth\n0 WriteUnits\n");
    std::fs::write(d.join("rope.txt"), deck).unwrap();
    let out = d.join("out");
    let o = run_quiet(&d.join("rope.txt"), &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let table = words(&out.join("rope.out"));
    assert_eq!(table.len(), 2, "{table:?}");
    assert_eq!(table[0][0], "Time");
    assert_eq!(table[1][0], "0.0000");
    let (_, rows) = read_csv_with_blanks(&out.join("channels.csv"));
    let fairlead: f64 = table[1][1].parse().unwrap();
    assert!((fairlead - rows[0][1]).abs() <= 5e-8 * rows[0][1]);
}

/// A line's `LineOutputs` flags `pKvUDVtscdb`, every flag MoorDyn knows:
/// `rope_Line1.out` has MoorDyn's columns for each, in MoorDyn's order
/// (positions, curvatures, velocities, water velocities, hydrodynamic
/// and VIV forces of the 5 nodes; tensions, damping forces, strains and
/// strain rates of the 4 segments; seabed forces of the nodes), and
/// `check` notes none as not computed; the positions are nodes.csv's, the
/// tension of each segment is EA times its strain (EA 2e4 N), to the 8
/// digits written, and in still water the rope (Cd and Ca 0, BA 0, no
/// VIV) has no water velocity and no hydrodynamic, VIV or damping force.
#[test]
fn a_lines_output_flags_are_moordyns_line_file() {
    let d = scratch("moordyn-line-out");
    let deck =
        rope_deck("FairTen1\n").replace("1 rope 1 2 1.0 4 -", "1 rope 1 2 1.0 4 pKvUDVtscdb");
    std::fs::write(d.join("rope.txt"), deck).unwrap();
    let (so, se) = text(&stancf(&["check", d.join("rope.txt").to_str().unwrap()]));
    assert!(
        so.contains("moordyn files               rope.out, rope_Line1.out, as MoorDyn"),
        "{so}"
    );
    assert!(!so.contains("LineOutputs"), "{so}{se}");
    let sc = swing(&d, 0.1);
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let table = words(&out.join("rope_Line1.out"));
    let mut header = vec!["Time".to_string()];
    let node = |q: &[&str]| -> Vec<String> {
        (0..5)
            .flat_map(|i| q.iter().map(move |s| format!("Node{i}{s}")))
            .collect()
    };
    let segment = |q: &str| -> Vec<String> { (1..=4).map(|j| format!("Seg{j}{q}")).collect() };
    header.extend(node(&["px", "py", "pz"]));
    header.extend(node(&["Ku"]));
    header.extend(node(&["vx", "vy", "vz"]));
    header.extend(node(&["Ux", "Uy", "Uz"]));
    header.extend(node(&["Dx", "Dy", "Dz"]));
    header.extend(node(&["Vx", "Vy", "Vz"]));
    header.extend(segment("Te"));
    header.extend((1..=4).flat_map(|j| ["cx", "cy", "cz"].map(|q| format!("Seg{j}{q}"))));
    header.extend(segment("St"));
    header.extend(segment("dSt"));
    header.extend(node(&["bx", "by", "bz"]));
    assert_eq!(table[0], header);
    let units: Vec<&str> = std::iter::once("(s)")
        .chain(std::iter::repeat_n("(m)", 15))
        .chain(std::iter::repeat_n("(1/m)", 5))
        .chain(std::iter::repeat_n("(m/s)", 30))
        .chain(std::iter::repeat_n("(N)", 30))
        .chain(std::iter::repeat_n("(N)", 4 + 12))
        .chain(std::iter::repeat_n("(-)", 4))
        .chain(std::iter::repeat_n("(-/s)", 4))
        .chain(std::iter::repeat_n("(N)", 15))
        .collect();
    assert_eq!(table[1], units);
    let at = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (_, nodes) = read_csv(&out.join("lines/1/nodes.csv"));
    assert_eq!(table.len() - 2, 11);
    for (k, row) in table[2..].iter().enumerate() {
        let v: Vec<f64> = row.iter().map(|w| w.parse().unwrap()).collect();
        for i in 0..5 {
            let n = &nodes[5 * k + i];
            for (c, q) in ["px", "py", "pz"].iter().enumerate() {
                let (have, want) = (v[at(&format!("Node{i}{q}"))], n[2 + c]);
                assert!(
                    (have - want).abs() <= 5e-8 * want.abs() + 1e-15,
                    "{have} against {want}"
                );
            }
            for q in ["Ux", "Uy", "Uz", "Dx", "Dy", "Dz", "Vx", "Vy", "Vz"] {
                assert_eq!(v[at(&format!("Node{i}{q}"))], 0.0, "{q}");
            }
        }
        for j in 1..=4 {
            let (tension, strain) = (v[at(&format!("Seg{j}Te"))], v[at(&format!("Seg{j}St"))]);
            assert!(tension > 0.0, "segment {j}: {tension} N");
            for q in ["cx", "cy", "cz"] {
                assert_eq!(v[at(&format!("Seg{j}{q}"))], 0.0, "{q}");
            }
            assert!(
                (tension - 2e4 * strain).abs() <= 2e-7 * tension,
                "{tension} against {strain}"
            );
        }
    }
}

/// The `d` flag's strain rate of each segment is the rate of its strain
/// `s` (both at the element's middle): against the central difference of
/// the written strains of a slow rope (80 kg/m, EA 200 N: an axial period
/// of 1.26 s) swung at 0.5 s, written every 1 ms step, to 1e-3 of the
/// largest rate. The difference's truncation (dt omega)^2 / 6 is below
/// 3e-5 of the rate, and the 8 digits written round the strains by 5e-8
/// of themselves, 2.5e-5 of them per 2 ms. The `c` flag's damping force
/// is BA (5 N s) times that rate along the rope (engineering strain), to
/// the 8 digits written.
#[test]
fn a_segments_strain_rate_is_the_rate_of_its_written_strain() {
    let d = scratch("moordyn-strain-rate");
    let deck = rope_deck("FairTen1\n")
        .replace("1 rope 1 2 1.0 4 -", "1 rope 1 2 1.0 4 csd")
        .replace(
            "rope 0.01 0.08 2.0e4 0 0 0 0 0 0",
            "rope 0.01 80 2.0e2 5 0 0 0 0 0",
        );
    std::fs::write(d.join("rope.txt"), deck).unwrap();
    let sc = write_scenario(
        &d,
        "swing.toml",
        "[system]\nmoordyn = \"rope.txt\"\n[[motions]]\npoint = 2\n\
         amplitude = [0.05, 0.0, 0.02]\nperiod = 0.5\n[analysis]\ntype = \"dynamic\"\n\
         time_scheme = \"galerkin\"\ntime_step = 0.001\nduration = 0.3\n",
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let table = words(&out.join("rope_Line1.out"));
    let rows: Vec<Vec<f64>> = table[2..]
        .iter()
        .map(|r| r.iter().map(|w| w.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 301);
    // Time, the 4 damping forces (x, y, z), the 4 strains, the 4 rates.
    let (strain, rate) = (13, 17);
    let largest = rows
        .iter()
        .flat_map(|r| r[rate..rate + 4].iter().map(|x| x.abs()))
        .fold(0.0, f64::max);
    assert!(largest > 0.1, "the rope hardly stretches: {largest} 1/s");
    for k in 1..rows.len() - 1 {
        let dt = rows[k + 1][0] - rows[k - 1][0];
        for j in 0..4 {
            let difference = (rows[k + 1][strain + j] - rows[k - 1][strain + j]) / dt;
            let r = rows[k][rate + j];
            assert!(
                (r - difference).abs() <= 1e-3 * largest,
                "t = {}, segment {}: {r} against {difference}",
                rows[k][0],
                j + 1
            );
            let c = &rows[k][1 + 3 * j..4 + 3 * j];
            let damping = (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]).sqrt();
            assert!(
                (damping - 5.0 * r.abs()).abs() <= 1e-7 * 5.0 * largest,
                "segment {}: {damping} N against BA |{r}|",
                j + 1
            );
        }
    }
}

/// MoorDyn writes no output file under `disableOutput 1`, and opens a
/// line's file only for the flags `pvUDVKctsd` (`b` alone opens none):
/// neither does stancf; channels.csv is stancf's own and stays.
#[test]
fn disabled_outputs_and_a_seabed_flag_alone_write_no_moordyn_files() {
    let d = scratch("moordyn-out-disabled");
    let run = |name: &str, deck: String| {
        std::fs::write(d.join(format!("{name}.txt")), deck).unwrap();
        let out = d.join(name);
        let o = run_quiet(&d.join(format!("{name}.txt")), &out, &[]);
        assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
        names(&out)
    };
    let disabled = rope_deck(OUTPUTS)
        .replace("1 rope 1 2 1.0 4 -", "1 rope 1 2 1.0 4 pt")
        .replace("50 WtrDpth\n", "50 WtrDpth\n1 disableOutput\n");
    let files = run("off", disabled);
    assert!(files.contains(&"channels.csv".to_string()));
    assert!(!files.iter().any(|f| f.ends_with(".out")), "{files:?}");
    let seabed = rope_deck("").replace("1 rope 1 2 1.0 4 -", "1 rope 1 2 1.0 4 b");
    let files = run("bed", seabed);
    assert!(!files.iter().any(|f| f.ends_with(".out")), "{files:?}");
}

/// A deck's body gets MoorDyn's `<deck>_Body<n>.out` (MoorDyn-C opens one
/// for every body): its header and units rows as MoorDyn writes them,
/// tab-separated, and each written time's reference point and roll,
/// pitch, yaw as bodies.csv has them, to the six significant digits of
/// C++'s default format (|error| <= 5e-6 |v|).
#[test]
fn a_decks_body_gets_moordyns_body_file() {
    let d = scratch("moordyn-body-out");
    std::fs::write(d.join("body.txt"), body_deck("", "", "Body1PZ\n")).unwrap();
    let sc = write_scenario(
        &d,
        "drop.toml",
        "[system]\nmoordyn = \"body.txt\"\n[analysis]\ntype = \"dynamic\"\n\
         time_scheme = \"galerkin\"\ntime_step = 0.05\nduration = 0.5\ninitial = \"reference\"\n",
    );
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let raw = std::fs::read_to_string(out.join("body_Body1.out")).unwrap();
    let mut lines = raw.lines();
    assert_eq!(lines.next(), Some("Time\t x\ty\tz\troll\tpitch\tyaw"));
    assert_eq!(
        lines.next(),
        Some("(s)\t (m)\t(m)\t(m)\t(deg)\t(deg)\t(deg)")
    );
    let table = words(&out.join("body_Body1.out"));
    let (_, bodies) = read_csv(&out.join("bodies.csv"));
    assert_eq!(table.len() - 2, bodies.len());
    for (row, b) in table[2..].iter().zip(&bodies) {
        let written: Vec<f64> = row.iter().map(|w| w.parse().unwrap()).collect();
        // bodies.csv: t, body, x, y, z, roll, pitch, yaw, ...
        let want = [b[0], b[2], b[3], b[4], b[5], b[6], b[7]];
        for (w, v) in written.iter().zip(want) {
            assert!((w - v).abs() <= 5e-6 * v.abs(), "{row:?} against {b:?}");
        }
    }
    // The body falls: the file follows it.
    assert!(bodies.last().unwrap()[4] != bodies[0][4]);
    let summary = read_json(&out.join("summary.json"));
    let names = summary["moordyn_out"].as_array().unwrap();
    assert!(names.iter().any(|n| n == "body_Body1.out"), "{names:?}");
}

/// A rod whose RodOutputs ask for positions and velocities gets MoorDyn's
/// `<deck>_Rod<n>.out`: `Node<i>px py pz` then `vx vy vz` for each of its
/// nodes (NumSegs and one), the main file's widths and numbers; a static
/// run's row is
/// t = 0 with the nodes of the rigid rod at rest, equally spaced along
/// its 4 m to the 8 digits written; the force flag `f` gets no columns
/// and a note.
#[test]
fn a_rods_output_flags_are_moordyns_rod_file() {
    let d = scratch("moordyn-rod-out");
    let deck = body_rod_deck("p", "0").replace("4       -", "4       pvf");
    let path = write_scenario(&d, "rods.txt", &deck);
    let o = stancf(&["check", path.to_str().unwrap()]);
    let said = text_of(&o);
    assert!(said.contains("rod 1's RodOutputs \"pvf\""), "{said}");
    assert!(
        said.contains("\"f\" (forces, water, seabed) not computed"),
        "{said}"
    );
    let out = d.join("out");
    let o = run_quiet(&path, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let table = words(&out.join("rods_Rod1.out"));
    assert_eq!(table[0].len(), 1 + 2 * 3 * 5);
    assert_eq!(
        (&table[0][1][..], &table[0][16][..]),
        ("Node0px", "Node0vx")
    );
    assert_eq!((&table[1][1][..], &table[1][16][..]), ("(m)", "(m/s)"));
    assert_eq!(table.len(), 3);
    let row: Vec<f64> = table[2].iter().map(|w| w.parse().unwrap()).collect();
    assert_eq!(row[0], 0.0);
    let node = |i: usize| [row[1 + 3 * i], row[2 + 3 * i], row[3 + 3 * i]];
    let gap = |a: [f64; 3], b: [f64; 3]| {
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
    };
    for i in 0..4 {
        assert!((gap(node(i), node(i + 1)) - 1.0).abs() <= 1e-6, "{row:?}");
    }
    assert!((gap(node(0), node(4)) - 4.0).abs() <= 1e-6);
    assert!(row[16..].iter().all(|v| *v == 0.0), "at rest: {row:?}");
    // The zero-length rod's `p`: one node.
    assert_eq!(
        words(&out.join("rods_Rod2.out"))[0],
        ["Time", "Node0px", "Node0py", "Node0pz"]
    );
}
