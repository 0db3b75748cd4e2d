//! `docs/equations.md` is generated from the derivation; this test regenerates it in memory
//! and fails when the checked-in file differs (the derivation or the printer changed).

use std::sync::OnceLock;

use walker_symbolic::{Derivation, latex};

const REGENERATE: &str = "cargo run -p walker-symbolic --bin walker-equations --release";

/// The derivation and its rendering, once for both tests.
fn fresh() -> &'static (Derivation, String) {
    static FRESH: OnceLock<(Derivation, String)> = OnceLock::new();
    FRESH.get_or_init(|| {
        let derivation = Derivation::new().expect("derivation");
        let text = latex::equations_markdown(&derivation).expect("rendering");
        (derivation, text)
    })
}

#[test]
fn equations_md_is_up_to_date() {
    let (_, fresh) = fresh();
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/equations.md");
    let checked_in = std::fs::read_to_string(&path)
        .unwrap_or_else(|e| format!("<cannot read {}: {e}>", path.display()));
    if checked_in != *fresh {
        let line = checked_in
            .lines()
            .zip(fresh.lines())
            .position(|(a, b)| a != b)
            .map_or_else(
                || checked_in.lines().count().min(fresh.lines().count()) + 1,
                |k| k + 1,
            );
        let shown = |s: &str| {
            s.lines()
                .nth(line - 1)
                .unwrap_or("<end of file>")
                .chars()
                .take(200)
                .collect::<String>()
        };
        let message = format!(
            "docs/equations.md is out of date (first difference at line {line}):\n  \
             checked in: {}\n  derived:    {}\nregenerate it with `{REGENERATE}` and commit it",
            shown(&checked_in),
            shown(fresh)
        );
        assert_eq!(checked_in.len(), fresh.len(), "{message}");
        assert!(checked_in == *fresh, "{message}");
    }
}

#[test]
fn equations_md_has_a_section_for_every_kernel() {
    let (derivation, text) = fresh();
    for k in &derivation.kernels {
        assert!(
            text.contains(&format!("### `{}`", k.name)),
            "no section for kernel {}",
            k.name
        );
    }
    // Math blocks are balanced: GitHub renders `$$` blocks on lines of their own.
    assert_eq!(text.lines().filter(|l| *l == "$$").count() % 2, 0);
}
