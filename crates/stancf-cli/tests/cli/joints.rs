//! Rods pinned to a free body, a joint between two bodies (docs/method.md
//! §15.14): MoorDyn's `Body<n>Pinned` on a free body and the TOML
//! `type = "pinned"` rod with `body`.

use crate::common::*;

/// bodies.csv's rows of body `id`: [x, y, z, roll, pitch, yaw] (m,
/// degrees), one per written time.
fn poses(out: &std::path::Path, id: f64) -> Vec<[f64; 6]> {
    let (_, rows) = read_csv(&out.join("bodies.csv"));
    rows.iter()
        .filter(|r| r[1] == id)
        .map(|r| std::array::from_fn(|k| r[2 + k]))
        .collect()
}

/// The global position of the point `local` (body axes) of a body at
/// `pose` (a row of [`poses`]).
fn point_of(pose: &[f64; 6], local: [f64; 3]) -> [f64; 3] {
    let r = rotation_of_angles([pose[3], pose[4], pose[5]]);
    std::array::from_fn(|i| pose[i] + (0..3).map(|j| r[i][j] * local[j]).sum::<f64>())
}

fn distance(a: [f64; 3], b: [f64; 3]) -> f64 {
    (0..3).map(|c| (a[c] - b[c]).powi(2)).sum::<f64>().sqrt()
}

/// The float and flap of md_BodiesAndRods at a static equilibrium in
/// `out` (a float of 1e6 kg with a can 10 m across fixed in it from
/// (0, 0, 2) to (0, 0, 15) and a flap of the same can pinned to it at
/// (2, 0, 2), leaning to (5, 0, 15)), checked against statics by hand:
/// the flap stands upright (a buoyant rod pinned at its foot: turned by
/// -atan(3/13) from its lean, to 1e-9 degrees), the float stays in the
/// plane of the flap (y, roll and yaw zero to 1e-9: the heading is held,
/// §15.14), the joint is closed to 1e-9 m, and the float floats on its
/// can in force and in moment. Force: rho A s_can = m - F_z / g to 1e-8
/// of it, s_can the length of the can under water along its axis (the
/// surface cuts only its side, no cap), F_z bodies.csv's pull on the
/// float of the lines and of the flap at the joint, g MoorDyn's 9.80665
/// (the static tolerance is 1e-10 of the rows). Moment about the float's
/// reference point (its centre of mass): bodies.csv's moment, the can's
/// weight at its middle and its buoyancy at the centroid of a cylinder
/// cut obliquely at tilt alpha, h / 2 + a^2 tan^2(alpha) / (8 h) up the
/// axis from the cut's foot and a^2 tan(alpha) / (4 h) across it towards
/// the deeper side (h = s_can, a = 5 m), to 1e-8 of the buoyancy's
/// moment at arm a.
fn assert_float_and_flap_balance(out: &std::path::Path, tag: &str) {
    let float = poses(out, 1.0)[0];
    let flap = poses(out, 2.0)[0];
    let lean = -(3.0f64 / 13.0).atan().to_degrees();
    let joint = point_of(&float, [2.0, 0.0, 2.0]);
    let gap = distance(joint, [flap[0], flap[1], flap[2]]);
    // The cans' lengths under water along their axes: the float's from
    // (0, 0, 2) in its axes; the flap's from its end A, upright.
    let foot = point_of(&float, [0.0, 0.0, 2.0]);
    let up = point_of(&float, [0.0, 0.0, 3.0]);
    let axis: [f64; 3] = std::array::from_fn(|c| up[c] - foot[c]);
    let s_can = -foot[2] / axis[2];
    let s_flap = -flap[2];
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let column = |name: &str| rows[0][header.iter().position(|h| h == name).unwrap()];
    let (g, a) = (9.80665, 5.0);
    let area = std::f64::consts::PI * a * a;
    let displaced = 1025.0 * area * s_can;
    let mass = 1e6 + 1000.0 * 13.0 - column("fz") / g;
    // The moment about the reference point, y (the float's plane is x-z).
    let (c, s) = (axis[2], (1.0 - axis[2] * axis[2]).sqrt());
    let across = if s > 0.0 {
        std::array::from_fn(|i| ([0.0, 0.0, 1.0][i] - c * axis[i]) / s)
    } else {
        [0.0; 3]
    };
    let tan = s / c;
    let along = s_can / 2.0 + a * a * tan * tan / (8.0 * s_can);
    let centroid: [f64; 3] = std::array::from_fn(|i| {
        foot[i] + along * axis[i] - a * a * tan / (4.0 * s_can) * across[i]
    });
    let middle = point_of(&float, [0.0, 0.0, 8.5]);
    let buoyancy = 1025.0 * g * area * s_can;
    let arm = |p: [f64; 3]| p[0] - float[0];
    // m_y of an upward force F at p: (p - x_ref) x F . e_y = -(p_x - x_x) F.
    let moment = column("my") - arm(centroid) * buoyancy + arm(middle) * 13_000.0 * g;
    eprintln!(
        "{tag}: float at {float:?}, flap pitch {} (upright at {lean}); joint gap {gap:.1e} m; \
         displaced {displaced:.6} kg against {mass:.6} kg (cans in by {s_can:.4} and \
         {s_flap:.4} m); moment {moment:.2e} N m of {:.3e}",
        flap[4],
        buoyancy * a
    );
    assert!((flap[4] - lean).abs() < 1e-9, "{} {lean}", flap[4]);
    for v in [float[1], float[3], float[5]] {
        assert!(v.abs() < 1e-9, "{float:?}");
    }
    assert!(gap < 1e-9, "{gap:e}");
    // Neither cap cut: the surface crosses each axis more than r tan(tilt)
    // from its ends.
    let reach = a * float[4].to_radians().tan().abs();
    assert!(s_can > reach && s_can < 13.0 - reach, "{s_can}");
    assert!(s_flap > 0.0 && s_flap < 178.0f64.sqrt(), "{s_flap}");
    assert!((displaced - mass).abs() < 1e-8 * mass, "{displaced} {mass}");
    assert!(moment.abs() < 1e-8 * buoyancy * a, "{moment}");
}

