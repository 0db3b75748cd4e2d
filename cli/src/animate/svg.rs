//! The animated SVG of a [`Film`]: one drawing whose moving parts carry SMIL `<animate>` and
//! `<animateTransform>` elements with one keyframe per frame (plus the last one repeated for the
//! hold at the end), so that a browser plays it without scripts and an SVG embedded as an image
//! (a README) moves too.
//!
//! The SVG is written as text: it is a handful of element kinds whose attributes are numbers,
//! and the animation elements it needs are not what a plotting library draws (plotters' SVG
//! backend draws still pictures). Numbers are written with 4 decimals in metres (0.1 mm, well
//! below a pixel) and trailing zeros cut, which keeps a walk of a few steps near 100 KB.

use super::caption::{LEGEND, frame_label};
use super::film::{Film, Patch};
use super::geometry::Point;

/// Colour of the normal force (Okabe-Ito blue).
pub const NORMAL_COLOUR: &str = "#0072b2";
/// Colour of the friction force (Okabe-Ito vermilion).
pub const FRICTION_COLOUR: &str = "#d55e00";
/// Colour of the slip marks (Okabe-Ito orange).
pub const SLIP_COLOUR: &str = "#e69f00";

/// `x` with at most 4 decimals, trailing zeros (and a trailing point) cut, `-0` written `0`.
#[must_use]
pub fn num(x: f64) -> String {
    let s = format!("{x:.4}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        &s
    };
    if s == "-0" {
        "0".to_owned()
    } else {
        s.to_owned()
    }
}

/// The opening of an SVG document of `width x height` pixels with a white background.
#[must_use]
pub fn header(width: u32, height: u32) -> String {
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{width}\" height=\"{height}\" \
         viewBox=\"0 0 {width} {height}\" font-family=\"DejaVu Sans, sans-serif\">\n\
         <rect width=\"{width}\" height=\"{height}\" fill=\"white\"/>\n"
    )
}

/// The broken line through `points`, each moved down by `down`, as path data.
fn broken_line(points: &[Point], down: f64) -> String {
    let mut d = String::new();
    for (i, p) in points.iter().enumerate() {
        d.push_str(&format!(
            "{}{} {}",
            if i == 0 { "M" } else { "L" },
            num(p.0),
            num(p.1 - down)
        ));
    }
    d
}

/// The floor from `x0` to `x1` (world m) with hatching below it, in world coordinates.
#[must_use]
pub fn floor(f: &Film, x0: f64, x1: f64) -> String {
    let b = &f.body;
    let mut d = broken_line(&f.floor.between(x0, x1), 0.0);
    let step = 0.25 * b.l;
    let mut x = (x0 / step).ceil() * step;
    while x <= x1 {
        let z = f.floor.z(x);
        d.push_str(&format!(
            "M{} {}l{} {}",
            num(x),
            num(z),
            num(-0.1 * b.l),
            num(-0.1 * b.l)
        ));
        x += step;
    }
    let mut out = patches(f);
    out.push_str(&format!(
        "<path d=\"{d}\" stroke=\"black\" stroke-width=\"{}\" fill=\"none\"/>\n",
        num(0.012 * b.l)
    ));
    out
}

/// The floor's patches of friction under the floor line, each with its step (counted from 1,
/// as the frame labels count) and `mu0` as a tooltip, in world coordinates.
fn patches(f: &Film) -> String {
    let w = 0.05 * f.body.l;
    let mut s = String::new();
    for p in &f.patches {
        let (x0, x1) = (f.floor.x_at(p.from), f.floor.x_at(p.to));
        let (r, g, bl) = Patch::colour(p.dry);
        s.push_str(&format!(
            "<path class=\"floor-patch\" d=\"{}\" stroke=\"rgb({r},{g},{bl})\" \
             stroke-width=\"{}\"><title>{}: mu0 = {}</title></path>\n",
            broken_line(&f.floor.between(x0, x1), 0.5 * w),
            num(w),
            p.step.map_or_else(
                || format!("{} m to {} m", num(p.from), num(p.to)),
                |k| format!("step {}", k + 1)
            ),
            p.mu0
        ));
    }
    s
}

