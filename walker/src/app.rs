//! The command-line front end's logic (kept in the library so that it is documented and
//! testable): scene resolution, validation of user input, and the JSON/text reports of
//! `walker simulate` and `walker sweep`.

use serde::Serialize;
use serde_json::json;
use walker_gen::scene::{Floor, Friction, Param, Scene, Torso};

use crate::model::{FrictionLaw, Kind, Model, Physical, Runtime};
use crate::progress::Progress;
use crate::sim::{SimConfig, StepResult, Walk, WalkLimits, walk};
use crate::sweep::{SweepPoint, mu0_grid, sweep_chains};

/// A user error: which input was wrong and what is accepted (exit code 2).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("invalid {field}: {message}")]
pub struct InputError {
    /// The flag or scene field.
    pub field: String,
    /// What is valid.
    pub message: String,
}

fn bad(field: &str, message: impl Into<String>) -> InputError {
    InputError {
        field: field.to_owned(),
        message: message.into(),
    }
}

/// Optional overrides of the runtime parameters (from flags).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Overrides {
    /// `--mu0`.
    pub mu0: Option<f64>,
    /// `--c`.
    pub c: Option<f64>,
    /// `--t-set`.
    pub t_set: Option<f64>,
    /// `--phi`.
    pub phi: Option<f64>,
    /// `--friction`.
    pub friction: Option<FrictionLaw>,
}

/// A resolved scene: how to build the model for given runtime parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct Setup {
    /// Level/active or slope/passive.
    pub kind: Kind,
    /// Whether the fast kernels with Table 1 compiled in are used (tanh friction only).
    pub fast: bool,
    /// The friction law.
    pub friction: FrictionLaw,
    /// Physical parameters.
    pub physical: Physical,
    /// Runtime parameters (defaults, scene values, then flags).
    pub runtime: Runtime,
}

impl Setup {
    /// Build the model with the runtime parameters `runtime`.
    pub fn model_with(&self, runtime: Runtime) -> Model {
        match (self.kind, self.friction, self.fast) {
            (Kind::ActiveLevel, FrictionLaw::Coulomb, _) => {
                Model::coulomb_level(self.physical, runtime)
            }
            (Kind::PassiveSlope, FrictionLaw::Coulomb, _) => {
                Model::coulomb_slope(self.physical, runtime)
            }
            (Kind::ActiveLevel, FrictionLaw::Tanh, true) => Model::active_level(runtime),
            (Kind::PassiveSlope, FrictionLaw::Tanh, true) => Model::passive_slope(runtime),
            (Kind::ActiveLevel, FrictionLaw::Tanh, false) => {
                Model::general_level(self.physical, runtime)
            }
            (Kind::PassiveSlope, FrictionLaw::Tanh, false) => {
                Model::general_slope(self.physical, runtime)
            }
        }
    }

    /// Build the model with the resolved runtime parameters.
    pub fn model(&self) -> Model {
        self.model_with(self.runtime)
    }
}

fn check(field: &str, v: f64, ok: bool, range: &str) -> Result<f64, InputError> {
    if v.is_finite() && ok {
        Ok(v)
    } else {
        Err(bad(
            field,
            format!("{v} is outside the valid range {range}"),
        ))
    }
}

/// Validate runtime parameters: `mu0 >= 0`, `c > 0`, `T_set > 0`, `phi` in `[0, pi/2)`,
/// gains `>= 0`, all finite.
pub fn validate_runtime(r: &Runtime) -> Result<(), InputError> {
    check("mu0", r.mu0, r.mu0 >= 0.0, "[0, inf)")?;
    check("c", r.c, r.c > 0.0, "(0, inf)")?;
    check("t-set", r.t_set, r.t_set > 0.0, "(0, inf)")?;
    check(
        "phi",
        r.phi,
        (0.0..std::f64::consts::FRAC_PI_2).contains(&r.phi),
        "[0, pi/2)",
    )?;
    check("K_P", r.k_p, r.k_p >= 0.0, "[0, inf)")?;
    check("K_D", r.k_d, r.k_d >= 0.0, "[0, inf)")?;
    Ok(())
}

fn validate_physical(p: &Physical) -> Result<(), InputError> {
    check("m1", p.m1, p.m1 > 0.0, "(0, inf)")?;
    check("m2", p.m2, p.m2 > 0.0, "(0, inf)")?;
    check("l", p.l, p.l > 0.0, "(0, inf)")?;
    check("I1", p.i1, p.i1 > 0.0, "(0, inf)")?;
    check("I2", p.i2, p.i2 > 0.0, "(0, inf)")?;
    check("g", p.g, p.g > 0.0, "(0, inf)")?;
    check(
        "alpha",
        p.alpha,
        p.alpha > 0.0 && p.alpha < std::f64::consts::PI,
        "(0, pi)",
    )?;
    Ok(())
}

