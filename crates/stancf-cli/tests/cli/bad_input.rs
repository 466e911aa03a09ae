//! One test per class of bad input: each is refused by both `run` and
//! `check` with exit code 2, a message naming the file and the offending
//! key, and no output folder written.

use crate::common::{expect_input_error, stancf, text};

/// A small valid scenario: the transverse impact, shortened.
const BASE: &str = crate::common::IMPACT;

#[test]
fn bad_input_malformed_toml() {
    expect_input_error(
        "malformed",
        &BASE.replace("length = 4.0", "length = = 4.0"),
        &["line 4"],
    );
}

#[test]
fn bad_input_unknown_key_at_any_level() {
    expect_input_error("unknown-top", &format!("colour = 1\n{BASE}"), &["colour"]);
    expect_input_error(
        "unknown-cable",
        &BASE.replace("length = 4.0", "lenght = 4.0"),
        &["lenght"],
    );
    expect_input_error(
        "unknown-analysis",
        &BASE.replace("type = \"dynamic\"", "type = \"dynamic\"\ntimestep = 1"),
        &["timestep"],
    );
    expect_input_error(
        "unknown-load",
        &BASE.replace("type = \"gravity\"", "type = \"gravity\"\nstrength = 2"),
        &["loads[0]", "strength"],
    );
    expect_input_error(
        "unknown-iv",
        &BASE.replace("node = \"A\"", "node = \"A\"\nspeed = 1"),
        &["speed"],
    );
    expect_input_error(
        "unknown-output",
        &BASE.replace("every = 4", "evry = 4"),
        &["evry"],
    );
}

#[test]
fn bad_input_missing_required_key() {
    expect_input_error(
        "missing-length",
        &BASE.replace("length = 4.0\n", ""),
        &["cable.length", "missing"],
    );
    expect_input_error(
        "missing-density",
        &BASE.replace("density = 1380.0\n", ""),
        &["material.density", "missing"],
    );
    expect_input_error(
        "missing-step",
        &BASE.replace("time_step = 5.0e-5\n", ""),
        &["analysis.time_step", "missing"],
    );
    expect_input_error(
        "missing-force",
        &BASE.replace("acceleration = [0.0, -9.81, 0.0]\n", ""),
        &["loads[0].acceleration", "missing"],
    );
}

#[test]
fn bad_input_zero_or_negative_quantities() {
    for (from, to, key) in [
        ("length = 4.0", "length = 0.0", "cable.length"),
        ("length = 4.0", "length = -4.0", "cable.length"),
        ("elements = 8", "elements = 0", "cable.elements"),
        ("elements = 8", "elements = -3", "cable.elements"),
        (
            "youngs_modulus = 3.4e9",
            "youngs_modulus = -1.0",
            "material.youngs_modulus",
        ),
        ("density = 1380.0", "density = 0", "material.density"),
        ("area = 3.0e-6", "area = -3.0e-6", "material.area"),
        (
            "second_moment = 1.25e-13",
            "second_moment = 0.0",
            "material.second_moment",
        ),
        (
            "time_step = 5.0e-5",
            "time_step = 0.0",
            "analysis.time_step",
        ),
        (
            "time_step = 5.0e-5",
            "time_step = -1e-5",
            "analysis.time_step",
        ),
        (
            "duration = 2.0e-3",
            "duration = -2.0e-3",
            "analysis.duration",
        ),
    ] {
        expect_input_error(
            &format!("nonpositive-{key}-{to}"),
            &BASE.replace(from, to),
            &[key],
        );
    }
}

#[test]
fn bad_input_step_longer_than_duration() {
    expect_input_error(
        "step-longer",
        &BASE.replace("time_step = 5.0e-5", "time_step = 5.0e-3"),
        &["analysis.time_step", "longer than the duration"],
    );
}

