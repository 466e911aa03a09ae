use super::*;

/// MoorDyn's docs' example of `current_profile_dynamic.txt`: five depths,
/// three times, ux and uy given.
const DYNAMIC: &str = "--------------------- MoorDyn dynamic currents File ----------
Tabulated file with the water currents components


     -40.0 -30.0 -20.0 -10.0   0.0

0.0    0.0   0.0   0.0   0.0   0.0   0.0   0.0   0.0   0.0   0.0
15.0   0.0   0.2   0.4   0.6   0.8   0.0   0.2   0.4   0.6   0.8
30.0   0.0   0.0   0.0   0.0   0.0   0.0   0.0   0.0   0.0   0.0
";

/// "The largest currents will be at 15 seconds at z = 0 where the 3d
/// water velocity vector will be (0.8, 0.8, 0.0)"; between rows and times
/// the current is linear in each, and it holds the last time's after it.
#[test]
fn moordyns_dynamic_profile_example_is_its_described_current() {
    let g = read_dynamic_profile(DYNAMIC).unwrap();
    assert_eq!(g.axes()[2], vec![-40.0, -30.0, -20.0, -10.0, 0.0]);
    assert_eq!(g.axes()[3], vec![0.0, 15.0, 30.0]);
    let at = |z: f64, t: f64| g.sample(&[123.0, -45.0, z], t).velocity;
    assert_eq!(at(0.0, 15.0), [0.8, 0.8, 0.0]);
    let mid = at(-25.0, 7.5);
    // 0.3 at z = -25 at 15 s, half of it at 7.5 s.
    assert!(
        (mid[0] - 0.15).abs() < 1e-15 && (mid[1] - 0.15).abs() < 1e-15,
        "{mid:?}"
    );
    assert_eq!(at(-5.0, 31.0), [0.0; 3]);
    let rate = g.sample(&[0.0, 0.0, 0.0], 20.0).acceleration;
    assert!((rate[0] + 0.8 / 15.0).abs() < 1e-15, "{rate:?}");
}

/// Depths given from the surface down are the same profile, and rows of
/// ux alone or of all three components are read as MoorDyn reads them.
#[test]
fn a_dynamic_profile_may_run_down_and_give_one_to_three_components() {
    let text = "a\nb\nc\nd\n0 -10 -20\n\n0 1 2 3\n10 1 2 3 4 5 6\n20 1 2 3 4 5 6 7 8 9\n";
    let g = read_dynamic_profile(text).unwrap();
    assert_eq!(g.axes()[2], vec![-20.0, -10.0, 0.0]);
    let at = |z: f64, t: f64| g.sample(&[0.0, 0.0, z], t).velocity;
    assert_eq!(at(0.0, 0.0), [1.0, 0.0, 0.0]);
    assert_eq!(at(-20.0, 10.0), [3.0, 6.0, 0.0]);
    assert_eq!(at(-10.0, 20.0), [2.0, 5.0, 8.0]);
}

#[test]
fn a_dynamic_profile_moordyn_cannot_read_is_refused_naming_its_line() {
    let head = "a\nb\nc\nd\n-20 -10 0\n\n";
    for (body, needles) in [
        ("0 1 2\n", vec!["line 7", "4, 7 or 10 numbers, got 3"]),
        ("0 1 2 3 4\n", vec!["line 7", "got 5"]),
        ("0 1 2 3\n0 1 2 3\n", vec!["line 8", "does not rise"]),
        ("0 1 x 3\n", vec!["line 7", "\"x\""]),
        ("", vec!["no rows"]),
    ] {
        let e = read_dynamic_profile(&format!("{head}{body}")).unwrap_err();
        for n in needles {
            assert!(e.contains(n), "{n}: {e}");
        }
    }
    let e = read_dynamic_profile("a\nb\nc\nd\n-20 -5 -10\n\n0 1 2 3\n").unwrap_err();
    assert!(e.contains("line 5") && e.contains("rise or fall"), "{e}");
    let e = read_dynamic_profile("a\nb\n").unwrap_err();
    assert!(e.contains("line 5"), "{e}");
}

