//! The whole `walker` command line as one function ([`main`]), and the same over a program's
//! own compiled models ([`main_with`]): a user's crate that compiles its model files from its
//! build script (`walker_gen::Compile`) gets `simulate`, `sweep`, `fixed-point`, `continue`,
//! `animate` and the rest over them with a `main` of one line. Parses the arguments
//! ([`crate::args`]), dispatches the commands and maps their errors to exit codes.
//!
//! Exit codes: 0 success (also for a walk that ends in a failure: that is a result), 2 invalid
//! input, 1 an I/O error.

use std::io::Write as _;
use std::process::ExitCode;

use clap::Parser;
use walker::contract::Compiled;
use walker::request::Field;

use crate::args::{Cli, Command, WalkFlags};
use crate::input::{self, InputError};
use crate::{animate, continue_cmd, floor, floor_study, gallery, report, reproduce, run};

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
    /// `walker design` found no periodic gait to start from: exit code 1.
    #[error("no design: {0}")]
    Design(String),
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
            CliError::File { .. } | CliError::Design(_) => 1,
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
                    init,
                },
            duration,
            max_steps,
            floor: floor_file,
            mu0_steps,
            phi_steps,
        } => {
            let limits = run::limits(&max_steps, duration, None)?;
            let floor_spec = floor::floor_of(
                floor_file.as_deref(),
                mu0_steps.as_deref(),
                phi_steps.as_deref(),
                mu0,
            )?;
            let mut setup = run::setup(&common, &common.overrides(mu0, t_set, phi)?)?;
            run::omega0_once(&setup, &common, omega0)?;
            run::set_omega0(&mut setup, omega0, |_| true, "finite")?;
            let model = run::model(&setup)?;
            let start = run::start(&model, &init)?;
            let cfg = common.config()?;
            let w = match floor_spec {
                None => run::simulate(&model, &start, &limits, &cfg)?,
                Some(spec) => {
                    let flag =
                        floor::flag_of(&setup, &common.set, phi, &spec, floor_file.is_some())?;
                    floor::simulate_on(&setup, spec, flag, &start, &limits, &cfg)?
                }
            };
            if common.json {
                emit(&(report::walk_json(&w) + "\n"))?;
            } else {
                emit(&report::walk_text(&w))?;
            }
        }
        Command::Survive {
            common,
            floor: floor_file,
            t_set,
            phi,
            walks,
            max_steps,
            first_walk,
            outcomes,
        } => {
            let spec = floor::floor_of(Some(&floor_file), None, None, None)?
                .ok_or_else(|| InputError::new("floor", "a floor file is required"))?;
            let setup = run::setup(&common, &common.overrides(None, t_set, phi)?)?;
            floor::params_once(&setup, &common.set, phi, &spec, Field::Floor)?;
            let start = run::model(&setup)?.start_state();
            let counts = floor::SurviveCounts {
                walks: &walks,
                max_steps: &max_steps,
                first_walk: &first_walk,
            };
            let r = floor::survive_on(&setup, spec, &start, &counts, &common.config()?)?;
            if common.json {
                emit(&format!("{}\n", floor::survive_json(&r)))?;
            } else {
                let mut text = floor::survive_text(&r);
                if outcomes {
                    for o in &r.outcomes {
                        text.push_str(&format!(
                            "walk {:6}: {:7} steps, {}\n",
                            o.walk,
                            o.steps,
                            o.failure.as_deref().unwrap_or("reached the limit")
                        ));
                    }
                }
                emit(&text)?;
            }
        }
        Command::Design(args) => match crate::design::run(&args) {
            Ok(text) => emit(&text)?,
            Err(crate::design::DesignCliError::Input(e)) => return Err(e.into()),
            Err(crate::design::DesignCliError::NoGait(m)) => return Err(CliError::Design(m)),
            Err(crate::design::DesignCliError::Write(e)) => return Err(e.into()),
        },
        Command::Mfpt {
            common,
            floor: floor_file,
            t_set,
            phi,
            mesh,
            samples,
            box_scale,
            half_widths,
            walks,
            max_steps,
        } => {
            let opts = crate::mfpt::options(
                &mesh,
                &samples,
                box_scale.as_deref(),
                half_widths.as_deref(),
            )?;
            let spec = floor::floor_of(Some(&floor_file), None, None, None)?
                .ok_or_else(|| InputError::new("floor", "a floor file is required"))?;
            let setup = run::setup(&common, &common.overrides(None, t_set, phi)?)?;
            floor::params_once(&setup, &common.set, phi, &spec, Field::Floor)?;
            let check = walks
                .as_deref()
                .map(|w| crate::mfpt::walk_counts(w, &max_steps))
                .transpose()?;
            let (r, mc) = crate::mfpt::mfpt_on(&setup, spec, &opts, check, &common.config()?)?;
            if common.json {
                emit(&format!("{}\n", crate::mfpt::mfpt_json(&r, mc.as_ref())))?;
            } else {
                emit(&crate::mfpt::mfpt_text(&r, mc.as_ref()))?;
            }
        }
        Command::Sweep {
            common,
            param,
            from,
            to,
            step,
            t_set,
            phi,
            restart,
            duration,
            max_steps,
            until_periodic,
        } => {
            let setup = run::setup(&common, &common.overrides(None, None, None)?)?;
            let param = param.as_deref().map_or_else(
                || {
                    let spec = setup.walker.spec();
                    spec.mu0.map_or("mu0".to_owned(), |i| {
                        spec.model.parameters[i].name.name.clone()
                    })
                },
                str::to_owned,
            );
            let limits = run::limits(&max_steps, Some(duration), until_periodic)?;
            let chains = match (t_set.is_empty(), phi.is_empty()) {
                (false, false) => {
                    return Err(InputError::new(
                        "phi",
                        "give either --t-set or --phi values: they chain the sweep",
                    )
                    .into());
                }
                (false, true) => Some(("T_set", &t_set[..])),
                (true, false) => Some(("phi", &phi[..])),
                (true, true) => None,
            };
            let req = run::SweepRequest {
                param: &param,
                from,
                to,
                step,
                chains,
                restart,
                set: input::assignments("set", &common.set)?
                    .into_iter()
                    .map(|(name, _)| name)
                    .collect(),
            };
            let res = run::sweep(&setup, &[], &req, &limits, &common.config()?)?;
            if common.json {
                emit(&format!("{}\n", report::sweep_json(&res)))?;
            } else {
                emit(&report::sweep_text(&res))?;
            }
        }
        Command::FixedPoint {
            common,
            mu0,
            t_set,
            phi,
            omega0,
            init,
            sensitivities,
        } => {
            let mut setup = run::setup(&common, &common.overrides(mu0, t_set, phi)?)?;
            run::omega0_once(&setup, &common, omega0)?;
            run::set_omega0(&mut setup, omega0, |w| w > 0.0, "finite and > 0")?;
            let model = run::model(&setup)?;
            let start = run::start(&model, &init)?;
            let cfg = common.config()?;
            let names: Vec<&str> = sensitivities.iter().map(String::as_str).collect();
            run::check_sensitivities(&setup, &cfg, &names)?;
            let search = run::fixed_point_search(&model, &start, &cfg);
            let mut out = report::fixed_point_report(&search, &model.spec().state_names());
            if let Ok(fp) = &search {
                let bounds = walker::poincare::multiplier_errors(&model, &cfg, fp);
                report::add_multiplier_errors(&mut out, &bounds);
            }
            if let (false, Ok(fp)) = (names.is_empty(), &search) {
                let sens = walker::sensitivity::sensitivities(&setup, &cfg, fp, &names);
                report::add_sensitivities(&mut out, &sens);
            }
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
                    init,
                },
            steps,
            duration,
            speed,
            fps,
            output,
            strobe,
            floor: floor_file,
            mu0_steps,
        } => {
            let steps = steps
                .as_deref()
                .map(|t| input::whole("steps", t, 1, animate::request::MAX_STEPS))
                .transpose()?;
            let req = animate::Request::new(steps, duration, speed, fps, &output, strobe)?;
            let floor_spec =
                floor::floor_of(floor_file.as_deref(), mu0_steps.as_deref(), None, mu0)?;
            let mut setup = run::setup(&common, &common.overrides(mu0, t_set, phi)?)?;
            run::omega0_once(&setup, &common, omega0)?;
            run::set_omega0(&mut setup, omega0, |_| true, "finite")?;
            let model = run::model(&setup)?;
            let start = run::start(&model, &init)?;
            let cfg = common.config()?;
            let written = match floor_spec {
                None => animate::animate(&model, &cfg, &start, &req)?,
                Some(spec) => {
                    let flag =
                        floor::flag_of(&setup, &common.set, phi, &spec, floor_file.is_some())?;
                    let walker = floor::walker_on(&setup, spec, flag)?;
                    let tr = animate::sample_on_floor(&walker, &cfg, &start, &req, flag)?;
                    if let Some(regions) = walker.regions() {
                        animate::write_on_patches(&model, &tr, &req, &regions)?
                    } else {
                        let drawn = tr.walk.steps.len() + 1;
                        let mu0: Vec<f64> = walker.steps(0).take(drawn).collect();
                        let slopes: Vec<f64> = walker
                            .slopes(0)
                            .map_or_else(Vec::new, |s| s.take(drawn).collect());
                        animate::write_on_floor(&model, &tr, &req, &mu0, &slopes)?
                    }
                }
            };
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
            at,
            period_two,
            init,
            max_step,
            csv,
            plot,
        } => {
            let setup = run::setup(&common, &common.overrides(None, None, None)?)?;
            let init = run::start_components(&run::model(&setup)?, &init)?;
            let req =
                continue_cmd::Request::new(setup, &param, from, to, &at, period_two, max_step)?
                    .with_init(init);
            let branches = continue_cmd::run(&req, &common.config()?)?;
            let name = req.param.as_str();
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
                let scene = common.scene.clone().unwrap_or_else(|| {
                    common
                        .model
                        .as_ref()
                        .map(|p| p.display().to_string())
                        .unwrap_or_default()
                });
                let j = continue_cmd::output::json(&scene, name, from, to, &branches);
                emit(&format!("{j}\n"))?;
            } else {
                emit(&continue_cmd::output::text(&branches))?;
            }
        }
        Command::Reproduce { out } => {
            let summary = reproduce::run(&out)?;
            emit(&summary)?;
        }
        Command::Gallery { out } => {
            let summary = gallery::run(&out)?;
            emit(&summary)?;
        }
        Command::FloorStudy {
            out,
            walks,
            max_steps,
        } => {
            let size = floor_study::size_of(&walks, &max_steps)?;
            let summary = floor_study::run(&out, size)?;
            emit(&summary)?;
        }
    }
    Ok(())
}

/// The `walker` command line over the models compiled into the `walker` library: parses the
/// process's arguments, runs the command, and returns its exit code.
#[must_use]
pub fn main() -> ExitCode {
    main_with(&[])
}

/// The `walker` command line with `models` (a crate's `MODELS`, written by
/// `walker_gen::Compile`) registered beside the library's own ([`walker::setup::register`]):
/// every model file with the canonical content of one of them runs its compiled kernels.
///
/// ```ignore
/// // src/main.rs of a crate that compiles its own walker (its build script writes
/// // compiled.rs; `examples/own-walker/` is this, built and tested):
/// include!(concat!(env!("OUT_DIR"), "/compiled.rs"));
/// fn main() -> std::process::ExitCode {
///     walker_cli::main_with(MODELS)
/// }
/// ```
#[must_use]
pub fn main_with(models: &'static [Compiled]) -> ExitCode {
    walker::setup::register(models);
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
