//! Bifurcation diagrams: the walking speed `V` against the continued parameter, one colour per
//! branch; stable parts solid, unstable (and neutral) parts dashed, parts that are not
//! physical (lift-off, double support, heel strike before `T_set`) in a light tint of the
//! branch's colour; special points marked and tagged (`FP`, `PD`, `LO`, `FAM`, ...).

use std::path::Path;

use plotters::coord::Shift;
use plotters::prelude::*;
use walker::continuation::{Branch, Point, Stability};

use crate::plot;

const COLORS: [RGBColor; 4] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
];

/// A diagram: named branches and the axes' labels.
#[derive(Clone, Debug)]
pub struct Diagram<'a> {
    /// Title.
    pub title: String,
    /// The parameter axis's label.
    pub x_label: String,
    /// The branches with their legend labels.
    pub branches: Vec<(String, &'a Branch)>,
    /// Simulated steady gaits `(parameter, V)` drawn as small black crosses under this legend
    /// label (none if empty).
    pub simulated: (String, Vec<(f64, f64)>),
    /// Where the legend goes (where the curves leave room).
    pub legend: SeriesLabelPosition,
}

/// A run of a branch drawn in one style: stable, physical, and its `(parameter, V)` points.
type Run = (bool, bool, Vec<(f64, f64)>);

/// Runs of consecutive points with the same stability and physicality (neighbouring runs share
/// their end point, so the curve is unbroken).
fn runs(points: &[Point]) -> Vec<Run> {
    let key = |p: &Point| (p.stability == Stability::Stable, p.physical);
    let mut out: Vec<Run> = Vec::new();
    for (i, p) in points.iter().enumerate() {
        let k = key(p);
        let xy = (p.parameter, p.cycle.speed);
        match out.last_mut() {
            Some(run) if (run.0, run.1) == k => run.2.push(xy),
            _ => {
                let mut pts = Vec::new();
                if i > 0 {
                    let q = &points[i - 1];
                    pts.push((q.parameter, q.cycle.speed));
                }
                pts.push(xy);
                out.push((k.0, k.1, pts));
            }
        }
    }
    out
}

fn range(d: &Diagram<'_>) -> ((f64, f64), (f64, f64)) {
    let (mut xr, mut yr) = (
        (f64::INFINITY, f64::NEG_INFINITY),
        (f64::INFINITY, f64::NEG_INFINITY),
    );
    for (_, b) in &d.branches {
        for p in &b.points {
            if p.parameter.is_finite() && p.cycle.speed.is_finite() {
                xr = (xr.0.min(p.parameter), xr.1.max(p.parameter));
                yr = (yr.0.min(p.cycle.speed), yr.1.max(p.cycle.speed));
            }
        }
    }
    let pad = |r: (f64, f64)| {
        if !(r.0.is_finite() && r.1.is_finite()) {
            return (0.0, 1.0);
        }
        let w = (r.1 - r.0).max(1e-9 * r.0.abs().max(1.0));
        (r.0 - 0.05 * w, r.1 + 0.08 * w)
    };
    (pad(xr), pad(yr))
}

fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, d: &Diagram<'_>) -> Result<(), String>
where
    DB::ErrorType: 'static,
{
    let e = |x: &dyn std::fmt::Display| x.to_string();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let ((x0, x1), (y0, y1)) = range(d);
    let mut chart = ChartBuilder::on(&root)
        .caption(&d.title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|x| e(&x))?;
    chart
        .configure_mesh()
        .x_desc(&d.x_label)
        .y_desc("V (m/s)")
        .label_style(("sans-serif", 13))
        .draw()
        .map_err(|x| e(&x))?;
    for (k, (name, b)) in d.branches.iter().enumerate() {
        let c = COLORS[k % COLORS.len()];
        let mut legend = Some(name.clone());
        for (stable, physical, pts) in runs(&b.points) {
            let color = if physical { c.to_rgba() } else { c.mix(0.3) };
            let style = color.stroke_width(2);
            let ann = if stable {
                chart.draw_series(LineSeries::new(pts, style))
            } else {
                chart.draw_series(DashedLineSeries::new(pts, 6, 5, style))
            }
            .map_err(|x| e(&x))?;
            if physical && let Some(label) = legend.take() {
                ann.label(label).legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 18, y)], c.stroke_width(2))
                });
            }
        }
        for p in b.special() {
            let Some(l) = p.label else { continue };
            if l.tag == "EP" || l.tag == "UZ" {
                continue;
            }
            let xy = (p.parameter, p.cycle.speed);
            // The marker at the point, the tag beside it, above and to the right.
            let marked = EmptyElement::at(xy)
                + Circle::new((0, 0), 4, c.filled())
                + Text::new(
                    l.tag.to_owned(),
                    (6, -16),
                    ("sans-serif", 13).into_font().color(&BLACK),
                );
            chart.draw_series([marked]).map_err(|x| e(&x))?;
        }
    }
    let (label, pts) = &d.simulated;
    if !pts.is_empty() {
        let cross = |p: (f64, f64)| Cross::new(p, 3, BLACK.stroke_width(1));
        chart
            .draw_series(
                pts.iter()
                    .copied()
                    .filter(|(x, y)| x.is_finite() && y.is_finite())
                    .map(cross),
            )
            .map_err(|x| e(&x))?
            .label(label.clone())
            .legend(move |(x, y)| Cross::new((x + 9, y), 3, BLACK.stroke_width(1)));
    }
    chart
        .configure_series_labels()
        .position(d.legend.clone())
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .label_font(("sans-serif", 13))
        .draw()
        .map_err(|x| e(&x))?;
    root.present().map_err(|x| e(&x))?;
    Ok(())
}

/// Write the diagram to `path`: SVG if it ends in `.svg`, PNG otherwise (800 x 500).
///
/// # Errors
/// The file could not be drawn or written (the message of plotters).
pub fn save(d: &Diagram<'_>, path: &Path) -> Result<(), String> {
    plot::register();
    if path.extension().is_some_and(|x| x == "svg") {
        draw(SVGBackend::new(path, (800, 500)).into_drawing_area(), d)
    } else {
        crate::png::write_png(path, (800, 500), |area| draw(area, d))
    }
}
