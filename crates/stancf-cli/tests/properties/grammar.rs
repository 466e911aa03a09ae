//! (a) Random scenarios from a grammar of the real keys: every section
//! and key of a scenario file, each sane or, at a random level of chaos,
//! missing or given an extreme or wrongly typed value.

use crate::bound::bound_work;
use proptest::prelude::*;
use proptest::sample::select;

/// Values of every kind that a key should not get, or only at its limits.
const WEIRD: &[&str] = &[
    "0",
    "-1",
    "0.0",
    "-0.0",
    "1",
    "2.5",
    "-2.5",
    "1e-300",
    "-1e-300",
    "1e300",
    "-1e300",
    "5e-324",
    "1.7976931348623157e308",
    "inf",
    "-inf",
    "nan",
    "9223372036854775807",
    "-9223372036854775808",
    "4294967296",
    "1000001",
    "17",
    "11",
    "\"\"",
    "\"A\"",
    "\"B\"",
    "\"all\"",
    "\"1e-3\"",
    "\"SAC-4\"",
    "\"dynamic\"",
    "\"gravity\"",
    "\"clamped\"",
    "\"a,b\\\"c\\nd\"",
    "true",
    "false",
    "[]",
    "[0]",
    "[0, 0]",
    "[0, 0, 0]",
    "[1, 2, 3, 4]",
    "[\"x\", 0, 0]",
    "[nan, 0, 0]",
    "[0, inf, 0]",
    "[1e300, 1e300, 1e300]",
    "[1e-300, 0, 0]",
    "[0, 0, -1e300]",
    "[[1, 2, 3]]",
    "[1, \"2\", 3]",
    "{}",
    "{ x = 1 }",
    "1979-05-27T07:32:00Z",
    "07:32:00",
    "0x10",
    "0o7",
    "0b1",
    "[2, 3]",
    "[10, 10, 10]",
    "[0, 11]",
    "[3, 0]",
    "[3, 3, 3, 3]",
    "[-1, 3]",
];

pub fn weird() -> BoxedStrategy<String> {
    select(WEIRD).prop_map(String::from).boxed()
}

pub fn f64_literal(v: f64) -> String {
    if v.is_nan() {
        "nan".into()
    } else if v.is_infinite() {
        if v > 0.0 {
            "inf".into()
        } else {
            "-inf".into()
        }
    } else {
        format!("{v:e}")
    }
}

/// Any number, from the whole range of i64 and f64.
pub fn wide_number() -> BoxedStrategy<String> {
    prop_oneof![
        any::<i64>().prop_map(|i| i.to_string()),
        any::<f64>().prop_map(f64_literal),
        (-330i32..330).prop_map(|e| format!("1e{e}")),
        (-330i32..330).prop_map(|e| format!("-1e{e}")),
    ]
    .boxed()
}

fn pick(values: &'static [&'static str]) -> BoxedStrategy<String> {
    select(values).prop_map(String::from).boxed()
}

fn sane_vector(components: &'static [&'static str]) -> BoxedStrategy<String> {
    prop::array::uniform3(select(components))
        .prop_map(|[a, b, c]| format!("[{a}, {b}, {c}]"))
        .boxed()
}

const SMALL: &[&str] = &[
    "0.0", "0.0", "0.0", "1.0", "-1.0", "0.5", "-9.81", "10.0", "-10.0", "2",
];

/// How values are drawn at a given level of chaos `p` (the chance that a
/// key is missing or gets a value from `WEIRD` or `wide_number`).
#[derive(Clone, Copy, Debug)]
struct Gen {
    p: f64,
}

type Kv = (String, Option<String>);

impl Gen {
    fn weights(self) -> (u32, u32) {
        let bad = (self.p * 10_000.0).round().max(1.0) as u32;
        (10_000 - bad.min(9_000), bad)
    }

    /// A key that a valid scenario has (or that has a default).
    fn key(self, key: &str, sane: BoxedStrategy<String>) -> BoxedStrategy<Kv> {
        let (good, bad) = self.weights();
        let key = key.to_string();
        prop_oneof![
            good => sane.prop_map(Some),
            bad.div_ceil(3) => Just(None),
            bad.div_ceil(3) => weird().prop_map(Some),
            bad.div_ceil(3) => wide_number().prop_map(Some),
        ]
        .prop_map(move |v| (key.clone(), v))
        .boxed()
    }

