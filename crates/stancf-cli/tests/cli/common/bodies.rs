//! Scenarios with rigid bodies for the tests of `bodies.rs`: a TOML buoy
//! held by three lines and a MoorDyn deck with a BODIES section.

/// The buoy of docs/method.md §15.8 as a TOML system: a free body of
/// 500 kg and 2 m^3 (net lift (1025 x 2 - 500) x 9.81 = 15 205.5 N),
/// its centre of mass 0.3 m below its reference point, held in 50 m of
/// water by lines of 60, 62 and 64 m (2 kg/m, EA 1e7 N, 12 elements)
/// from anchors 50 m out to three points on its underside 1 m from its
/// axis; `body_keys` (TOML lines) added to its `[[bodies]]` entry,
/// `analysis` the `[analysis]` body.
pub fn moored_buoy(body_keys: &str, analysis: &str) -> String {
    let mut s = String::from(
        "title = \"moored buoy\"\n[water]\ndepth = 50.0\ndensity = 1025.0\n\
         [[line_types]]\nname = \"chain\"\ndiameter = 0.02\nmass_per_length = 2.0\n\
         ea = 1.0e7\ncd = 1.2\nca = 1.0\n",
    );
    s.push_str(&format!(
        "[[bodies]]\nid = 1\ntype = \"free\"\nposition = [0.0, 0.0, -10.0]\nmass = 500.0\n\
         centre_of_mass = [0.0, 0.0, -0.3]\ninertia = [300.0, 300.0, 200.0]\nvolume = 2.0\n\
         {body_keys}\n"
    ));
    for k in 0..3 {
        let angle = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let (c, s_) = (angle.cos(), angle.sin());
        s.push_str(&format!(
            "[[points]]\nid = {}\ntype = \"body\"\nbody = 1\nposition = [{c:?}, {s_:?}, -0.5]\n\
             [[points]]\nid = {}\ntype = \"fixed\"\nposition = [{:?}, {:?}, -50.0]\n\
             [[lines]]\nid = {}\ntype = \"chain\"\nlength = {:?}\nelements = 12\na = {}\nb = {}\n",
            k + 1,
            k + 4,
            50.0 * c,
            50.0 * s_,
            k + 1,
            60.0 + 2.0 * k as f64,
            k + 4,
            k + 1
        ));
    }
    s.push_str(&format!("[analysis]\n{analysis}\n"));
    s
}

/// A body hanging by a nylon line in 100 m of water, after OpenFAST's
/// r-test `md_BdyExtLdDmpg` (a MoorDyn-F deck) with moments of inertia
/// and without its EXTERNAL LOADS: free body 1 of 21 244 kg (BODIES row
/// `body_row`, or the default when empty) at z = -50 m, point 1 on it
/// (POINTS row `body_point`, or the default when empty), point 2 fixed
/// at the surface, a line of 48 m between them; `outputs` (channel
/// names, one per line) in OUTPUTS.
pub fn body_deck(body_row: &str, body_point: &str, outputs: &str) -> String {
    let body_row = if body_row.is_empty() {
        " 1     free       0      0    -50     0      0      0    2.1244e4    0    1.0e4|1.0e4|1.5e4    0     0        0"
    } else {
        body_row
    };
    let body_point = if body_point.is_empty() {
        " 1        Body1     0        0         0        0        0        0        0"
    } else {
        body_point
    };
    format!(
        "A point mass suspended by a line (after r-test md_BdyExtLdDmpg)
------------------------- LINE TYPES --------------------------------------------------
TypeName  Diam    Mass/m    EA       BA/-zeta    EI      Cd    Ca    CdAx  CaAx
 (-)       (m)      (kg/m)        (N)      (Pa-s/-)  (n-m^2)   (-)   (-)   (-)   (-)
nylon     0.124      35.0      5000000.0     -1.0      0.0     1.0   0.0   1.0   0.0
---------------------------- BODIES -----------------------------------------------------
ID   Attachment  X0     Y0    Z0     r0     p0     y0      Mass     CG*       I*     Volume    CdA*     Ca
(#)     (-)      (m)    (m)   (m)   (deg)  (deg)  (deg)    (kg)     (m)    (kg-m^2)  (m^3)    (m^2)     (-)
{body_row}
----------------------- POINTS ----------------------------------------------
ID      Attachment      X        Y         Z        M        V       CdA      CA
(-)       (-)      (m)      (m)       (m)      (kg)    (m^3)    (m^2)     (-)
{body_point}
 2        Fixed     0        0         0        0        0        0        0
-------------------------- LINES -------------------------------------------------
ID  LineType    AttachA   AttachB  UnstrLen  NumSegs   LineOutputs
(-)      (-)       (-)     (-)     (m)       (-)        (-)
 1      nylon       2       1      48        10          -
-------------------------- SOLVER OPTIONS---------------------------------------------------
0.005    dtM          - time step to use in mooring integration (s)
0.1      dtOut        - time step size to be written to output files (s)
100      WtrDpth
------------------------------ OUTPUTS -----------------------------------------------------
{outputs}--------------------------- need this line -------------------------------------------------
"
    )
}

/// MoorDyn's rotation of roll, pitch and yaw in degrees (its intrinsic
/// x-y'-z'': R = R_x R_y R_z), written out here to check the angles
/// stancf writes.
pub fn rotation_of_angles(deg: [f64; 3]) -> [[f64; 3]; 3] {
    let [r, p, y] = deg.map(f64::to_radians);
    let (sr, cr) = r.sin_cos();
    let (sp, cp) = p.sin_cos();
    let (sy, cy) = y.sin_cos();
    let rx = [[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]];
    let ry = [[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]];
    let rz = [[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]];
    let mul = |a: [[f64; 3]; 3], b: [[f64; 3]; 3]| -> [[f64; 3]; 3] {
        std::array::from_fn(|i| std::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum()))
    };
    mul(mul(rx, ry), rz)
}

