//! The instruction set on tiny hand-built modules: each instruction against the Rust expression
//! the emitter writes for it, the float functions per option, hoisting, reciprocals, leaves as
//! outputs, register reuse, the errors; and random graphs against [`Graph::eval`].

use proptest::prelude::*;

use super::float::{inline_sin_cos, inline_tanh};
use super::*;
use crate::ir::{Graph, Kernel, Module, Node, NodeId, Shape};
use crate::options::{Division, EmitOptions, Float, FloatFunctions};

/// A module with one kernel `k` of arguments `args` and the outputs `build` returns (given the
/// argument nodes).
fn module(args: &[&str], build: impl FnOnce(&mut Module, &[NodeId]) -> Vec<NodeId>) -> Module {
    let mut m = Module::new("t");
    let inputs: Vec<NodeId> = args.iter().map(|a| m.graph.input(a)).collect();
    let outs = build(&mut m, &inputs);
    m.kernels.push(Kernel {
        name: "k".to_owned(),
        doc: String::new(),
        equation: String::new(),
        args: args.iter().map(|a| (*a).to_owned()).collect(),
        output_shape: Shape::Vector(outs.len()),
        outputs: outs
            .into_iter()
            .enumerate()
            .map(|(i, n)| (format!("o{i}"), n))
            .collect(),
    });
    m
}

fn options(division: Division, float_functions: FloatFunctions, no_std: bool) -> EmitOptions {
    EmitOptions {
        division,
        float_functions,
        no_std,
        ..EmitOptions::default()
    }
}

/// Kernel `k` of `m` at `args` (parameters `params`).
fn eval(m: &Module, o: &EmitOptions, params: &[f64], args: &[f64]) -> Vec<f64> {
    let tape = TapeModule::new(m, o).expect("a valid module");
    let prepared = tape.prepare(params).expect("one value per parameter");
    let k = tape.kernel_index("k").expect("kernel k");
    let mut out = vec![0.0; tape.kernel(k).map_or(0, TapeKernel::output_len)];
    tape.eval(k, &prepared, args, &mut out, &mut Scratch::new())
        .expect("right lengths");
    out
}

/// Bit for bit, a NaN matching any NaN (see the module docs).
fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

fn assert_same(got: &[f64], want: &[f64], what: &str) {
    assert_eq!(got.len(), want.len(), "{what}");
    for (i, (g, w)) in got.iter().zip(want).enumerate() {
        assert!(
            same(*g, *w),
            "{what}: output {i}: {g:e} ({:#x}) != {w:e} ({:#x})",
            g.to_bits(),
            w.to_bits()
        );
    }
}

/// Arguments that exercise signed zeros, subnormals, infinities, NaN, the branches of the
/// inline `sin_cos` (below `2^-27`, `pi/4`, `2^20 pi/2`) and `tanh` (below `2^-27`, 0.625, 22).
const SPECIAL: [f64; 18] = [
    0.0,
    -0.0,
    5e-324,
    -1e-310,
    1e-9,
    0.5,
    -0.624_999_999_999,
    0.625,
    std::f64::consts::FRAC_PI_4,
    3.0,
    -7.5,
    21.999,
    22.5,
    1.7e6,
    -3e300,
    f64::INFINITY,
    f64::NEG_INFINITY,
    f64::NAN,
];

/// `n` points spread over `[-6, 6]` (a deterministic grid, not round numbers).
fn grid(n: usize) -> impl Iterator<Item = f64> {
    #[allow(clippy::cast_precision_loss, reason = "small counts")]
    (0..n).map(move |i| -6.0 + 12.0 * (i as f64 + 0.2871) / n as f64)
}

#[test]
fn arithmetic_instructions_round_as_the_emitted_expressions() {
    let m = module(&["x", "y"], |m, a| {
        let (x, y) = (a[0], a[1]);
        let xy = m.graph.mul(x, y);
        vec![
            m.graph.add(x, y),
            m.graph.sub(x, y),
            xy,
            m.graph.div(x, y),
            m.graph.neg(xy),
            m.graph.abs(x),
        ]
    });
    let o = options(Division::Exact, FloatFunctions::Inline, false);
    for &x in &SPECIAL {
        for y in SPECIAL.iter().copied().chain(grid(7)) {
            let got = eval(&m, &o, &[], &[x, y]);
            assert_same(
                &got,
                &[x + y, x - y, x * y, x / y, -(x * y), x.abs()],
                "arith",
            );
        }
    }
}