#[test]
fn bad_input_non_finite_number() {
    expect_input_error(
        "nan",
        &BASE.replace("length = 4.0", "length = nan"),
        &["cable.length", "finite"],
    );
    expect_input_error(
        "inf",
        &BASE.replace("origin = [-2.0, 0.0, 0.0]", "origin = [-2.0, inf, 0.0]"),
        &["cable.origin", "finite"],
    );
    expect_input_error(
        "inf-velocity",
        &BASE.replace("velocity = [0.0, 10.0, 0.0]", "velocity = [0.0, -inf, 0.0]"),
        &["initial_velocity[0].velocity", "finite"],
    );
}

#[test]
fn bad_input_unknown_choices() {
    expect_input_error(
        "element",
        &BASE.replace("element = \"SAC-2\"", "element = \"SAC-4\""),
        &["cable.element", "SAC-4"],
    );
    expect_input_error(
        "strain",
        &BASE.replace(
            "quadrature = [3, 3]",
            "quadrature = [3, 3]\naxial_strain = \"log\"",
        ),
        &["analysis.axial_strain", "log"],
    );
    expect_input_error(
        "curvature",
        &BASE.replace(
            "quadrature = [3, 3]",
            "quadrature = [3, 3]\ncurvature = \"approx\"",
        ),
        &["analysis.curvature", "approx"],
    );
    expect_input_error(
        "load-type",
        &BASE.replace("type = \"gravity\"", "type = \"magnet\""),
        &["loads[0].type", "magnet"],
    );
}

#[test]
fn bad_input_node_index_out_of_range() {
    expect_input_error(
        "node-range",
        &BASE.replace("node = 8", "node = 9"),
        &["initial_velocity[1].node", "out of range"],
    );
    expect_input_error(
        "node-name",
        &BASE.replace("node = \"A\"", "node = \"C\""),
        &["initial_velocity[0].node", "\"C\""],
    );
    expect_input_error(
        "force-node",
        &BASE.replace(
            "[[initial_velocity]]\nnode = \"A\"",
            "[[loads]]\ntype = \"point-force\"\nnode = 12\nforce = [1.0, 0.0, 0.0]\n[[initial_velocity]]\nnode = \"A\"",
        ),
        &["loads[1].node", "out of range"],
    );
}

#[test]
fn bad_input_zero_direction_vector() {
    expect_input_error(
        "zero-dir",
        &BASE.replace("direction = [1.0, 0.0, 0.0]", "direction = [0.0, 0.0, 0.0]"),
        &["cable.direction", "zero vector"],
    );
}

#[test]
fn bad_input_vector_without_three_components() {
    expect_input_error(
        "two-comp",
        &BASE.replace("origin = [-2.0, 0.0, 0.0]", "origin = [-2.0, 0.0]"),
        &["cable.origin", "3 components"],
    );
    expect_input_error(
        "four-comp",
        &BASE.replace(
            "velocity = [0.0, 10.0, 0.0]",
            "velocity = [0.0, 10.0, 0.0, 1.0]",
        ),
        &["initial_velocity[0].velocity", "3 components"],
    );
}

#[test]
fn bad_input_quadrature_points() {
    expect_input_error(
        "zero-points",
        &BASE.replace("quadrature = [3, 3]", "quadrature = [0, 3]"),
        &["analysis.quadrature", "between 1 and 10"],
    );
    expect_input_error(
        "eleven-points",
        &BASE.replace("quadrature = [3, 3]", "quadrature = [3, 11]"),
        &["analysis.quadrature", "between 1 and 10"],
    );
    expect_input_error(
        "one-number",
        &BASE.replace("quadrature = [3, 3]", "quadrature = [3]"),
        &["analysis.quadrature"],
    );
}

#[test]
fn bad_input_zero_time_layers() {
    expect_input_error(
        "layers",
        &BASE.replace(
            "quadrature = [3, 3]",
            "quadrature = [3, 3]\ntime_layers = 0",
        ),
        &["analysis.time_layers", "between 1 and 16"],
    );
}

#[test]
fn unreadable_file_is_an_input_error() {
    let o = stancf(&["run", "/nonexistent/scenario.toml"]);
    let (_, se) = text(&o);
    assert_eq!(o.status.code(), Some(2));
    assert!(se.contains("/nonexistent/scenario.toml"), "{se}");
}

