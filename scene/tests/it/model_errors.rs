//! One test per class of model-file error: each names the exact `file:line:column` and what
//! was expected. The base model is a small rimless-wheel-like walker written here so that the
//! line numbers below can be read off it.

use walker_scene::model::{Model, ModelError, ModelErrorKind};

/// The base model; line numbers are in the comments of the tests.
const MINI: &str = r#"format = 1
name = "mini"

[[coordinate]]
name = "x"
unit = "m"
doc = "foot x"
[[coordinate]]
name = "z"
unit = "m"
doc = "foot z"
[[coordinate]]
name = "th"
unit = "rad"
doc = "leg"

[[parameter]]
name = "m"
unit = "kg"
doc = "mass"
range = "(0, inf)"
default = 1.0
[[parameter]]
name = "l"
unit = "m"
doc = "length"
range = "(0, inf)"
default = 1.0
[[parameter]]
name = "g"
unit = "m/s^2"
doc = "gravity"
range = "(0, inf)"
default = 9.81
[[parameter]]
name = "alpha"
unit = "rad"
doc = "spoke angle"
range = "(0, pi)"
default = 0.5
[[parameter]]
name = "mu0"
unit = "-"
doc = "friction"
range = "[0, inf)"
default = 0.4

[floor]
gravity = "g"

[[body]]
name = "hip"
mass = "m"
com = ["x + l*sin(th)", "z + l*cos(th)"]

[[point]]
name = "foot"
at = ["x + l*sin(th) - l*sin(th - alpha)", "z + l*cos(th) - l*cos(th - alpha)"]

[stance]
friction = ["none", "coulomb"]
mu0 = "mu0"

[strike]
point = "foot"
guard = "alpha/2 - th"

[relabel]
th = "th - alpha"
"#;

/// Lines 70-84, appended to [`MINI`]: one input under output-following control.
const CONTROLLED: &str = r#"
[[input]]
name = "u"
doc = "torque"
force = ["0", "0", "1"]

[control]
kp = "m"
kd = "m"

[[output]]
name = "y"
h = "th"
desired = { shape = "hold", value = "alpha/2" }
"#;

/// `MINI` with `from` replaced by `to` (exactly once), loaded.
fn load_with(base: &str, from: &str, to: &str) -> Result<Model, ModelError> {
    assert_eq!(base.matches(from).count(), 1, "`{from}` must occur once");
    Model::from_toml(&base.replacen(from, to, 1), "mini.toml")
}

/// Asserts an error of `kind` at `line:column` whose message contains `fragment`.
fn assert_error(result: Result<Model, ModelError>, kind: ModelErrorKind, at: &str, fragment: &str) {
    assert!(result.is_err(), "expected an error at {at}: {fragment}");
    let Err(err) = result else { return };
    let text = err.to_string();
    assert!(
        text.starts_with(&format!("mini.toml:{at}: ")),
        "wrong location: {text} (expected {at})"
    );
    assert!(text.contains(fragment), "`{text}` lacks `{fragment}`");
    assert_eq!(err.kind(), Some(kind), "{text}");
}

#[test]
fn the_base_models_load() -> Result<(), ModelError> {
    Model::from_toml(MINI, "mini.toml")?;
    let m = Model::from_toml(&format!("{MINI}{CONTROLLED}"), "mini.toml")?;
    assert_eq!(m.outputs[0].aux.name, "v_y");
    Ok(())
}

#[test]
fn a_toml_syntax_error_names_its_line() {
    // Line 2: the string is not closed.
    let r = load_with(MINI, "name = \"mini\"", "name = \"mini");
    assert_error(r, ModelErrorKind::Toml, "2:13", "");
}

#[test]
fn an_unknown_field_is_an_error_at_its_key() {
    let r = load_with(MINI, "mass = \"m\"", "masss = \"m\"");
    assert_error(r, ModelErrorKind::Toml, "53:1", "unknown field `masss`");
}

#[test]
fn a_missing_field_is_an_error_at_its_table() {
    let r = load_with(MINI, "mass = \"m\"\n", "");
    assert_error(r, ModelErrorKind::Toml, "51:1", "missing field `mass`");
}