/// Resolve `--scene` (`active-level`, `passive-slope` or a scene file) and the flags.
pub fn resolve(scene: &str, ov: &Overrides) -> Result<Setup, InputError> {
    let mut setup = match scene {
        "active-level" => Setup {
            kind: Kind::ActiveLevel,
            fast: true,
            friction: FrictionLaw::Tanh,
            physical: Physical::TABLE1,
            runtime: Runtime::default(),
        },
        "passive-slope" => Setup {
            kind: Kind::PassiveSlope,
            fast: true,
            friction: FrictionLaw::Tanh,
            physical: Physical::TABLE1,
            runtime: Runtime {
                phi: 0.2,
                mu0: 0.2,
                ..Runtime::default()
            },
        },
        path if path.ends_with(".toml") => from_scene_file(path)?,
        other => {
            return Err(bad(
                "scene",
                format!("unknown scene {other:?}; use active-level, passive-slope or a FILE.toml"),
            ));
        }
    };
    if let Some(f) = ov.friction {
        setup.friction = f;
    }
    let r = &mut setup.runtime;
    if let Some(v) = ov.mu0 {
        r.mu0 = v;
    }
    if let Some(v) = ov.c {
        r.c = v;
    }
    if let Some(v) = ov.t_set {
        r.t_set = v;
    }
    if let Some(v) = ov.phi {
        if setup.kind == Kind::ActiveLevel && v != 0.0 {
            return Err(bad(
                "phi",
                "the active walker walks on level ground: phi must be 0",
            ));
        }
        r.phi = v;
    }
    validate_runtime(&setup.runtime)?;
    validate_physical(&setup.physical)?;
    Ok(setup)
}

fn from_scene_file(path: &str) -> Result<Setup, InputError> {
    let scene = Scene::from_file(path).map_err(|e| bad("scene", e.to_string()))?;
    let kind = match (scene.floor, scene.torso) {
        (Floor::Level, Torso::Actuated) => Kind::ActiveLevel,
        (Floor::Slope, Torso::Passive) => Kind::PassiveSlope,
        (f, t) => {
            return Err(bad(
                "scene",
                format!(
                    "floor = {f} with torso = {t} is not simulated (level/actuated or slope/passive)"
                ),
            ));
        }
    };
    let fx = |p: Param, d: f64| scene.fixed_value(p).unwrap_or(d);
    let t1 = Physical::TABLE1;
    let physical = Physical {
        m1: fx(Param::M1, t1.m1),
        m2: fx(Param::M2, t1.m2),
        l: fx(Param::L, t1.l),
        i1: fx(Param::I1, t1.i1),
        i2: fx(Param::I2, t1.i2),
        g: fx(Param::G, t1.g),
        alpha: fx(Param::Alpha, t1.alpha),
    };
    let d = Runtime::default();
    let mut runtime = Runtime {
        mu0: fx(Param::Mu0, d.mu0),
        c: fx(Param::C, d.c),
        t_set: fx(Param::TSet, d.t_set),
        k_p: fx(Param::KP, d.k_p),
        k_d: fx(Param::KD, d.k_d),
        phi: fx(
            Param::Phi,
            if kind == Kind::PassiveSlope { 0.2 } else { 0.0 },
        ),
    };
    let friction = match scene.friction {
        Friction::Tanh => FrictionLaw::Tanh,
        Friction::None => {
            runtime.mu0 = 0.0;
            FrictionLaw::Tanh
        }
        Friction::Coulomb => FrictionLaw::Coulomb,
    };
    Ok(Setup {
        kind,
        fast: false,
        friction,
        physical,
        runtime,
    })
}

/// The JSON report of a walk: `{"status", "failure", "steps"}`.
pub fn walk_json(w: &Walk) -> serde_json::Value {
    json!({
        "status": w.failure.as_ref().map_or("ok", |f| f.name()),
        "failure": w.failure,
        "steps": w.steps,
    })
}

/// Run `walker simulate`.
pub fn simulate(
    setup: &Setup,
    omega0: Option<f64>,
    limits: &WalkLimits,
    cfg: &SimConfig,
) -> Result<Walk, InputError> {
    let model = setup.model();
    let w0 = omega0.unwrap_or_else(|| model.default_omega0());
    check("omega0", w0, true, "finite")?;
    if limits.duration.is_nan() || limits.duration <= 0.0 {
        return Err(bad(
            "duration",
            format!("{} is outside the valid range (0, inf)", limits.duration),
        ));
    }
    Ok(walk(&model, cfg, model.initial_state(w0), limits))
}