/// The wheel's spokes around a hub at the origin with spoke 0 straight down, as a path.
#[must_use]
pub fn spokes_path(f: &Film) -> String {
    let b = &f.body;
    let mut d = String::new();
    for k in 0..b.spokes {
        let a = k as f64 * b.alpha;
        d.push_str(&format!(
            "M0 0L{} {}",
            num(b.l * a.sin()),
            num(-b.l * a.cos())
        ));
    }
    d
}

/// The playback description shared by every animation element: duration, key times, looping.
struct Timing {
    /// ` dur=".." keyTimes=".." repeatCount="indefinite"`.
    attrs: String,
    /// The key time of each frame (the hold's end, 1, comes after them).
    key_times: Vec<f64>,
    /// The duration, as written (s).
    dur: String,
}

impl Timing {
    fn of(f: &Film) -> Self {
        let dur = f.duration();
        let key_times: Vec<f64> = (0..f.frames.len())
            .map(|i| f.playback_time(i) / dur)
            .collect();
        let mut kt: Vec<String> = key_times.iter().map(|&k| num_key(k)).collect();
        kt.push("1".to_owned());
        Timing {
            attrs: format!(
                " dur=\"{}s\" keyTimes=\"{}\" repeatCount=\"indefinite\"",
                num(dur),
                kt.join(";")
            ),
            key_times,
            dur: num(dur),
        }
    }
}

/// A key time with 6 decimals (a microsecond in a second of playback).
fn num_key(k: f64) -> String {
    let s = format!("{k:.6}");
    s.trim_end_matches('0').trim_end_matches('.').to_owned()
}

/// The values of one animated attribute: one per frame, the last repeated for the hold.
fn values(v: impl Iterator<Item = String>) -> String {
    let mut v: Vec<String> = v.collect();
    if let Some(last) = v.last().cloned() {
        v.push(last);
    }
    v.join(";")
}

/// An `<animateTransform>` of `kind` (`translate`, `rotate`) through `vals`.
fn animate_transform(kind: &str, vals: &str, t: &Timing) -> String {
    format!(
        "<animateTransform attributeName=\"transform\" type=\"{kind}\" values=\"{vals}\"{}/>\n",
        t.attrs
    )
}

/// An `<animate>` of `attr` through `vals`.
fn animate(attr: &str, vals: &str, t: &Timing) -> String {
    format!(
        "<animate attributeName=\"{attr}\" values=\"{vals}\"{}/>\n",
        t.attrs
    )
}

/// An `<animate>` of `attr` through `vals` at the key times `keys` (from 0 to 1, as many).
fn animate_keyed(attr: &str, keys: &[f64], vals: &[String], t: &Timing) -> String {
    let kt: Vec<String> = keys.iter().map(|&k| num_key(k)).collect();
    format!(
        "<animate attributeName=\"{attr}\" values=\"{}\" keyTimes=\"{}\" dur=\"{}s\" \
         repeatCount=\"indefinite\"/>\n",
        vals.join(";"),
        kt.join(";"),
        t.dur
    )
}

/// Points as `x z` translate values.
fn translations(points: impl Iterator<Item = Point>) -> String {
    values(points.map(|p| format!("{} {}", num(p.0), num(p.1))))
}