#[test]
fn a_value_of_the_wrong_type_is_an_error_at_the_value() {
    let r = load_with(MINI, "default = 9.81", "default = \"9.81\"");
    assert_error(r, ModelErrorKind::Toml, "34:11", "invalid type");
}

#[test]
fn a_format_other_than_one_is_refused() {
    let r = load_with(MINI, "format = 1", "format = 2");
    assert_error(r, ModelErrorKind::Format, "1:10", "expected 1");
}

#[test]
fn a_name_declared_twice_is_an_error_at_the_second() {
    let r = load_with(MINI, "name = \"l\"", "name = \"m\"");
    assert_error(
        r,
        ModelErrorKind::Duplicate,
        "24:8",
        "`m` is declared twice",
    );
}

/// `MINI` with one more parameter called `name`, declared after `m` (from line 23).
fn with_parameter(name: &str) -> Result<Model, ModelError> {
    let extra = format!(
        "[[parameter]]\nname = \"{name}\"\nunit = \"kg\"\ndoc = \"another mass\"\nrange = \"(0, inf)\"\ndefault = 1.0\n[[parameter]]\nname = \"l\""
    );
    load_with(MINI, "[[parameter]]\nname = \"l\"", &extra)
}

#[test]
fn parameters_that_differ_only_in_case_get_fields_of_their_own() -> Result<(), ModelError> {
    // `M` beside `m`: the fields are `mm` and `m` (docs/model-format.md, "Names").
    let model = with_parameter("M")?;
    let names: Vec<&str> = model
        .parameters
        .iter()
        .map(|p| p.name.name.as_str())
        .collect();
    assert_eq!(
        walker_scene::model::fields::param_fields(&names)[..2],
        ["m".to_owned(), "mm".to_owned()]
    );
    Ok(())
}

#[test]
fn parameters_whose_fields_would_really_collide_are_an_error_at_the_later() {
    // `m_hh` is the field of `m_hh` and, beside `m_h`, of `m_H`.
    let text = MINI.replacen(
        "[[parameter]]\nname = \"l\"",
        "[[parameter]]\nname = \"m_hh\"\nunit = \"kg\"\ndoc = \"a\"\nrange = \"(0, inf)\"\ndefault = 1.0\n\
         [[parameter]]\nname = \"m_h\"\nunit = \"kg\"\ndoc = \"b\"\nrange = \"(0, inf)\"\ndefault = 1.0\n\
         [[parameter]]\nname = \"m_H\"\nunit = \"kg\"\ndoc = \"c\"\nrange = \"(0, inf)\"\ndefault = 1.0\n\
         [[parameter]]\nname = \"l\"",
        1,
    );
    let r = Model::from_toml(&text, "mini.toml");
    assert_error(
        r,
        ModelErrorKind::Duplicate,
        "36:8",
        "`m_hh` and `m_H` would both be the field `m_hh`",
    );
}

#[test]
fn a_start_value_must_name_a_coordinate_or_velocity_and_use_parameters_only() {
    let r = load_with(MINI, "[stance]", "[start]\nfoo = \"1\"\n\n[stance]");
    assert_error(
        r,
        ModelErrorKind::UnknownReference,
        "61:1",
        "expected a coordinate or a velocity",
    );
    let r = load_with(MINI, "[stance]", "[start]\nthd = \"th\"\n\n[stance]");
    assert_error(r, ModelErrorKind::SymbolNotAllowed, "61:8", "start `thd`");
    let r = load_with(
        MINI,
        "[stance]",
        "[start]\nth = \"-l\"\nthd = \"2*l\"\n\n[stance]",
    );
    let model = r.expect("a start in parameters loads");
    assert_eq!(model.start.len(), 2);
    assert!(
        !model.start[0].velocity && model.start[1].velocity,
        "coordinates first"
    );
}

#[test]
fn two_points_of_one_name_are_an_error() {
    let r = load_with(
        MINI,
        "[stance]",
        "[[point]]\nname = \"foot\"\nat = [\"x\", \"z\"]\n\n[stance]",
    );
    assert_error(
        r,
        ModelErrorKind::Duplicate,
        "61:8",
        "point `foot` is declared twice",
    );
}

