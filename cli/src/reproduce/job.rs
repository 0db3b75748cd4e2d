//! The whole `walker reproduce` job: collect the data, write the CSV files, the figures (the
//! bifurcation diagrams by continuation among them) and `summary.txt` into one directory.

use std::fs::{self, File};
use std::io::Write as _;
use std::path::Path;

use super::animations::write_animations;
use super::bifurcation::write_bifurcation;
use super::csv::write_csvs;
use super::data::collect;
use super::error::WriteError;
use super::figures::write_figures;
use super::stability::stability;
use super::summary::summary;

/// Run everything and write the CSV files, the figures (PNG and SVG) and `summary.txt` into
/// `out`; returns the summary. The directory and `summary.txt` are made first, so that an
/// unwritable `out` is reported before the minute of computing.
///
/// # Errors
/// `out` could not be created, or a file in it could not be written (the error names it).
pub fn run(out: &Path) -> Result<String, WriteError> {
    fs::create_dir_all(out).map_err(WriteError::file(out))?;
    let summary_path = out.join("summary.txt");
    let mut summary_file = File::create(&summary_path).map_err(WriteError::file(&summary_path))?;
    let d = collect()?;
    write_csvs(out, &d)?;
    write_figures(out, &d)?;
    write_animations(out)?;
    write_bifurcation(out, &d)?;
    let mut s = summary(&d);
    s.push_str(&stability(out)?);
    summary_file
        .write_all(s.as_bytes())
        .map_err(WriteError::file(&summary_path))?;
    Ok(s)
}