/// How far the force f (its first three numbers) is from the vertical
/// force fz: the largest of |f_x|, |f_y| and |f_z - fz| (N).
pub fn vertical_miss(f: &[f64], fz: f64) -> f64 {
    (f[2] - fz).abs().max(f[0].abs()).max(f[1].abs())
}

/// Steps `handle` to t = 0.1, 0.2, ..., 1.0 s with the coupling arrays at
/// `at(t)` and their rates `rate(t)` (the host's motion), and the largest
/// of `miss(f)` over the intervals' mean forces f.
pub fn worst_interval_mean(
    handle: &mut stancf::coupling::CoupledSystem,
    at: impl Fn(f64) -> Vec<f64>,
    rate: impl Fn(f64) -> Vec<f64>,
    miss: impl Fn(&[f64]) -> f64,
) -> f64 {
    (1..=10)
        .map(|k| {
            let t = 0.1 * k as f64;
            let f = handle
                .step_to(t, &at(t), Some(&rate(t)))
                .unwrap()
                .interval_mean;
            miss(&f)
        })
        .fold(0.0, f64::max)
}

/// A 1000 kg body (no volume, moments 50 kg m^2) hung level at z = -30 m
/// by three equal 30 m ropes (2 kg/m, `diameter`, `ea`; 10 elements each)
/// from the corners of a unit triangle about its centre at the surface,
/// its ropes on body points at the same corners, in 100 m of water; the
/// body's extra keys `body_keys`; a static run.
pub fn weight_on_three_ropes(diameter: f64, ea: f64, body_keys: &str) -> String {
    let mut ropes = String::new();
    for k in 0..3 {
        let a = 2.0 * std::f64::consts::PI * k as f64 / 3.0;
        let (x, y) = (a.cos(), a.sin());
        ropes.push_str(&format!(
            "[[points]]\nid = {}\ntype = \"fixed\"\nposition = [{x:?}, {y:?}, 0.0]\n\
             [[points]]\nid = {}\ntype = \"body\"\nbody = 1\nposition = [{x:?}, {y:?}, 0.0]\n\
             [[lines]]\nid = {}\ntype = \"rope\"\nlength = 30.0\nelements = 10\na = {}\nb = {}\n",
            2 * k + 1,
            2 * k + 2,
            k + 1,
            2 * k + 1,
            2 * k + 2
        ));
    }
    format!(
        "title = \"weight on three ropes\"\n[water]\ndepth = 100.0\ndensity = 1025.0\n\
         [[line_types]]\nname = \"rope\"\ndiameter = {diameter:?}\nmass_per_length = 2.0\nea = {ea:?}\n\
         [[bodies]]\nid = 1\ntype = \"free\"\nposition = [0.0, 0.0, -30.0]\nmass = 1000.0\n\
         inertia = [50.0, 50.0, 50.0]\n{body_keys}\n{ropes}[analysis]\ntype = \"static\"\n"
    )
}
