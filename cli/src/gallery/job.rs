//! The whole `walker gallery` job: run the sweeps, write the CSV files, the figures and
//! `summary.txt` into one directory.

use std::fs::{self, File};
use std::io::Write as _;
use std::path::Path;

use super::bifurcation;
use super::csv::write_csvs;
use super::data::collect;
use super::figures::write_figures;
use super::summary::summary;
use crate::reproduce::WriteError;

/// Run every model of the gallery and write its CSV files, its figures (PNG and SVG), the
/// bifurcation diagrams and `summary.txt` into `out`; returns the summary. The directory and `summary.txt` are made
/// first, so that an unwritable `out` is reported before the computing.
///
/// # Errors
/// `out` could not be created, or a file in it could not be written (the error names it).
pub fn run(out: &Path) -> Result<String, WriteError> {
    fs::create_dir_all(out).map_err(WriteError::file(out))?;
    let summary_path = out.join("summary.txt");
    let mut summary_file = File::create(&summary_path).map_err(WriteError::file(&summary_path))?;
    let runs = collect()?;
    for run in &runs {
        write_csvs(out, run)?;
        write_figures(out, run)?;
    }
    let diagrams = bifurcation::compute();
    bifurcation::write(out, &diagrams)?;
    let s = summary(&runs, &diagrams);
    summary_file
        .write_all(s.as_bytes())
        .map_err(WriteError::file(&summary_path))?;
    Ok(s)
}
