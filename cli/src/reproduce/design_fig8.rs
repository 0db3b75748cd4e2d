//! The figure beside Fig. 8 (d), by `walker design --fig8 DIR`: at each `mu0` of
//! [`MU0S`], the specific resistance of the paper's sweep (its three `T_set`, the paper's
//! quintic and `tanh` law, 100 s walks) against that of the designed shape (an order-5 Bezier
//! ramp, `T_set` and its inner points `a2`, `a3` designed, the foot held under Coulomb
//! friction; `docs/design.md`), as `design_fig8.svg` / `.png` and `design_fig8.csv`, with the
//! claim that the design is at least as good as the sweep's best at every `mu0`.
//!
//! Its own command, not part of `walker reproduce`: the four designs and the twelve walks cost
//! 12.8 s of CPU in the test profile (the binary CI's reproduce test runs), which that test
//! would add to every CI run, and the summary the README quotes would change. The lines
//! returned are in the summary's format, so that `walker reproduce` can take them as they are.

use std::fmt::Write as _;
use std::fs;
use std::path::Path;

use walker::design::{Design, DesignRequest, Margins, Objective, Vary};
use walker::model::{Friction, ImpactLaw};
use walker::setup::{Overrides, Setup, walker_of};
use walker::sim::{SimConfig, WalkLimits, walk};

use super::error::WriteError;
use super::figures::{fig, save_figure};
use crate::plot::Series;

/// The `mu0` of the figure (those of `docs/design.md`'s table, inside Fig. 8's range 0-1).
pub const MU0S: [f64; 4] = [0.4, 0.5, 0.6, 0.8];
/// The paper's `T_set` of Fig. 8.
const T_SETS: [f64; 3] = [0.2, 0.3, 0.4];
/// The paper's model file.
const PAPER: &str = include_str!("../../../models/paper-active.toml");
/// The paper's quintic line in it.
const QUINTIC: &str =
    r#"desired = { shape = "quintic", from = "-alpha/2", to = "alpha/2", duration = "T_set" }"#;
/// `alpha / 2` of Table 1 (the quintic's ends; `a2 = -alpha/2`, `a3 = alpha/2` is the quintic).
const HALF_ALPHA: f64 = 0.261_799_387_799_149_4;

/// The paper's walker with its ramp an order-5 Bezier whose inner points `a2`, `a3` are
/// parameters, Coulomb friction at the stance and the impact, on a floor of `mu0`.
fn shaped(mu0: f64) -> Result<Setup, WriteError> {
    let bezier = r#"desired = { shape = "bezier", points = ["-alpha/2", "-alpha/2", "a2", "a3", "alpha/2", "alpha/2"], duration = "T_set" }"#;
    let params = format!(
        "[[parameter]]\nname = \"a2\"\nunit = \"rad\"\ndoc = \"third control point of the desired trajectory\"\nrange = \"(-inf, inf)\"\ndefault = {}\n[[parameter]]\nname = \"a3\"\nunit = \"rad\"\ndoc = \"fourth control point of the desired trajectory\"\nrange = \"(-inf, inf)\"\ndefault = {}\n[floor]",
        -HALF_ALPHA, HALF_ALPHA
    );
    let text = PAPER
        .replace(QUINTIC, bezier)
        .replacen("[floor]", &params, 1);
    let bad = |e: String| WriteError::Setup(format!("the shaped paper walker: {e}"));
    let model = walker_scene::model::Model::from_toml(&text, "paper-active (shaped)")
        .map_err(|e| bad(e.to_string()))?;
    let runtime = walker_load::runtime_source();
    let mut setup = Setup::of(walker_of(model, Some(&runtime)).map_err(|e| bad(e.to_string()))?);
    setup
        .apply(&Overrides {
            set: vec![("mu0".into(), mu0)],
            friction: Some(Friction::Coulomb),
            impact: Some(ImpactLaw::Coulomb),
            ..Overrides::default()
        })
        .map_err(|e| bad(e.to_string()))?;
    Ok(setup)
}

/// The paper's sweep at `mu0`: `SR` of the last step of a 100 s walk from the start (at most
/// 1000 steps, as `walker sweep`'s defaults) for each of its `T_set`; `None` where it fails.
fn sweep_srs(mu0: f64) -> Result<Vec<Option<f64>>, WriteError> {
    let cfg = SimConfig::default();
    let limits = WalkLimits {
        max_steps: 1000,
        duration: 100.0,
        ..WalkLimits::default()
    };
    T_SETS
        .iter()
        .map(|&t_set| {
            let mut s = Setup::active_level().map_err(|e| WriteError::Setup(e.to_string()))?;
            s.set("mu0", mu0)
                .and_then(|()| s.set("T_set", t_set))
                .map_err(|e| WriteError::Setup(e.to_string()))?;
            let m = s.model().map_err(|e| WriteError::Setup(e.to_string()))?;
            let w = walk(&m, &cfg, &m.start_state(), &limits);
            Ok(w.failure
                .is_none()
                .then(|| w.steps.last().and_then(|x| x.sr))
                .flatten())
        })
        .collect()
}

