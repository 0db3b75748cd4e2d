//! The expression parser: precedence and associativity, exact literals, errors with their
//! positions, and the pretty-printer's round trip.

use walker_scene::model::{BinOp, Expr, ExprKind, Func, Number, ParseErrorKind, parse_expr};

fn parsed(text: &str) -> Option<Expr> {
    parse_expr(text).ok()
}

fn printed(text: &str) -> String {
    parsed(text).map_or_else(|| "<error>".to_owned(), |e| e.to_string())
}

/// The error's kind and start byte.
fn error(text: &str) -> Option<(ParseErrorKind, usize)> {
    parse_expr(text).err().map(|e| (e.kind, e.span.start))
}

#[test]
fn unary_minus_binds_looser_than_a_power() {
    let e = parsed("-x^2");
    assert!(matches!(
        e.map(|e| e.kind),
        Some(ExprKind::Neg(inner)) if matches!(inner.kind, ExprKind::Pow(_, 2))
    ));
}

#[test]
fn products_and_sums_are_left_associative() {
    assert_eq!(printed("a - b - c"), "a - b - c");
    assert_eq!(printed("a - (b - c)"), "a - (b - c)");
    assert_eq!(printed("a / b / c"), "a / b / c");
    assert_eq!(printed("a / (b * c)"), "a / (b * c)");
    let e = parsed("a - b - c");
    assert!(matches!(
        e.map(|e| e.kind),
        Some(ExprKind::Binary(BinOp::Sub, lhs, _)) if matches!(lhs.kind, ExprKind::Binary(BinOp::Sub, ..))
    ));
}

#[test]
fn products_bind_tighter_than_sums() {
    assert_eq!(printed("x + l*sin(th1)"), "x + l * sin(th1)");
    assert_eq!(printed("(a + b)*cos(th_st)"), "(a + b) * cos(th_st)");
    assert_eq!(printed("(a + b)^-1"), "(a + b)^-1");
    assert_eq!(printed("(a + b)^(3)"), "(a + b)^3");
    assert_eq!(printed("(x^2)^3"), "(x^2)^3");
    assert_eq!(printed("(-x)^2"), "(-x)^2");
    assert_eq!(printed("-(a*b)"), "-(a * b)");
    assert_eq!(printed("a * -b"), "a * -b");
}

#[test]
fn literals_stay_exact() {
    let n = |t: &str| match parsed(t).map(|e| e.kind) {
        Some(ExprKind::Number(n)) => Some((n.mantissa().to_owned(), n.exponent())),
        _ => None,
    };
    assert_eq!(n("0.163"), Some(("163".to_owned(), -3)));
    assert_eq!(n("1e-3"), Some(("1".to_owned(), -3)));
    assert_eq!(n("12"), Some(("12".to_owned(), 0)));
    assert_eq!(n("1500"), Some(("15".to_owned(), 2)));
    assert_eq!(n("0.000"), Some(("0".to_owned(), 0)));
    assert_eq!(n("2.5E+2"), Some(("25".to_owned(), 1)));
    // 0.1 + 0.2 is exactly 3e-1 here, unlike in binary floating point.
    assert_eq!(Number::new("3", -1), Number::new("30", -2));
}

#[test]
fn sin_and_cos_are_calls() {
    assert!(matches!(
        parsed("sin(th1 - alpha)").map(|e| e.kind),
        Some(ExprKind::Call(Func::Sin, _))
    ));
    assert!(matches!(
        parsed("cos(th1/2 + phi)").map(|e| e.kind),
        Some(ExprKind::Call(Func::Cos, _))
    ));
}

#[test]
fn spans_cover_the_text_of_each_node() {
    let e = parsed("  l*sin(th1) ");
    assert_eq!(e.map(|e| (e.span.start, e.span.end)), Some((2, 12)));
}

