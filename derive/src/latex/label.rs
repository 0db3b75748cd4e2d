//! The LaTeX names of kernel outputs: `\lambda_{I2}`, `\dot{\theta}_1^+`, `M_{12}`, partial
//! derivatives for the Jacobian kernels.

use crate::kernels::{Kernel, Shape};

fn escape_text(s: &str) -> String {
    s.replace('_', "\\_")
}

/// The LaTeX label of a velocity or acceleration component `k` of `q`.
fn q_label(k: usize, dots: &str, post: &str) -> Option<String> {
    let base = ["x", "z", "\\theta_1", "\\theta_2"].get(k)?;
    Some(match k {
        0 | 1 => format!("\\{dots}{{{base}}}{post}"),
        _ => format!("\\{dots}{{\\theta}}_{}{post}", k - 1),
    })
}

pub(super) fn split_index(name: &str) -> (&str, Option<usize>) {
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    (stem, name[stem.len()..].parse().ok())
}

/// The LaTeX label of output `k` of a kernel.
pub fn output_label(kernel: &Kernel, k: usize) -> String {
    let Some((name, _)) = kernel.outputs.get(k) else {
        return String::new();
    };
    if let Shape::Matrix(rows, cols) = kernel.shape {
        let (i, j) = (k / cols, k % cols);
        if kernel.name.ends_with("_jacobian") && rows == 4 && j < kernel.args.len() {
            let (dots, post) = if kernel.name.starts_with("impact") {
                ("dot", "^+")
            } else {
                ("ddot", "")
            };
            if let Some(row) = q_label(i, dots, post) {
                return format!(
                    "\\frac{{\\partial {row}}}{{\\partial {}}}",
                    super::table().latex(kernel.args[j])
                );
            }
        }
        let (stem, _) = split_index(name);
        return format!("{}_{{{}{}}}", escape_stem(stem), i + 1, j + 1);
    }
    let (stem, index) = split_index(name);
    let fixed = match name.as_str() {
        "lambda" => Some("\\lambda".to_owned()),
        "lambda_t" => Some("\\lambda_t".to_owned()),
        "lambda_n" => Some("\\lambda_n".to_owned()),
        "x_f" => Some("\\bar{x}".to_owned()),
        "z_f" => Some("\\bar{z}".to_owned()),
        "xd_f" => Some("\\dot{\\bar{x}}".to_owned()),
        "zd_f" => Some("\\dot{\\bar{z}}".to_owned()),
        _ => None,
    };
    if let Some(f) = fixed {
        return f;
    }
    match (stem, index) {
        ("lambdaI", Some(i)) => format!("\\lambda_{{I{}}}", i + 1),
        ("qdp", Some(i)) => q_label(i, "dot", "^+").unwrap_or_else(|| format!("\\dot{{q}}^+_{i}")),
        ("qdd", Some(i)) => q_label(i, "ddot", "").unwrap_or_else(|| format!("\\ddot{{q}}_{i}")),
        (s, Some(i)) => format!("{}_{{{}}}", escape_stem(s), i + 1),
        (s, None) => escape_stem(s),
    }
}

fn escape_stem(stem: &str) -> String {
    if stem.chars().count() == 1 {
        stem.to_owned()
    } else {
        format!("\\mathrm{{{}}}", escape_text(stem))
    }
}
