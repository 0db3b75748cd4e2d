//! Helpers shared by the command line's end-to-end tests.

/// The decimal numbers (`0.45`, `62.95`; not integers, not `1e-6`) in `text`: the figures a
/// README caption or table quotes from a job's `summary.txt`.
pub fn decimals(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut current = String::new();
    for c in text.chars().chain(std::iter::once(' ')) {
        if c.is_ascii_digit() || (c == '.' && !current.is_empty() && !current.contains('.')) {
            current.push(c);
        } else {
            if current.contains('.') && !current.ends_with('.') {
                out.push(current.clone());
            }
            current.clear();
        }
    }
    out
}
