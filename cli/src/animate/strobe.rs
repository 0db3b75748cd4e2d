//! The stick diagram (`walker animate --strobe`): the walker drawn at equal time intervals over
//! the whole walk in one still picture, as walking papers print gaits (the paper's Figs. 11
//! and 14), over the floor with the slip marks the stance feet left; as SVG (text, as the
//! animation) or PNG (plotters). Each pose is its stance leg, its fore leg, its rear leg and
//! the torso: all twelve spokes of every pose would hide the gait.

use std::path::Path;

use plotters::prelude::*;

use super::film::Film;
use super::geometry::Point;
use super::raster;
use super::svg::{SLIP_COLOUR, escape, floor, header, num};
use super::view::View;

/// The stick diagram's width (px).
pub const STROBE_WIDTH: u32 = 1000;

/// `f` with a still view of the whole walk, [`STROBE_WIDTH`] pixels wide.
#[must_use]
pub fn still(f: &Film) -> Film {
    let hubs: Vec<Point> = f.poses.iter().map(|p| p.hub).collect();
    Film {
        view: View::fit(&f.body, &hubs, STROBE_WIDTH),
        ..f.clone()
    }
}

/// The stick diagram of `f` (already [`still`]) as SVG text.
#[must_use]
pub fn strobe_svg(f: &Film) -> String {
    let (w, h) = (f.view.width, f.view.height);
    let b = &f.body;
    let c = f.view.fixed;
    let mut s = header(w, h);
    s.push_str(&format!(
        "<g transform=\"translate({} {}) scale({} {}) translate({} {})\">\n",
        num(f64::from(w) / 2.0),
        num(f.view.top),
        num(f.view.scale),
        num(-f.view.scale),
        num(-c.0),
        num(-c.1)
    ));
    let (x0, x1) = f.view.x_range(c);
    s.push_str(&floor(f, x0, x1));
    for m in f.marks_at(f.marks.len().saturating_sub(1)) {
        let (p, q) = (f.floor.point_at(m.lo), f.floor.point_at(m.hi));
        s.push_str(&format!(
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\" stroke=\"{SLIP_COLOUR}\" \
             stroke-width=\"{}\"/>\n",
            num(p.0),
            num(p.1),
            num(q.0),
            num(q.1),
            num(0.03 * b.l)
        ));
    }
    for p in &f.poses {
        let mut d = String::new();
        for e in &p.stick_legs() {
            d.push_str(&format!(
                "M{} {}L{} {}",
                num(p.hub.0),
                num(p.hub.1),
                num(e.0),
                num(e.1)
            ));
        }
        let lines = if b.spokes == 0 {
            p.sticks.clone()
        } else {
            vec![(p.torso[0], p.torso[1])]
        };
        for (a, c) in lines {
            d.push_str(&format!(
                "M{} {}L{} {}",
                num(a.0),
                num(a.1),
                num(c.0),
                num(c.1)
            ));
        }
        s.push_str(&format!(
            "<path d=\"{d}\" stroke=\"#555\" stroke-opacity=\"0.7\" stroke-width=\"{}\" \
             fill=\"none\"/>\n",
            num(0.01 * b.l)
        ));
    }
    s.push_str("</g>\n");
    s.push_str(&format!(
        "<text x=\"10\" y=\"20\" font-size=\"14\">{}</text>\n",
        escape(&f.title)
    ));
    s.push_str(&format!(
        "<text x=\"10\" y=\"40\" font-size=\"14\">{}</text>\n",
        escape(&interval_text(f))
    ));
    if let Some(fail) = &f.failure {
        s.push_str(&format!(
            "<text x=\"10\" y=\"60\" font-size=\"14\" fill=\"#c00\">{}</text>\n",
            escape(fail)
        ));
    }
    s.push_str("</svg>\n");
    s
}

/// What the diagram shows: how many poses, how far apart in time.
fn interval_text(f: &Film) -> String {
    let dt = f.frames.get(1).map_or(0.0, |g| g.time) - f.frames.first().map_or(0.0, |g| g.time);
    let drawn = if f.body.spokes == 0 {
        "the links between the model's points"
    } else {
        "stance, fore and rear legs, torso"
    };
    format!(
        "{} poses every {} s (the last at the failure, if any): {drawn}; orange: slip",
        f.poses.len(),
        num(dt)
    )
}

/// Write the stick diagram of `f` (already [`still`]) as a PNG at `path`.
///
/// # Errors
/// Plotters could not draw or write the file (the message says which).
pub fn strobe_png(f: &Film, path: &Path) -> Result<(), String> {
    crate::plot::register();
    crate::png::write_png(path, (f.view.width, f.view.height), |area| {
        draw_strobe(&area, f)
    })
}

/// Draws the stick diagram of `f` on `area`.
fn draw_strobe(
    area: &DrawingArea<BitMapBackend<'_>, plotters::coord::Shift>,
    f: &Film,
) -> Result<(), String> {
    let e = |x: &dyn std::fmt::Display| x.to_string();
    area.fill(&WHITE).map_err(|x| e(&x))?;
    let c = f.view.fixed;
    raster::floor(area, f, c)?;
    raster::slip(area, f, c, f.marks.len().saturating_sub(1))?;
    for p in &f.poses {
        raster::stick(area, f, p, c, RGBColor(0x55, 0x55, 0x55))?;
    }
    let font = ("sans-serif", 14).into_font();
    area.draw(&Text::new(f.title.clone(), (10, 8), font.clone()))
        .map_err(|x| e(&x))?;
    area.draw(&Text::new(interval_text(f), (10, 28), font.clone()))
        .map_err(|x| e(&x))?;
    if let Some(fail) = &f.failure {
        area.draw(&Text::new(
            fail.clone(),
            (10, 48),
            font.color(&RGBColor(0xcc, 0, 0)),
        ))
        .map_err(|x| e(&x))?;
    }
    area.present().map_err(|x| e(&x))?;
    Ok(())
}