#[test]
fn a_reserved_name_cannot_be_declared() {
    for (name, fragment) in [
        ("mu", "`mu` is reserved"),
        ("t", "`t` is reserved"),
        ("sin", "`sin` is reserved"),
        (
            "thd",
            "`thd` is reserved: it is the velocity of coordinate `th`",
        ),
        (
            "xdd",
            "`xdd` is reserved: it is the acceleration of coordinate `x`",
        ),
    ] {
        let r = load_with(MINI, "name = \"l\"", &format!("name = \"{name}\""));
        assert_error(r, ModelErrorKind::Reserved, "24:8", fragment);
    }
}

#[test]
fn a_coordinate_named_like_another_ones_velocity_is_reserved() {
    let r = load_with(MINI, "name = \"th\"", "name = \"xd\"");
    assert_error(
        r,
        ModelErrorKind::Reserved,
        "13:8",
        "velocity or acceleration of coordinate `x`",
    );
}

#[test]
fn an_expression_syntax_error_points_inside_the_string() {
    // `mass = "m*"`: the string's text starts at column 9; the end is column 11.
    let r = load_with(MINI, "mass = \"m\"", "mass = \"m*\"");
    assert_error(
        r,
        ModelErrorKind::Syntax,
        "53:11",
        "expected an expression after `*`",
    );
}

#[test]
fn an_unknown_function_is_named() {
    let r = load_with(MINI, "\"x + l*sin(th)\"", "\"x + l*tan(th)\"");
    assert_error(
        r,
        ModelErrorKind::Syntax,
        "54:15",
        "unknown function `tan`: only sin and cos",
    );
}

#[test]
fn an_exponent_must_be_an_integer_literal() {
    let r = load_with(MINI, "mass = \"m\"", "mass = \"m^1.5\"");
    assert_error(
        r,
        ModelErrorKind::Syntax,
        "53:11",
        "exponent must be an integer literal",
    );
}

#[test]
fn an_unknown_symbol_is_an_error_at_its_column() {
    let r = load_with(MINI, "\"x + l*sin(th)\"", "\"x + L*sin(th)\"");
    assert_error(
        r,
        ModelErrorKind::UnknownSymbol,
        "54:13",
        "unknown symbol `L`",
    );
}

#[test]
fn a_velocity_in_a_mass_is_not_allowed() {
    let r = load_with(MINI, "mass = \"m\"", "mass = \"m + thd\"");
    assert_error(
        r,
        ModelErrorKind::SymbolNotAllowed,
        "53:13",
        "`thd` is a velocity",
    );
}

#[test]
fn an_error_in_a_string_with_escapes_points_at_its_opening_quote() {
    let r = load_with(MINI, "mass = \"m\"", "mass = \"\\u006d + q\"");
    assert_error(
        r,
        ModelErrorKind::UnknownSymbol,
        "53:8",
        "unknown symbol `q`",
    );
}

#[test]
fn sin_of_a_length_is_not_an_angle_combination() {
    let r = load_with(MINI, "\"x + l*sin(th)\"", "\"x + l*sin(l)\"");
    assert_error(
        r,
        ModelErrorKind::NotAnAngleCombination,
        "54:19",
        "`sin` of something that is not an angle combination: `l` is not an angle",
    );
}

#[test]
fn cos_of_a_product_of_angles_is_not_an_angle_combination() {
    let r = load_with(MINI, "\"z + l*cos(th)\"", "\"z + l*cos(th*alpha)\"");
    assert_error(
        r,
        ModelErrorKind::NotAnAngleCombination,
        "54:36",
        "`th * alpha` is not linear",
    );
}

#[test]
fn sin_with_a_constant_term_is_not_an_angle_combination() {
    let r = load_with(MINI, "\"x + l*sin(th)\"", "\"x + l*sin(th + 1)\"");
    assert_error(
        r,
        ModelErrorKind::NotAnAngleCombination,
        "54:19",
        "constant term `1`",
    );
}

