//! Fuzzing the expression parser and the model loader: no input panics, and every error
//! points inside its input.

use proptest::prelude::*;
use walker_scene::model::{
    BinOp, Expr, ExprKind, Func, Model, ModelError, Number, Span, parse_expr,
};

const SHIPPED: [&str; 3] = [
    include_str!("../../../models/paper-active.toml"),
    include_str!("../../../models/paper-passive.toml"),
    include_str!("../../../models/compass-gait.toml"),
];

/// Tokens of the expression language and a few that are not.
fn token() -> impl Strategy<Value = &'static str> {
    prop::sample::select(vec![
        "x",
        "th1",
        "alpha",
        "sin",
        "cos",
        "tan",
        "(",
        ")",
        "+",
        "-",
        "*",
        "/",
        "^",
        "2",
        "-1",
        "0.163",
        "1e-3",
        "1e",
        "1.",
        ".",
        " ",
        "_a",
        "é",
        "0",
        "99999999999999999999",
        ",",
    ])
}

/// Random trees over a few symbols, exact numbers and every operator.
fn tree() -> impl Strategy<Value = Expr> {
    let leaf = prop_oneof![
        prop::sample::select(vec!["x", "th1", "a_b", "K2"])
            .prop_map(|s| Expr::new(ExprKind::Symbol(s.to_owned()), Span::default())),
        (0_u64..100_000, -8_i64..8).prop_map(|(m, e)| {
            let n = Number::new(&m.to_string(), e).unwrap_or_else(|| Number::integer(0));
            Expr::new(ExprKind::Number(n), Span::default())
        }),
    ];
    leaf.prop_recursive(6, 64, 2, |inner| {
        let node = |k| Expr::new(k, Span::default());
        prop_oneof![
            inner
                .clone()
                .prop_map(move |a| node(ExprKind::Neg(Box::new(a)))),
            (
                inner.clone(),
                inner.clone(),
                prop::sample::select(vec![BinOp::Add, BinOp::Sub, BinOp::Mul, BinOp::Div])
            )
                .prop_map(move |(a, b, op)| node(ExprKind::Binary(
                    op,
                    Box::new(a),
                    Box::new(b)
                ))),
            (inner.clone(), -3_i64..5).prop_map(move |(a, n)| node(ExprKind::Pow(Box::new(a), n))),
            (inner, prop::bool::ANY).prop_map(move |(a, s)| {
                node(ExprKind::Call(
                    if s { Func::Sin } else { Func::Cos },
                    Box::new(a),
                ))
            }),
        ]
    })
}

/// A mutation of a model file's lines.
#[derive(Clone, Debug)]
enum Mutation {
    Delete(usize),
    Duplicate(usize),
    Replace(usize, &'static str),
    Expression(usize, String),
    Truncate(usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        1 => any::<usize>().prop_map(Mutation::Delete),
        1 => any::<usize>().prop_map(Mutation::Duplicate),
        2 => (
            any::<usize>(),
            prop::sample::select(vec![
                "\"\"",
                "\"x\"",
                "\"th1 +\"",
                "1",
                "-1.0",
                "\"(1, 0)\"",
                "[]",
                "[\"0\"]",
                "true",
                "\"sin(l)\"",
                "\"alpha\"",
                "{ shape = \"hold\" }",
                "\"[0, pi/0)\"",
                "\"mu\"",
                "\"hip\"",
                "\"é\\t\"",
                "\"th1/0\"",
                "\"x^1.5\"",
            ])
        )
            .prop_map(|(i, v)| Mutation::Replace(i, v)),
        1 => any::<usize>().prop_map(Mutation::Truncate),
        6 => (any::<usize>(), "[a-z0-9 +*/^()._-]{0,16}").prop_map(|(i, e)| Mutation::Expression(i, e)),
    ]
}

fn apply(text: &str, mutations: &[Mutation]) -> String {
    let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
    let mut truncate = None;
    for m in mutations {
        let n = lines.len().max(1);
        match *m {
            Mutation::Delete(i) if !lines.is_empty() => {
                lines.remove(i % n);
            }
            Mutation::Duplicate(i) if !lines.is_empty() => {
                let l = lines[i % n].clone();
                lines.insert(i % n, l);
            }
            Mutation::Replace(i, v) if !lines.is_empty() => {
                let l = &mut lines[i % n];
                if let Some(eq) = l.find(" = ") {
                    l.truncate(eq + 3);
                    l.push_str(v);
                }
            }
            Mutation::Expression(i, ref e) if !lines.is_empty() => {
                // Replace the first string on the line by a random expression.
                let l = &mut lines[i % n];
                if let Some(open) = l.find('"')
                    && let Some(len) = l[open + 1..].find('"')
                {
                    l.replace_range(open + 1..open + 1 + len, e);
                }
            }
            Mutation::Truncate(at) => truncate = Some(at),
            _ => {}
        }
    }
    let mut out = lines.join("\n");
    if let Some(at) = truncate {
        let mut at = at % (out.len() + 1);
        while !out.is_char_boundary(at) {
            at -= 1;
        }
        out.truncate(at);
    }
    out
}

/// Every error of the loader lies inside the text (the line after a final newline counts).
fn check_location(text: &str, result: &Result<Model, ModelError>) -> Result<(), TestCaseError> {
    if let Err(e) = result {
        let at = e.location();
        prop_assert!(at.is_some(), "{e}");
        let at = at.map_or((0, 0), |l| (l.line, l.column));
        let lines = text.matches('\n').count() + 1;
        prop_assert!(at.0 >= 1 && at.0 <= lines, "{e}: line outside 1..={lines}");
        let width = text
            .split('\n')
            .nth(at.0 - 1)
            .map_or(0, |l| l.chars().count());
        prop_assert!(
            at.1 >= 1 && at.1 <= width + 1,
            "{e}: column outside 1..={}",
            width + 1
        );
        let prefix = format!("m.toml:{}:{}: ", at.0, at.1);
        prop_assert!(e.to_string().starts_with(&prefix), "{e}");
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn arbitrary_strings_never_panic_and_errors_lie_in_the_input(s in ".{0,40}") {
        if let Err(e) = parse_expr(&s) {
            prop_assert!(e.span.start <= e.span.end && e.span.end <= s.len(), "{e:?} in {s:?}");
            prop_assert!(s.is_char_boundary(e.span.start));
        }
    }

    #[test]
    fn token_sequences_never_panic_and_errors_lie_in_the_input(
        tokens in prop::collection::vec(token(), 0..16)
    ) {
        let s = tokens.concat();
        match parse_expr(&s) {
            Ok(e) => {
                let again = parse_expr(&e.to_string());
                prop_assert!(again.is_ok_and(|a| a.same_as(&e)), "{s:?} -> {e}");
            }
            Err(e) => prop_assert!(e.span.start <= e.span.end && e.span.end <= s.len(), "{e:?} in {s:?}"),
        }
    }

    #[test]
    fn printing_any_tree_parses_back_to_it(e in tree()) {
        let text = e.to_string();
        let again = parse_expr(&text);
        prop_assert!(again.as_ref().is_ok_and(|a| a.same_as(&e)), "{text} -> {again:?}");
    }

}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(1000))]

    #[test]
    fn mutated_model_files_never_panic_and_errors_lie_in_the_file(
        which in 0_usize..3,
        mutations in prop::collection::vec(mutation(), 1..4),
    ) {
        let text = apply(SHIPPED[which], &mutations);
        let result = Model::from_toml(&text, "m.toml");
        check_location(&text, &result)?;
    }
}
