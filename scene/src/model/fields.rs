//! The Rust field of each parameter in a generated `Params` struct: one rule, read by the
//! loader (which refuses two parameters with one field) and by the code generator.
//!
//! A field is its parameter's name in ASCII lower case (`I1` -> `i1`, `T_set` -> `t_set`), as
//! Rust's style asks. Where two parameters have the same lower case (`M` for the hip mass beside
//! `m` for the feet, the notation of much of the walking literature), each of them whose name has
//! capitals writes every capital `X` as `xx` instead (`M` -> `mm`, `m_H` -> `m_hh`); a name
//! without capitals keeps its lower case. Within such a group the fields differ (the capitals
//! stand at different places); no field starts with `_` or holds `__`, so the generated code
//! stays clean of Rust's and clippy's naming lints (`pub_underscore_fields`,
//! `used_underscore_binding`, `non_snake_case`). Two names can still meet (`mm` beside `M` and
//! `m`), and then the loader refuses the later one.

/// The field of every parameter of `names`, in their order (the module documentation).
#[must_use]
pub fn param_fields(names: &[&str]) -> Vec<String> {
    let lower: Vec<String> = names.iter().map(|n| n.to_ascii_lowercase()).collect();
    names
        .iter()
        .zip(&lower)
        .map(|(name, low)| {
            let shared = lower.iter().filter(|l| *l == low).count() > 1;
            if shared && name.chars().any(|c| c.is_ascii_uppercase()) {
                escaped(name)
            } else {
                low.clone()
            }
        })
        .collect()
}

/// `name` with every capital `X` written `xx`.
fn escaped(name: &str) -> String {
    let mut out = String::with_capacity(name.len() + 4);
    for c in name.chars() {
        if c.is_ascii_uppercase() {
            out.push(c.to_ascii_lowercase());
            out.push(c.to_ascii_lowercase());
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::param_fields;

    #[test]
    fn a_name_alone_in_its_lower_case_is_its_lower_case() {
        assert_eq!(param_fields(&["I1", "T_set", "m"]), ["i1", "t_set", "m"]);
    }

    #[test]
    fn names_that_differ_only_in_case_get_distinct_fields() {
        assert_eq!(param_fields(&["m", "M", "l"]), ["m", "mm", "l"]);
        assert_eq!(
            param_fields(&["m_H", "m_h", "M_h"]),
            ["m_hh", "m_h", "mm_h"]
        );
    }

    #[test]
    fn names_that_really_collide_still_do() {
        let f = param_fields(&["m_hh", "m_H", "m_h"]);
        assert_eq!(f[0], f[1]);
    }
}
