//! A model's identity: its parsed content in one canonical text, without what no derivation
//! reads (the file's layout and comments, the model's name, titles, references, docs and LaTeX).
//!
//! Two files with the same canonical text derive the same kernels, so a compiled variant is
//! found by it, not by the file's bytes: a reformatted or commented copy of a shipped model runs
//! compiled. Expressions are printed from their trees (`2*l` and `2 * l` are one text; `l*2` is
//! another, which only costs a copy the compiled speed), numbers exactly (`1.0` and `1` are one
//! number), parameter defaults round-trip (`{:?}` of the `f64`).
//!
//! The equality test compares the canonical texts themselves; [`Model::identity`], a 64-bit
//! FNV-1a hash of the text, is for display and quick look-ups only, so a collision of hashes
//! can never select another model's kernels.

use crate::model::types::{Desired, FallCondition, Model, ModelExpr};

impl Model {
    /// The canonical text of what the derivation sees (the module documentation): one line per
    /// declaration, in the file's order.
    #[must_use]
    pub fn canonical(&self) -> String {
        let mut out = String::new();
        let e = |x: &ModelExpr| x.expr.to_string();
        let mut line = |s: String| {
            out.push_str(&s);
            out.push('\n');
        };
        for c in &self.coordinates {
            line(format!("coordinate {} {:?}", c.name.name, c.unit));
        }
        for p in &self.parameters {
            line(format!(
                "parameter {} [{}] {} {:?} {:?}",
                p.name.name, p.unit, p.range, p.default, p.stage
            ));
        }
        let slope = self.floor.slope.as_ref().map(|s| s.name.as_str());
        line(format!("floor {} {slope:?}", self.floor.gravity.name));
        for b in &self.bodies {
            let rotation = b
                .rotation
                .as_ref()
                .map(|(angle, inertia)| format!("{} {}", e(angle), e(inertia)));
            line(format!(
                "body {} {} ({}, {}) {rotation:?}",
                b.name.name,
                e(&b.mass),
                e(&b.com[0]),
                e(&b.com[1])
            ));
        }
        for p in &self.points {
            line(format!(
                "point {} ({}, {})",
                p.name.name,
                e(&p.at[0]),
                e(&p.at[1])
            ));
        }
        let names = |n: &Option<crate::model::types::Name>| n.as_ref().map(|n| n.name.clone());
        line(format!(
            "stance {:?} {:?} {:?}",
            self.stance.friction,
            names(&self.stance.mu0),
            names(&self.stance.c)
        ));
        line(format!(
            "strike {} {:?} {}",
            self.strike.point.name,
            self.strike.guard.as_ref().map(e),
            self.strike.ahead
        ));
        for f in &self.falls {
            let condition = match &f.condition {
                FallCondition::Point(p) => format!("point {}", p.name),
                FallCondition::Guard(g) => format!("guard {}", e(g)),
            };
            line(format!("fall {} {condition}", f.name.name));
        }
        for r in &self.relabel {
            line(format!("relabel {} {}", r.coordinate, e(&r.value)));
        }
        for s in &self.start {
            line(format!(
                "start {} {} {}",
                s.coordinate,
                s.velocity,
                e(&s.value)
            ));
        }
        if let Some(s) = &self.section {
            let given: Vec<String> = s
                .given
                .iter()
                .map(|(i, x)| format!("{i}={}", e(x)))
                .collect();
            line(format!("section {:?} [{}]", s.free, given.join(", ")));
        }
        let locks: Vec<String> = self.impact.locks.iter().map(e).collect();
        line(format!(
            "impact {:?} [{}] {}",
            self.impact.law,
            locks.join(", "),
            self.impact.double_support
        ));
        for i in &self.inputs {
            let force: Vec<String> = i.force.iter().map(e).collect();
            line(format!("input {} [{}]", i.name.name, force.join(", ")));
        }
        if let Some(c) = &self.control {
            line(format!("control {} {}", c.kp.name, c.kd.name));
        }
        for o in &self.outputs {
            let desired = match &o.desired {
                Desired::Quintic { from, to, duration } => {
                    format!("quintic {} {} {}", e(from), e(to), e(duration))
                }
                Desired::Hold { value } => format!("hold {}", e(value)),
                Desired::Bezier { points, duration } => {
                    let p: Vec<String> = points.iter().map(e).collect();
                    format!("bezier [{}] {}", p.join(", "), e(duration))
                }
            };
            line(format!(
                "output {} {} {} {desired}",
                o.name.name,
                e(&o.h),
                o.aux.name
            ));
        }
        line(format!("descriptors {:?}", self.descriptors));
        if let Some(p) = &self.power_until {
            line(format!("power_until {}", e(p)));
        }
        out
    }

    /// A 64-bit FNV-1a hash of [`Model::canonical`], for display (`walker describe`) and quick
    /// look-ups; equality is decided on the canonical text.
    #[must_use]
    pub fn identity(&self) -> u64 {
        fnv1a(self.canonical().as_bytes())
    }
}

/// The 64-bit FNV-1a hash of `bytes` (a fixed, documented function, so an identity printed by
/// one build is the same in every other).
#[must_use]
pub fn fnv1a(bytes: &[u8]) -> u64 {
    const OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
    const PRIME: u64 = 0x0100_0000_01b3;
    bytes
        .iter()
        .fold(OFFSET, |h, b| (h ^ u64::from(*b)).wrapping_mul(PRIME))
}