/// A text that is visible from key time `from` to `to` (`None`: to the end) and hidden
/// otherwise, at pixel `(x, y)`.
fn timed_text(
    text: &str,
    (x, y): (f64, f64),
    colour: &str,
    from: f64,
    to: Option<f64>,
    dur: f64,
) -> String {
    let (vals, kt) = match (from > 0.0, to) {
        (false, Some(b)) => ("visible;hidden".to_owned(), format!("0;{}", num_key(b))),
        (false, None) => ("visible".to_owned(), "0".to_owned()),
        (true, Some(b)) => (
            "hidden;visible;hidden".to_owned(),
            format!("0;{};{}", num_key(from), num_key(b)),
        ),
        (true, None) => ("hidden;visible".to_owned(), format!("0;{}", num_key(from))),
    };
    format!(
        "<text x=\"{}\" y=\"{}\" font-size=\"14\" fill=\"{colour}\" visibility=\"hidden\">{}\
         <animate attributeName=\"visibility\" values=\"{vals}\" keyTimes=\"{kt}\" \
         calcMode=\"discrete\" dur=\"{}s\" repeatCount=\"indefinite\"/></text>\n",
        num(x),
        num(y),
        escape(text),
        num(dur)
    )
}

/// `s` with the XML special characters escaped.
#[must_use]
pub fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The arrowhead markers of the two forces.
fn markers() -> String {
    [("normal", NORMAL_COLOUR), ("friction", FRICTION_COLOUR)]
        .iter()
        .map(|(id, c)| {
            format!(
                "<marker id=\"{id}\" viewBox=\"0 0 10 10\" refX=\"8\" refY=\"5\" \
                 markerWidth=\"4\" markerHeight=\"4\" orient=\"auto\">\
                 <path d=\"M0 0L10 5L0 10z\" fill=\"{c}\"/></marker>"
            )
        })
        .collect::<Vec<_>>()
        .join("")
}

/// The animated SVG of `f`.
#[must_use]
pub fn animated_svg(f: &Film) -> String {
    let (w, h) = (f.view.width, f.view.height);
    let t = Timing::of(f);
    let dur = f.duration();
    let b = &f.body;
    let mut s = header(w, h);
    s.push_str(&format!("<defs>{}</defs>\n", markers()));
    // The world: metres, z up, with the camera's centre at the picture's reference point.
    s.push_str(&format!(
        "<g transform=\"translate({} {}) scale({} {})\">\n",
        num(f64::from(w) / 2.0),
        num(f.view.top),
        num(f.view.scale),
        num(-f.view.scale)
    ));
    let centres: Vec<Point> = f.poses.iter().map(|p| f.view.centre(p.hub)).collect();
    let c0 = centres.first().copied().unwrap_or(f.view.fixed);
    s.push_str(&format!(
        "<g transform=\"translate({} {})\">\n",
        num(-c0.0),
        num(-c0.1)
    ));
    if f.view.follow {
        s.push_str(&animate_transform(
            "translate",
            &translations(centres.iter().map(|c| (-c.0, -c.1))),
            &t,
        ));
    }
    // The floor under every place the camera looks at.
    let (lo, hi) = centres
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, z), c| {
            let (x0, x1) = f.view.x_range(*c);
            (a.min(x0), z.max(x1))
        });
    if lo.is_finite() {
        s.push_str(&floor(f, lo - b.l, hi + b.l));
    }
    s.push_str(&slip_marks(f, &t));
    if b.spokes == 0 {
        s.push_str(&stick_lines(f, &t));
    } else {
        s.push_str(&wheel(f, &t));
    }
    s.push_str(&forces(f, &t));
    s.push_str("</g>\n</g>\n");
    // Captions, in pixels.
    s.push_str(&format!(
        "<text x=\"10\" y=\"20\" font-size=\"14\">{}</text>\n<text x=\"10\" y=\"{}\" \
         font-size=\"12\" fill=\"#555\">{}</text>\n",
        escape(&f.title),
        h - 10,
        LEGEND
    ));
    s.push_str(&labels(f, &t, dur));
    if let Some(fail) = &f.failure {
        let from = t.key_times.last().copied().unwrap_or(0.0);
        s.push_str(&timed_text(fail, (10.0, 60.0), "#c00", from, None, dur));
    }
    s.push_str("</svg>\n");
    s
}