/// OpenFAST's md_BodiesAndRods (a wave energy converter: the float and
/// flap of [`assert_float_and_flap_balance`], three nylon lines to one
/// point under the float): `check` names the joint, and the static
/// analysis balances the float and the flap.
#[test]
fn openfasts_md_bodies_and_rods_flap_stands_upright_on_its_float() {
    let d = scratch("md-bodies-and-rods");
    let deck = copy_fixture(&d, "md-bodies-and-rods-moordyn.txt", "moordyn.dat");
    let (stdout, _) = text(&stancf(&["check", deck.to_str().unwrap()]));
    assert!(
        stdout.contains("pinned at end A to point 7 (on free body 1, a joint"),
        "{stdout}"
    );
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    assert_eq!(
        read_json(&out.join("summary.json"))["static_path"],
        "load path"
    );
    assert_float_and_flap_balance(&out, "md_BodiesAndRods");
}

/// MoorDyn's own BodiesAndRods.dat: md_BodiesAndRods with a buoyant cable
/// from an anchor 200 m off to the float's reference point over two free
/// points, the float and both cans out of the water in the deck's pose.
/// The load path from the lines' catenaries stalls at load factor 0 (the
/// float hangs on slack lines until its cans float it); pseudo-transient
/// continuation (docs/method.md §6.9, (M26b)) reaches the equilibrium,
/// `run` says so, summary.json's `static_path` names it, and the float
/// and flap balance as in [`assert_float_and_flap_balance`] (the cable
/// pulls the float aside and pitches it by 12.7 degrees).
#[test]
fn moordyns_bodies_and_rods_reaches_its_equilibrium_by_pseudo_transient_continuation() {
    let d = scratch("md-bodies-and-rods-cable");
    let deck = copy_fixture(&d, "bodies-and-rods-cable-moordyn.txt", "BodiesAndRods.dat");
    let out = d.join("out");
    let o = run_quiet(&deck, &out, &[]);
    let (_, stderr) = text(&o);
    assert_eq!(o.status.code(), Some(0), "{stderr}");
    assert!(stderr.contains("pseudo-transient continuation"), "{stderr}");
    // Its nylon lines, left shortened by the first flow (with their
    // compression kept), are released to their own law and the flow
    // followed on: none is left carrying compression.
    assert!(!stderr.contains("shortens it"), "{stderr}");
    assert_eq!(
        read_json(&out.join("summary.json"))["static_path"],
        "pseudo-transient continuation"
    );
    assert_float_and_flap_balance(&out, "BodiesAndRods.dat");
}

