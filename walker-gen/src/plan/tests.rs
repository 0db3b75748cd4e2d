//! Tests of the passes: validation, power expansion, reciprocals, hoisting and scheduling.

use super::*;
use crate::error::EmitError;
use crate::ir::{Kernel, Module, Node, NodeId, Shape};
use crate::options::Division;

fn module_with(outputs: impl FnOnce(&mut Module) -> Vec<NodeId>) -> Module {
    let mut m = Module::new("t");
    let outs = outputs(&mut m);
    m.kernels.push(Kernel {
        name: "k".to_owned(),
        doc: String::new(),
        equation: String::new(),
        args: vec!["x".to_owned()],
        output_shape: Shape::Vector(outs.len()),
        outputs: outs
            .into_iter()
            .enumerate()
            .map(|(i, n)| (format!("o{i}"), n))
            .collect(),
    });
    m
}

#[test]
fn parameter_only_nodes_are_hoisted() {
    let m = module_with(|m| {
        let a = m.param("a", "");
        let b = m.param("b", "");
        let x = m.graph.input("x");
        let ab = m.graph.add(a, b);
        vec![m.graph.mul(ab, x)]
    });
    let plan = Plan::new(&m, Division::Exact).expect("valid");
    assert_eq!(plan.fields.len(), 1);
    assert_eq!(plan.fields.first().map(|f| f.name.as_str()), Some("k0"));
}

#[test]
fn shared_denominator_becomes_one_reciprocal() {
    let m = module_with(|m| {
        let x = m.graph.input("x");
        let s = m.graph.sin(x);
        let one = m.graph.constant(1.0);
        let d = m.graph.add(one, x);
        vec![m.graph.div(s, d), m.graph.div(x, d)]
    });
    let plan = Plan::new(&m, Division::SharedReciprocal).expect("valid");
    let divs = plan
        .kernels
        .iter()
        .flat_map(|k| &k.block.nodes)
        .filter(|n| matches!(plan.graph.node(**n), Node::Div(..)))
        .count();
    assert_eq!(divs, 1);
}

#[test]
fn undeclared_input_is_rejected() {
    let m = module_with(|m| vec![m.graph.input("y")]);
    assert!(matches!(
        Plan::new(&m, Division::Exact),
        Err(EmitError::UndeclaredInput { .. })
    ));
}

#[test]
fn reserved_and_duplicate_names_are_rejected() {
    for name in ["sin_cos", "tanh", "prepare"] {
        let mut m = module_with(|m| vec![m.graph.input("x")]);
        m.kernels[0].args = vec![name.to_owned()];
        assert_eq!(
            matches!(
                Plan::new(&m, Division::Exact),
                Err(EmitError::BadName { .. })
            ),
            name != "prepare",
            "argument {name}"
        );
        let mut m = module_with(|m| vec![m.graph.input("x")]);
        m.kernels[0].name = name.to_owned();
        assert!(matches!(
            Plan::new(&m, Division::Exact),
            Err(EmitError::BadName { .. })
        ));
    }
    let mut m = module_with(|m| vec![m.graph.input("x")]);
    m.kernels[0].args = vec!["p".to_owned()];
    assert!(matches!(
        Plan::new(&m, Division::Exact),
        Err(EmitError::BadName { .. })
    ));
    let mut m = module_with(|m| vec![m.graph.input("x")]);
    m.declare_param("k0", "");
    assert!(matches!(
        Plan::new(&m, Division::Exact),
        Err(EmitError::BadName { .. })
    ));
    let mut m = module_with(|m| vec![m.graph.input("x")]);
    let twin = m.kernels[0].clone();
    m.kernels.push(twin);
    assert!(matches!(
        Plan::new(&m, Division::Exact),
        Err(EmitError::Duplicate { .. })
    ));
    let mut m = module_with(|m| vec![m.graph.input("x")]);
    m.kernels[0].output_shape = Shape::Matrix(2, 2);
    assert!(matches!(
        Plan::new(&m, Division::Exact),
        Err(EmitError::ShapeMismatch { .. })
    ));
}

#[test]
fn sine_and_cosine_pair() {
    let m = module_with(|m| {
        let x = m.graph.input("x");
        vec![m.graph.sin(x), m.graph.cos(x)]
    });
    let plan = Plan::new(&m, Division::Exact).expect("valid");
    let steps = plan.kernels.first().map(|k| k.block.steps.clone());
    assert!(matches!(steps.as_deref(), Some([Step::SinCos { .. }])));
}

/// The critical path by hand: `(a + b) * x` with `a + b` hoisted to `prepare` is one
/// multiplication (4 cycles); `sin(x) / (1 + x)` is the sine (40) then the division (14), the
/// addition beside the sine being off the path.
#[test]
fn the_critical_path_counts_the_longest_chain_only() {
    let hoisted = module_with(|m| {
        let a = m.param("a", "");
        let b = m.param("b", "");
        let x = m.graph.input("x");
        let ab = m.graph.add(a, b);
        vec![m.graph.mul(ab, x)]
    });
    let plan = Plan::new(&hoisted, Division::Exact).expect("valid");
    assert_eq!(crate::stats::critical_path(&plan, 0), 4);

    let quotient = module_with(|m| {
        let x = m.graph.input("x");
        let s = m.graph.sin(x);
        let one = m.graph.constant(1.0);
        let d = m.graph.add(one, x);
        vec![m.graph.div(s, d), x]
    });
    let plan = Plan::new(&quotient, Division::Exact).expect("valid");
    assert_eq!(crate::stats::critical_path(&plan, 0), 40 + 14);
    // Two dependent divisions: each on the path.
    let chained = module_with(|m| {
        let x = m.graph.input("x");
        let one = m.graph.constant(1.0);
        let d = m.graph.add(one, x);
        let q = m.graph.div(x, d);
        vec![m.graph.div(q, d)]
    });
    let plan = Plan::new(&chained, Division::Exact).expect("valid");
    assert_eq!(crate::stats::critical_path(&plan, 0), 4 + 14 + 14);
}