/// The wheel and the torso, carried by the hub.
fn wheel(f: &Film, t: &Timing) -> String {
    let b = &f.body;
    let sw = num(0.02 * b.l);
    let mut s = String::new();
    s.push_str(&format!(
        "<g transform=\"translate({} {})\">\n",
        num(f.poses.first().map_or(0.0, |p| p.hub.0)),
        num(f.poses.first().map_or(0.0, |p| p.hub.1))
    ));
    s.push_str(&animate_transform(
        "translate",
        &translations(f.poses.iter().map(|p| p.hub)),
        t,
    ));
    s.push_str("<g>\n");
    s.push_str(&animate_transform(
        "rotate",
        &values(f.poses.iter().map(|p| num(p.rotation.to_degrees()))),
        t,
    ));
    s.push_str(&format!(
        "<path d=\"{}\" stroke=\"#333\" stroke-width=\"{sw}\" stroke-linecap=\"round\"/>\n</g>\n",
        spokes_path(f)
    ));
    s.push_str("<g>\n");
    s.push_str(&animate_transform(
        "rotate",
        &values(f.frames.iter().map(|fr| num(fr.state[3].to_degrees()))),
        t,
    ));
    s.push_str(&format!(
        "<line x1=\"{}\" y1=\"0\" x2=\"{}\" y2=\"0\" stroke=\"#777\" stroke-width=\"{}\" \
         stroke-linecap=\"round\"/>\n</g>\n",
        num(-b.r),
        num(b.r),
        num(0.06 * b.l)
    ));
    s.push_str(&format!(
        "<circle r=\"{}\" fill=\"black\"/>\n</g>\n",
        num(0.05 * b.l)
    ));
    s
}

/// A stick figure's links, each a line whose ends move with the walk.
fn stick_lines(f: &Film, t: &Timing) -> String {
    let mut s = format!(
        "<g stroke=\"#333\" stroke-width=\"{}\" stroke-linecap=\"round\">\n",
        num(0.04 * f.body.l)
    );
    let links = f.poses.first().map_or(0, |p| p.sticks.len());
    for j in 0..links {
        // The link's ends `[x1, y1, x2, y2]` in each pose.
        let ends = |p: &super::geometry::Pose| {
            let (a, c) = p.sticks[j];
            [a.0, a.1, c.0, c.1]
        };
        let first = ends(&f.poses[0]);
        s.push_str(&format!(
            "<line x1=\"{}\" y1=\"{}\" x2=\"{}\" y2=\"{}\">\n",
            num(first[0]),
            num(first[1]),
            num(first[2]),
            num(first[3])
        ));
        for (k, attr) in ["x1", "y1", "x2", "y2"].into_iter().enumerate() {
            let v = values(f.poses.iter().map(|p| num(ends(p)[k])));
            s.push_str(&animate(attr, &v, t));
        }
        s.push_str("</line>\n");
    }
    s.push_str("</g>\n");
    s
}

/// The stance foot's dot and the ground reaction's normal and friction parts as arrows from it.
fn forces(f: &Film, t: &Timing) -> String {
    let b = &f.body;
    let mut s = String::from("<g>\n");
    s.push_str(&animate_transform(
        "translate",
        &translations(f.poses.iter().map(|p| p.foot)),
        t,
    ));
    for (id, colour, pick) in [
        ("normal", NORMAL_COLOUR, 0),
        ("friction", FRICTION_COLOUR, 1),
    ] {
        let v = |p: &super::geometry::Pose| {
            if pick == 0 {
                p.normal_force
            } else {
                p.friction_force
            }
        };
        s.push_str(&format!(
            "<line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"0\" stroke=\"{colour}\" stroke-width=\"{}\" \
             marker-end=\"url(#{id})\">\n",
            num(0.025 * b.l)
        ));
        s.push_str(&animate(
            "x2",
            &values(f.poses.iter().map(|p| num(v(p).0))),
            t,
        ));
        s.push_str(&animate(
            "y2",
            &values(f.poses.iter().map(|p| num(v(p).1))),
            t,
        ));
        s.push_str("</line>\n");
    }
    s.push_str(&format!(
        "<circle r=\"{}\" fill=\"{SLIP_COLOUR}\" stroke=\"black\" stroke-width=\"{}\"/>\n</g>\n",
        num(0.035 * b.l),
        num(0.008 * b.l)
    ));
    s
}

