//! Figures and VTK output: `run --plot` and `plot DIR` write valid PNG and
//! SVG figures, and `run --vtk` writes PolyData files that read back to the
//! nodes, arrays and times of the run's result files.

use crate::common::{check_png, read_csv, scratch, stancf, text, vtk_array, write_scenario};
use std::path::Path;

/// A small valid scenario: the transverse impact, shortened.
const BASE: &str = crate::common::IMPACT;

/// An SVG file that a browser would draw, with its title in it.
fn check_svg(path: &Path, title: &str) {
    let s = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    assert!(s.starts_with("<svg"), "{}", path.display());
    assert!(s.trim_end().ends_with("</svg>"), "{}", path.display());
    assert!(s.contains(title), "{}: no title {title:?}", path.display());
    assert!(
        s.len() > 2_000 && s.len() < 10_000_000,
        "{}: {} bytes",
        path.display(),
        s.len()
    );
}

/// `run --plot` draws the run's figures next to its results, `plot DIR`
/// redraws them from the files; a folder without results is an input
/// error.
#[test]
fn run_plot_and_plot_dir_write_valid_figures() {
    let d = scratch("plots");
    let sc = write_scenario(
        &d,
        "p.toml",
        &BASE.replace("title = \"test\"", "title = \"plot test\""),
    );
    let out = d.join("res");
    let o = stancf(&[
        "run",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--plot",
    ]);
    let (so, se) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{se}");
    assert!(
        so.contains("figures: shapes, energy, stress_map, convergence"),
        "{so}"
    );
    let figures = [
        ("shapes", "plot test: shapes"),
        ("energy", "plot test: energies"),
        ("stress_map", "plot test: axial stress"),
        ("convergence", "plot test: residuals"),
    ];
    for (name, title) in figures {
        check_png(&out.join(format!("{name}.png")));
        check_svg(&out.join(format!("{name}.svg")), title);
    }
    // Redrawn from the files alone.
    for (name, _) in figures {
        std::fs::remove_file(out.join(format!("{name}.png"))).unwrap();
    }
    let o = stancf(&["plot", out.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    for (name, _) in figures {
        check_png(&out.join(format!("{name}.png")));
    }
    let o = stancf(&["plot", d.to_str().unwrap()]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2), "{se}");
    assert!(se.contains("no summary.json"), "{se}");
}

/// `run --vtk`: one PolyData file per written step and the collection with
/// the times; read back, the polyline passes through the nodes of
/// nodes.csv and its arrays have the right sizes and values.
#[test]
fn vtk_files_read_back() {
    let d = scratch("vtk");
    let sc = write_scenario(&d, "v.toml", BASE);
    let out = d.join("res");
    let o = stancf(&[
        "run",
        sc.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
        "--vtk",
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let (_, hist) = read_csv(&out.join("history.csv"));
    let (_, nodes) = read_csv(&out.join("nodes.csv"));
    let (_, stress) = read_csv(&out.join("stress.csv"));
    let pvd = std::fs::read_to_string(out.join("cable.pvd")).unwrap();
    assert!(pvd.contains("type=\"Collection\""));
    let entries: Vec<(f64, String)> = pvd
        .lines()
        .filter(|l| l.starts_with("<DataSet"))
        .map(|l| {
            let attr = |a: &str| {
                let k = l.find(&format!("{a}=\"")).unwrap() + a.len() + 2;
                l[k..k + l[k..].find('"').unwrap()].to_string()
            };
            (attr("timestep").parse().unwrap(), attr("file"))
        })
        .collect();
    assert_eq!(entries.len(), hist.len(), "one file per written step");
    let per_element = 16;
    let n_points = 8 * (per_element - 1) + 1;
    for (k, (t, file)) in entries.iter().enumerate() {
        assert_eq!(*t, hist[k][0], "time of {file}");
        let xml = std::fs::read_to_string(out.join(file)).unwrap();
        assert!(
            xml.contains(&format!("NumberOfPoints=\"{n_points}\"")),
            "{file}"
        );
        let pos = vtk_array(&xml, "position");
        assert_eq!(pos.len(), 3 * n_points);
        // Through every node of nodes.csv at this time.
        let at_t: Vec<&Vec<f64>> = nodes.iter().filter(|r| r[0] == *t).collect();
        assert_eq!(at_t.len(), 9);
        for (j, node) in at_t.iter().enumerate() {
            let p = j * (per_element - 1);
            for c in 0..3 {
                assert!(
                    (pos[3 * p + c] - node[2 + c]).abs() < 1e-12,
                    "{file}: node {j}: {} vs {}",
                    pos[3 * p + c],
                    node[2 + c]
                );
            }
        }
        assert_eq!(vtk_array(&xml, "velocity").len(), 3 * n_points);
        let s = vtk_array(&xml, "s");
        assert_eq!(s.len(), n_points);
        assert_eq!(s[0], 0.0);
        assert!((s[n_points - 1] - 4.0).abs() < 1e-12);
        let sigma = vtk_array(&xml, "axial_stress");
        assert_eq!(sigma.len(), n_points);
        assert_eq!(vtk_array(&xml, "curvature").len(), n_points);
        // The free end's stress is the one stress.csv has there.
        let end = stress.iter().find(|r| r[0] == *t && r[1] == 0.0).unwrap();
        assert!(
            (sigma[0] - end[2]).abs() <= 1e-9 * end[2].abs().max(1.0),
            "{file}"
        );
        let conn = vtk_array(&xml, "connectivity");
        assert_eq!(conn, (0..n_points).map(|i| i as f64).collect::<Vec<_>>());
        assert_eq!(vtk_array(&xml, "offsets"), vec![n_points as f64]);
    }
    // The initial velocities of the struck ends.
    let xml = std::fs::read_to_string(out.join(&entries[0].1)).unwrap();
    let v = vtk_array(&xml, "velocity");
    assert_eq!(v[1], 10.0);
    assert_eq!(v[3 * (n_points - 1) + 1], -10.0);
}