    /// An optional key: present in about `present` of the cases.
    fn optional(self, key: &str, present: f64, sane: BoxedStrategy<String>) -> BoxedStrategy<Kv> {
        let key_s = key.to_string();
        let w = (present * 100.0).round() as u32;
        prop_oneof![
            100 - w => Just((key_s, None)),
            w.max(1) => self.key(key, sane),
        ]
        .boxed()
    }

    /// Now and then an unknown key (a typo).
    fn stray(self) -> BoxedStrategy<Vec<Kv>> {
        let (good, bad) = self.weights();
        prop_oneof![
            good => Just(Vec::new()),
            bad => (select(&["lenght", "Type", "node ", "velocity_", "elements2", "x"][..]), weird())
                .prop_map(|(k, v)| vec![(format!("{k:?}"), Some(v))]),
        ]
        .boxed()
    }
}

fn render_table(header: &str, keys: &[Kv], out: &mut String) {
    out.push_str(header);
    out.push('\n');
    for (k, v) in keys {
        if let Some(v) = v {
            out.push_str(&format!("{k} = {v}\n"));
        }
    }
    out.push('\n');
}

fn node(with_all: bool) -> BoxedStrategy<String> {
    if with_all {
        pick(&["\"A\"", "\"B\"", "0", "1", "2", "\"all\"", "\"all\""])
    } else {
        pick(&[
            "\"A\"", "\"B\"", "\"A\"", "\"B\"", "\"A\"", "\"B\"", "0", "1", "2",
        ])
    }
}

fn constraint(g: Gen) -> BoxedStrategy<Vec<Kv>> {
    let (good, bad) = g.weights();
    let kind = prop_oneof![
        good => pick(&["\"clamped\"", "\"pinned\"", "\"prescribed\""]),
        bad => weird(),
    ];
    (
        kind,
        g.key("node", node(false)),
        g.optional("fix_curvature", 0.1, pick(&["true", "false"])),
        g.optional("velocity", 0.3, sane_vector(SMALL)),
        g.optional("amplitude", 0.3, sane_vector(&["0.0", "0.01", "-0.02"])),
        g.optional("frequency", 0.3, pick(&["0.0", "2.0", "50.0"])),
        g.optional("phase", 0.2, pick(&["0.0", "1.5707963267948966"])),
        g.stray(),
    )
        .prop_map(|(kind, n, fc, v, a, f, ph, stray)| {
            let mut kv = vec![("type".to_string(), Some(kind.clone())), n];
            match kind.as_str() {
                "\"clamped\"" => kv.push(fc),
                "\"prescribed\"" => kv.extend([v, a, f, ph]),
                "\"pinned\"" => {}
                _ => kv.extend([fc, v]),
            }
            kv.extend(stray);
            kv
        })
        .boxed()
}

fn load(g: Gen) -> BoxedStrategy<Vec<Kv>> {
    let (good, bad) = g.weights();
    let kind = prop_oneof![
        good => pick(&["\"gravity\"", "\"point-force\"", "\"end-moment\"", "\"air-drag\""]),
        bad => weird(),
    ];
    (
        kind,
        g.key("acceleration", sane_vector(&["0.0", "0.0", "-9.81", "1.0"])),
        g.key("node", node(false)),
        g.key("force", sane_vector(&["0.0", "-1.0", "0.5", "100.0"])),
        g.key("moment", sane_vector(&["0.0", "0.0", "1e-4", "-4.25e-4"])),
        (
            g.key("drag_coefficient", pick(&["1.5", "0.0", "1.2"])),
            g.key("fluid_density", pick(&["1.225", "0.0", "1000.0"])),
            g.optional("diameter", 0.3, pick(&["3.7e-3", "1e-2"])),
            g.optional("fluid_velocity", 0.3, sane_vector(&["0.0", "1.0", "-5.0"])),
            g.optional("model", 0.4, pick(&["\"full\"", "\"normal\""])),
            g.optional("tangential_coefficient", 0.2, pick(&["0.0", "0.1"])),
        ),
        g.stray(),
    )
        .prop_map(|(kind, acc, n, f, m, (c, rho, d, u, model, ct), stray)| {
            let mut kv = vec![("type".to_string(), Some(kind.clone()))];
            match kind.as_str() {
                "\"gravity\"" => kv.push(acc),
                "\"point-force\"" => kv.extend([n, f]),
                "\"end-moment\"" => kv.extend([n, m]),
                "\"air-drag\"" => kv.extend([c, rho, d, u, model, ct]),
                _ => kv.extend([acc, n]),
            }
            kv.extend(stray);
            kv
        })
        .boxed()
}

