//! `walker`: simulate the paper's walkers, sweep the friction coefficient, and reproduce the
//! paper's figures. The arguments are defined in [`walker_cli::args`]; this file dispatches
//! the commands and maps their errors to exit codes.
//!
//! Exit codes: 0 success (also for a walk that ends in a failure: that is a result), 2 invalid
//! input, 1 an I/O error.

use std::io::Write as _;
use std::process::ExitCode;

use clap::Parser;
use walker::model::Kind;
use walker::sim::WalkLimits;
use walker_cli::args::{Cli, Command, WalkFlags};
use walker_cli::input::{InputError, check, duration as positive_duration, tolerance};
use walker_cli::{animate, continue_cmd, report, reproduce, run};

/// Why a command did not finish, and its exit code.
#[derive(Debug, thiserror::Error)]
enum CliError {
    /// Invalid input: exit code 2.
    #[error(transparent)]
    Input(#[from] InputError),
    /// Writing the output files failed: exit code 1.
    #[error(transparent)]
    Write(#[from] reproduce::WriteError),
    /// An animation could not be made: exit code 2 for bad input, else 1.
    #[error(transparent)]
    Animate(#[from] animate::AnimateError),
    /// Writing to standard output failed (a closed pipe): exit code 1.
    #[error("cannot write to standard output: {0}")]
    Stdout(#[source] std::io::Error),
    /// A continuation found no branch (1) or was given bad input (2).
    #[error(transparent)]
    Continue(#[from] continue_cmd::ContinueError),
    /// Writing a file of `walker continue` failed: exit code 1.
    #[error("cannot write {path}: {message}")]
    File {
        /// The file.
        path: String,
        /// What went wrong.
        message: String,
    },
}

impl CliError {
    fn exit_code(&self) -> u8 {
        match self {
            CliError::Input(_) => 2,
            CliError::Write(_) | CliError::Stdout(_) => 1,
            CliError::Animate(e) => e.exit_code(),
            CliError::Continue(e) => e.exit_code(),
            CliError::File { .. } => 1,
        }
    }
}

/// Print `text` on standard output; an error (a closed pipe) is returned, not a panic as with
/// `print!`.
fn emit(text: &str) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    out.write_all(text.as_bytes())
        .and_then(|()| out.flush())
        .map_err(CliError::Stdout)
}

fn run(cli: Cli) -> Result<(), CliError> {
    match cli.command {
        Command::Simulate {
            common,
            walk:
                WalkFlags {
                    mu0,
                    t_set,
                    omega0,
                    phi,
                },
            duration,
            max_steps,
        } => {
            let ov = common.overrides(mu0, t_set, phi);
            let setup = run::setup(&common.scene, &ov)?;
            let duration = duration
                .map(|d| positive_duration("duration", d))
                .transpose()?;
            let limits = WalkLimits {
                max_steps,
                duration: duration.unwrap_or(f64::INFINITY),
                record: false,
                periodic: None,
            };
            let w = run::simulate(&setup, omega0, &limits, &common.config()?)?;
            if common.json {
                emit(&format!("{}\n", report::walk_json(&w)))?;
            } else {
                emit(&report::walk_text(&w))?;
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
            // A non-finite `--mu0-from` is refused by `run::sweep`, naming it (not as `mu0`).
            let ov = common.overrides(
                Some(mu0_from.max(0.0)).filter(|m| m.is_finite()),
                t_set.first().copied(),
                phi.first().copied(),
            );
            let setup = run::setup(&common.scene, &ov)?;
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
                &common.config()?,
            )?;
            if common.json {
                emit(&format!("{}\n", serde_json::json!({ "chains": res })))?;
            } else {
                emit(&report::sweep_text(&res, active))?;
            }
        }
        Command::FixedPoint {
            common,
            mu0,
            t_set,
            phi,
            omega0,
        } => {
            let ov = common.overrides(mu0, t_set, phi);
            let setup = run::setup(&common.scene, &ov)?;
            let search = run::fixed_point_search(&setup, omega0, &common.config()?)?;
            let out = report::fixed_point_report(&search);
            if common.json {
                emit(&format!("{}\n", out.json))?;
            } else {
                emit(&out.text)?;
            }
        }
        Command::Animate {
            common,
            walk:
                WalkFlags {
                    mu0,
                    t_set,
                    omega0,
                    phi,
                },
            steps,
            duration,
            speed,
            fps,
            output,
            strobe,
        } => {
            let req = animate::Request::new(steps, duration, speed, fps, &output, strobe)?;
            let setup = run::setup(&common.scene, &common.overrides(mu0, t_set, phi))?;
            let model = setup.model();
            let w0 = omega0.unwrap_or_else(|| model.default_omega0());
            check("omega0", w0, true, "finite")?;
            let written =
                animate::animate(&model, &common.config()?, model.initial_state(w0), &req)?;
            if common.json {
                emit(&format!("{}\n", serde_json::json!(written)))?;
            } else {
                emit(&written.text())?;
            }
        }
        Command::Continue {
            common,
            param,
            from,
            to,
            set,
            at,
            period_two,
            max_step,
            csv,
            plot,
        } => {
            let setup = run::setup(&common.scene, &common.overrides(None, None, None))?;
            let req = continue_cmd::Request::new(
                setup, &param, from, to, &set, &at, period_two, max_step,
            )?;
            let branches = continue_cmd::run(&req, &common.config()?)?;
            let name = req.param.name();
            if let Some(path) = &csv {
                std::fs::write(path, continue_cmd::output::csv(&branches)).map_err(|e| {
                    CliError::File {
                        path: path.display().to_string(),
                        message: e.to_string(),
                    }
                })?;
            }
            if let Some(path) = &plot {
                let d = continue_cmd::diagram::Diagram {
                    title: format!(
                        "V against {name} (solid: stable, dashed: unstable, pale: not physical)"
                    ),
                    x_label: name.to_owned(),
                    branches: branches
                        .iter()
                        .map(|b| (format!("period {}", b.period), b))
                        .collect(),
                    simulated: (String::new(), Vec::new()),
                    legend: plotters::chart::SeriesLabelPosition::LowerRight,
                };
                continue_cmd::diagram::save(&d, path).map_err(|message| CliError::File {
                    path: path.display().to_string(),
                    message,
                })?;
            }
            if common.json {
                let j = continue_cmd::output::json(&common.scene, name, from, to, &branches);
                emit(&format!("{j}\n"))?;
            } else {
                emit(&continue_cmd::output::text(&branches))?;
            }
        }
        Command::Reproduce { out } => {
            let summary = reproduce::run(&out)?;
            emit(&summary)?;
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
