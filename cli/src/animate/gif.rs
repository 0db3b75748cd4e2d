//! The animated GIF of a [`Film`]: every frame drawn in pixels ([`super::raster`]), mapped to
//! one global palette (the drawing's own colours, a grey ramp for the anti-aliased text and a
//! 6x6x6 colour cube for what else blending makes) and encoded with the `gif` crate, looping
//! forever. GIF delays are whole centiseconds; the rounding error is carried from frame to
//! frame, so that the playback clock never drifts more than 5 ms from the walk's.

use std::collections::HashMap;

use gif::{Encoder, Frame, Repeat};
use plotters::prelude::*;

use super::film::Film;
use super::raster;

/// The most pixels a GIF may have in all its frames together (`frames x width x height`):
/// 600 frames of 640 x 360 pixels. It bounds the time and the memory of a request; the file
/// itself is smaller, about 10 KB a frame at 640 x 360.
pub const MAX_GIF_PIXELS: u64 = 600 * 640 * 360;

/// The global palette, as RGB triples.
fn palette() -> Vec<[u8; 3]> {
    let mut p: Vec<[u8; 3]> = vec![
        [0xff, 0xff, 0xff],
        [0x00, 0x00, 0x00],
        [0x33, 0x33, 0x33],
        [0x55, 0x55, 0x55],
        [0x00, 0x72, 0xb2],
        [0xd5, 0x5e, 0x00],
        [0xe6, 0x9f, 0x00],
        [0xcc, 0x00, 0x00],
    ];
    for k in 1..16u8 {
        let v = k * 16;
        p.push([v, v, v]);
    }
    for r in 0..6u8 {
        for g in 0..6u8 {
            for b in 0..6u8 {
                p.push([r * 51, g * 51, b * 51]);
            }
        }
    }
    p
}

/// Maps colours to their nearest palette entry, remembering each colour seen (a frame has a
/// few hundred distinct colours at most: the drawing's and the text's blends).
struct Quantiser {
    palette: Vec<[u8; 3]>,
    seen: HashMap<[u8; 3], u8>,
}

impl Quantiser {
    fn new() -> Self {
        Quantiser {
            palette: palette(),
            seen: HashMap::new(),
        }
    }

    fn index(&mut self, c: [u8; 3]) -> u8 {
        if let Some(&i) = self.seen.get(&c) {
            return i;
        }
        let d = |p: &[u8; 3]| {
            (0..3)
                .map(|k| (i32::from(p[k]) - i32::from(c[k])).pow(2))
                .sum::<i32>()
        };
        let (i, _) = self
            .palette
            .iter()
            .enumerate()
            .min_by_key(|(_, p)| d(p))
            .unwrap_or((0, &[0; 3]));
        let i = u8::try_from(i).unwrap_or(0);
        self.seen.insert(c, i);
        i
    }

    fn flat(&self) -> Vec<u8> {
        self.palette.iter().flatten().copied().collect()
    }
}

/// The GIF of `f` as bytes.
///
/// # Errors
/// The picture is larger than a GIF allows (65535 pixels a side), or drawing or encoding
/// failed (the message says which).
pub fn animated_gif(f: &Film) -> Result<Vec<u8>, String> {
    crate::plot::register();
    let (w, h) = (f.view.width, f.view.height);
    let (gw, gh) = (
        u16::try_from(w).map_err(|_| format!("width {w} is above a GIF's 65535"))?,
        u16::try_from(h).map_err(|_| format!("height {h} is above a GIF's 65535"))?,
    );
    let mut q = Quantiser::new();
    let mut out = Vec::new();
    {
        let mut enc = Encoder::new(&mut out, gw, gh, &q.flat()).map_err(|e| e.to_string())?;
        enc.set_repeat(Repeat::Infinite)
            .map_err(|e| e.to_string())?;
        let mut rgb = vec![0u8; w as usize * h as usize * 3];
        let mut shown = 0.0;
        for i in 0..f.frames.len() {
            {
                let area = BitMapBackend::with_buffer(&mut rgb, (w, h)).into_drawing_area();
                raster::frame(&area, f, i)?;
                area.present().map_err(|e| e.to_string())?;
            }
            let pixels: Vec<u8> = rgb
                .chunks_exact(3)
                .map(|c| q.index([c[0], c[1], c[2]]))
                .collect();
            let mut frame = Frame::from_indexed_pixels(gw, gh, pixels, None);
            // A frame is shown until the next one; the last for the hold.
            let clock = if i + 1 == f.frames.len() {
                f.duration()
            } else {
                f.playback_time(i + 1)
            };
            let cs = ((clock - shown) * 100.0).round().clamp(1.0, 65535.0);
            shown += cs / 100.0;
            frame.delay = cs as u16;
            enc.write_frame(&frame).map_err(|e| e.to_string())?;
        }
    }
    Ok(out)
}
