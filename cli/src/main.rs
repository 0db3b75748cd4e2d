//! `walker`: simulate the paper's walkers, sweep the friction coefficient, and reproduce the
//! paper's figures.
//!
//! Exit codes: 0 success (also for a walk that ends in a failure: that is a result), 2 invalid
//! input, 1 an I/O error.

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use walker::model::{FrictionLaw, Kind};
use walker::ode::Method;
use walker::setup::{Overrides, Setup};
use walker::sim::{SimConfig, WalkLimits};
use walker_cli::input::{InputError, duration as positive_duration, tolerance};
use walker_cli::{report, reproduce, run};

/// Why a command did not finish, and its exit code.
#[derive(Debug, thiserror::Error)]
enum CliError {
    /// Invalid input: exit code 2.
    #[error(transparent)]
    Input(#[from] InputError),
    /// Writing the output failed: exit code 1.
    #[error(transparent)]
    Io(#[from] std::io::Error),
}

impl CliError {
    fn exit_code(&self) -> u8 {
        match self {
            CliError::Input(_) => 2,
            CliError::Io(_) => 1,
        }
    }
}

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
fn config(c: &Common) -> Result<SimConfig, InputError> {
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

fn run(cli: Cli) -> Result<(), CliError> {
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
            let setup = Setup::resolve(&common.scene, &ov).map_err(InputError::from)?;
            let duration = duration
                .map(|d| positive_duration("duration", d))
                .transpose()?;
            let limits = WalkLimits {
                max_steps,
                duration: duration.unwrap_or(f64::INFINITY),
                record: false,
                periodic: None,
            };
            let w = run::simulate(&setup, omega0, &limits, &config(&common)?)?;
            if common.json {
                println!("{}", report::walk_json(&w));
            } else {
                print!("{}", report::walk_text(&w));
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
            let setup = Setup::resolve(&common.scene, &ov).map_err(InputError::from)?;
            let active = setup.kind == Kind::ActiveLevel;
            let chains = if active { t_set } else { phi };
            let duration = positive_duration("duration", duration)?;
            let periodic = until_periodic
                .map(|x| tolerance("until-periodic", x))
                .transpose()?;
            let limits = WalkLimits {
                max_steps,
                duration,
                record: false,
                periodic,
            };
            let res = run::sweep(
                &setup,
                &chains,
                mu0_from,
                mu0_to,
                mu0_step,
                restart,
                &limits,
                &config(&common)?,
            )?;
            if common.json {
                println!("{}", serde_json::json!({ "chains": res }));
            } else {
                print!("{}", report::sweep_text(&res, active));
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
            let setup = Setup::resolve(&common.scene, &ov).map_err(InputError::from)?;
            let search = run::fixed_point_search(&setup, omega0, &config(&common)?)?;
            let out = report::fixed_point_report(&search);
            if common.json {
                println!("{}", out.json);
            } else {
                print!("{}", out.text);
            }
        }
        Command::Reproduce { out } => {
            let summary = reproduce::run(&out)?;
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
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code())
        }
    }
}