#[test]
fn an_angle_outside_sin_and_cos_in_a_position_is_used_as_a_length() {
    let r = load_with(MINI, "\"x + l*sin(th)\"", "\"x + th\"");
    assert_error(
        r,
        ModelErrorKind::AngleAsLength,
        "54:13",
        "an angle used as a length: `th`",
    );
}

#[test]
fn an_angle_parameter_in_a_point_is_used_as_a_length() {
    let r = load_with(MINI, "at = [\"x + l*sin(th)", "at = [\"x + alpha*sin(th)");
    assert_error(
        r,
        ModelErrorKind::AngleAsLength,
        "58:12",
        "`alpha` is an angle",
    );
}

#[test]
fn division_by_a_zero_constant_is_an_error() {
    let r = load_with(MINI, "mass = \"m\"", "mass = \"m/(1 - 1)\"");
    assert_error(
        r,
        ModelErrorKind::DivisionByZero,
        "53:11",
        "division by zero",
    );
}

#[test]
fn an_empty_range_is_an_error_at_the_range() {
    let r = load_with(MINI, "range = \"(0, pi)\"", "range = \"(pi, 0)\"");
    assert_error(
        r,
        ModelErrorKind::Range,
        "39:9",
        "the interval (pi, 0) is empty",
    );
}

#[test]
fn a_half_open_point_range_is_empty() {
    let r = load_with(MINI, "range = \"(0, pi)\"", "range = \"[1, 1)\"");
    assert_error(r, ModelErrorKind::Range, "39:9", "is empty");
}

#[test]
fn a_default_outside_its_range_is_an_error_at_the_default() {
    let r = load_with(MINI, "default = 0.5", "default = 4.0");
    assert_error(
        r,
        ModelErrorKind::Range,
        "40:11",
        "lies outside its range (0, pi)",
    );
}

#[test]
fn a_malformed_range_says_what_a_range_looks_like() {
    let r = load_with(MINI, "range = \"(0, pi)\"", "range = \"0 to pi\"");
    assert_error(
        r,
        ModelErrorKind::Range,
        "39:9",
        "expected an interval such as",
    );
}

#[test]
fn the_first_two_coordinates_must_be_lengths() {
    let r = load_with(
        MINI,
        "name = \"z\"\nunit = \"m\"",
        "name = \"z\"\nunit = \"rad\"",
    );
    assert_error(r, ModelErrorKind::Inconsistent, "10:8", "must be a length");
}

#[test]
fn fewer_than_three_coordinates_is_an_error() {
    let r = load_with(
        MINI,
        "[[coordinate]]\nname = \"th\"\nunit = \"rad\"\ndoc = \"leg\"\n",
        "",
    );
    assert!(matches!(
        &r,
        Err(e) if e.kind() == Some(ModelErrorKind::Count)
            && e.to_string().contains("expected at least three")
    ));
}

#[test]
fn a_strike_point_must_be_a_declared_point() {
    let r = load_with(MINI, "point = \"foot\"", "point = \"hand\"");
    assert_error(
        r,
        ModelErrorKind::UnknownReference,
        "65:9",
        "expected the name of a declared [[point]]",
    );
}

#[test]
fn a_fall_point_must_be_a_declared_point() {
    let r = load_with(
        MINI,
        "[relabel]",
        "[[fall]]\nname = \"down\"\npoint = \"knee\"\ndoc = \"fell\"\n\n[relabel]",
    );
    assert_error(
        r,
        ModelErrorKind::UnknownReference,
        "70:9",
        "fall point = `knee`",
    );
}

#[test]
fn a_fall_needs_exactly_one_of_point_and_guard() {
    let r = load_with(
        MINI,
        "[relabel]",
        "[[fall]]\nname = \"down\"\ndoc = \"fell\"\n\n[relabel]",
    );
    assert_error(
        r,
        ModelErrorKind::Inconsistent,
        "68:1",
        "exactly one of `point` and `guard`",
    );
}

#[test]
fn relabelling_an_unknown_coordinate_is_an_error() {
    let r = load_with(MINI, "th = \"th - alpha\"", "ph = \"th - alpha\"");
    assert_error(
        r,
        ModelErrorKind::UnknownReference,
        "69:1",
        "relabel `ph`: expected a coordinate",
    );
}