/// The buoy of `moored_buoy` (pushed at 0.3 m/s in surge) with a rod
/// (4 m, 0.2 m across, 60 kg/m) pinned under it at (0, 0, -0.6) in its
/// axes, in TOML (`type = "pinned"`, `body = 1`, ends in the body's axes):
/// after the static analysis the rod hangs plumb (roll and pitch zero to
/// 1e-7 degrees, the static tolerance); it starts with the buoy's point's
/// velocity (a joint moves with its point), swings as the buoy drifts
/// (more than 0.1 degree in 4 s), and its end A stays on the buoy's point
/// at every written step to 1e-9 m.
#[test]
fn a_toml_rod_pinned_to_a_free_buoy_hangs_and_swings_with_it() {
    let analysis = "type = \"dynamic\"\ninitial = \"static\"\ntime_step = 0.05\nduration = 4.0";
    let mut scenario = moored_buoy("velocity = [0.3, 0.0, 0.0]", analysis);
    scenario.push_str(
        "[[rod_types]]\nname = \"pipe\"\ndiameter = 0.2\nmass_per_length = 60.0\ncd = 1.0\n\
         ca = 1.0\n[[rods]]\nid = 1\ntype = \"pinned\"\nbody = 1\nrod_type = \"pipe\"\n\
         end_a = [0.0, 0.0, -0.6]\nend_b = [0.0, 0.0, -4.6]\nsegments = 4\n",
    );
    let d = scratch("toml-joint");
    let sc = write_scenario(&d, "joint.toml", &scenario);
    let out = d.join("out");
    let o = run_quiet(&sc, &out, &["--plot", "--vtk"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let buoy = poses(&out, 1.0);
    let rod = poses(&out, 2.0);
    drawn_for_paraview(&out, buoy.len());
    assert_eq!(buoy.len(), rod.len());
    let mut gap = 0.0f64;
    let mut swing = 0.0f64;
    for (b, r) in buoy.iter().zip(&rod) {
        gap = gap.max(distance(point_of(b, [0.0, 0.0, -0.6]), [r[0], r[1], r[2]]));
        swing = swing.max(r[3].abs().max(r[4].abs()));
    }
    eprintln!(
        "TOML joint: the rod starts at roll {} and pitch {} degrees, swings to {swing:.3} \
         degrees; the joint opened {gap:.1e} m",
        rod[0][3], rod[0][4]
    );
    assert!(
        rod[0][3].abs() < 1e-7 && rod[0][4].abs() < 1e-7,
        "{:?}",
        rod[0]
    );
    assert!(swing > 0.1, "{swing}");
    assert!(gap < 1e-9, "{gap:e}");
}

/// The bodies figure is drawn, and ParaView gets the rigid parts of every
/// written step (`bodies.pvd`, one `vtk/bodies_<k>.vtp` each, `steps` of
/// them): the rod (4 m, radius 0.1 m) from the buoy's point, the buoy's
/// three axes and its four spokes (three fairleads and the joint's
/// point), the rod's body's three axes, each cell with its body's id.
fn drawn_for_paraview(out: &std::path::Path, steps: usize) {
    check_png(&out.join("bodies.png"));
    let pvd = std::fs::read_to_string(out.join("bodies.pvd")).unwrap();
    assert_eq!(pvd.matches("<DataSet ").count(), steps);
    let xml = std::fs::read_to_string(out.join("vtk/bodies_000000.vtp")).unwrap();
    let (rod, axis) = (vtk_array(&xml, "rod"), vtk_array(&xml, "axis"));
    let (body, radius) = (vtk_array(&xml, "body"), vtk_array(&xml, "radius"));
    let mut want_rod = vec![0.0; 11];
    want_rod[0] = 1.0;
    assert_eq!(rod, want_rod);
    let want_axis = [0.0, 1.0, 2.0, 3.0, 0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0];
    assert_eq!(axis, want_axis);
    let want_body = [2.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0];
    assert_eq!(body, want_body);
    assert_eq!(radius[0], 0.1);
    let p = vtk_array(&xml, "position");
    let length = distance([p[0], p[1], p[2]], [p[3], p[4], p[5]]);
    assert!((length - 4.0).abs() < 1e-12, "{length}");
}

/// A rod (4 m, 0.2 m across, 60 kg/m: 240 kg displacing 128.8 kg of
/// water) pinned under a coupled body that holds nothing else, in TOML
/// (`type = "pinned"`, `body = 1`; docs/method.md §15.17): the run's
/// static equilibrium (bodies.csv's first rows) hangs it plumb under the
/// body and gives the body its pull, -(m - rho V) g, to 1e-9 of it;
/// through the coupling API, `initialize` returns the same
/// force, and as the host lifts the body at 2 m/s^2 from rest the rod
/// follows and pulls -(m (g + a) - rho V g) (B35), each interval's mean
/// to 1e-9 of it (the pin's force is the rod's momentum change less its
/// weight's and buoyancy's impulses; no drag or added mass here).
#[test]
fn a_rod_pinned_to_a_coupled_body_pulls_it_by_its_weight_and_its_lift() {
    let d = scratch("rod-on-coupled-body");
    let scenario = "title = \"rod on a coupled body\"\n[water]\ndepth = 50.0\ndensity = 1025.0\n\
         [[bodies]]\nid = 1\ntype = \"coupled\"\nposition = [0.0, 0.0, -10.0]\n\
         [[rod_types]]\nname = \"pipe\"\ndiameter = 0.2\nmass_per_length = 60.0\n\
         [[rods]]\nid = 1\ntype = \"pinned\"\nbody = 1\nrod_type = \"pipe\"\n\
         end_a = [0.0, 0.0, -0.6]\nend_b = [0.0, 0.0, -4.6]\nsegments = 4\n\
         [analysis]\ntype = \"dynamic\"\ninitial = \"static\"\ntime_step = 0.05\nduration = 0.05\n";
    let file = write_scenario(&d, "rod.toml", scenario);
    let out = d.join("out");
    let o = run_quiet(&file, &out, &[]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o).1);
    let g = 9.81;
    let (mass, displaced) = (240.0, 1025.0 * std::f64::consts::PI * 0.01 * 4.0);
    let hanging = -(mass - displaced) * g;
    let (header, rows) = read_csv(&out.join("bodies.csv"));
    let col = |name: &str| header.iter().position(|h| h == name).unwrap();
    let fz = rows[0][col("fz")];
    assert!(
        (fz - hanging).abs() < 1e-9 * hanging.abs(),
        "{fz} {hanging}"
    );
    assert!(rows[1][col("roll")].abs() < 1e-9 && rows[1][col("pitch")].abs() < 1e-9);
    let mut c = stancf_cli::coupling::open(&file).expect("a coupled system");
    assert_eq!(c.coupled_body_ids, [1]);
    let pose = |t: f64| [0.0, 0.0, -10.0 + t * t, 0.0, 0.0, 0.0];
    let rate = |t: f64| [0.0, 0.0, 2.0 * t, 0.0, 0.0, 0.0];
    let f0 = c
        .handle
        .initialize(&pose(0.0), Some(&rate(0.0)))
        .expect("equilibrium");
    assert!((f0[2] - hanging).abs() < 1e-9 * hanging.abs(), "{f0:?}");
    let lifted = -(mass * (g + 2.0) - displaced * g);
    let mut worst = 0.0f64;
    for k in 1..=20 {
        let t = 0.05 * k as f64;
        let f = c
            .handle
            .step_to(t, &pose(t), Some(&rate(t)))
            .unwrap()
            .interval_mean;
        worst = worst
            .max((f[2] - lifted).abs())
            .max(f[0].abs())
            .max(f[1].abs());
    }
    eprintln!(
        "a rod on a coupled body: hangs by {fz:.6} N, lifted pulls {lifted:.6} N to {worst:.1e}"
    );
    assert!(worst < 1e-9 * lifted.abs(), "{worst:e}");
}
