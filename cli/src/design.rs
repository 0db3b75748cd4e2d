//! `walker design`: the run-time parameters that make the best periodic gait of a model on its
//! floor, with the friction the gait needs as a constraint (the library's
//! [`walker::design`]; `docs/design.md`). This module parses the flags into a
//! [`DesignRequest`] and formats the [`Design`] as a table or JSON.

use walker::design::{
    Design, DesignError, DesignRequest, DesignStatus, GaitBounds, MAX_RESTARTS, Margins, Objective,
    Vary,
};

use crate::args::Common;
use crate::input::{InputError, number};
use crate::run;

/// The objective, as the command line spells it.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum ObjectiveArg {
    /// Specific resistance `SR = p / (m_t g V)` of the periodic gait.
    #[value(name = "specific_resistance")]
    SpecificResistance,
    /// Mean input power `p` of the periodic gait (W).
    #[value(name = "power")]
    Power,
    /// The friction the gait needs: max of `|lambda_t|/lambda_n` over the stance and the
    /// heel strike's impulse ratio.
    #[value(name = "friction")]
    Friction,
    /// The gait's mean speed V = dx / T, maximised; on an actuated walker with --max-power.
    #[value(name = "speed")]
    Speed,
}

/// The flags of `walker design`.
#[derive(clap::Args, Debug)]
pub struct DesignArgs {
    /// The shared flags (`--model`, `--set`, `--friction`, `--impact`, tolerances, `--json`).
    #[command(flatten)]
    pub common: Common,
    /// The parameters to vary, comma-separated, each NAME=LO:HI or NAME=LO:HI:START (the
    /// start defaults to the model's value, with --set), e.g. `T_set=0.1:0.6`.
    #[arg(long, value_delimiter = ',', required_unless_present = "fig8")]
    pub vary: Vec<String>,
    /// Instead of one design: the figure beside the paper's Fig. 8 (d) into DIR (the
    /// designed Bezier ramp's SR at mu0 = 0.4, 0.5, 0.6, 0.8 against the paper's sweep;
    /// `design_fig8.svg`, `.png`, `.csv`), printing the claim it checks; about 20 s. With
    /// `--scene active-level`.
    #[arg(long, value_name = "DIR", conflicts_with = "vary")]
    pub fig8: Option<std::path::PathBuf>,
    /// What to minimise.
    #[arg(long, value_enum, default_value = "specific_resistance")]
    pub objective: ObjectiveArg,
    /// Every multiplier's modulus at most 1 minus this, in [0, 1).
    #[arg(value_parser = number::finite, long = "multiplier-margin", default_value_t = 0.05, allow_hyphen_values = true)]
    pub multiplier_margin: f64,
    /// The friction ratios (stance and strike) at most mu0 minus this, >= 0.
    #[arg(value_parser = number::finite, long = "friction-margin", default_value_t = 0.01, allow_hyphen_values = true)]
    pub friction_margin: f64,
    /// The normal force at least this (N), >= 0.
    #[arg(value_parser = number::finite, long = "normal-margin", default_value_t = 0.0, allow_hyphen_values = true)]
    pub normal_margin: f64,
    /// The strike at least this long after the end of the desired trajectories' last ramp
    /// (T - T_set >= this, s; for a model with ramps), >= 0.
    #[arg(value_parser = number::finite, long = "ramp-margin", default_value_t = 0.01, allow_hyphen_values = true)]
    pub ramp_margin: f64,
    /// Bounds on the inputs along the stance, max |u_i| <= U: one for every input, or one per
    /// input, comma-separated; each finite and > 0.
    #[arg(long = "max-input", value_delimiter = ',', allow_hyphen_values = true)]
    pub max_input: Vec<String>,
    /// The swing foot's clearance H (m, finite and > 0): its height above the floor at least
    /// H * 4 s (1 - s) at every stance sample, s = t / T (H at mid-stance, 0 where it leaves
    /// the floor and where it strikes). Not for a walker without a swing foot.
    #[arg(value_parser = number::positive, long, allow_hyphen_values = true)]
    pub clearance: Option<f64>,
    /// The gait's mean speed V at least this (m/s, finite and > 0). Not with --objective speed.
    #[arg(value_parser = number::positive, long = "min-speed", allow_hyphen_values = true)]
    pub min_speed: Option<f64>,
    /// The gait's mean speed V at most this (m/s, finite, > 0 and at least --min-speed; equal
    /// to it for a gait at one speed). Not with --objective speed.
    #[arg(value_parser = number::positive, long = "max-speed", allow_hyphen_values = true)]
    pub max_speed: Option<f64>,
    /// The gait's mean input power p at most this (W, finite and > 0; an actuated walker): the
    /// effort bound --objective speed needs. Not with --objective power.
    #[arg(value_parser = number::positive, long = "max-power", allow_hyphen_values = true)]
    pub max_power: Option<f64>,
    /// The solver's limit on objective evaluations: a whole number in [1, 10000].
    #[arg(
        long = "max-evaluations",
        default_value = "100",
        allow_hyphen_values = true
    )]
    pub max_evaluations: String,
    /// The solver's relative tolerance on the objective and the parameters, in (0, 1).
    #[arg(value_parser = number::fraction, long, default_value_t = 1e-10, allow_hyphen_values = true)]
    pub tol: f64,
    /// Random restarts: this many more solves, from starts drawn uniformly within the bounds
    /// (a whole number in [0, 100]); the best design is reported, with every solve's outcome.
    #[arg(long, default_value = "0", allow_hyphen_values = true)]
    pub restarts: String,
    /// The seed of the restarts' starts: a whole number in [0, 2^64 - 1].
    #[arg(long, default_value = "0", allow_hyphen_values = true)]
    pub seed: String,
}