#[test]
fn float_functions_are_those_the_options_emit() {
    // sqrt x, a lone sin x, a lone cos y, tanh x, and sin z with cos z (one `sin_cos`).
    let m = module(&["x", "y", "z"], |m, a| {
        let (x, y, z) = (a[0], a[1], a[2]);
        vec![
            m.graph.sqrt(x),
            m.graph.sin(x),
            m.graph.cos(y),
            m.graph.tanh(x),
            m.graph.sin(z),
            m.graph.cos(z),
        ]
    });
    type Want = fn(f64, f64, f64) -> [f64; 6];
    let cases: [(FloatFunctions, bool, Want); 3] = [
        (FloatFunctions::Inline, false, |x, y, z| {
            let (s, c) = inline_sin_cos(z);
            [x.sqrt(), x.sin(), y.cos(), inline_tanh(x), s, c]
        }),
        (FloatFunctions::Std, false, |x, y, z| {
            let (s, c) = z.sin_cos();
            [x.sqrt(), x.sin(), y.cos(), x.tanh(), s, c]
        }),
        (FloatFunctions::Inline, true, |x, y, z| {
            let (s, c) = libm::sincos(z);
            [
                libm::sqrt(x),
                libm::sin(x),
                libm::cos(y),
                libm::tanh(x),
                s,
                c,
            ]
        }),
    ];
    let points: Vec<f64> = SPECIAL.iter().copied().chain(grid(2001)).collect();
    for (ff, no_std, want) in cases {
        let o = options(Division::Exact, ff, no_std);
        let tape = TapeModule::new(&m, &o).expect("valid");
        let prepared = tape.prepare(&[]).expect("no parameters");
        let k = tape.kernel_index("k").expect("k");
        let mut scratch = tape.scratch();
        let mut out = [0.0; 6];
        for (i, &x) in points.iter().enumerate() {
            let (y, z) = (
                points[(i * 7 + 3) % points.len()],
                points[(i * 13 + 5) % points.len()],
            );
            tape.eval(k, &prepared, &[x, y, z], &mut out, &mut scratch)
                .expect("lengths");
            assert_same(
                &out,
                &want(x, y, z),
                &format!("{ff:?} no_std={no_std} at {x}, {y}, {z}"),
            );
        }
    }
    // The three implementations differ on these points, so the test tells them apart.
    let differ = |f: fn(f64) -> f64, g: fn(f64) -> f64| points.iter().any(|&x| !same(f(x), g(x)));
    assert!(differ(inline_tanh, f64::tanh) && differ(inline_tanh, libm::tanh));
    assert!(differ(|x| inline_sin_cos(x).0, f64::sin));
}

#[test]
fn a_sine_and_cosine_of_one_argument_are_one_instruction() {
    let m = module(&["x"], |m, a| vec![m.graph.sin(a[0]), m.graph.cos(a[0])]);
    let tape = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    assert_eq!(tape.kernels()[0].instructions(), 1);
}

#[test]
fn independent_instructions_of_one_operation_share_a_dispatch() {
    // x*y + z, y*z + x, z*x + y and the products themselves (outputs, so not fused), built
    // product, sum, product, sum...: in id order six dispatches, scheduled products then sums.
    let m = module(&["x", "y", "z"], |m, a| {
        let mut outs = Vec::new();
        for i in 0..3 {
            let p = m.graph.mul(a[i], a[(i + 1) % 3]);
            outs.push(m.graph.add(p, a[(i + 2) % 3]));
            outs.push(p);
        }
        outs
    });
    let tape = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    let k = &tape.kernels()[0];
    assert_eq!((k.instructions(), k.dispatches()), (6, 2));
    let (x, y, z) = (0.1, -2.3, 7.7);
    let got = eval(&m, &EmitOptions::default(), &[], &[x, y, z]);
    let want = [x * y + z, x * y, y * z + x, y * z, z * x + y, z * x];
    assert_same(&got, &want, "runs");
}

