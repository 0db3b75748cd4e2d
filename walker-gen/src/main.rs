//! `walker-gen`: the generator as a command-line tool, for builds that are not cargo's.
//!
//! ```text
//! walker-gen emit --scene walker/scenes/active-level.toml [--f32] [--no-std] [--unchecked] [--exact-division]
//!                 [--float-functions inline|std] [-o kernels.rs]
//! walker-gen stats --scene walker/scenes/active-level.toml [--f32] [--exact-division] [--toml]
//! walker-gen emit --model models/compass-gait.toml [--fix name=value ...] [--friction tanh]
//!                 [--f32] [--no-std] [-o kernels.rs]
//! walker-gen stats --model models/compass-gait.toml [--fix name=value ...]
//! ```
//!
//! Bad input prints a message naming the field and exits with code 2.

use std::io::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Args, Parser, Subcommand, ValueEnum};
use walker_gen::{Config, Division, Error, Float, FloatFunctions, SceneError};

#[derive(Parser)]
#[command(
    name = "walker-gen",
    version,
    about = "Generates closed-form Rust kernels of the slippery walker"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Writes the kernels of a scene as one Rust file.
    Emit {
        #[command(flatten)]
        common: Common,
        /// Use libm instead of std float methods (for `#![no_std]` crates).
        #[arg(long)]
        no_std: bool,
        /// Leave out the checked entry points (`<kernel>_checked` and `KernelError`).
        #[arg(long)]
        unchecked: bool,
        /// How `f64` std code evaluates `sin_cos` and `tanh`: the file's own functions
        /// (`inline`) or std's methods (`std`). No effect with `--f32` or `--no-std`.
        #[arg(long, value_enum, default_value_t = FloatFunctionsArg::Inline)]
        float_functions: FloatFunctionsArg,
        /// Output file (written only if it changes); standard output if absent or `-`.
        #[arg(short = 'o', long = "out")]
        out: Option<PathBuf>,
    },
    /// Prints the operation counts of the generated kernels.
    Stats {
        #[command(flatten)]
        common: Common,
        /// Print TOML data instead of a table.
        #[arg(long)]
        toml: bool,
    },
}

/// `--float-functions`, the command-line face of [`FloatFunctions`].
#[derive(Clone, Copy, ValueEnum)]
enum FloatFunctionsArg {
    /// Private accurate and fast `sin_cos` and `tanh` written into the file.
    Inline,
    /// std's `x.sin_cos()` and `x.tanh()`.
    Std,
}

impl From<FloatFunctionsArg> for FloatFunctions {
    fn from(arg: FloatFunctionsArg) -> FloatFunctions {
        match arg {
            FloatFunctionsArg::Inline => FloatFunctions::Inline,
            FloatFunctionsArg::Std => FloatFunctions::Std,
        }
    }
}

#[derive(Args)]
#[group(required = true, multiple = false, id = "source")]
struct Source {
    /// The scene file (TOML): one of the paper's walker structures with fixed parameters, or a
    /// model scene (`model = "FILE"` with its friction law, fixed parameters and kernels).
    #[arg(long)]
    scene: Option<PathBuf>,
    /// A model file (TOML, `docs/model-format.md`): any planar walker.
    #[arg(long)]
    model: Option<PathBuf>,
}

/// A `name=value` pair of `--fix`.
fn parse_fix(s: &str) -> Result<(String, f64), String> {
    let (name, value) = s
        .split_once('=')
        .ok_or_else(|| format!("`{s}`: expected name=value"))?;
    let v: f64 = value
        .trim()
        .parse()
        .map_err(|_| format!("`{s}`: the value of `{name}` is not a number"))?;
    if !v.is_finite() {
        return Err(format!("`{s}`: the value of `{name}` must be finite"));
    }
    Ok((name.trim().to_owned(), v))
}

#[derive(Clone, Copy, ValueEnum)]
enum FrictionArg {
    None,
    Tanh,
    Coulomb,
}

#[derive(Args)]
struct Common {
    #[command(flatten)]
    source: Source,
    /// With --model: substitute a parameter at generation time (repeatable).
    #[arg(long, value_parser = parse_fix, requires = "model")]
    fix: Vec<(String, f64)>,
    /// With --model: the stance foot's friction law (default: the model's first law other
    /// than none).
    #[arg(long, value_enum, requires = "model")]
    friction: Option<FrictionArg>,
    /// Generate `f32` code instead of `f64`.
    #[arg(long)]
    f32: bool,
    /// One correctly rounded division per quotient (no shared reciprocals).
    #[arg(long)]
    exact_division: bool,
}

impl Common {
    fn config(&self) -> Config {
        let mut config = Config::new();
        if let Some(scene) = &self.source.scene {
            config.scene_file(scene);
        }
        if let Some(model) = &self.source.model {
            config.model_file(model);
            for (name, v) in &self.fix {
                config.fix(name, *v);
            }
            if let Some(f) = self.friction {
                config.friction(match f {
                    FrictionArg::None => walker_gen::Friction::None,
                    FrictionArg::Tanh => walker_gen::Friction::Tanh,
                    FrictionArg::Coulomb => walker_gen::Friction::Coulomb,
                });
            }
        }
        config
            .float(if self.f32 { Float::F32 } else { Float::F64 })
            .division(if self.exact_division {
                Division::Exact
            } else {
                Division::SharedReciprocal
            });
        config
    }
}

/// A failure of the tool: a generator error or an I/O error on standard output.
#[derive(Debug, thiserror::Error)]
enum CliError {
    #[error(transparent)]
    Gen(#[from] Error),
    #[error("cannot write to standard output: {0}")]
    Stdout(#[from] std::io::Error),
    #[error("cannot encode the stats as TOML: {0}")]
    Toml(#[from] toml::ser::Error),
}

fn run(cli: Cli) -> Result<(), CliError> {
    let mut stdout = std::io::stdout().lock();
    match cli.command {
        Command::Emit {
            common,
            no_std,
            unchecked,
            float_functions,
            out,
        } => {
            let mut config = common.config();
            config
                .no_std(no_std)
                .checked(!unchecked)
                .float_functions(float_functions.into());
            match out.filter(|p| p.as_os_str() != "-") {
                Some(path) => {
                    let report = config.out_file(path).generate()?;
                    eprintln!(
                        "walker-gen: {} {} ({} bytes)",
                        if report.written {
                            "wrote"
                        } else {
                            "unchanged:"
                        },
                        report.out_file.display(),
                        report.bytes
                    );
                }
                None => stdout.write_all(config.render()?.as_bytes())?,
            }
        }
        Command::Stats { common, toml } => {
            let stats = common.config().stats()?;
            if toml {
                stdout.write_all(toml::to_string(&stats)?.as_bytes())?;
            } else {
                stdout.write_all(stats.table().as_bytes())?;
            }
        }
    }
    stdout.flush()?;
    Ok(())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let scene = match &cli.command {
        Command::Emit { common, .. } | Command::Stats { common, .. } => common
            .source
            .scene
            .clone()
            .or_else(|| common.source.model.clone())
            .unwrap_or_default(),
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            // Validation errors name the field; say which file it is in.
            let located = matches!(
                e,
                CliError::Gen(
                    Error::Scene(SceneError::Read { .. } | SceneError::Syntax { .. })
                        | Error::Model(_)
                        | Error::ModelScene { .. }
                )
            );
            if located {
                eprintln!("walker-gen: error: {e}");
            } else {
                eprintln!("walker-gen: error: {}: {e}", scene.display());
            }
            ExitCode::from(2)
        }
    }
}