#[test]
fn errors_say_what_was_expected_and_where() {
    assert_eq!(
        error("a *"),
        Some((
            ParseErrorKind::ExpectedExpression {
                after: "after `*`".to_owned()
            },
            3
        ))
    );
    assert_eq!(
        error("tan(x)"),
        Some((ParseErrorKind::UnknownFunction("tan".to_owned()), 0))
    );
    assert_eq!(error("x^y"), Some((ParseErrorKind::NonIntegerExponent, 2)));
    assert_eq!(
        error("x^2.5"),
        Some((ParseErrorKind::NonIntegerExponent, 2))
    );
    assert_eq!(
        error("x^2^3"),
        Some((ParseErrorKind::NonIntegerExponent, 2))
    );
    assert_eq!(
        error("sin x"),
        Some((ParseErrorKind::ExpectedParen("sin"), 0))
    );
    assert_eq!(
        error("2 x"),
        Some((ParseErrorKind::ExpectedOperator("x".to_owned()), 2))
    );
    assert_eq!(
        error("x # y"),
        Some((ParseErrorKind::ExpectedOperator("#".to_owned()), 2))
    );
    assert_eq!(error("# y"), Some((ParseErrorKind::UnexpectedChar('#'), 0)));
    assert_eq!(
        error("1."),
        Some((ParseErrorKind::BadNumber("expected a digit after `.`"), 0))
    );
    assert!(matches!(
        error("(a + b"),
        Some((ParseErrorKind::Unclosed { open: 0, .. }, 6))
    ));
    assert!(matches!(
        error(""),
        Some((ParseErrorKind::ExpectedExpression { .. }, 0))
    ));
    assert!(matches!(
        error("x^99999999999999999999"),
        Some((ParseErrorKind::TooLarge, 2))
    ));
}

#[test]
fn deep_nesting_is_an_error_not_a_stack_overflow() {
    let deep = format!("{}x{}", "(".repeat(100_000), ")".repeat(100_000));
    assert!(matches!(error(&deep), Some((ParseErrorKind::TooDeep, _))));
    let long = vec!["x"; 10_000].join(" + ");
    assert!(matches!(error(&long), Some((ParseErrorKind::TooDeep, _))));
    let minus = format!("{}x", "-".repeat(100_000));
    assert!(matches!(error(&minus), Some((ParseErrorKind::TooDeep, _))));
    // A sum of a hundred terms is fine.
    assert!(parsed(&vec!["x"; 100].join(" + ")).is_some());
}

#[test]
fn printing_then_parsing_gives_the_same_tree() {
    for text in [
        "x + l*sin(th1)",
        "-x^2",
        "-(x^2)",
        "(-x)^2",
        "a - (b - c) + (d + e)",
        "a/(b/c)*d",
        "(a + b)^-1",
        "0.163*1e-3 - 2.50e4",
        "-alpha/2",
        "- - x",
        "sin(th1/2 + phi)*cos(-(th1 - th2))",
        "x^-1^1",
    ] {
        let Some(e) = parsed(text) else {
            assert!(text.contains("^-1^1"), "`{text}` must parse");
            continue;
        };
        let again = parsed(&e.to_string());
        assert!(again.is_some_and(|a| a.same_as(&e)), "`{text}` -> `{e}`");
    }
}

/// `Expr::eval` evaluates as written, and `Expr::derivative` differentiates by the chain
/// rule: checked on an expression with every construct against the value and the derivative
/// worked out by hand.
#[test]
fn an_expression_evaluates_and_differentiates_as_written() {
    let e = walker_scene::model::parse_expr("-a/2 + b^2*sin(2*a) - cos(a - b)/b").expect("parses");
    let (a, b) = (0.3_f64, 1.7_f64);
    let at = |name: &str| match name {
        "a" => Some(a),
        "b" => Some(b),
        _ => None,
    };
    let value = -a / 2.0 + b.powi(2) * (2.0 * a).sin() - (a - b).cos() / b;
    assert_eq!(e.eval(&at), Some(value));
    let da = -0.5 + b * b * 2.0 * (2.0 * a).cos() + (a - b).sin() / b;
    let db = 2.0 * b * (2.0 * a).sin() - (a - b).sin() / b + (a - b).cos() / (b * b);
    let got_a = e.derivative("a").eval(&at).expect("evaluates");
    let got_b = e.derivative("b").eval(&at).expect("evaluates");
    assert!(
        (got_a - da).abs() < 1e-14 * da.abs().max(1.0),
        "{got_a} against {da}"
    );
    assert!(
        (got_b - db).abs() < 1e-14 * db.abs().max(1.0),
        "{got_b} against {db}"
    );
    assert_eq!(e.eval(&|_| None), None, "an unknown symbol has no value");
}
