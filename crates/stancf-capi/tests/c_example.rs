//! examples/coupling/oc4_surge.c compiles against the header and the
//! library and drives the OC4 DeepCwind fairleads (its bitwise agreement
//! with the Python example is crates/stancf-py/tests/test_simulation.py's
//! claim).

mod common;

use common::{compile, repo, scratch};

#[test]
fn the_c_example_compiles_and_prints_the_oc4_fairlead_tensions() {
    let dir = scratch("c-example");
    let exe = dir.join("oc4_surge");
    compile(&repo("examples/coupling/oc4_surge.c"), &exe, "c99");
    let run = common::c_program(&exe)
        .arg(repo("examples/oc4-deepcwind-moordyn.txt"))
        .arg("0.3")
        .output()
        .unwrap();
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let text = String::from_utf8(run.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("t,tension_4,tension_5,tension_6"));
    let rows: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 3);
    for (k, row) in rows.iter().enumerate() {
        assert_eq!(row[0], [0.1, 0.2, 0.30000000000000004][k]);
        // The deck's pretension, 1.1e6 N, shifted by the surge: fairlead
        // 4 (anchor at -x) pulled, 5 and 6 slackened and equal by symmetry.
        assert!(
            row[1..].iter().all(|t| (1.0e6..1.2e6).contains(t)),
            "{row:?}"
        );
        assert!(row[1] > row[2] && row[2] == row[3], "{row:?}");
    }
}