fn initial_velocity(g: Gen) -> BoxedStrategy<Vec<Kv>> {
    (
        g.key("node", node(true)),
        g.optional("velocity", 0.9, sane_vector(SMALL)),
        g.optional(
            "angular_velocity",
            0.3,
            sane_vector(&["0.0", "0.0", "1.0", "-3.0"]),
        ),
        g.optional("center", 0.2, sane_vector(&["0.0", "0.5", "-2.0"])),
        g.stray(),
        prop::bool::weighted(g.p),
    )
        .prop_map(|(n, v, w, c, stray, wild)| {
            // A rotation only with node = "all", unless chaos says otherwise.
            let all = n.1.as_deref() == Some("\"all\"");
            let mut kv = if all || wild {
                vec![n, v, w, c]
            } else {
                vec![n, v]
            };
            kv.extend(stray);
            kv
        })
        .boxed()
}

fn analysis(g: Gen) -> BoxedStrategy<Vec<Kv>> {
    // A valid duration is a few steps; time_step and duration may still
    // each be replaced by anything.
    let steps = (select(&[1e-5, 5e-5, 1e-4, 1e-3, 1e-2][..]), 1u32..=10);
    (
        g.optional(
            "type",
            0.7,
            pick(&["\"dynamic\"", "\"dynamic\"", "\"dynamic\"", "\"static\""]),
        ),
        steps.prop_flat_map(move |(dt, k)| {
            (
                g.key("time_step", Just(f64_literal(dt)).boxed()),
                g.key("duration", Just(f64_literal(dt * k as f64)).boxed()),
            )
        }),
        (
            g.optional("time_layers", 0.2, pick(&["1", "2", "3"])),
            g.optional(
                "quadrature",
                0.3,
                pick(&[
                    "[3, 3]",
                    "[5, 3]",
                    "[2, 2]",
                    "[1, 1]",
                    "[5, 4, 3]",
                    "[10, 10]",
                    "[3, 10, 1]",
                ]),
            ),
            g.optional(
                "solver",
                0.3,
                pick(&["\"newton\"", "\"broyden\"", "\"modified-newton\""]),
            ),
            g.optional("time_scheme", 0.3, pick(&["\"p2\"", "\"galerkin\""])),
            g.optional("tolerance", 0.3, pick(&["1e-10", "1e-8", "1e-6", "1e-14"])),
            g.optional("max_iterations", 0.3, pick(&["50", "1", "3", "200"])),
            g.optional("load_steps", 0.3, pick(&["1", "2", "5"])),
        ),
        (
            g.optional("curvature", 0.2, pick(&["\"paper\"", "\"exact\""])),
            g.optional("axial_strain", 0.2, pick(&["\"green\"", "\"engineering\""])),
            g.optional(
                "constraint_method",
                0.3,
                pick(&["\"multiplier\"", "\"elimination\""]),
            ),
            g.optional("planar_reduction", 0.3, pick(&["true", "false"])),
        ),
        g.stray(),
    )
        .prop_map(
            |(kind, (dt, t), (l, q, s, ts, tol, it, ls), (c, ax, cm, pr), stray)| {
                let mut kv = vec![kind, dt, t, l, q, s, ts, tol, it, ls, c, ax, cm, pr];
                kv.extend(stray);
                kv
            },
        )
        .boxed()
}

/// Whether a section is there: in about `present` of the cases with no
/// chaos, less often with more.
fn section(g: Gen, present: f64) -> BoxedStrategy<bool> {
    let present = (present * (1.0 - g.p)).clamp(0.0, 1.0);
    prop::bool::weighted(present).boxed()
}