#[test]
fn relabelling_the_stance_foot_is_an_error() {
    let r = load_with(MINI, "th = \"th - alpha\"", "x = \"x\"");
    assert_error(
        r,
        ModelErrorKind::UnknownReference,
        "69:1",
        "are not relabelled",
    );
}

#[test]
fn a_force_needs_one_expression_per_coordinate() {
    let r = load_with(
        &format!("{MINI}{CONTROLLED}"),
        "force = [\"0\", \"0\", \"1\"]",
        "force = [\"0\", \"1\"]",
    );
    assert_error(
        r,
        ModelErrorKind::Count,
        "74:9",
        "one expression per coordinate, 3; found 2",
    );
}

#[test]
fn control_without_inputs_is_an_error() {
    let r = Model::from_toml(
        &format!("{MINI}\n[control]\nkp = \"m\"\nkd = \"m\"\n"),
        "mini.toml",
    );
    assert_error(
        r,
        ModelErrorKind::Inconsistent,
        "71:1",
        "[control] without [[input]]",
    );
}

#[test]
fn inputs_without_control_are_an_error() {
    let r = load_with(
        &format!("{MINI}{CONTROLLED}"),
        "[control]\nkp = \"m\"\nkd = \"m\"\n",
        "",
    );
    assert_error(
        r,
        ModelErrorKind::Inconsistent,
        "71:1",
        "[[input]] without [control]",
    );
}

#[test]
fn as_many_outputs_as_inputs() {
    let two = format!(
        "{MINI}{CONTROLLED}\n[[output]]\nname = \"y2\"\nh = \"th\"\ndesired = {{ shape = \"hold\", value = \"0\" }}\n"
    );
    let r = Model::from_toml(&two, "mini.toml");
    assert_error(
        r,
        ModelErrorKind::Count,
        "80:1",
        "2 [[output]] for 1 [[input]]",
    );
}

#[test]
fn a_desired_trajectory_uses_parameters_only() {
    let r = load_with(
        &format!("{MINI}{CONTROLLED}"),
        "value = \"alpha/2\"",
        "value = \"th/2\"",
    );
    assert_error(
        r,
        ModelErrorKind::SymbolNotAllowed,
        "83:38",
        "`th` is a coordinate; expected a parameter",
    );
}

#[test]
fn mu0_is_required_for_the_friction_laws_listed() {
    let r = load_with(MINI, "mu0 = \"mu0\"\n", "");
    assert_error(r, ModelErrorKind::Inconsistent, "60:1", "needs `mu0`");
}

#[test]
fn c_is_required_with_the_tanh_law() {
    let r = load_with(MINI, "[\"none\", \"coulomb\"]", "[\"none\", \"tanh\"]");
    assert_error(r, ModelErrorKind::Inconsistent, "60:1", "needs `c`");
}

#[test]
fn gravity_must_be_a_declared_parameter() {
    let r = load_with(MINI, "gravity = \"g\"", "gravity = \"G\"");
    assert_error(
        r,
        ModelErrorKind::UnknownReference,
        "49:11",
        "expected the name of a declared parameter",
    );
}

#[test]
fn the_slope_must_be_an_angle_parameter() {
    let r = load_with(MINI, "gravity = \"g\"", "gravity = \"g\"\nslope = \"l\"");
    assert_error(
        r,
        ModelErrorKind::UnknownReference,
        "50:9",
        "expected an angle parameter",
    );
}

#[test]
fn a_body_angle_must_be_an_angle_combination() {
    let r = load_with(
        MINI,
        "mass = \"m\"",
        "mass = \"m\"\ninertia = \"m\"\nangle = \"l\"",
    );
    assert_error(
        r,
        ModelErrorKind::NotAnAngleCombination,
        "55:10",
        "`l` is not an angle",
    );
}

#[test]
fn a_bad_model_name_is_refused() {
    let r = load_with(MINI, "name = \"mini\"", "name = \"Mini\"");
    assert_error(
        r,
        ModelErrorKind::BadName,
        "2:8",
        "expected [a-z][a-z0-9-]*",
    );
}

