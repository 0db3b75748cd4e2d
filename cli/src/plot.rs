//! Line and point plots written as PNG and SVG with plotters, using the bundled DejaVu Sans font
//! (`cli/assets/DejaVuSans.ttf`, licence in `cli/assets/DejaVuSans-LICENSE.txt`): one panel
//! ([`save`]) or several side by side under one title ([`save_grid`]). A series is a line (with
//! the figure's markers) or markers of one [`Marker`] shape only, in the colour of its position
//! or of a palette index it names.

use std::path::Path;
use std::sync::Once;

use plotters::chart::SeriesLabelPosition;
use plotters::coord::Shift;
use plotters::element::{Drawable, PointCollection};
use plotters::prelude::*;
use plotters::style::FontStyle;
use plotters_backend::{BackendCoord, DrawingErrorKind};

static FONT: &[u8] = include_bytes!("../assets/DejaVuSans.ttf");
static REGISTER: Once = Once::new();

/// Register the bundled font as `sans-serif` for plotters (once; later calls do nothing).
pub fn register() {
    REGISTER.call_once(|| {
        let _ = plotters::style::register_font("sans-serif", FontStyle::Normal, FONT);
    });
}

/// The shape of a series drawn as markers only ([`Series::markers`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Marker {
    /// A filled disc.
    Circle,
    /// A circle's outline.
    Ring,
    /// An upright filled triangle.
    Triangle,
    /// A filled square.
    Square,
    /// A filled square on its corner.
    Diamond,
    /// A diagonal cross.
    Cross,
    /// An upright cross.
    Plus,
}

/// The palette index of black ([`Series::color`]).
pub const BLACK: usize = 5;

/// One named series of `(x, y)` points.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    /// Legend label (none if empty).
    pub label: String,
    /// The points (non-finite points are dropped).
    pub points: Vec<(f64, f64)>,
    /// The palette index of its colour; `None`: the index of its position in the figure.
    pub color: Option<usize>,
    /// `None`: a line (with markers if the figure has them); a shape: only markers of it.
    pub marker: Option<Marker>,
}

impl Series {
    /// A series from a label and points, drawn as a line.
    pub fn new(label: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self {
            label: label.into(),
            points: points
                .into_iter()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect(),
            color: None,
            marker: None,
        }
    }

    /// This series in the palette's colour `index` (modulo the palette's length; [`BLACK`]).
    #[must_use]
    pub fn color(self, index: usize) -> Self {
        Self {
            color: Some(index),
            ..self
        }
    }