fn scenario_with(g: Gen) -> BoxedStrategy<String> {
    let title = g.optional(
        "title",
        0.5,
        select(
            &[
                "plain",
                "with, a comma",
                "quote \" and \\ backslash",
                "é ü 中",
                "",
                "line\nbreak",
            ][..],
        )
        .prop_map(|s| toml::Value::String(s.to_string()).to_string())
        .boxed(),
    );
    let cable = (
        g.key("length", pick(&["0.5", "1.0", "4.0", "2"])),
        g.key("elements", pick(&["1", "2", "3", "4"])),
        g.optional("element", 0.6, pick(&["\"SAC-2\"", "\"SAC-3\""])),
        g.optional("origin", 0.4, sane_vector(&["0.0", "-2.0", "1.5"])),
        g.optional(
            "direction",
            0.4,
            pick(&[
                "[1.0, 0.0, 0.0]",
                "[0.0, 1.0, 0.0]",
                "[0.0, 0.0, 1.0]",
                "[1.0, 1.0, 0.0]",
                "[0.6, 0.0, 0.8]",
            ]),
        ),
        g.optional(
            "grading",
            0.3,
            pick(&[
                "{ toward = \"A\", ratio = 2.0 }",
                "{ toward = \"B\", ratio = 1.0 }",
                "{ toward = \"both\", ratio = 4.0 }",
                "{ toward = \"B\", ratio = 0.5 }",
            ]),
        ),
        g.stray(),
    )
        .prop_map(|(a, b, c, d, e, f, stray)| {
            let mut kv = vec![a, b, c, d, e, f];
            kv.extend(stray);
            kv
        });
    let material = (
        g.key("youngs_modulus", pick(&["3.4e9", "0.91e6", "2.1e11"])),
        g.key("density", pick(&["1380.0", "1202.0", "7850"])),
        g.key("area", pick(&["3.0e-6", "1.075e-5", "1e-4"])),
        g.key("second_moment", pick(&["1.25e-13", "9.15e-12", "1e-9"])),
        g.optional("diameter", 0.3, pick(&["1.95e-3", "3.7e-3"])),
        g.stray(),
    )
        .prop_map(|(a, b, c, d, e, stray)| {
            let mut kv = vec![a, b, c, d, e];
            kv.extend(stray);
            kv
        });
    (
        title,
        (section(g, 0.98), cable),
        (section(g, 0.98), material),
        prop::collection::vec(constraint(g), 0..=2),
        prop::collection::vec(load(g), 0..=3),
        prop::collection::vec(initial_velocity(g), 0..=2),
        (section(g, 0.95), analysis(g)),
        (
            section(g, 0.5),
            g.key("every", pick(&["1", "2", "3", "100"])),
            g.stray(),
        ),
        g.stray(),
    )
        .prop_map(
            move |(
                title,
                (has_cable, cable),
                (has_mat, mat),
                cons,
                loads,
                ivs,
                (has_an, an),
                (has_out, every, ostray),
                top,
            )| {
                let mut s = String::new();
                for (k, v) in [title].iter().chain(&top) {
                    if let Some(v) = v {
                        s.push_str(&format!("{k} = {v}\n"));
                    }
                }
                s.push('\n');
                if has_cable {
                    render_table("[cable]", &cable, &mut s);
                }
                if has_mat {
                    render_table("[material]", &mat, &mut s);
                }
                for c in &cons {
                    render_table("[[constraints]]", c, &mut s);
                }
                for l in &loads {
                    render_table("[[loads]]", l, &mut s);
                }
                for iv in &ivs {
                    render_table("[[initial_velocity]]", iv, &mut s);
                }
                if has_an {
                    render_table("[analysis]", &an, &mut s);
                }
                if has_out {
                    let mut kv = vec![every];
                    kv.extend(ostray);
                    render_table("[output]", &kv, &mut s);
                }
                s
            },
        )
        .prop_map(bound_work)
        .boxed()
}

/// Random scenarios at a random level of chaos: a third of them with every
/// key sane (these reach the solver), the others with some keys missing or
/// given extreme or wrongly typed values.
pub fn random_scenario() -> BoxedStrategy<String> {
    select(&[0.0, 0.0, 0.0, 0.0, 0.01, 0.03, 0.1, 0.3][..])
        .prop_flat_map(|p| scenario_with(Gen { p }))
        .boxed()
}
