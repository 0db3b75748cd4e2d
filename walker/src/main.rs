//! `walker`: simulate the paper's walkers, sweep the friction coefficient, and reproduce the
//! paper's figures.
//!
//! Exit codes: 0 success (also for a walk that ends in a failure: that is a result), 2 invalid
//! input, 1 an I/O error.

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use walker::app::{self, Overrides};
use walker::model::FrictionLaw;
use walker::ode::Method;
use walker::sim::{SimConfig, WalkLimits};

/// Command-line interface.
#[derive(Parser, Debug)]
#[command(
    name = "walker",
    version,
    about = "Limit-cycle walking on slippery ground"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

/// Integrator choice.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
enum MethodArg {
    /// Dormand-Prince 8(5,3).
    Dop853,
    /// Rosenbrock RODAS4 (stiff friction, large mu0 c).
    Rodas4,
}

/// Friction law choice.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
enum FrictionArg {
    /// mu = -mu0 tanh(c xd) (Eqs. 26, 37): the paper's simulations.
    Tanh,
    /// Exact Coulomb friction (Eq. 25) with stick-slip.
    Coulomb,
}

fn friction(f: FrictionArg) -> FrictionLaw {
    match f {
        FrictionArg::Tanh => FrictionLaw::Tanh,
        FrictionArg::Coulomb => FrictionLaw::Coulomb,
    }
}

/// Flags shared by the simulation commands.
#[derive(clap::Args, Debug)]
struct Common {
    /// `active-level`, `passive-slope` or a scene FILE.toml.
    #[arg(long)]
    scene: String,
    /// Friction law (default: the scene's; tanh for the built-in scenes).
    #[arg(long, value_enum)]
    friction: Option<FrictionArg>,
    /// Friction law sharpness c (s/m), > 0.
    #[arg(long, allow_hyphen_values = true)]
    c: Option<f64>,
    /// Integrator.
    #[arg(long, value_enum, default_value = "dop853")]
    method: MethodArg,
    /// Relative tolerance of the integrator, in (0, 1) (default 1e-10; 1e-8 with rodas4).
    #[arg(long, allow_hyphen_values = true)]
    rtol: Option<f64>,
    /// Absolute tolerance of the integrator, in (0, 1) (default 1e-12; 1e-10 with rodas4).
    #[arg(long, allow_hyphen_values = true)]
    atol: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    json: bool,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Simulate one walk.
    Simulate {
        #[command(flatten)]
        common: Common,
        /// Friction coefficient mu0, >= 0.
        #[arg(long, allow_hyphen_values = true)]
        mu0: Option<f64>,
        /// Ramp duration T_set (s), > 0 (active walker).
        #[arg(long = "t-set", allow_hyphen_values = true)]
        t_set: Option<f64>,
        /// Initial angular velocity omega0 (rad/s).
        #[arg(long, allow_hyphen_values = true)]
        omega0: Option<f64>,
        /// Slope angle phi (rad), in [0, pi/2) (passive wheel).
        #[arg(long, allow_hyphen_values = true)]
        phi: Option<f64>,
        /// Stop after the step that passes this time (s).
        #[arg(long, allow_hyphen_values = true)]
        duration: Option<f64>,
        /// Stop after this many steps.
        #[arg(long = "max-steps", allow_hyphen_values = true, default_value_t = 100)]
        max_steps: usize,
    },
    /// Sweep mu0 (procedures P1a-P5a / P1b-P5b).
    Sweep {
        #[command(flatten)]
        common: Common,
        /// First mu0.
        #[arg(long = "mu0-from", allow_hyphen_values = true)]
        mu0_from: f64,
        /// Last mu0.
        #[arg(long = "mu0-to", allow_hyphen_values = true)]
        mu0_to: f64,
        /// Increment of mu0, > 0.
        #[arg(long = "mu0-step", allow_hyphen_values = true)]
        mu0_step: f64,
        /// T_set values (active walker; repeat for several chains).
        #[arg(long = "t-set", allow_hyphen_values = true)]
        t_set: Vec<f64>,
        /// Slope angles (passive wheel; repeat for several chains).
        #[arg(long, allow_hyphen_values = true)]
        phi: Vec<f64>,
        /// Start every mu0 from the initial condition instead of the previous steady state.
        #[arg(long)]
        restart: bool,
        /// Walk each mu0 for this long (s).
        #[arg(long, default_value_t = 100.0, allow_hyphen_values = true)]
        duration: f64,
        /// At most this many steps per mu0.
        #[arg(long = "max-steps", allow_hyphen_values = true, default_value_t = 1000)]
        max_steps: usize,
        /// Stop a mu0 early once its gait is periodic: when the step-to-step change of T, dx
        /// and p, continued geometrically, adds up to at most this (relative; in (0, 1)). The
        /// last step then stands for the rest of the duration.
        #[arg(long = "until-periodic", allow_hyphen_values = true)]
        until_periodic: Option<f64>,
    },
    /// Find the limit cycle (fixed point of the Poincare map) and its Floquet multipliers.
    FixedPoint {
        #[command(flatten)]
        common: Common,
        /// Friction coefficient mu0, >= 0.
        #[arg(long, allow_hyphen_values = true)]
        mu0: Option<f64>,
        /// Ramp duration T_set (s), > 0 (active walker).
        #[arg(long = "t-set", allow_hyphen_values = true)]
        t_set: Option<f64>,
        /// Slope angle phi (rad), in [0, pi/2) (passive wheel).
        #[arg(long, allow_hyphen_values = true)]
        phi: Option<f64>,
        /// Initial angular velocity omega0 of the warm-up walk (rad/s).
        #[arg(long, allow_hyphen_values = true)]
        omega0: Option<f64>,
    },
    /// Reproduce the paper's figures and claims.
    Reproduce {
        /// Output directory.
        #[arg(long, default_value = "reproduce-out")]
        out: std::path::PathBuf,
    },
}

