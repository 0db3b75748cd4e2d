//! A frame of a [`Film`] drawn in pixels with plotters (the GIF's frames, the PNG stick
//! diagram): the floor, the slip marks, the walker, the forces and the captions, in the same
//! colours as the SVG.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::caption::{LEGEND, frame_label};
use super::film::{Film, Patch};
use super::geometry::{Point, Pose};

/// Colour of the normal force (the SVG's `NORMAL_COLOUR`).
const NORMAL: RGBColor = RGBColor(0x00, 0x72, 0xb2);
/// Colour of the friction force (the SVG's `FRICTION_COLOUR`).
const FRICTION: RGBColor = RGBColor(0xd5, 0x5e, 0x00);
/// Colour of the slip marks (the SVG's `SLIP_COLOUR`).
const SLIP: RGBColor = RGBColor(0xe6, 0x9f, 0x00);

/// A drawing error of plotters, as text.
fn err(e: impl std::fmt::Display) -> String {
    e.to_string()
}

/// A world point in pixels with the camera at `centre`.
fn px(f: &Film, centre: Point, p: Point) -> (i32, i32) {
    let (x, y) = f.view.to_px(centre, p);
    // Far-off points are clamped: plotters draws in i32 pixels.
    (
        x.clamp(-1e6, 1e6).round() as i32,
        y.clamp(-1e6, 1e6).round() as i32,
    )
}

/// The part of the segment from `p` to `q` (world) inside the picture, in pixels; `None` if
/// none of it is (Liang and Barsky's clipping). Plotters moves each point outside the drawing
/// area onto its edge, which bends a line that leaves the picture (a slope running out below
/// it, or past its side a leg's length on), so the floor's lines are cut here first. A level
/// line is cut where plotters would have moved its ends, to the same pixels.
fn clipped(f: &Film, centre: Point, p: Point, q: Point) -> Option<[(i32, i32); 2]> {
    let (a, b) = (f.view.to_px(centre, p), f.view.to_px(centre, q));
    let (w, h) = (f64::from(f.view.width), f64::from(f.view.height));
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0_f64, 1.0_f64);
    for (towards, room) in [(-dx, a.0), (dx, w - a.0), (-dy, a.1), (dy, h - a.1)] {
        if towards == 0.0 {
            if room < 0.0 {
                return None;
            }
        } else if towards < 0.0 {
            t0 = t0.max(room / towards);
        } else {
            t1 = t1.min(room / towards);
        }
    }
    let at = |t: f64| ((a.0 + t * dx).round() as i32, (a.1 + t * dy).round() as i32);
    (t0 <= t1).then(|| [at(t0), at(t1)])
}

/// Line width in pixels of `metres` (at least 1).
fn width(f: &Film, metres: f64) -> u32 {
    (metres * f.view.scale).round().clamp(1.0, 50.0) as u32
}

/// The floor across the picture, with hatching below it, the camera at `centre`.
///
/// # Errors
/// Plotters could not draw.
pub fn floor<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    f: &Film,
    centre: Point,
) -> Result<(), String> {
    let b = &f.body;
    let (x0, x1) = f.view.x_range(centre);
    let (x0, x1) = (x0 - b.l, x1 + b.l);
    let line = |p: Point, q: Point| {
        PathElement::new(
            vec![px(f, centre, p), px(f, centre, q)],
            BLACK.stroke_width(2),
        )
    };
    // The floor's broken lines are drawn a piece at a time, each cut to the picture.
    let w = 0.05 * b.l;
    for p in &f.patches {
        let (a, z) = (f.floor.x_at(p.from), f.floor.x_at(p.to));
        let (r, g, bl) = Patch::colour(p.dry);
        let band = RGBColor(r, g, bl).stroke_width(width(f, w));
        for piece in f.floor.between(a, z).windows(2) {
            let [(xa, za), (xb, zb)] = [piece[0], piece[1]];
            if let Some(ends) = clipped(f, centre, (xa, za - 0.5 * w), (xb, zb - 0.5 * w)) {
                area.draw(&PathElement::new(ends.to_vec(), band))
                    .map_err(err)?;
            }
        }
    }
    for piece in f.floor.between(x0, x1).windows(2) {
        if let Some(ends) = clipped(f, centre, piece[0], piece[1]) {
            area.draw(&PathElement::new(ends.to_vec(), BLACK.stroke_width(2)))
                .map_err(err)?;
        }
    }
    let step = 0.25 * b.l;
    let mut x = (x0 / step).ceil() * step;
    while x <= x1 {
        let z = f.floor.z(x);
        area.draw(&line((x, z), (x - 0.1 * b.l, z - 0.1 * b.l)))
            .map_err(err)?;
        x += step;
    }
    Ok(())
}

/// The walker of `pose` (spokes, torso, hub; or a stick figure's links) in `colour`, the
/// camera at `centre`.
///
/// # Errors
/// Plotters could not draw.
pub fn walker<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    f: &Film,
    pose: &Pose,
    centre: Point,
    colour: RGBColor,
) -> Result<(), String> {
    let b = &f.body;
    if b.spokes == 0 {
        for &(a, c) in &pose.sticks {
            area.draw(&PathElement::new(
                vec![px(f, centre, a), px(f, centre, c)],
                colour.stroke_width(width(f, 0.04 * b.l)),
            ))
            .map_err(err)?;
        }
        return Ok(());
    }
    let hub = px(f, centre, pose.hub);
    for &end in &pose.spokes {
        area.draw(&PathElement::new(
            vec![hub, px(f, centre, end)],
            colour.stroke_width(width(f, 0.02 * b.l)),
        ))
        .map_err(err)?;
    }
    let torso = pose.torso.map(|p| px(f, centre, p)).to_vec();
    area.draw(&PathElement::new(
        torso,
        colour.mix(0.75).stroke_width(width(f, 0.06 * b.l)),
    ))
    .map_err(err)?;
    area.draw(&Circle::new(hub, width(f, 0.05 * b.l), colour.filled()))
        .map_err(err)?;
    Ok(())
}