/// A text table of a walk.
pub fn walk_text(w: &Walk) -> String {
    let mut s = String::from("step          T         dx          V          p         SR\n");
    let opt = |v: Option<f64>| v.map_or_else(|| "-".to_owned(), |x| format!("{x:.6}"));
    for (k, st) in w.steps.iter().enumerate() {
        s.push_str(&format!(
            "{k:4} {:10.6} {:10.6} {:10.6} {:>10} {:>10}\n",
            st.period,
            st.dx,
            st.speed,
            opt(st.p),
            opt(st.sr)
        ));
    }
    match &w.failure {
        None => s.push_str("status: ok\n"),
        Some(f) => s.push_str(&format!(
            "status: {} at step {}\n{}\n",
            f.name(),
            f.step(),
            serde_json::to_string(f).unwrap_or_default()
        )),
    }
    s
}

/// One sweep chain (one `T_set` or `phi`) in a report.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Chain {
    /// `T_set` (active) or `phi` (passive).
    pub value: f64,
    /// The points of the chain.
    pub points: Vec<SweepPoint>,
}

/// Run `walker sweep` over `mu0` for each of `chains` (`T_set` or `phi` values; empty: the
/// scene's value).
#[allow(clippy::too_many_arguments)]
pub fn sweep(
    setup: &Setup,
    chains: &[f64],
    mu0_from: f64,
    mu0_to: f64,
    mu0_step: f64,
    restart: bool,
    limits: &WalkLimits,
    cfg: &SimConfig,
) -> Result<Vec<Chain>, InputError> {
    check("mu0-from", mu0_from, mu0_from >= 0.0, "[0, inf)")?;
    check("mu0-to", mu0_to, mu0_to >= mu0_from, "[mu0-from, inf)")?;
    check("mu0-step", mu0_step, mu0_step > 0.0, "(0, inf)")?;
    let grid = mu0_grid(mu0_from, mu0_to, mu0_step);
    if grid.len() > 100_000 {
        return Err(bad("mu0-step", "too many points (more than 100000)"));
    }
    let active = setup.kind == Kind::ActiveLevel;
    let base = setup.runtime;
    let chains: Vec<f64> = if chains.is_empty() {
        vec![if active { base.t_set } else { base.phi }]
    } else {
        chains.to_vec()
    };
    for &c in &chains {
        let r = if active {
            Runtime { t_set: c, ..base }
        } else {
            Runtime { phi: c, ..base }
        };
        validate_runtime(&r)?;
    }
    let make = |c: f64, mu0: f64| {
        let r = if active {
            Runtime {
                t_set: c,
                mu0,
                ..base
            }
        } else {
            Runtime {
                phi: c,
                mu0,
                ..base
            }
        };
        setup.model_with(r)
    };
    let initial = |c: f64| {
        let m = make(c, 0.0);
        m.initial_state(m.default_omega0())
    };
    let bar = Progress::new("sweep", chains.len() * grid.len());
    let res = sweep_chains(&chains, make, cfg, &grid, initial, limits, restart, &|| {
        bar.tick()
    });
    bar.finish();
    Ok(chains
        .iter()
        .zip(res)
        .map(|(&value, points)| Chain { value, points })
        .collect())
}

/// A text table of a sweep.
pub fn sweep_text(chains: &[Chain], active: bool) -> String {
    let mut s = String::new();
    for ch in chains {
        let name = if active { "T_set" } else { "phi" };
        s.push_str(&format!(
            "{name} = {}\n  mu0   steps          T         dx          V         SR  status\n",
            ch.value
        ));
        for p in &ch.points {
            let l: Option<&StepResult> = p.last.as_ref();
            let f = |g: fn(&StepResult) -> Option<f64>| {
                l.and_then(g)
                    .map_or_else(|| "-".to_owned(), |x| format!("{x:.6}"))
            };
            s.push_str(&format!(
                "{:5.3} {:7} {:>10} {:>10} {:>10} {:>10}  {}\n",
                p.mu0,
                p.steps,
                f(|s| Some(s.period)),
                f(|s| Some(s.dx)),
                f(|s| Some(s.speed)),
                f(|s| s.sr),
                p.failure
                    .as_ref()
                    .map_or(if p.periodic { "periodic" } else { "ok" }, |x| x.name())
            ));
        }
    }
    s
}
