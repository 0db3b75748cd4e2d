//! Doc-comment text of the generated items: `#[doc]` attributes from lines, wrapping at 96
//! characters, lists of names in backticks and the "Returns" line of a kernel.

use proc_macro2::TokenStream;
use quote::quote;

use crate::ir::{Kernel, Shape};

pub(super) fn doc_attrs(lines: &[String]) -> Vec<TokenStream> {
    lines
        .iter()
        .flat_map(|l| l.split('\n').map(str::to_owned).collect::<Vec<_>>())
        .map(|l| {
            let l = l.trim_end();
            let l = if l.is_empty() {
                String::new()
            } else {
                format!(" {l}")
            };
            quote!(#[doc = #l])
        })
        .collect()
}

/// `text` broken at spaces into lines of at most 96 characters (a `/// ` line of at most 100),
/// for the doc comments of the checked entry points. A longer word stays whole.
pub(super) fn wrap(text: &str) -> String {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ').filter(|w| !w.is_empty()) {
        if !line.is_empty() && line.len() + 1 + word.len() > 96 {
            lines.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    lines.push(line);
    lines.join("\n")
}

pub(super) fn code_list(items: &[String]) -> String {
    items
        .iter()
        .map(|s| format!("`{s}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

pub(super) fn returns_doc(k: &Kernel) -> String {
    let names: Vec<&str> = k.outputs.iter().map(|o| o.0.as_str()).collect();
    match k.output_shape {
        Shape::Scalar => format!("Returns `{}`.", names.join("")),
        Shape::Vector(_) => format!("Returns `[{}]`.", names.join(", ")),
        Shape::Matrix(_, c) => {
            let rows: Vec<String> = names
                .chunks(c.max(1))
                .map(|r| format!("[{}]", r.join(", ")))
                .collect();
            format!("Returns, row-major, `[{}]`.", rows.join(", "))
        }
    }
}
