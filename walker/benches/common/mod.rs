//! Helpers shared by the walker benches: timing, error measures, a hand-written SVG plot.

#![allow(dead_code, reason = "each bench binary uses a subset")]

use std::fmt::Write as _;
use std::time::Instant;

/// Median of a sample (sorted in place); NaN for an empty sample.
pub fn median(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// Runs `f` repeatedly (at least `min_reps`, until `budget_s` seconds are used or `max_reps`
/// runs) and returns all wall times in seconds.
pub fn time_reps<T>(
    mut f: impl FnMut() -> T,
    min_reps: usize,
    max_reps: usize,
    budget_s: f64,
) -> Vec<f64> {
    let mut times = Vec::new();
    let start = Instant::now();
    while times.len() < min_reps
        || (times.len() < max_reps && start.elapsed().as_secs_f64() < budget_s)
    {
        let t0 = Instant::now();
        std::hint::black_box(f());
        times.push(t0.elapsed().as_secs_f64());
    }
    times
}

/// Relative difference `|a - b| / |b|` (absolute when `b == 0`).
pub fn rel(a: f64, b: f64) -> f64 {
    let d = (a - b).abs();
    if b == 0.0 { d } else { d / b.abs() }
}

/// Normwise relative difference `max |a_i - b_i| / max |b_i|`.
pub fn rel_norm(a: &[f64], b: &[f64]) -> f64 {
    let s = b.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let d = a
        .iter()
        .zip(b)
        .fold(0.0_f64, |m, (x, y)| m.max((x - y).abs()));
    if s == 0.0 { d } else { d / s }
}

/// One curve of a log-log plot.
pub struct Curve {
    /// Legend label.
    pub label: String,
    /// Stroke colour.
    pub color: &'static str,
    /// `(x, y)` points (positive).
    pub points: Vec<(f64, f64)>,
}

/// One panel of the figure.
pub struct Panel {
    /// Title.
    pub title: String,
    /// Curves.
    pub curves: Vec<Curve>,
}

/// A row of log-log panels as SVG (axes with decade ticks, polylines with point markers).
pub fn svg_loglog(panels: &[Panel], xlabel: &str, ylabel: &str) -> String {
    let (pw, ph, ml, mr, mt, mb) = (330.0, 300.0, 62.0, 12.0, 28.0, 48.0);
    let w = pw * panels.len() as f64;
    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="11">"#,
        h = ph + 30.0
    );
    let _ = writeln!(s, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let finite = |v: f64| v.is_finite() && v > 0.0;
    let pts = panels
        .iter()
        .flat_map(|p| p.curves.iter().flat_map(|c| c.points.iter().copied()))
        .filter(|&(x, y)| finite(x) && finite(y));
    let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (x, y) in pts {
        x0 = x0.min(x.log10());
        x1 = x1.max(x.log10());
        y0 = y0.min(y.log10());
        y1 = y1.max(y.log10());
    }
    let (x0, x1, y0, y1) = (x0.floor(), x1.ceil(), y0.floor(), y1.ceil());
    for (k, p) in panels.iter().enumerate() {
        let ox = pw * k as f64;
        let sx = |x: f64| ox + ml + (x.log10() - x0) / (x1 - x0) * (pw - ml - mr);
        let sy = |y: f64| mt + (y1 - y.log10()) / (y1 - y0) * (ph - mt - mb);
        let _ = writeln!(
            s,
            r#"<rect x="{}" y="{mt}" width="{}" height="{}" fill="none" stroke="black"/>"#,
            ox + ml,
            pw - ml - mr,
            ph - mt - mb
        );
        let _ = writeln!(
            s,
            r#"<text x="{}" y="16" text-anchor="middle" font-weight="bold">{}</text>"#,
            ox + ml + (pw - ml - mr) / 2.0,
            p.title
        );
        let mut e = x0 as i32;
        while e <= x1 as i32 {
            let x = sx(10f64.powi(e));
            let _ = writeln!(
                s,
                r##"<line x1="{x}" y1="{mt}" x2="{x}" y2="{}" stroke="#ddd"/><text x="{x}" y="{}" text-anchor="middle">1e{e}</text>"##,
                ph - mb,
                ph - mb + 14.0
            );
            e += 1;
        }
        let mut e = y0 as i32;
        let ystep = if y1 - y0 > 10.0 { 2 } else { 1 };
        while e <= y1 as i32 {
            let y = sy(10f64.powi(e));
            let _ = writeln!(
                s,
                r##"<line x1="{}" y1="{y}" x2="{}" y2="{y}" stroke="#ddd"/><text x="{}" y="{}" text-anchor="end">1e{e}</text>"##,
                ox + ml,
                ox + pw - mr,
                ox + ml - 4.0,
                y + 4.0
            );
            e += ystep;
        }
        let _ = writeln!(
            s,
            r#"<text x="{}" y="{}" text-anchor="middle">{xlabel}</text>"#,
            ox + ml + (pw - ml - mr) / 2.0,
            ph - mb + 30.0
        );
        let _ = writeln!(
            s,
            r#"<text transform="translate({},{}) rotate(-90)" text-anchor="middle">{ylabel}</text>"#,
            ox + 14.0,
            mt + (ph - mt - mb) / 2.0
        );
        for (i, c) in p.curves.iter().enumerate() {
            let mut line = String::new();
            for &(x, y) in c.points.iter().filter(|&&(x, y)| finite(x) && finite(y)) {
                let _ = write!(line, "{:.1},{:.1} ", sx(x), sy(y));
                let _ = writeln!(
                    s,
                    r#"<circle cx="{:.1}" cy="{:.1}" r="2.2" fill="{}"/>"#,
                    sx(x),
                    sy(y),
                    c.color
                );
            }
            let _ = writeln!(
                s,
                r#"<polyline points="{line}" fill="none" stroke="{}" stroke-width="1.5"/>"#,
                c.color
            );
            let ly = mt + 12.0 + 14.0 * i as f64;
            let _ = writeln!(
                s,
                r#"<line x1="{}" y1="{ly}" x2="{}" y2="{ly}" stroke="{}" stroke-width="2"/><text x="{}" y="{}">{}</text>"#,
                ox + pw - mr - 110.0,
                ox + pw - mr - 92.0,
                c.color,
                ox + pw - mr - 88.0,
                ly + 4.0,
                c.label
            );
        }
    }
    let _ = writeln!(
        s,
        r#"<text x="6" y="{}" font-size="10">generated by walker/benches/work_precision.rs</text>"#,
        ph + 22.0
    );
    s.push_str("</svg>\n");
    s
}