/// Why `walker design` did not give a design.
#[derive(Debug, thiserror::Error)]
pub enum DesignCliError {
    /// A bad request (exit code 2).
    #[error(transparent)]
    Input(#[from] InputError),
    /// No periodic gait at the start (exit code 1).
    #[error("{0}")]
    NoGait(String),
    /// The figure of `--fig8` could not be written (exit code 1).
    #[error(transparent)]
    Write(#[from] crate::reproduce::WriteError),
}

/// One `NAME=LO:HI[:START]` of `--vary`, the start defaulting to `current(NAME)`.
///
/// # Errors
/// [`InputError`] on `vary` for a malformed item or a bound that is not a number.
pub fn parse_vary(item: &str, current: impl Fn(&str) -> Option<f64>) -> Result<Vary, InputError> {
    let bad = || {
        InputError::new(
            "vary",
            format!(
                "`{}`: expected NAME=LO:HI or NAME=LO:HI:START with numbers",
                walker::request::shown::name(item)
            ),
        )
    };
    let (name, range) = item.split_once('=').ok_or_else(bad)?;
    let parts: Vec<f64> = range
        .split(':')
        .map(|t| t.trim().parse::<f64>().map_err(|_| bad()))
        .collect::<Result<_, _>>()?;
    let name = name.trim().to_owned();
    let (lo, hi, start) = match parts[..] {
        [lo, hi] => (lo, hi, current(&name).unwrap_or(f64::NAN)),
        [lo, hi, s] => (lo, hi, s),
        _ => return Err(bad()),
    };
    Ok(Vary {
        name,
        lo,
        hi,
        start,
    })
}

/// The bounds of `--max-input`, each a number (the library checks their range and count).
///
/// # Errors
/// [`InputError`] on `max-input` for an item that is not a number.
pub fn parse_max_input(items: &[String]) -> Result<Vec<f64>, InputError> {
    items
        .iter()
        .map(|t| {
            t.trim().parse::<f64>().map_err(|_| {
                InputError::new(
                    "max-input",
                    format!(
                        "`{}`: expected a number > 0, or one per input, comma-separated",
                        walker::request::shown::name(t)
                    ),
                )
            })
        })
        .collect()
}

/// Run `walker design`: the text (a table, or one JSON object with `--json`) to print.
///
/// # Errors
/// [`DesignCliError::Input`] for a bad request, naming the flag and the valid range;
/// [`DesignCliError::NoGait`] where the start has no periodic gait.
pub fn run(args: &DesignArgs) -> Result<String, DesignCliError> {
    if let Some(dir) = &args.fig8 {
        let common = &args.common;
        let setup = run::setup(common, &common.overrides(None, None, None)?)?;
        let name = setup.walker.spec().name();
        if name != "paper-active" {
            return Err(InputError::new(
                "fig8",
                format!(
                    "the figure is of the paper's active walker (`--scene active-level`), not `{name}`"
                ),
            )
            .into());
        }
        return Ok(crate::reproduce::design_fig8::write_design_fig8(dir)?);
    }
    let common = &args.common;
    let setup = run::setup(common, &common.overrides(None, None, None)?)?;
    let cfg = common.config()?;
    let vary = args
        .vary
        .iter()
        .map(|v| parse_vary(v, |n| setup.params.get(n)))
        .collect::<Result<Vec<_>, _>>()?;
    let max_evaluations = crate::input::whole("max-evaluations", &args.max_evaluations, 1, 10_000)?;
    let tol = crate::input::check(
        "tol",
        args.tol,
        args.tol > 0.0 && args.tol < 1.0,
        "in (0, 1)",
    )?;
    let req = DesignRequest {
        vary,
        objective: match args.objective {
            ObjectiveArg::SpecificResistance => Objective::SpecificResistance,
            ObjectiveArg::Power => Objective::Power,
            ObjectiveArg::Friction => Objective::Friction,
            ObjectiveArg::Speed => Objective::Speed,
        },
        margins: Margins {
            multiplier: args.multiplier_margin,
            friction: args.friction_margin,
            normal: args.normal_margin,
            ramp: args.ramp_margin,
        },
        max_evaluations,
        tol,
        max_input: parse_max_input(&args.max_input)?,
        bounds: GaitBounds {
            clearance: args.clearance,
            min_speed: args.min_speed,
            max_speed: args.max_speed,
            max_power: args.max_power,
        },
    };
    let restarts = crate::input::whole("restarts", &args.restarts, 0, MAX_RESTARTS)?;
    let seed = args.seed.trim().parse::<u64>().map_err(|_| {
        InputError::new(
            "seed",
            format!(
                "`{}`: expected a whole number in [0, {}]",
                walker::request::shown::name(&args.seed),
                u64::MAX
            ),
        )
    })?;
    let d = if restarts == 0 {
        walker::design::design(&setup, &cfg, &req)
    } else {
        walker::design::design_with_restarts(&setup, &cfg, &req, restarts, seed)
    };
    let d = d.map_err(|e| match e {
        DesignError::NoGaitAtStart { .. } => DesignCliError::NoGait(e.to_string()),
        DesignError::Margin { which, .. } => {
            InputError::new(&format!("{which}-margin"), e.to_string()).into()
        }
        DesignError::Restarts { .. } => InputError::new("restarts", e.to_string()).into(),
        DesignError::MaxInput { .. }
        | DesignError::MaxInputCount { .. }
        | DesignError::NoInputsToBound { .. } => InputError::new("max-input", e.to_string()).into(),
        DesignError::Bound { which, .. } | DesignError::BoundOnObjective { which, .. } => {
            InputError::new(which, e.to_string()).into()
        }
        DesignError::SpeedNeedsEffort { .. } | DesignError::NoInputsForPower { .. } => {
            InputError::new("max-power", e.to_string()).into()
        }
        DesignError::SpeedRange { .. } => InputError::new("max-speed", e.to_string()).into(),
        DesignError::NoSwingFoot { .. } => InputError::new("clearance", e.to_string()).into(),
        other => InputError::new("vary", other.to_string()).into(),
    })?;
    Ok(if common.json {
        format!("{}\n", json(&d))
    } else {
        text(&d)
    })
}

/// The design as one JSON object.
#[must_use]
pub fn json(d: &Design) -> String {
    serde_json::to_string(d).unwrap_or_else(|e| format!("{{\"error\":\"{e}\"}}"))
}

/// A design's status as its JSON writes it (`optimal`, `feasible`, `infeasible`).
fn status_name(status: DesignStatus) -> String {
    serde_json::to_value(status)
        .ok()
        .and_then(|v| v.as_str().map(str::to_owned))
        .unwrap_or_default()
}

/// The design as a table.
#[must_use]
pub fn text(d: &Design) -> String {
    let mut s = String::new();
    s.push_str(&format!(
        "design: {} (solver: {}), {} gait evaluations\n",
        status_name(d.status),
        d.solver,
        d.evaluations
    ));
    if let Some(v) = &d.violated {
        s.push_str(&format!("violated: {v}\n"));
    }
    s.push_str(&format!(
        "objective {} = {:.12} (start {:.12}), KKT residual {:.3e}\n",
        d.objective, d.value, d.start_value, d.kkt_residual
    ));
    s.push_str("parameter        value            lo        hi        d(objective)\n");
    for p in &d.parameters {
        s.push_str(&format!(
            "{:<16} {:<16.12} {:<9} {:<9} {:+.6e}\n",
            p.name, p.value, p.lo, p.hi, p.gradient
        ));
    }
    let fp = &d.gait.fixed_point;
    s.push_str(&format!(
        "gait: T = {:.10} s, dx = {:.10} m, V = {:.10} m/s, p = {:.10} W, SR = {:.12}\n",
        fp.period, fp.dx, fp.speed, d.gait.power, d.gait.specific_resistance
    ));
    if let Some(c) = d.gait.clearance {
        s.push_str(&format!(
            "swing foot clearance: {c:.6e} m (the largest H with height >= H 4 s (1 - s))\n"
        ));
    }
    s.push_str(&format!("fixed point: {:?}\n", fp.state_plus.as_slice()));
    for m in &fp.multipliers {
        s.push_str(&format!(
            "multiplier {:+.10} {:+.10}i |.| = {:.10}\n",
            m.re,
            m.im,
            m.modulus()
        ));
    }
    s.push_str(&format!("constraints (mu0 = {}):\n", d.mu0));
    s.push_str("name              value          sense limit          slack          holds\n");
    for c in &d.constraints {
        s.push_str(&format!(
            "{:<17} {:<14.10} {:<5} {:<14.10} {:<+14.6e} {}\n",
            c.name, c.value, c.sense, c.limit, c.slack, c.holds
        ));
    }
    if !d.restarts.is_empty() {
        s.push_str("restarts (the request's start first):\n");
        for (i, r) in d.restarts.iter().enumerate() {
            match (&r.status, r.value) {
                (Some(status), Some(value)) => s.push_str(&format!(
                    "{i:>3} from {:?}: {}, {value:.12} at {:?}\n",
                    r.start,
                    status_name(*status),
                    r.parameters
                )),
                _ => s.push_str(&format!(
                    "{i:>3} from {:?}: {}\n",
                    r.start,
                    r.error.as_deref().unwrap_or("no design")
                )),
            }
        }
    }
    s
}
