//! Tests of the graph builder's folding and of the module declarations.

use super::*;

fn g() -> (Graph, NodeId, NodeId) {
    let mut g = Graph::new();
    let a = g.input("a");
    let b = g.input("b");
    (g, a, b)
}

#[test]
fn commutative_operands_share() {
    let (mut g, a, b) = g();
    assert_eq!(g.mul(a, b), g.mul(b, a));
    assert_eq!(g.add(a, b), g.add(b, a));
}

#[test]
fn identities_fold() {
    let (mut g, a, _) = g();
    let (zero, one, m1) = (g.constant(0.0), g.constant(1.0), g.constant(-1.0));
    assert_eq!(g.add(a, zero), a);
    assert_eq!(g.mul(one, a), a);
    assert_eq!(g.mul(a, zero), zero);
    let am1 = g.mul(a, m1);
    assert_eq!(g.node(am1), Node::Neg(a));
    let na = g.neg(a);
    assert_eq!(g.neg(na), a);
    assert_eq!(g.powi(a, 1), a);
    assert_eq!(g.powi(a, 0), one);
    assert_eq!(g.sub(a, a), zero);
}

#[test]
fn constants_fold_exactly_and_normalise_negative_zero() {
    let mut g = Graph::new();
    let (two, three) = (g.constant(2.0), g.constant(3.0));
    let six = g.mul(two, three);
    assert_eq!(g.as_const(six), Some(6.0));
    assert_eq!(g.constant(-0.0), g.constant(0.0));
    let zero = g.constant(0.0);
    let inf = g.div(two, zero);
    assert!(g.node(inf) != Node::Const(Const::new(f64::INFINITY)));
}

#[test]
fn negations_are_pulled_out() {
    let (mut g, a, b) = g();
    let na = g.neg(a);
    let ab = g.mul(a, b);
    let nab = g.mul(na, b);
    assert_eq!(g.node(nab), Node::Neg(ab));
    let c = g.constant(-2.0);
    let two = g.constant(2.0);
    let twoa = g.mul(two, a);
    let ca = g.mul(c, a);
    assert_eq!(g.node(ca), Node::Neg(twoa));
    let d = g.sub(a, b);
    let nd = g.neg(d);
    assert_eq!(g.node(nd), Node::Sub(b, a));
}

#[test]
fn division_by_power_of_two_is_a_multiplication() {
    let (mut g, a, _) = g();
    let four = g.constant(4.0);
    let q = g.div(a, four);
    let quarter = g.constant(0.25);
    assert_eq!(g.node(q), Node::Mul(quarter, a));
}

#[test]
fn eval_matches_direct_arithmetic() {
    let (mut g, a, b) = g();
    let s = g.sin(a);
    let p = g.powi(b, 3);
    let q = g.div(s, p);
    let v = g.eval(&[q], &[], &|n| if n == "a" { 0.5 } else { 1.5 });
    assert_eq!(v, vec![0.5_f64.sin() / (1.5 * 1.5 * 1.5)]);
}
