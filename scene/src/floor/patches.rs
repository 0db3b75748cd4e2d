//! A floor of patches by position (`kind = "patches"`): the friction `mu0` as a
//! piecewise-constant function of the position along the floor, read from the file and
//! checked.
//!
//! ```toml
//! kind = "patches"
//! mu0 = 0.4              # the floor's friction outside the patches
//! [[patch]]
//! from = 2.0             # metres along the floor, half-open [from, to)
//! to = 2.6
//! mu0 = 0.05
//! ```

use serde::Deserialize;
use toml::Spanned;

use super::{At, FloorPlan, FloorSpec, Quantity, at};

/// The most patches a floor lists (each costs the walker one prepared model per distinct
/// value of `mu0`, made when the floor meets the walker).
pub const MAX_PATCHES: usize = 10_000;

/// The largest distance along the floor a patch may start or end at (m): well beyond any
/// walk (a million steps of a metre), and small enough that a position's rounding near it
/// (`2e-7` m) is far below a step.
pub const MAX_PATCH_POSITION: f64 = 1e9;

/// One patch of a floor of patches: the friction `mu0` on `[from, to)` metres along the floor.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FloorPatch {
    /// Where the patch begins (m along the floor, included).
    pub from: f64,
    /// Where it ends (m along the floor, excluded), `> from`.
    pub to: f64,
    /// The friction coefficient on the patch, `> 0` and finite.
    pub mu0: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawPatches {
    #[allow(dead_code, reason = "read by `RawKind`")]
    kind: String,
    mu0: Option<Spanned<f64>>,
    /// Refused by name: a floor of patches sets the friction only.
    phi: Option<Spanned<toml::Value>>,
    patch: Option<Spanned<Vec<Spanned<RawPatch>>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPatch {
    from: Option<Spanned<f64>>,
    to: Option<Spanned<f64>>,
    mu0: Option<Spanned<f64>>,
}

/// A position along the floor a patch can start or end at.
fn position(x: f64) -> Result<f64, String> {
    if x.is_finite() && x.abs() <= MAX_PATCH_POSITION {
        Ok(x)
    } else {
        Err(format!(
            "{x}: must be finite, in [-{MAX_PATCH_POSITION:e}, {MAX_PATCH_POSITION:e}] m"
        ))
    }
}

/// The floor of a `patches` file: its `mu0` outside the patches (`> 0` and finite), 1 to
/// [`MAX_PATCHES`] patches, each with `from < to` (finite, in metres) and its `mu0`, listed in
/// order along the floor and not overlapping (a patch starts at or after the end of the one
/// before). No `phi`: the slope stays the walker's.
pub(super) fn patches(raw: RawPatches) -> Result<FloorPlan, At> {
    if let Some(phi) = raw.phi {
        return Err(at(
            phi.span().start,
            "phi",
            "a patches floor sets the friction only (the slope stays the walker's); remove phi \
             or use a uniform, steps or random floor",
        ));
    }
    let Some(mu0) = raw.mu0 else {
        return Err(at(
            0,
            "mu0",
            "missing: a patches floor gives mu0, the friction outside its patches (> 0 and \
             finite)",
        ));
    };
    let mu0 = Quantity::Mu0
        .check(*mu0.get_ref())
        .map_err(|m| at(mu0.span().start, "mu0", m))?;
    let Some(list) = raw.patch else {
        return Err(at(
            0,
            "patch",
            format!(
                "missing: a patches floor lists 1 to {MAX_PATCHES} [[patch]] tables, each with \
                 from, to and mu0"
            ),
        ));
    };
    let items = list.get_ref();
    if items.is_empty() || items.len() > MAX_PATCHES {
        return Err(at(
            list.span().start,
            "patch",
            format!(
                "{} patches: must list 1 to {MAX_PATCHES} [[patch]] tables",
                items.len()
            ),
        ));
    }
    let mut out: Vec<FloorPatch> = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        let table_at = item.span().start;
        let p = item.get_ref();
        let value = |v: &Option<Spanned<f64>>, name: &str, what: &str| {
            let field = format!("patch[{i}].{name}");
            match v {
                None => Err(at(table_at, field, format!("missing: {what}"))),
                Some(v) => Ok((*v.get_ref(), v.span().start, field)),
            }
        };
        let (from, from_at, from_field) = value(
            &p.from,
            "from",
            "where the patch begins (m along the floor)",
        )?;
        let from = position(from).map_err(|m| at(from_at, from_field.clone(), m))?;
        let (to, to_at, to_field) = value(&p.to, "to", "where the patch ends (m along the floor)")?;
        let to = position(to).map_err(|m| at(to_at, to_field.clone(), m))?;
        if to <= from {
            return Err(at(
                to_at,
                to_field,
                format!("{to}: must be > patch[{i}].from = {from} (a patch is [from, to))"),
            ));
        }
        let (m, m_at, m_field) = value(&p.mu0, "mu0", "the friction on the patch (> 0)")?;
        let m = Quantity::Mu0.check(m).map_err(|e| at(m_at, m_field, e))?;
        if let Some(before) = out.last()
            && from < before.to
        {
            return Err(at(
                from_at,
                from_field,
                format!(
                    "{from}: must be >= patch[{}].to = {} (patches are listed in order along \
                     the floor and do not overlap)",
                    i - 1,
                    before.to
                ),
            ));
        }
        out.push(FloorPatch { from, to, mu0: m });
    }
    Ok(FloorPlan {
        mu0: Some(FloorSpec::Patches { mu0, patches: out }),
        phi: None,
    })
}