    /// This series as markers of `shape` only, without a line.
    #[must_use]
    pub fn markers(self, shape: Marker) -> Self {
        Self {
            marker: Some(shape),
            ..self
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
    /// Where the legend goes; `None`: plotters' default (middle right).
    pub legend: Option<SeriesLabelPosition>,
    /// The y axis's range; `None`: the points' range with a margin.
    pub y_range: Option<(f64, f64)>,
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
    let (mut xr, mut yr) = (pad(xr), fig.y_range.unwrap_or_else(|| pad(yr)));
    if fig.equal_axes {
        let w = (xr.1 - xr.0).max((yr.1 - yr.0) * 2.0);
        let (xc, yc) = ((xr.0 + xr.1) / 2.0, (yr.0 + yr.1) / 2.0);
        xr = (xc - w / 2.0, xc + w / 2.0);
        yr = (yc - w / 4.0, yc + w / 4.0);
    }
    (xr, yr)
}

/// A marker of a shape and colour at a data or pixel coordinate: one element type for every
/// shape, so that a series and its legend entry draw it alike.
struct MarkerElement<C> {
    at: C,
    shape: Marker,
    color: RGBColor,
}

impl<'a, C: 'a> PointCollection<'a, C> for &'a MarkerElement<C> {
    type Point = &'a C;
    type IntoIter = std::iter::Once<&'a C>;
    fn point_iter(self) -> Self::IntoIter {
        std::iter::once(&self.at)
    }
}

impl<C, DB: DrawingBackend> Drawable<DB> for MarkerElement<C> {
    fn draw<I: Iterator<Item = BackendCoord>>(
        &self,
        mut points: I,
        backend: &mut DB,
        _: (u32, u32),
    ) -> Result<(), DrawingErrorKind<DB::ErrorType>> {
        const R: i32 = 4;
        let Some((x, y)) = points.next() else {
            return Ok(());
        };
        let (fill, line) = (self.color.filled(), self.color.stroke_width(2));
        let d = R + 1;
        match self.shape {
            Marker::Circle => backend.draw_circle((x, y), R as u32, &fill, true),
            Marker::Ring => backend.draw_circle((x, y), R as u32, &line, false),
            Marker::Triangle => {
                backend.fill_polygon([(x, y - d), (x + d, y + R), (x - d, y + R)], &fill)
            }
            Marker::Square => backend.draw_rect((x - R, y - R), (x + R, y + R), &fill, true),
            Marker::Diamond => {
                backend.fill_polygon([(x, y - d), (x + d, y), (x, y + d), (x - d, y)], &fill)
            }
            Marker::Cross => {
                backend.draw_line((x - R, y - R), (x + R, y + R), &line)?;
                backend.draw_line((x - R, y + R), (x + R, y - R), &line)
            }
            Marker::Plus => {
                backend.draw_line((x - d, y), (x + d, y), &line)?;
                backend.draw_line((x, y - d), (x, y + d), &line)
            }
        }
    }
}

/// Draw `fig` on `root` (the whole image) and write the image.
fn draw<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, fig: &Figure) -> Result<(), String>
where
    DB::ErrorType: 'static,
{
    let e = |x: &dyn std::fmt::Display| x.to_string();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    draw_panel(&root, fig)?;
    root.present().map_err(|x| e(&x))?;
    Ok(())
}

/// Draw `fig` on `area` (a whole image or one panel of it).
fn draw_panel<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, fig: &Figure) -> Result<(), String>
where
    DB::ErrorType: 'static,
{
    let e = |x: &dyn std::fmt::Display| x.to_string();
    let ((x0, x1), (y0, y1)) = range(fig);
    let mut chart = ChartBuilder::on(area)
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
        let c = COLORS[s.color.unwrap_or(k) % COLORS.len()];
        if let Some(shape) = s.marker {
            let ann = chart
                .draw_series(s.points.iter().map(|&at| MarkerElement {
                    at,
                    shape,
                    color: c,
                }))
                .map_err(|x| e(&x))?;
            if !s.label.is_empty() {
                ann.label(s.label.clone())
                    .legend(move |(x, y)| MarkerElement {
                        at: (x + 9, y),
                        shape,
                        color: c,
                    });
            }
            continue;
        }
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
        let mut labels = chart.configure_series_labels();
        if let Some(at) = &fig.legend {
            labels.position(at.clone());
        }
        labels
            .background_style(WHITE.mix(0.8))
            .border_style(plotters::style::colors::BLACK)
            .label_font(("sans-serif", 13))
            .draw()
            .map_err(|x| e(&x))?;
    }
    Ok(())
}

/// Draw `panels` on `root` in rows of `cols` under the caption `title`, and write the image.
fn draw_grid<DB: DrawingBackend>(
    root: DrawingArea<DB, Shift>,
    title: &str,
    panels: &[Figure],
    cols: usize,
) -> Result<(), String>
where
    DB::ErrorType: 'static,
{
    let e = |x: &dyn std::fmt::Display| x.to_string();
    root.fill(&WHITE).map_err(|x| e(&x))?;
    let body = root.titled(title, ("sans-serif", 24)).map_err(|x| e(&x))?;
    let cols = cols.max(1);
    let rows = panels.len().div_ceil(cols).max(1);
    for (area, fig) in body.split_evenly((rows, cols)).iter().zip(panels) {
        draw_panel(area, fig)?;
    }
    root.present().map_err(|x| e(&x))?;
    Ok(())
}

/// Write `fig` as `stem.png` and `stem.svg`.
pub fn save(fig: &Figure, stem: &Path) -> Result<(), String> {
    register();
    let png = stem.with_extension("png");
    let svg = stem.with_extension("svg");
    crate::png::write_png(&png, (800, 500), |area| draw(area, fig))?;
    draw(SVGBackend::new(&svg, (800, 500)).into_drawing_area(), fig)?;
    Ok(())
}

/// Write `panels` in rows of `cols` under the caption `title` as `stem.png` and `stem.svg`, the
/// whole image `size` pixels.
pub fn save_grid(
    title: &str,
    panels: &[Figure],
    cols: usize,
    size: (u32, u32),
    stem: &Path,
) -> Result<(), String> {
    register();
    let png = stem.with_extension("png");
    let svg = stem.with_extension("svg");
    crate::png::write_png(&png, size, |area| draw_grid(area, title, panels, cols))?;
    draw_grid(
        SVGBackend::new(&svg, size).into_drawing_area(),
        title,
        panels,
        cols,
    )?;
    Ok(())
}