#[test]
fn a_product_used_once_fuses_into_its_user_with_two_roundings() {
    // a*b + c, a*b - c, c - a*b, (a*b)*c, each product used once: four instructions. At
    // a = 1 + 2^-30, b = 1 - 2^-30, c = -1 the product rounds to 1, so a*b + c is 0, where a
    // fused multiply-add would give -2^-60.
    let m = module(&["a", "b", "c"], |m, v| {
        let (a, b, c) = (v[0], v[1], v[2]);
        // Four distinct products (the graph shares equal nodes): (2^i a) * b.
        let p: Vec<NodeId> = (0..4)
            .map(|i| {
                let s = m.graph.constant(f64::from(1 << i));
                let sa = m.graph.mul(s, a);
                m.graph.mul(sa, b)
            })
            .collect();
        vec![
            m.graph.add(p[0], c),
            m.graph.sub(p[1], c),
            m.graph.sub(c, p[2]),
            m.graph.mul(p[3], c),
        ]
    });
    let tape = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    // Three scalings (1 * a folds to a) and four fused instructions.
    assert_eq!(tape.kernels()[0].instructions(), 3 + 4);
    let points = [
        (1.0 + 2f64.powi(-30), 1.0 - 2f64.powi(-30), -1.0),
        (0.1, 0.3, -0.03),
        (-0.0, 5.0, 0.0),
        (1e308, 10.0, -f64::INFINITY),
    ];
    for (a, b, c) in points {
        let got = eval(&m, &EmitOptions::default(), &[], &[a, b, c]);
        let want = [a * b + c, 2.0 * a * b - c, c - 4.0 * a * b, 8.0 * a * b * c];
        assert_same(&got, &want, "fused");
    }
    let (a, b, c) = points[0];
    assert_eq!(eval(&m, &EmitOptions::default(), &[], &[a, b, c])[0], 0.0);
    assert!(a.mul_add(b, c) != 0.0, "a fused multiply-add differs here");
}

#[test]
fn parameter_only_values_are_computed_by_prepare() {
    // (a + b) * x: `a + b` is hoisted; the kernel is one multiplication.
    let m = module(&["x"], |m, a| {
        let (p, q) = (m.param("a", ""), m.param("b", ""));
        let s = m.graph.add(p, q);
        vec![m.graph.mul(s, a[0])]
    });
    let tape = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    assert_eq!(tape.kernels()[0].instructions(), 1);
    let prepared = tape.prepare(&[0.1, 0.2]).expect("two parameters");
    assert_eq!(prepared.values(), &[0.1 + 0.2]);
    assert_same(
        &eval(&m, &EmitOptions::default(), &[0.1, 0.2], &[3.0]),
        &[(0.1 + 0.2) * 3.0],
        "hoisted",
    );
}

#[test]
fn division_follows_the_strategy() {
    // Two quotients by one state-dependent denominator: `s * (1 / d)` when shared (as the
    // emitter writes them), `s / d` when exact; and a parameter-only denominator inverted in
    // `prepare`.
    let m = module(&["x"], |m, a| {
        let x = a[0];
        let one = m.graph.constant(1.0);
        let d = m.graph.add(one, x);
        let s = m.graph.sin(x);
        let p = m.param("r", "");
        vec![m.graph.div(s, d), m.graph.div(x, d), m.graph.div(x, p)]
    });
    let mut differs = false;
    for x in grid(101) {
        let p = 0.3;
        // A lone sine: std's `sin`.
        let (s, d) = (x.sin(), 1.0 + x);
        let shared = eval(&m, &EmitOptions::default(), &[p], &[x]);
        let r = 1.0 / d;
        assert_same(&shared, &[s * r, x * r, x * (1.0 / p)], "shared reciprocal");
        let exact = eval(
            &m,
            &options(Division::Exact, FloatFunctions::Inline, false),
            &[p],
            &[x],
        );
        assert_same(&exact, &[s / d, x / d, x / p], "exact");
        differs |= !same(s * r, s / d);
    }
    assert!(differs, "the two strategies differ somewhere on the grid");
}

#[test]
fn outputs_may_be_arguments_constants_and_prepared_values() {
    let m = module(&["x", "unused"], |m, a| {
        let p = m.param("a", "");
        let c = m.graph.constant(2.5);
        let two = m.graph.constant(2.0);
        let twice = m.graph.mul(two, p);
        vec![a[0], c, p, twice, a[0]]
    });
    let tape = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    assert_eq!(tape.kernels()[0].instructions(), 0);
    let got = eval(&m, &EmitOptions::default(), &[-0.0], &[-0.0, 9.0]);
    assert_same(&got, &[-0.0, 2.5, -0.0, 2.0 * -0.0, -0.0], "leaves");
}