#[test]
fn power_descriptors_need_inputs() {
    let r = Model::from_toml(
        &format!("{MINI}\n[descriptors]\nreport = [\"T\", \"power\"]\n"),
        "mini.toml",
    );
    assert_error(r, ModelErrorKind::Inconsistent, "72:16", "needs inputs");
}

#[test]
fn an_error_in_a_literal_string_points_inside_it() {
    let r = load_with(MINI, "mass = \"m\"", "mass = 'm + q'");
    assert_error(
        r,
        ModelErrorKind::UnknownSymbol,
        "53:13",
        "unknown symbol `q`",
    );
}

#[test]
fn an_error_in_a_multi_line_string_points_at_its_start() {
    let r = load_with(MINI, "mass = \"m\"", "mass = \"\"\"\nm + q\"\"\"");
    assert_error(
        r,
        ModelErrorKind::UnknownSymbol,
        "53:8",
        "unknown symbol `q`",
    );
}

#[test]
fn columns_count_characters_not_bytes() {
    // `doc = "lég" x`: the `x` is the 13th character and the 14th byte.
    let r = load_with(MINI, "doc = \"leg\"", "doc = \"lég\" x");
    assert_error(r, ModelErrorKind::Toml, "15:13", "");
}

#[test]
fn a_section_names_every_component_but_the_foot_once_free_or_given() {
    // Line 60: `[section]` (before `[stance]`), line 61 `free`, line 62 `given`.
    let with = |section: &str| load_with(MINI, "[stance]", &format!("{section}\n\n[stance]"));
    let model = with("[section]\nfree = [\"thd\"]\ngiven = { th = \"-alpha/2\", xd = \"0\" }")
        .expect("a complete section loads");
    let section = model.section.expect("the section");
    // State [x, z, th, xd, zd, thd]: thd is component 5, th 2 and xd 3.
    assert_eq!(section.free, [5]);
    assert_eq!(
        section.given.iter().map(|(i, _)| *i).collect::<Vec<_>>(),
        [2, 3]
    );
    assert_error(
        with("[section]\nfree = [\"thd\"]\ngiven = { xd = \"0\" }"),
        ModelErrorKind::Inconsistent,
        "60:1",
        "`th` is neither free nor given",
    );
    assert_error(
        with("[section]\nfree = [\"z\", \"thd\"]\ngiven = { th = \"0\", xd = \"0\" }"),
        ModelErrorKind::Inconsistent,
        "61:9",
        "x = z = 0",
    );
    assert_error(
        with("[section]\nfree = [\"thd\", \"th\"]\ngiven = { th = \"0\", xd = \"0\" }"),
        ModelErrorKind::Duplicate,
        "62:11",
        "both free and given",
    );
    assert_error(
        with("[section]\nfree = [\"thd\"]\ngiven = { th = \"xd\", xd = \"0\" }"),
        ModelErrorKind::SymbolNotAllowed,
        "62:17",
        "expected a parameter or a free component (thd)",
    );
    assert_error(
        with("[section]\nfree = [\"thdd\"]"),
        ModelErrorKind::UnknownReference,
        "61:9",
        "expected a coordinate or a velocity",
    );
}

#[test]
fn a_start_parameter_appears_in_the_start_only() {
    let omega = "[[parameter]]\nname = \"omega0\"\nunit = \"rad/s\"\ndoc = \"start\"\nrange = \"(-inf, inf)\"\ndefault = 0.5\nstage = \"start\"\n\n[floor]";
    let base = MINI.replacen("[floor]", omega, 1);
    let model = load_with(&base, "[stance]", "[start]\nthd = \"omega0\"\n\n[stance]")
        .expect("a start parameter in [start] loads");
    assert_eq!(model.start.len(), 1);
    // Line 74 after the 8 added lines: the strike guard.
    assert_error(
        load_with(
            &base,
            "guard = \"alpha/2 - th\"",
            "guard = \"alpha/2 - th + omega0\"",
        ),
        ModelErrorKind::SymbolNotAllowed,
        "74:25",
        "`omega0` is a parameter of the start",
    );
    assert_error(
        load_with(&base, "mu0 = \"mu0\"", "mu0 = \"omega0\""),
        ModelErrorKind::SymbolNotAllowed,
        "70:7",
        "expected a parameter of the dynamics",
    );
    assert_error(
        load_with(MINI, "default = 0.4", "default = 0.4\nstage = \"later\""),
        ModelErrorKind::Toml,
        "47:9",
        "expected \"run\", \"generation\" or \"start\"",
    );
}