/// MoorDyn's docs' example of `current_profile_4d.txt` (its rows of z
/// written "-0" among them): zero at t = 0, at 15 s (+-1, +-1, 0) at
/// z = 0 and (+-0.5, +-0.5, 0) at z = -3 with the signs of x and y.
const GRID_4D: &str = "2 2 2 2
-1 1
-2 2
-3 0
0 15
-1 -2 -3 0 0.0 0.0 0.0
-1 -2 0 0 0.0 0.0 0.0
-1 2 -3 0 0.0 0.0 0.0
-1 2 0 0 0.0 0.0 0.0
1 -2 -3 0 0.0 0.0 0.0
1 -2 0 0 0.0 0.0 0.0
1 2 -3 0 0.0 0.0 0.0
1 2 0 0 0.0 0.0 0.0
-1 -2 -3 15 -0.5 -0.5 0.0
-1 -2 0 15 -1.0 -1.0 0.0
-1 2 -3 15 -0.5 0.5 0.0
-1 2 -0 15 -1.0 1.0 0.0
1 -2 -3 15 0.5 -0.5 0.0
1 -2 -0 15 1.0 -1.0 0.0
1 2 -3 15 0.5 0.5 0.0
1 2 -0 15 1.0 1.0 0.0
";

#[test]
fn moordyns_4d_grid_example_is_its_described_current() {
    let g = read_grid_4d(GRID_4D).unwrap();
    let at = |p: [f64; 3], t: f64| g.sample(&p, t).velocity;
    assert_eq!(at([1.0, 2.0, 0.0], 15.0), [1.0, 1.0, 0.0]);
    assert_eq!(at([-1.0, 2.0, 0.0], 15.0), [-1.0, 1.0, 0.0]);
    assert_eq!(at([1.0, -2.0, -3.0], 15.0), [0.5, -0.5, 0.0]);
    assert_eq!(at([1.0, 2.0, -1.5], 7.5), [0.375, 0.375, 0.0]);
    assert_eq!(at([0.0, 0.0, -1.0], 0.0), [0.0; 3]);
    // Beyond the grid: the nearest node's.
    assert_eq!(at([5.0, 9.0, 2.0], 40.0), [1.0, 1.0, 0.0]);
}

#[test]
fn a_4d_grid_with_a_node_missing_repeated_or_off_its_axes_is_refused_naming_the_line() {
    let rows: Vec<&str> = GRID_4D.lines().collect();
    let without = |skip: usize| -> String {
        rows.iter()
            .enumerate()
            .filter(|(i, _)| *i != skip)
            .map(|(_, l)| format!("{l}\n"))
            .collect()
    };
    let e = read_grid_4d(&without(5)).unwrap_err();
    assert!(
        e.contains("1 of the grid's 16 nodes") && e.contains("(-1, -2, -3, 0)"),
        "{e}"
    );
    let repeated = format!("{GRID_4D}1 2 0 15 1.0 1.0 0.0\n");
    let e = read_grid_4d(&repeated).unwrap_err();
    assert!(e.contains("line 22") && e.contains("line 21"), "{e}");
    let off = GRID_4D.replace("1 2 -3 15 0.5", "1 2 -2 15 0.5");
    let e = read_grid_4d(&off).unwrap_err();
    assert!(e.contains("line 20") && e.contains("z = -2"), "{e}");
    let counted = GRID_4D.replace("-3 0\n0 15", "-3 -1 0\n0 15");
    let e = read_grid_4d(&counted).unwrap_err();
    assert!(e.contains("line 4") && e.contains("3 given"), "{e}");
    let falling = GRID_4D.replacen("-1 1\n", "1 -1\n", 1);
    let e = read_grid_4d(&falling).unwrap_err();
    assert!(e.contains("line 2") && e.contains("rise"), "{e}");
    let e = read_grid_4d("2 2 x 2\n").unwrap_err();
    assert!(e.contains("line"), "{e}");
    // A count beyond its axis's values is refused by the axis's line (the
    // counts are bounded by the file; the rows are kept by node in a map,
    // so a grid of far more nodes than rows allocates nothing its size).
    let huge = GRID_4D
        .replacen("2 2 2 2", "2 2 2 4611686018427387904", 1)
        .replacen("0 15\n", "0 15 16\n", 1);
    let e = read_grid_4d(&huge).unwrap_err();
    assert!(e.contains("line 5") || e.contains("overflows"), "{e}");
}