/// One line on the floor per stance foot, growing over the stretch its foot slides over while
/// it is the stance foot, then staying. Each piece of floor has a group of the marks of the feet
/// that landed on it, turned to its slope from its corner (the one group of a floor of one
/// slope turns about the origin).
fn slip_marks(f: &Film, t: &Timing) -> String {
    let b = &f.body;
    let pieces: Vec<(Point, f64, f64)> = f.floor.pieces().collect();
    let mut groups = vec![String::new(); pieces.len()];
    let mut i = 0;
    while i < f.marks.len() {
        let step = f.marks[i].step;
        let end = f.marks[i..]
            .iter()
            .position(|m| m.step != step)
            .map_or(f.marks.len(), |n| i + n);
        let landed = f.marks[i].landed;
        let piece = pieces.iter().rposition(|p| p.1 <= landed).unwrap_or(0);
        // Positions from the piece's corner (0 on a floor of one slope).
        let at = |x: f64| num(x - pieces[piece].1);
        // Before its step the mark is a point where the foot will land; during its step it
        // follows the foot; after it, it keeps its last extent. Only the mark's own frames are
        // keyframes, so that all marks together have as many as the frames.
        let mut keys = Vec::with_capacity(end - i + 2);
        let (mut lo, mut hi) = (Vec::new(), Vec::new());
        if i > 0 {
            keys.push(0.0);
            lo.push(at(landed));
            hi.push(at(landed));
        }
        for j in i..end {
            keys.push(t.key_times[j]);
            lo.push(at(f.marks[j].lo));
            hi.push(at(f.marks[j].hi));
        }
        keys.push(1.0);
        lo.push(at(f.marks[end - 1].lo));
        hi.push(at(f.marks[end - 1].hi));
        let g = &mut groups[piece];
        g.push_str(&format!(
            "<line x1=\"{0}\" y1=\"0\" x2=\"{0}\" y2=\"0\">\n",
            at(landed)
        ));
        g.push_str(&animate_keyed("x1", &keys, &lo, t));
        g.push_str(&animate_keyed("x2", &keys, &hi, t));
        g.push_str("</line>\n");
        i = end;
    }
    let mut s = String::new();
    for (&((x, z), _, phi), lines) in pieces.iter().zip(&groups) {
        if lines.is_empty() && pieces.len() > 1 {
            continue;
        }
        let from = if (x, z) == (0.0, 0.0) {
            String::new()
        } else {
            format!("translate({} {}) ", num(x), num(z))
        };
        s.push_str(&format!(
            "<g transform=\"{from}rotate({})\" stroke=\"{SLIP_COLOUR}\" stroke-width=\"{}\">\n",
            num(-phi.to_degrees()),
            num(0.03 * b.l)
        ));
        s.push_str(lines);
        s.push_str("</g>\n");
    }
    s
}

/// The step counter and time, to 0.1 s: one text per distinct label, visible while it holds.
fn labels(f: &Film, t: &Timing, dur: f64) -> String {
    let mut s = String::new();
    let mut i = 0;
    while i < f.frames.len() {
        let text = frame_label(&f.frames[i], 1);
        let mut j = i + 1;
        while j < f.frames.len() && frame_label(&f.frames[j], 1) == text {
            j += 1;
        }
        let to = (j < f.frames.len()).then(|| t.key_times[j]);
        s.push_str(&timed_text(
            &text,
            (10.0, 40.0),
            "black",
            t.key_times[i],
            to,
            dur,
        ));
        i = j;
    }
    s
}
