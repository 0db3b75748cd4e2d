//! Large kernels: emitting stays linear and shallow (test threads have 2 MB stacks), and long
//! sums are cut into `let`s instead of nesting without bound.

use walker_gen::{EmitOptions, Kernel, Module, Shape, emit};

/// `sum_i (i + 1/2) sin(x) x^(i mod 7 + 1)`, built left to right as a derivation would.
fn long_sum(n: usize) -> Module {
    let mut m = Module::new("large");
    let g = &mut m.graph;
    let x = g.input("x");
    let s = g.sin(x);
    let mut acc = g.constant(0.0);
    for i in 0..n {
        let c = g.constant(0.5 + f64::from(u32::try_from(i).unwrap_or(u32::MAX)));
        let cs = g.mul(c, s);
        let p = g.powi(x, i32::try_from(i % 7).unwrap_or(0) + 1);
        let term = g.mul(cs, p);
        acc = g.add(acc, term);
    }
    m.kernels.push(Kernel {
        name: "long_sum".to_owned(),
        doc: "A long sum.".to_owned(),
        equation: String::new(),
        args: vec!["x".to_owned()],
        outputs: vec![("s".to_owned(), acc)],
        output_shape: Shape::Scalar,
    });
    m
}

#[test]
fn a_twenty_thousand_term_sum_emits_flat_and_parses() {
    let src = emit(&long_sum(20_000), &EmitOptions::default()).expect("emit");
    assert!(syn::parse_file(&src).is_ok());
    let longest = src.lines().map(str::len).max().unwrap_or(0);
    assert!(longest <= 100, "a line of {longest} characters");
    assert!(!src.contains("(("), "nested parentheses in a flat sum");
}
