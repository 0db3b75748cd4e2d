//! The three shipped model files load, and what they declare comes out as the format says.

use walker_scene::model::{
    CoordinateUnit, Descriptor, Desired, FallCondition, Model, ModelError, Stage, SymbolKind,
};
use walker_scene::{Friction, ImpactLaw};

const ACTIVE: &str = include_str!("../../../models/paper-active.toml");
const PASSIVE: &str = include_str!("../../../models/paper-passive.toml");
const COMPASS: &str = include_str!("../../../models/compass-gait.toml");

fn load(text: &str, name: &str) -> Result<Model, ModelError> {
    Model::from_toml(text, name)
}

#[test]
fn the_three_shipped_models_load() -> Result<(), ModelError> {
    for (text, name) in [
        (ACTIVE, "paper-active"),
        (PASSIVE, "paper-passive"),
        (COMPASS, "compass-gait"),
    ] {
        let m = load(text, &format!("models/{name}.toml"))?;
        assert_eq!(m.name, name);
    }
    Ok(())
}

#[test]
fn the_files_on_disk_load_by_path() -> Result<(), ModelError> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../models");
    let m = Model::from_file(&dir.join("compass-gait.toml"))?;
    assert_eq!(m.coordinates.len(), 4);
    Ok(())
}

#[test]
fn a_missing_file_is_a_read_error_naming_the_path() {
    let err = Model::from_file(std::path::Path::new("no/such/model.toml"));
    assert!(matches!(&err, Err(ModelError::Read { path, .. }) if path == "no/such/model.toml"));
}

#[test]
fn the_active_walkers_symbols_come_in_canonical_order() -> Result<(), ModelError> {
    let m = load(ACTIVE, "paper-active.toml")?;
    let names: Vec<&str> = m.symbols().iter().map(|s| s.name.as_str()).collect();
    assert_eq!(
        names,
        [
            "x", "z", "th1", "th2", "xd", "zd", "th1d", "th2d", "xdd", "zdd", "th1dd", "th2dd",
            "m1", "m2", "l", "I1", "I2", "g", "alpha", "mu0", "c", "T_set", "K_P", "K_D", "omega0",
            "u", "mu", "v", "t"
        ]
    );
    let angles: Vec<&str> = m
        .symbols()
        .iter()
        .filter(|s| s.angle)
        .map(|s| s.name.as_str())
        .collect();
    assert_eq!(angles, ["th1", "th2", "alpha"]);
    assert_eq!(
        m.symbol("th1d").map(|s| (s.kind, s.index)),
        Some((SymbolKind::Velocity, 2))
    );
    assert_eq!(m.symbol_index("t"), Some(names.len() - 1));
    Ok(())
}

#[test]
fn alpha_has_base_angle_divisor_two_because_it_appears_as_alpha_over_two() -> Result<(), ModelError>
{
    for (text, name) in [(ACTIVE, "a"), (PASSIVE, "p")] {
        let m = load(text, name)?;
        assert_eq!(m.base_angle_divisor("alpha"), Some(2));
        assert_eq!(m.base_angle_divisor("th1"), Some(1));
        assert_eq!(m.base_angle_divisor("l"), None);
    }
    let m = load(PASSIVE, "p")?;
    assert_eq!(m.base_angle_divisor("phi"), Some(1));
    let c = load(COMPASS, "c")?;
    assert_eq!(c.base_angle_divisor("th_st"), Some(1));
    assert_eq!(c.base_angle_divisor("phi"), Some(1));
    Ok(())
}

#[test]
fn the_active_walker_has_its_sections() -> Result<(), ModelError> {
    let m = load(ACTIVE, "a")?;
    assert_eq!(m.coordinates[2].unit, CoordinateUnit::Angle);
    // Table 1 and g, the friction and the control, and the start's omega0 (Eq. 33).
    assert_eq!(m.parameters.len(), 13);
    assert!(m.parameters[..12].iter().all(|p| p.stage == Stage::Run));
    assert_eq!(m.parameters[12].stage, Stage::Start);
    assert_eq!(m.start.len(), 3);
    let section = m.section.as_ref().expect("a section");
    assert_eq!(section.free, [4, 6], "xd and th1d");
    assert_eq!(m.floor.gravity.name, "g");
    assert!(m.floor.slope.is_none());
    assert_eq!(m.bodies.len(), 2);
    assert!(m.bodies.iter().all(|b| b.rotation.is_some()));
    assert_eq!(m.points.len(), 3);
    assert_eq!(
        m.stance.friction,
        [Friction::None, Friction::Tanh, Friction::Coulomb]
    );
    assert_eq!(m.strike.point.name, "fore_foot");
    assert!(m.strike.ahead);
    assert!(matches!(m.falls[0].condition, FallCondition::Guard(_)));
    assert_eq!(m.relabel.len(), 1);
    assert_eq!(m.relabel[0].coordinate, 2);
    assert_eq!(m.relabel[0].value.expr.to_string(), "th1 - alpha");
    assert_eq!(m.impact.law, ImpactLaw::Frictionless);
    assert_eq!(m.impact.locks.len(), 1);
    assert_eq!(m.inputs[0].force.len(), 4);
    assert_eq!(m.control.as_ref().map(|c| c.kp.name.as_str()), Some("K_P"));
    assert_eq!(m.outputs[0].aux.name, "v");
    assert!(matches!(
        &m.outputs[0].desired,
        Desired::Quintic { from, .. } if from.expr.to_string() == "-alpha / 2"
    ));
    assert_eq!(m.descriptors, Descriptor::ALL);
    Ok(())
}

#[test]
fn the_passive_and_compass_models_have_no_inputs_and_a_slope() -> Result<(), ModelError> {
    for text in [PASSIVE, COMPASS] {
        let m = load(text, "m")?;
        assert!(m.inputs.is_empty() && m.control.is_none() && m.outputs.is_empty());
        assert_eq!(m.floor.slope.as_ref().map(|s| s.name.as_str()), Some("phi"));
        assert_eq!(
            m.descriptors,
            [
                Descriptor::Period,
                Descriptor::StepLength,
                Descriptor::Speed
            ]
        );
    }
    let c = load(COMPASS, "c")?;
    assert_eq!(c.impact.law, ImpactLaw::Coulomb);
    assert_eq!(c.relabel.len(), 2);
    Ok(())
}

#[test]
fn expression_locations_point_into_the_file() -> Result<(), ModelError> {
    let m = load(ACTIVE, "a")?;
    let guard = m.strike.guard.as_ref().map(|g| g.location);
    let line = ACTIVE
        .lines()
        .position(|l| l.starts_with("guard = \"alpha/2 - th1\""))
        .map(|i| i + 1);
    assert_eq!(guard.map(|g| (g.line, g.column)), line.map(|l| (l, 10)));
    Ok(())
}