/// The slip marks on the floor at frame `i`, the camera at `centre`.
///
/// # Errors
/// Plotters could not draw.
pub fn slip<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    f: &Film,
    centre: Point,
    i: usize,
) -> Result<(), String> {
    let b = &f.body;
    for m in f.marks_at(i) {
        let (p, q) = (f.floor.point_at(m.lo), f.floor.point_at(m.hi));
        area.draw(&PathElement::new(
            vec![px(f, centre, p), px(f, centre, q)],
            SLIP.stroke_width(width(f, 0.03 * b.l).max(3)),
        ))
        .map_err(err)?;
    }
    Ok(())
}

/// The stick figure of `pose` (a wheel's stance, fore and rear legs and the torso; a biped's
/// links) in thin lines of `colour`, the camera at `centre`.
///
/// # Errors
/// Plotters could not draw.
pub fn stick<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    f: &Film,
    pose: &Pose,
    centre: Point,
    colour: RGBColor,
) -> Result<(), String> {
    for &(a, c) in &pose.sticks {
        area.draw(&PathElement::new(
            vec![px(f, centre, a), px(f, centre, c)],
            colour.stroke_width(1),
        ))
        .map_err(err)?;
    }
    if f.body.spokes == 0 {
        return Ok(());
    }
    let hub = px(f, centre, pose.hub);
    for end in pose.stick_legs() {
        area.draw(&PathElement::new(
            vec![hub, px(f, centre, end)],
            colour.stroke_width(1),
        ))
        .map_err(err)?;
    }
    let torso = pose.torso.map(|p| px(f, centre, p)).to_vec();
    area.draw(&PathElement::new(torso, colour.stroke_width(1)))
        .map_err(err)?;
    Ok(())
}

/// An arrow from `from` along the drawn vector `v` (world m) in `colour`.
fn arrow<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    f: &Film,
    centre: Point,
    from: Point,
    v: Point,
    colour: RGBColor,
) -> Result<(), String> {
    let (a, tip) = (
        px(f, centre, from),
        px(f, centre, (from.0 + v.0, from.1 + v.1)),
    );
    let (dx, dy) = (f64::from(tip.0 - a.0), f64::from(tip.1 - a.1));
    let len = dx.hypot(dy);
    if len < 1.0 {
        return Ok(());
    }
    area.draw(&PathElement::new(vec![a, tip], colour.stroke_width(3)))
        .map_err(err)?;
    let (ux, uy) = (dx / len, dy / len);
    let head = 9.0;
    let corner = |s: f64| {
        (
            (f64::from(tip.0) - head * ux + s * 0.5 * head * uy).round() as i32,
            (f64::from(tip.1) - head * uy - s * 0.5 * head * ux).round() as i32,
        )
    };
    area.draw(&Polygon::new(
        vec![tip, corner(1.0), corner(-1.0)],
        colour.filled(),
    ))
    .map_err(err)?;
    Ok(())
}

/// Frame `i` of `f` as the animation shows it: the floor, the slip marks so far, the walker, the
/// forces on the stance foot, the captions and, on the last frame of a failed walk, the failure.
///
/// # Errors
/// Plotters could not draw.
pub fn frame<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    f: &Film,
    i: usize,
) -> Result<(), String> {
    let (Some(pose), Some(fr)) = (f.poses.get(i), f.frames.get(i)) else {
        return Ok(());
    };
    let b = &f.body;
    let centre = f.view.centre(pose.hub);
    area.fill(&WHITE).map_err(err)?;
    floor(area, f, centre)?;
    slip(area, f, centre, i)?;
    walker(area, f, pose, centre, RGBColor(0x33, 0x33, 0x33))?;
    arrow(area, f, centre, pose.foot, pose.normal_force, NORMAL)?;
    arrow(area, f, centre, pose.foot, pose.friction_force, FRICTION)?;
    area.draw(&Circle::new(
        px(f, centre, pose.foot),
        width(f, 0.035 * b.l),
        SLIP.filled(),
    ))
    .map_err(err)?;
    let font = ("sans-serif", 14).into_font();
    area.draw(&Text::new(f.title.clone(), (10, 8), font.clone()))
        .map_err(err)?;
    area.draw(&Text::new(frame_label(fr, 2), (10, 28), font.clone()))
        .map_err(err)?;
    let h = i32::try_from(f.view.height).unwrap_or(i32::MAX);
    area.draw(&Text::new(
        LEGEND,
        (10, h - 20),
        ("sans-serif", 12)
            .into_font()
            .color(&RGBColor(0x55, 0x55, 0x55)),
    ))
    .map_err(err)?;
    if i + 1 == f.frames.len()
        && let Some(fail) = &f.failure
    {
        area.draw(&Text::new(
            fail.clone(),
            (10, 48),
            font.color(&RGBColor(0xcc, 0, 0)),
        ))
        .map_err(err)?;
    }
    Ok(())
}
