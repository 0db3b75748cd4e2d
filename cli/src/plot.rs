//! Line and point plots written as PNG and SVG with plotters, using the bundled DejaVu Sans font
//! (`cli/assets/DejaVuSans.ttf`, licence in `cli/assets/DejaVuSans-LICENSE.txt`).

use std::path::Path;
use std::sync::Once;

use plotters::prelude::*;
use plotters::style::FontStyle;

static FONT: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

/// Register the bundled font as `sans-serif` for plotters (once; later calls do nothing).
pub fn register() {
    REGISTER.call_once(|| {
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, FONT);
    });
}

/// One named series of `(x, y)` points.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend label.
    pub label: String,
    /// The points (non-finite points are dropped).
    pub points: Vec<(f64, f64)>,
}

impl Series {
    /// A series from a label and points.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self {
            label: label.into(),
            points: points
                .into_iter()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect(),
        }
    }
}

/// A figure with one panel.
#[derive(Clone, Debug, PartialEq)]
pub struct Figure {
    /// Title.
    pub title: String,
    /// Label of the x axis.
    pub x_label: String,
    /// Label of the y axis.
    pub y_label: String,
    /// The series.
    pub series: Vec<Series>,
    /// Draw markers at the points (as well as lines).
    pub markers: bool,
    /// Use the same scale on both axes (stick diagrams).
    pub equal_axes: bool,
}

const COLORS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(0, 0, 0),
];

fn range(fig: &Figure) -> ((f64, f64), (f64, f64)) {
    let mut xr = (f64::INFINITY, f64::NEG_INFINITY);
    let mut yr = xr;
    for s in &fig.series {
        for &(x, y) in &s.points {
            xr = (xr.0.min(x), xr.1.max(x));
            yr = (yr.0.min(y), yr.1.max(y));
        }
    }
    let pad = |r: (f64, f64)| {
        if !(r.0.is_finite() && r.1.is_finite()) {
            return (0.0, 1.0);
        }
        let w = (r.1 - r.0).max(1e-9 * r.0.abs().max(1.0));
        (r.0 - 0.05 * w, r.1 + 0.05 * w)
    };
    let (mut xr, mut yr) = (pad(xr), pad(yr));
    if fig.equal_axes {
        let w = (xr.1 - xr.0).max((yr.1 - yr.0) * 2.0);
        let (xc, yc) = ((xr.0 + xr.1) / 2.0, (yr.0 + yr.1) / 2.0);
        xr = (xc - w / 2.0, xc + w / 2.0);
        yr = (yc - w / 4.0, yc + w / 4.0);
    }
    (xr, yr)
}

fn draw<DB: DrawingBackend>(
    root: DrawingArea<DB, plotters::coord::Shift>,
    fig: &Figure,
) -> Result<(), String>
where
    DB::ErrorType: 'static,
{
    let e = |x: &dyn std::fmt::Display| x.to_string();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let ((x0, x1), (y0, y1)) = range(fig);
    let mut chart = ChartBuilder::on(&root)
        .caption(&fig.title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(|x| e(&x))?;
    chart
        .configure_mesh()
        .x_desc(&fig.x_label)
        .y_desc(&fig.y_label)
        .label_style(("sans-serif", 13))
        .draw()
        .map_err(|x| e(&x))?;
    for (k, s) in fig.series.iter().enumerate() {
        let c = COLORS[k % COLORS.len()];
        let ann = chart
            .draw_series(LineSeries::new(s.points.iter().copied(), c.stroke_width(2)))
            .map_err(|x| e(&x))?;
        if !s.label.is_empty() {
            ann.label(s.label.clone()).legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 18, y)], c.stroke_width(2))
            });
        }
        if fig.markers {
            chart
                .draw_series(PointSeries::of_element(
                    s.points.iter().copied(),
                    3,
                    c.filled(),
                    &|p, r, st| Circle::new(p, r, st),
                ))
                .map_err(|x| e(&x))?;
        }
    }
    if fig.series.iter().any(|s| !s.label.is_empty()) {
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .label_font(("sans-serif", 13))
            .draw()
            .map_err(|x| e(&x))?;
    }
    root.present().map_err(|x| e(&x))?;
    Ok(())
}

/// Write `fig` as `stem.png` and `stem.svg`.
pub fn save(fig: &Figure, stem: &Path) -> Result<(), String> {
    register();
    let png = stem.with_extension("png");
    let svg = stem.with_extension("svg");
    draw(
        BitMapBackend::new(&png, (800, 500)).into_drawing_area(),
        fig,
    )?;
    draw(SVGBackend::new(&svg, (800, 500)).into_drawing_area(), fig)?;
    Ok(())
}