/// The shape's design at `mu0` from `(T_set, a2, a3) = start`.
fn design_at(mu0: f64, start: [f64; 3]) -> Result<Design, WriteError> {
    let setup = shaped(mu0)?;
    let vary = [("T_set", 0.2, 0.4), ("a2", -0.8, 0.8), ("a3", -0.8, 0.8)]
        .iter()
        .zip(start)
        .map(|(&(name, lo, hi), start)| Vary {
            name: name.into(),
            lo,
            hi,
            start,
        })
        .collect();
    let req = DesignRequest {
        vary,
        objective: Objective::SpecificResistance,
        margins: Margins::default(),
        max_evaluations: 100,
        tol: 1e-10,
        max_input: Vec::new(),
        bounds: walker::design::GaitBounds::default(),
    };
    walker::design::design(&setup, &SimConfig::default(), &req)
        .map_err(|e| WriteError::Setup(format!("the design at mu0 = {mu0}: {e}")))
}

/// Compute the sweep and the designs, write `design_fig8.csv` and the figure `design_fig8`
/// (PNG and SVG) into `out`; returns the claim's lines. Each `mu0`'s design starts from the
/// previous one's (the first from the quintic at `T_set = 0.4`): a design that holds the foot
/// on a floor holds it on a less slippery one, so each start is feasible.
///
/// # Errors
/// `out` or a file in it could not be written, or a walker could not be set up.
pub fn write_design_fig8(out: &Path) -> Result<String, WriteError> {
    fs::create_dir_all(out).map_err(WriteError::file(out))?;
    let mut csv = String::from(
        "mu0,sweep_sr_t_set_0.2,sweep_sr_t_set_0.3,sweep_sr_t_set_0.4,sweep_best_sr,design_sr,design_status,design_t_set,design_a2,design_a3,design_kkt_residual\n",
    );
    let mut text = String::from(
        "- Beside Fig. 8 (d): the designed shape's SR against the paper's sweep (best of T_set 0.2, 0.3, 0.4):\n",
    );
    let mut designed = Vec::new();
    let mut per_t: Vec<Vec<(f64, f64)>> = vec![Vec::new(); T_SETS.len()];
    let mut start = [0.4, -HALF_ALPHA, HALF_ALPHA];
    let mut all_hold = true;
    for mu0 in MU0S {
        let srs = sweep_srs(mu0)?;
        let best = srs.iter().flatten().copied().fold(f64::INFINITY, f64::min);
        for (k, sr) in srs.iter().enumerate() {
            if let Some(sr) = sr {
                per_t[k].push((mu0, *sr));
            }
        }
        let d = design_at(mu0, start)?;
        let p: Vec<f64> = d.parameters.iter().map(|p| p.value).collect();
        let ok = d.status != walker::design::DesignStatus::Infeasible;
        if ok {
            start = [p[0], p[1], p[2]];
            designed.push((mu0, d.value));
        }
        let holds = ok && d.value <= best;
        all_hold &= holds;
        let cell = |x: &Option<f64>| x.map_or(String::new(), |v| v.to_string());
        let _ = writeln!(
            csv,
            "{mu0},{},{},{},{best},{},{:?},{},{},{},{:e}",
            cell(&srs[0]),
            cell(&srs[1]),
            cell(&srs[2]),
            d.value,
            d.status,
            p[0],
            p[1],
            p[2],
            d.kkt_residual
        );
        let _ = writeln!(
            text,
            "  mu0 = {mu0}: sweep best SR {best:.5}, design {:.5} ({:?}, T_set {:.4}, a2 {:.4}, a3 {:.4}): {}",
            d.value,
            d.status,
            p[0],
            p[1],
            p[2],
            if holds { "holds" } else { "FAILS" }
        );
    }
    let _ = writeln!(
        text,
        "  design SR <= sweep's best SR at every mu0: {}",
        if all_hold { "holds" } else { "FAILS" }
    );
    let path = out.join("design_fig8.csv");
    fs::write(&path, csv).map_err(WriteError::file(path))?;
    let mut series: Vec<Series> = T_SETS
        .iter()
        .zip(per_t)
        .map(|(t, pts)| Series::new(format!("sweep, T_set = {t} (tanh)"), pts))
        .collect();
    series.push(Series::new("designed shape (Coulomb, foot held)", designed));
    let f = fig(
        "Beside Fig. 8 (d): SR of the designed ramp against the paper's sweep",
        "mu0",
        "SR",
        series,
        true,
    );
    save_figure(&f, &out.join("design_fig8"))?;
    Ok(text)
}
