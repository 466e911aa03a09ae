//! The sweep's grid, keys, cells and table.
use super::*;

#[test]
fn sets_parse_with_arrays_and_words() {
    let a = parse_set("analysis.time_step=1e-4,5e-5").unwrap();
    assert_eq!(a.key, "analysis.time_step");
    assert_eq!(
        a.values,
        vec![toml::Value::Float(1e-4), toml::Value::Float(5e-5)]
    );
    let a = parse_set("loads.0.acceleration=[0,-9.81,0],[0,-1.62,0]").unwrap();
    assert_eq!(a.values.len(), 2);
    assert!(matches!(&a.values[0], toml::Value::Array(v) if v.len() == 3));
    let a = parse_set("analysis.solver=newton,broyden").unwrap();
    assert_eq!(a.values[1], toml::Value::String("broyden".into()));
    let a = parse_set(r#"title="a, b","say \"hi, you\"",'c:\d, e'"#).unwrap();
    let strings: Vec<&str> = a.values.iter().map(|v| v.as_str().unwrap()).collect();
    assert_eq!(strings, ["a, b", "say \"hi, you\"", "c:\\d, e"]);
    let a = parse_set("title=don't,x").unwrap();
    assert_eq!(a.values.len(), 2);
    assert_eq!(a.values[0].as_str(), Some("don't"));
    assert!(parse_set("analysis.time_step").is_err());
    assert!(parse_set("a..b=1").is_err());
}

#[test]
fn apply_reaches_tables_and_list_entries() {
    let mut doc: toml::Table =
        "[analysis]\ntime_step = 1.0\n[[loads]]\ntype = \"gravity\"\n[[loads]]\ntype = \"air-drag\"\ndrag_coefficient = 1.0\n"
            .parse()
            .unwrap();
    apply(&mut doc, "analysis.time_step", toml::Value::Float(0.5)).unwrap();
    apply(&mut doc, "analysis.tolerance", toml::Value::Float(1e-9)).unwrap();
    apply(
        &mut doc,
        "loads.1.drag_coefficient",
        toml::Value::Float(1.5),
    )
    .unwrap();
    assert_eq!(doc["analysis"]["time_step"].as_float(), Some(0.5));
    assert_eq!(doc["analysis"]["tolerance"].as_float(), Some(1e-9));
    assert_eq!(doc["loads"][1]["drag_coefficient"].as_float(), Some(1.5));
    assert!(apply(
        &mut doc,
        "loads.2.drag_coefficient",
        toml::Value::Float(1.0)
    )
    .unwrap_err()
    .contains("no index 2"));
    assert!(apply(&mut doc, "analysis.time_step.x", toml::Value::Float(1.0)).is_err());
}

#[test]
fn grid_is_the_cartesian_product_first_axis_slowest() {
    let axes = [parse_set("a=1,2").unwrap(), parse_set("b=3,4,5").unwrap()];
    assert_eq!(grid_size(&[2, 3]), Ok(6));
    let int = |i| toml::Value::Integer(i);
    let g: Vec<Vec<toml::Value>> = (0..6)
        .map(|k| point(&axes, k).into_iter().cloned().collect())
        .collect();
    assert_eq!(g[0], vec![int(1), int(3)]);
    assert_eq!(g[1], vec![int(1), int(4)]);
    assert_eq!(g[3], vec![int(2), int(3)]);
    assert_eq!(g[5], vec![int(2), int(5)]);
}

#[test]
fn a_grid_above_the_limit_is_refused_from_its_list_lengths() {
    assert_eq!(grid_size(&[100, 100]), Ok(MAX_POINTS));
    let e = grid_size(&[100, 100, 2]).unwrap_err();
    assert!(e.contains("20000 points (100 x 100 x 2)"), "{e}");
    assert!(e.contains("limit of 10000"), "{e}");
    // A product past usize does not wrap around to a small number.
    let e = grid_size(&[usize::MAX, 2]).unwrap_err();
    assert!(e.contains("more than 18446744073709551615 points"), "{e}");
}

#[test]
fn keys_given_twice_or_inside_one_another_are_refused() {
    assert!(check_keys(&["analysis.time_step", "loads.0.drag_coefficient"]).is_ok());
    assert!(check_keys(&["loads.1", "loads.10"]).is_ok());
    let e = check_keys(&["a.b", "c", "a.b"]).unwrap_err();
    assert!(e.contains("the key a.b is given twice"), "{e}");
    let e = check_keys(&["loads.0.acceleration", "loads.0"]).unwrap_err();
    assert!(
        e.contains("the keys loads.0 and loads.0.acceleration overlap"),
        "{e}"
    );
}

#[test]
fn a_list_index_has_one_spelling() {
    let mut doc: toml::Table = "[[loads]]\ntype = \"gravity\"\n".parse().unwrap();
    for bad in ["loads.00.type", "loads.+0.type", "loads.0x0.type"] {
        let e = apply(&mut doc, bad, toml::Value::String("x".into())).unwrap_err();
        assert!(e.contains("is not an index"), "{bad}: {e}");
    }
    apply(&mut doc, "loads.0.type", toml::Value::String("x".into())).unwrap();
}

#[test]
fn csv_fields_are_quoted_only_when_needed() {
    assert_eq!(csv_field("5e-5"), "5e-5");
    assert_eq!(csv_field("[0, -10, 0]"), "\"[0, -10, 0]\"");
    assert_eq!(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    assert_eq!(csv_field("two\nlines"), "\"two\nlines\"");
}
