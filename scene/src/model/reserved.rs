//! The names a model may not declare, because the expression language, the generated code or
//! a friction law already uses them. A coordinate, velocity, parameter, input or auxiliary
//! input is an identifier of the generated Rust (an argument of the kernels, or a field of the
//! generated `Params` named by its name in lower case), so it may not take a name the
//! generated file binds: a coordinate called `sigma` would stand where the Coulomb law's
//! sliding direction is passed and change every result silently.

/// Names no declaration may take, each with why (the list of `docs/model-format.md`).
pub const RESERVED_NAMES: [(&str, &str); 9] = [
    (
        "t",
        "the time since the last impact, in guards and trajectories",
    ),
    (
        "mu",
        "the friction coefficient of the stance phase (Eq. 24)",
    ),
    ("sin", "a function of the expression language"),
    ("cos", "a function of the expression language"),
    (
        "sigma",
        "the kernels' argument for the Coulomb law's sliding direction",
    ),
    ("p", "the kernels' first argument, the prepared parameters"),
    ("prepare", "a function of the generated code"),
    (
        "tanh",
        "a function of the generated code (the tanh friction law)",
    ),
    ("sin_cos", "a function of the generated code"),
];

/// Name patterns no declaration may take: `(pattern, why)`; the pattern is a letter followed by
/// one or more decimal digits.
pub const RESERVED_PATTERNS: [(char, &str); 2] = [
    ('t', "the generated code's temporaries `t0`, `t1`, .."),
    (
        'k',
        "the generated code's prepared constants `k0`, `k1`, ..",
    ),
];

/// Rust's keywords (strict, reserved and edition-2024 `gen`): a name of the generated code may
/// not be one.
pub const RUST_KEYWORDS: [&str; 52] = [
    "as", "break", "const", "continue", "crate", "else", "enum", "extern", "false", "fn", "for",
    "if", "impl", "in", "let", "loop", "match", "mod", "move", "mut", "pub", "ref", "return",
    "self", "Self", "static", "struct", "super", "trait", "true", "type", "unsafe", "use", "where",
    "while", "async", "await", "dyn", "abstract", "become", "box", "do", "final", "macro",
    "override", "priv", "typeof", "unsized", "virtual", "yield", "try", "gen",
];

/// Why `name` is reserved ("it is ..."), or `None` if a model may declare it. `name` is
/// compared as written and in lower case (a parameter's `Params` field is its name in lower
/// case).
#[must_use]
pub fn reserved_because(name: &str) -> Option<String> {
    let lower = name.to_ascii_lowercase();
    for candidate in [name, lower.as_str()] {
        let case = if candidate == name {
            String::new()
        } else {
            format!(" (in lower case, `{candidate}`)")
        };
        if let Some((_, why)) = RESERVED_NAMES.iter().find(|(n, _)| *n == candidate) {
            return Some(format!("it is{case} {why}"));
        }
        if RUST_KEYWORDS.contains(&candidate) {
            return Some(format!(
                "it is{case} a Rust keyword, and names are identifiers of the generated code"
            ));
        }
        let mut chars = candidate.chars();
        if let Some(first) = chars.next()
            && let Some((_, why)) = RESERVED_PATTERNS.iter().find(|(c, _)| *c == first)
            && candidate.len() > 1
            && chars.all(|c| c.is_ascii_digit())
        {
            return Some(format!("it is{case} one of {why}"));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::reserved_because;

    #[test]
    fn generated_and_language_names_are_reserved_and_others_are_not() {
        for name in [
            "sigma", "t", "mu", "p", "t0", "k12", "K3", "fn", "Type", "tanh",
        ] {
            assert!(reserved_because(name).is_some(), "{name}");
        }
        for name in [
            "th", "t_set", "T_set", "k", "kp", "x", "sigma0", "mu0", "tk1",
        ] {
            assert!(reserved_because(name).is_none(), "{name}");
        }
    }
}