/// The integrator settings of the flags: the method's default tolerances, overridden by
/// `--rtol` and `--atol` (each in (0, 1), else an input error naming the flag).
fn config(c: &Common) -> Result<SimConfig, app::InputError> {
    let base = match c.method {
        MethodArg::Dop853 => SimConfig::default(),
        MethodArg::Rodas4 => SimConfig {
            method: Method::Rodas4,
            rtol: 1e-8,
            atol: 1e-10,
            ..SimConfig::default()
        },
    };
    Ok(SimConfig {
        rtol: c.rtol.map_or(Ok(base.rtol), |x| tolerance("rtol", x))?,
        atol: c.atol.map_or(Ok(base.atol), |x| tolerance("atol", x))?,
        ..base
    })
}

/// A relative or absolute tolerance given as the flag `field`: in (0, 1), else an error naming
/// the flag and the range.
fn tolerance(field: &str, x: f64) -> Result<f64, app::InputError> {
    if x > 0.0 && x < 1.0 {
        Ok(x)
    } else {
        Err(app::InputError {
            field: field.to_owned(),
            message: format!("{x} is outside the valid range (0, 1)"),
        })
    }
}

fn run(cli: Cli) -> Result<(), (u8, String)> {
    let input = |e: app::InputError| (2, format!("error: {e}"));
    match cli.command {
        Command::Simulate {
            common,
            mu0,
            t_set,
            omega0,
            phi,
            duration,
            max_steps,
        } => {
            let ov = Overrides {
                mu0,
                c: common.c,
                t_set,
                phi,
                friction: common.friction.map(friction),
            };
            let setup = app::resolve(&common.scene, &ov).map_err(input)?;
            if let Some(d) = duration.filter(|d| !(d.is_finite() && *d > 0.0)) {
                return Err(input(app::InputError {
                    field: "duration".to_owned(),
                    message: format!("{d} is outside the valid range (0, inf)"),
                }));
            }
            let limits = WalkLimits {
                max_steps,
                duration: duration.unwrap_or(f64::INFINITY),
                record: false,
                periodic: None,
            };
            let w = app::simulate(&setup, omega0, &limits, &config(&common).map_err(input)?)
                .map_err(input)?;
            if common.json {
                println!("{}", app::walk_json(&w));
            } else {
                print!("{}", app::walk_text(&w));
            }
        }
        Command::Sweep {
            common,
            mu0_from,
            mu0_to,
            mu0_step,
            t_set,
            phi,
            restart,
            duration,
            max_steps,
            until_periodic,
        } => {
            let ov = Overrides {
                mu0: Some(mu0_from.max(0.0)),
                c: common.c,
                t_set: t_set.first().copied(),
                phi: phi.first().copied(),
                friction: common.friction.map(friction),
            };
            let setup = app::resolve(&common.scene, &ov).map_err(input)?;
            let active = setup.kind == walker::model::Kind::ActiveLevel;
            let chains = if active { t_set } else { phi };
            if !(duration.is_finite() && duration > 0.0) {
                return Err(input(app::InputError {
                    field: "duration".to_owned(),
                    message: format!("{duration} is outside the valid range (0, inf)"),
                }));
            }
            let periodic = until_periodic
                .map(|x| tolerance("until-periodic", x))
                .transpose()
                .map_err(input)?;
            let limits = WalkLimits {
                max_steps,
                duration,
                record: false,
                periodic,
            };
            let res = app::sweep(
                &setup,
                &chains,
                mu0_from,
                mu0_to,
                mu0_step,
                restart,
                &limits,
                &config(&common).map_err(input)?,
            )
            .map_err(input)?;
            if common.json {
                println!("{}", serde_json::json!({ "chains": res }));
            } else {
                print!("{}", app::sweep_text(&res, active));
            }
        }
        Command::FixedPoint {
            common,
            mu0,
            t_set,
            phi,
            omega0,
        } => {
            let ov = Overrides {
                mu0,
                c: common.c,
                t_set,
                phi,
                friction: common.friction.map(friction),
            };
            let setup = app::resolve(&common.scene, &ov).map_err(input)?;
            let out =
                walker::poincare::cli_report(&setup, omega0, &config(&common).map_err(input)?)
                    .map_err(input)?;
            if common.json {
                println!("{}", out.json);
            } else {
                print!("{}", out.text);
            }
        }
        Command::Reproduce { out } => {
            let summary = walker::reproduce::run(&out).map_err(|e| (1, format!("error: {e}")))?;
            print!("{summary}");
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(c) => c,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err((code, msg)) => {
            eprintln!("{msg}");
            ExitCode::from(code)
        }
    }
}
