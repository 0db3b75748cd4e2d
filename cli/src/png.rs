//! PNG files of plotters' bitmap drawings, encoded by the `png` crate.
//!
//! plotters writes PNGs itself only through its `bitmap_encoder` feature, which links the
//! `image` crate with its JPEG decoder and generic image machinery: about 40 s of CPU in a
//! fresh release build, to write PNGs only. Here a drawing renders into an RGB buffer
//! (plotters' `BitMapBackend::with_buffer`) and the buffer is encoded with the settings `image`
//! used (8-bit RGB, fast compression, adaptive filtering from `Sub`), so the files are the same
//! bytes as before.

use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;

/// Draws a `width x height` image with `draw` and writes it to `path` as a PNG.
///
/// # Errors
/// `draw`'s error, or the file could not be created or written (the message names it).
pub fn write_png(
    path: &Path,
    (width, height): (u32, u32),
    draw: impl FnOnce(DrawingArea<BitMapBackend<'_>, Shift>) -> Result<(), String>,
) -> Result<(), String> {
    let len = usize::try_from(u64::from(width) * u64::from(height) * 3).map_err(|_| {
        format!(
            "{}: an image of {width} x {height} is too large",
            path.display()
        )
    })?;
    let mut rgb = vec![0u8; len];
    draw(BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area())?;
    let io = |e: &dyn std::fmt::Display| format!("{}: {e}", path.display());
    let file = File::create(path).map_err(|e| io(&e))?;
    let mut encoder = png::Encoder::new(BufWriter::new(file), width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    encoder.set_filter(png::FilterType::Sub);
    encoder.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
    let mut writer = encoder.write_header().map_err(|e| io(&e))?;
    writer.write_image_data(&rgb).map_err(|e| io(&e))?;
    writer.finish().map_err(|e| io(&e))
}