#[test]
fn registers_of_dead_values_are_reused() {
    // x0 = x, x_{i+1} = x_i * x + i: a chain of 400 operations needs a few registers.
    let m = module(&["x"], |m, a| {
        let mut v = a[0];
        for i in 1..=200 {
            let p = m.graph.mul(v, a[0]);
            let c = m.graph.constant(f64::from(i));
            v = m.graph.add(p, c);
        }
        vec![v]
    });
    let tape = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    let k = &tape.kernels()[0];
    // Each step one instruction, the product fused into the sum.
    assert_eq!(k.instructions(), 200);
    // One argument, 200 constants, and two temporaries at most.
    assert!(k.registers() <= 1 + 200 + 2, "{} registers", k.registers());
    let mut want = 0.7_f64;
    for i in 1..=200 {
        want = want * 0.7 + f64::from(i);
    }
    assert_same(
        &eval(&m, &EmitOptions::default(), &[], &[0.7]),
        &[want],
        "chain",
    );
}

#[test]
fn wrong_lengths_and_foreign_values_are_errors() {
    let m = module(&["x"], |m, a| {
        let p = m.param("a", "");
        vec![m.graph.mul(p, a[0])]
    });
    let tape = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    let other = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    assert!(matches!(
        tape.prepare(&[]),
        Err(TapeError::ParamCount {
            expected: 1,
            got: 0
        })
    ));
    let prepared = tape.prepare(&[2.0]).expect("one parameter");
    let k = tape.kernel_index("k").expect("k");
    let mut s = Scratch::new();
    let mut out = [7.0];
    assert!(matches!(
        tape.eval(k, &prepared, &[], &mut out, &mut s),
        Err(TapeError::ArgumentCount {
            expected: 1,
            got: 0,
            ..
        })
    ));
    assert!(matches!(
        tape.eval(k, &prepared, &[1.0], &mut [0.0; 2], &mut s),
        Err(TapeError::OutputCount {
            expected: 1,
            got: 2,
            ..
        })
    ));
    assert!(matches!(
        tape.eval(KernelIndex(1), &prepared, &[1.0], &mut out, &mut s),
        Err(TapeError::UnknownKernel { index: 1, count: 1 })
    ));
    let foreign = other.prepare(&[2.0]).expect("one parameter");
    assert!(matches!(
        tape.eval(k, &foreign, &[1.0], &mut out, &mut s),
        Err(TapeError::ForeignPrepared)
    ));
    assert_eq!(out, [7.0], "an error leaves the outputs alone");
    assert!(tape.kernel_index("nope").is_none());
    tape.eval(k, &prepared, &[1.5], &mut out, &mut s)
        .expect("right lengths");
    assert_eq!(out, [3.0]);
}

#[test]
fn f32_and_invalid_modules_are_refused() {
    let m = module(&["x"], |_, a| vec![a[0]]);
    let f32 = EmitOptions {
        float: Float::F32,
        ..EmitOptions::default()
    };
    assert!(matches!(
        TapeModule::new(&m, &f32),
        Err(TapeError::Unsupported { .. })
    ));
    let bad = module(&["x"], |m, _| vec![m.graph.input("y")]);
    assert!(matches!(
        TapeModule::new(&bad, &EmitOptions::default()),
        Err(TapeError::Plan(crate::EmitError::UndeclaredInput { .. }))
    ));
}

#[test]
fn calls_do_not_allocate_once_the_scratch_has_grown() {
    let m = module(&["x"], |m, a| {
        let s = m.graph.sin(a[0]);
        let t = m.graph.tanh(s);
        vec![m.graph.mul(t, a[0])]
    });
    let tape = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    let prepared = tape.prepare(&[]).expect("no parameters");
    let k = tape.kernel_index("k").expect("k");
    let mut s = Scratch::new();
    let mut out = [0.0];
    tape.eval(k, &prepared, &[0.3], &mut out, &mut s)
        .expect("lengths");
    let (ptr, cap) = (s.regs.as_ptr(), s.regs.capacity());
    assert_eq!(s.registers(), tape.kernels()[0].registers());
    for x in grid(50) {
        tape.eval(k, &prepared, &[x], &mut out, &mut s)
            .expect("lengths");
    }
    assert_eq!((s.regs.as_ptr(), s.regs.capacity()), (ptr, cap));
    assert_eq!(tape.scratch().registers(), tape.kernels()[0].registers());
}