#[test]
fn the_power_is_counted_until_a_time_in_the_parameters_and_only_with_inputs() {
    let controlled = format!("{MINI}{CONTROLLED}");
    let with = |extra: &str| Model::from_toml(&format!("{controlled}{extra}"), "mini.toml");
    let model = with("\n[descriptors]\npower_until = \"2*alpha\"\n").expect("loads");
    assert_eq!(
        model.power_until.map(|e| e.text),
        Some("2*alpha".to_owned())
    );
    assert_error(
        with("\n[descriptors]\npower_until = \"th\"\n"),
        ModelErrorKind::SymbolNotAllowed,
        "86:16",
        "descriptors power_until",
    );
    assert_error(
        load_with(
            MINI,
            "[relabel]",
            "[descriptors]\npower_until = \"1\"\n\n[relabel]",
        ),
        ModelErrorKind::Inconsistent,
        "69:15",
        "needs inputs",
    );
}

/// Line 83 of `MINI` + `CONTROLLED` with the desired trajectory `desired` (inline table body).
fn with_desired(desired: &str) -> Result<Model, ModelError> {
    load_with(
        &format!("{MINI}{CONTROLLED}"),
        "shape = \"hold\", value = \"alpha/2\"",
        desired,
    )
}

#[test]
fn a_bezier_desired_trajectory_loads_with_its_points() -> Result<(), ModelError> {
    let m = with_desired(
        "shape = \"bezier\", points = [\"-alpha/2\", \"0\", \"alpha/2\"], duration = \"l\"",
    )?;
    let desired = &m.outputs[0].desired;
    assert!(matches!(
        desired,
        walker_scene::model::Desired::Bezier { .. }
    ));
    if let walker_scene::model::Desired::Bezier { points, duration } = desired {
        assert_eq!(points.len(), 3);
        assert_eq!(points[0].text, "-alpha/2");
        assert_eq!(duration.text, "l");
    }
    Ok(())
}

#[test]
fn a_bezier_needs_two_points_at_least() {
    // Column 40: the `[` of the points.
    let r = with_desired("shape = \"bezier\", points = [\"0\"], duration = \"l\"");
    assert_error(
        r,
        ModelErrorKind::Count,
        "83:40",
        "1 given; expected 2 to 16",
    );
}

#[test]
fn a_bezier_needs_its_points() {
    let r = with_desired("shape = \"bezier\", duration = \"l\"");
    assert_error(r, ModelErrorKind::Toml, "83:11", "missing field `points`");
}

#[test]
fn a_bezier_point_must_not_be_empty() {
    let r = with_desired("shape = \"bezier\", points = [\"0\", \"\"], duration = \"l\"");
    assert_error(r, ModelErrorKind::Syntax, "83:47", "points[1]");
}

#[test]
fn a_bezier_point_is_an_expression_of_parameters() {
    // Column 47: `th` inside the second point's string.
    let r = with_desired("shape = \"bezier\", points = [\"0\", \"th\"], duration = \"l\"");
    assert_error(
        r,
        ModelErrorKind::SymbolNotAllowed,
        "83:47",
        "`th` is a coordinate; expected a parameter",
    );
}

#[test]
fn a_bezier_duration_must_be_positive() {
    let r = with_desired("shape = \"bezier\", points = [\"0\", \"1\"], duration = \"-l\"");
    assert_error(
        r,
        ModelErrorKind::Physics,
        "83:64",
        "expected a duration > 0",
    );
}

#[test]
fn points_do_not_belong_to_a_quintic() {
    let r = with_desired(
        "shape = \"quintic\", from = \"0\", to = \"1\", duration = \"l\", points = [\"0\", \"1\"]",
    );
    assert_error(
        r,
        ModelErrorKind::Toml,
        "83:79",
        "`points` does not belong to shape \"quintic\"",
    );
}