#[test]
fn bad_input_constraints() {
    let pin = |extra: &str| {
        BASE.replace(
            "[[loads]]\ntype = \"gravity\"",
            &format!("{extra}\n[[loads]]\ntype = \"gravity\""),
        )
        .replace(
            "[[initial_velocity]]\nnode = \"A\"\nvelocity = [0.0, 10.0, 0.0]\n",
            "",
        )
    };
    expect_input_error(
        "constraint-node",
        &pin("[[constraints]]\ntype = \"pinned\"\nnode = 11"),
        &["constraints[0].node", "out of range"],
    );
    expect_input_error(
        "constraint-type",
        &pin("[[constraints]]\ntype = \"welded\"\nnode = \"A\""),
        &["constraints[0].type", "welded"],
    );
    expect_input_error(
        "constraint-conflict",
        &pin("[[constraints]]\ntype = \"clamped\"\nnode = \"A\"\n[[constraints]]\ntype = \"pinned\"\nnode = 0"),
        &["constraints[1]", "conflicts with constraints[0]", "node 0"],
    );
    expect_input_error(
        "constraint-unknown-key",
        &pin("[[constraints]]\ntype = \"pinned\"\nnode = \"A\"\nstiffness = 3"),
        &["constraints[0]", "stiffness"],
    );
    expect_input_error(
        "fix-curvature-sac2",
        &pin("[[constraints]]\ntype = \"clamped\"\nnode = \"A\"\nfix_curvature = true"),
        &["constraints[0].fix_curvature", "SAC-3"],
    );
    // An initial velocity on a pinned node contradicts the pin.
    expect_input_error(
        "velocity-vs-pin",
        &pin("[[constraints]]\ntype = \"pinned\"\nnode = \"B\""),
        &["initial_velocity[0].velocity", "pinned"],
    );
}

#[test]
fn bad_input_static_without_constraints_against_rigid_motions() {
    let statik = BASE
        .replace("type = \"dynamic\"", "type = \"static\"")
        .replace(
            "[[initial_velocity]]\nnode = \"A\"\nvelocity = [0.0, 10.0, 0.0]\n[[initial_velocity]]\nnode = 8\nvelocity = [0.0, -10.0, 0.0]\n",
            "",
        );
    expect_input_error("static-free", &statik, &["constraints", "rigid motions"]);
    let one_pin = statik.replace(
        "[[loads]]\ntype = \"gravity\"",
        "[[constraints]]\ntype = \"pinned\"\nnode = 4\n[[loads]]\ntype = \"gravity\"",
    );
    expect_input_error(
        "static-one-pin",
        &one_pin,
        &["constraints", "rigid motions"],
    );
}

#[test]
fn bad_input_drag() {
    let drag = |extra: &str| {
        BASE.replace(
            "[[loads]]\ntype = \"gravity\"",
            &format!("[[loads]]\ntype = \"air-drag\"\n{extra}\n[[loads]]\ntype = \"gravity\""),
        )
    };
    expect_input_error(
        "drag-model",
        &drag("drag_coefficient = 1.0\nfluid_density = 1.2\nmodel = \"turbulent\""),
        &["loads[0].model", "turbulent"],
    );
    expect_input_error(
        "drag-negative",
        &drag("drag_coefficient = -1.0\nfluid_density = 1.2"),
        &["loads[0].drag_coefficient", ">= 0"],
    );
    expect_input_error(
        "drag-missing",
        &drag("fluid_density = 1.2"),
        &["loads[0].drag_coefficient", "missing"],
    );
    expect_input_error(
        "drag-tangential-full",
        &drag("drag_coefficient = 1.0\nfluid_density = 1.2\ntangential_coefficient = 0.1"),
        &["loads[0].tangential_coefficient", "normal"],
    );
    expect_input_error(
        "solver",
        &BASE.replace(
            "quadrature = [3, 3]",
            "quadrature = [3, 3]\nsolver = \"secant\"",
        ),
        &["analysis.solver", "secant"],
    );
}
