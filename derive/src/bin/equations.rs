//! Writes `docs/equations.md`: every kernel of the derivation in LaTeX, the paper's closed
//! forms at the impact posture and the double-support conditions.
//!
//! ```sh
//! cargo run -p walker-symbolic --bin walker-equations --release [-- OUTPUT]
//! ```
//!
//! `OUTPUT` defaults to `docs/equations.md` of the workspace. The times of the derivation and
//! of the rendering go to stderr.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use walker_symbolic::{Derivation, latex};

fn main() -> ExitCode {
    let path = std::env::args_os().nth(1).map_or_else(
        || PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../docs/equations.md"),
        PathBuf::from,
    );
    let start = Instant::now();
    let derivation = match Derivation::new() {
        Ok(d) => d,
        Err(e) => {
            eprintln!("derivation failed: {e}");
            return ExitCode::FAILURE;
        }
    };
    let derived = start.elapsed();
    let text = match latex::equations_markdown(&derivation) {
        Ok(t) => t,
        Err(e) => {
            eprintln!("rendering failed: {e}");
            return ExitCode::FAILURE;
        }
    };
    let rendered = start.elapsed() - derived;
    if let Err(e) = std::fs::write(&path, &text) {
        eprintln!("cannot write {}: {e}", path.display());
        return ExitCode::FAILURE;
    }
    let path = path.canonicalize().unwrap_or(path);
    eprintln!(
        "derivation of {} kernels: {:.3} s; rendering: {:.3} s; wrote {} ({} bytes)",
        derivation.kernels.len(),
        derived.as_secs_f64(),
        rendered.as_secs_f64(),
        path.display(),
        text.len()
    );
    ExitCode::SUCCESS
}
