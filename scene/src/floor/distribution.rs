//! The distribution of a random floor's `[mu0]` table, read from the file and checked, and the
//! mass a truncated normal's interval holds.

use serde::Deserialize;
use toml::Spanned;

use super::{At, Distribution, MIN_TRUNCATED_MASS, Quantity, at};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct RawDistribution {
    distribution: Spanned<String>,
    lo: Option<Spanned<f64>>,
    hi: Option<Spanned<f64>>,
    mean: Option<Spanned<f64>>,
    sd: Option<Spanned<f64>>,
    dry: Option<Spanned<f64>>,
    icy: Option<Spanned<f64>>,
    dry_length: Option<Spanned<f64>>,
    icy_length: Option<Spanned<f64>>,
}

/// The distribution of a random floor's `[mu0]` or `[phi]` table (`q`): its `distribution` and
/// exactly the fields that distribution takes, each within its range (the values `> 0` for
/// `mu0`, finite for `phi`; the lengths of a Markov chain's patches in `[1, 1e9]`).
pub(super) fn distribution(raw: Spanned<RawDistribution>, q: Quantity) -> Result<Distribution, At> {
    let table_at = raw.span().start;
    let p = q.name();
    let raw = raw.into_inner();
    let fields = [
        ("lo", &raw.lo),
        ("hi", &raw.hi),
        ("mean", &raw.mean),
        ("sd", &raw.sd),
        ("dry", &raw.dry),
        ("icy", &raw.icy),
        ("dry_length", &raw.dry_length),
        ("icy_length", &raw.icy_length),
    ];
    let name = raw.distribution.get_ref().as_str();
    let takes: &[&str] = match name {
        "uniform" => &["lo", "hi"],
        "truncated-normal" => &["mean", "sd", "lo", "hi"],
        "markov" => &["dry", "icy", "dry_length", "icy_length"],
        other => {
            return Err(at(
                raw.distribution.span().start,
                format!("{p}.distribution"),
                format!(
                    "{:?}: expected \"uniform\", \"truncated-normal\" or \"markov\"",
                    other.chars().take(40).collect::<String>()
                ),
            ));
        }
    };
    for (field, value) in fields {
        match (takes.contains(&field), value) {
            (false, Some(v)) => {
                return Err(at(
                    v.span().start,
                    format!("{p}.{field}"),
                    format!(
                        "not a field of distribution \"{name}\"; it takes {}",
                        takes.join(", ")
                    ),
                ));
            }
            (true, None) => {
                return Err(at(
                    table_at,
                    format!("{p}.{field}"),
                    format!(
                        "missing: distribution \"{name}\" takes {}",
                        takes.join(", ")
                    ),
                ));
            }
            _ => {}
        }
    }
    // Every field the distribution takes is present (checked above).
    let get = |v: &Option<Spanned<f64>>| {
        v.as_ref()
            .map_or((f64::NAN, table_at), |s| (*s.get_ref(), s.span().start))
    };
    let value = |v: &Option<Spanned<f64>>, field: &str| {
        let (x, offset) = get(v);
        q.check(x)
            .map_err(|m| at(offset, format!("{p}.{field}"), m))
    };
    let interval = || -> Result<(f64, f64), At> {
        let lo = value(&raw.lo, "lo")?;
        let hi = value(&raw.hi, "hi")?;
        if hi > lo {
            Ok((lo, hi))
        } else {
            Err(at(
                get(&raw.hi).1,
                format!("{p}.hi"),
                format!("{hi}: must be > {p}.lo = {lo}"),
            ))
        }
    };
    match name {
        "uniform" => {
            let (lo, hi) = interval()?;
            Ok(Distribution::Uniform { lo, hi })
        }
        "truncated-normal" => {
            let (lo, hi) = interval()?;
            let (mean, mean_at) = get(&raw.mean);
            if !mean.is_finite() {
                return Err(at(
                    mean_at,
                    format!("{p}.mean"),
                    format!("{mean}: must be finite"),
                ));
            }
            let sd = value(&raw.sd, "sd")?;
            let mass = normal_mass(mean, sd, lo, hi);
            if mass.is_nan() || mass < MIN_TRUNCATED_MASS {
                return Err(at(
                    table_at,
                    p,
                    format!(
                        "[lo, hi] = [{lo}, {hi}] holds {mass:.3e} of the normal's mass (mean \
                         {mean}, sd {sd}); it must hold at least {MIN_TRUNCATED_MASS}: widen \
                         the interval or move the mean into it"
                    ),
                ));
            }
            Ok(Distribution::TruncatedNormal { mean, sd, lo, hi })
        }
        _ => {
            let dry = value(&raw.dry, "dry")?;
            let icy = value(&raw.icy, "icy")?;
            let length = |v: &Option<Spanned<f64>>, field: &str| {
                let (x, offset) = get(v);
                if (1.0..=1e9).contains(&x) {
                    Ok(x)
                } else {
                    Err(at(
                        offset,
                        format!("{p}.{field}"),
                        format!("{x}: must be in [1, 1e9] steps (the mean length of a patch)"),
                    ))
                }
            };
            Ok(Distribution::Markov {
                dry,
                icy,
                dry_length: length(&raw.dry_length, "dry_length")?,
                icy_length: length(&raw.icy_length, "icy_length")?,
            })
        }
    }
}

/// The mass of `[lo, hi]` under the normal of `mean` and `sd`.
#[must_use]
pub fn normal_mass(mean: f64, sd: f64, lo: f64, hi: f64) -> f64 {
    let z = |x: f64| (x - mean) / (sd * std::f64::consts::SQRT_2);
    // Phi(b) - Phi(a) = (erfc(-b) - erfc(-a)) / 2, accurate in either tail with the sign
    // chosen so that the smaller erfc values are subtracted.
    let (a, b) = (z(lo), z(hi));
    if a >= 0.0 {
        0.5 * (libm::erfc(a) - libm::erfc(b))
    } else {
        0.5 * (libm::erfc(-b) - libm::erfc(-a))
    }
}
