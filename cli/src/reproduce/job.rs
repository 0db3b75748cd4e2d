//! The whole `walker reproduce` job: collect the data, write the CSV files, the figures and
//! `summary.txt` into one directory.

use std::fs;
use std::io;
use std::path::Path;

use super::csv::write_csvs;
use super::data::collect;
use super::figures::write_figures;
use super::stability::stability;
use super::summary::summary;

/// Run everything and write the CSV files, the figures (PNG and SVG) and `summary.txt` into
/// `out`; returns the summary.
///
/// # Errors
/// `out` could not be created, or a file in it could not be written.
pub fn run(out: &Path) -> io::Result<String> {
    fs::create_dir_all(out)?;
    let d = collect();
    write_csvs(out, &d)?;
    write_figures(out, &d).map_err(io::Error::other)?;
    let mut s = summary(&d);
    s.push_str(&stability(out)?);
    fs::write(out.join("summary.txt"), &s)?;
    Ok(s)
}