/// One operation of a random graph: an opcode and operands (indices into the nodes so far,
/// reduced modulo their number).
#[derive(Clone, Debug)]
struct RandomOp {
    op: u8,
    a: usize,
    b: usize,
    n: i32,
}

fn random_op() -> impl Strategy<Value = RandomOp> {
    (0..12_u8, any::<usize>(), any::<usize>(), -3..5_i32).prop_map(|(op, a, b, n)| RandomOp {
        op,
        a,
        b,
        n,
    })
}

/// A random module over arguments `x`, `y`, `z`, parameters `r`, `q` and constants, whose
/// outputs are the last `outputs` nodes built.
fn random_module(ops: &[RandomOp], outputs: usize) -> Module {
    module(&["x", "y", "z"], |m, a| {
        let mut nodes: Vec<NodeId> = a.to_vec();
        nodes.push(m.param("r", ""));
        nodes.push(m.param("q", ""));
        for c in [0.5, -1.25, 3.0] {
            nodes.push(m.graph.constant(c));
        }
        for o in ops {
            let (a, b) = (nodes[o.a % nodes.len()], nodes[o.b % nodes.len()]);
            let g: &mut Graph = &mut m.graph;
            let n = match o.op {
                0 | 1 => g.add(a, b),
                2 => g.sub(a, b),
                3 | 4 => g.mul(a, b),
                5 => g.div(a, b),
                6 => g.neg(a),
                7 => g.powi(a, o.n),
                8 => g.sqrt(a),
                9 => g.sin(a),
                10 => g.cos(a),
                _ => {
                    if o.n > 2 {
                        g.abs(a)
                    } else {
                        g.tanh(a)
                    }
                }
            };
            nodes.push(n);
        }
        nodes.iter().rev().take(outputs).copied().collect()
    })
}

proptest! {
    /// With exact division and std's float functions, the emitted code computes what
    /// `Graph::eval` computes (each node once, `powi` by the same chain): so must the tape,
    /// whatever the graph, hoisting and register reuse.
    #[test]
    fn random_graphs_evaluate_as_graph_eval(
        ops in prop::collection::vec(random_op(), 1..60),
        outputs in 1..6_usize,
        args in prop::array::uniform3(-4.0..4.0_f64),
        params in prop::array::uniform2(0.1..3.0_f64),
    ) {
        let m = random_module(&ops, outputs);
        let roots: Vec<NodeId> = m.kernels[0].outputs.iter().map(|o| o.1).collect();
        let want = m.graph.eval(&roots, &params, &|name| match name {
            "x" => args[0],
            "y" => args[1],
            _ => args[2],
        });
        let got = eval(&m, &options(Division::Exact, FloatFunctions::Std, false), &params, &args);
        for (g, w) in got.iter().zip(&want) {
            let nodes: Vec<Node> = m.graph.iter().map(|n| n.1).collect();
            prop_assert!(same(*g, *w), "{g:e} != {w:e} for {nodes:?}");
        }
    }
}

#[test]
fn a_tape_and_its_prepared_values_are_shared_between_threads() {
    fn shared<T: Send + Sync>() {}
    fn sent<T: Send>() {}
    shared::<TapeModule>();
    shared::<Prepared>();
    sent::<Scratch>();
    // One tape and one parameter set, one scratch per thread: the same bits in each.
    let m = module(&["x"], |m, a| {
        let p = m.param("r", "");
        let s = m.graph.sin(a[0]);
        vec![m.graph.mul(s, p)]
    });
    let tape = TapeModule::new(&m, &EmitOptions::default()).expect("valid");
    let prepared = tape.prepare(&[1.5]).expect("one parameter");
    let k = tape.kernel_index("k").expect("k");
    let results: Vec<f64> = std::thread::scope(|s| {
        let handles: Vec<_> = (0..2)
            .map(|_| {
                s.spawn(|| {
                    let mut out = [0.0];
                    tape.eval(k, &prepared, &[0.25], &mut out, &mut tape.scratch())
                        .map(|()| out[0])
                })
            })
            .collect();
        handles
            .into_iter()
            .map(|h| h.join().ok().and_then(Result::ok).unwrap_or(f64::NAN))
            .collect()
    });
    assert_eq!(results, vec![0.25_f64.sin() * 1.5; 2]);
}
