//! The `walker` command line's arguments as clap definitions: the commands, their flags (each
//! flag's doc comment is its `--help` text) and the conversion of the shared flags into the
//! library's settings. What the flags mean is checked in [`crate::input`] and [`crate::run`].

use std::path::PathBuf;

use clap::{Parser, Subcommand};
use walker::model::{Friction, ImpactLaw};
use walker::ode::Method;
use walker::setup::Overrides;
use walker::sim::SimConfig;

use crate::input::{InputError, assignments, number};

/// Command-line interface.
#[derive(Parser, Debug)]
#[command(
    name = "walker",
    version,
    about = "Limit-cycle walking on slippery ground"
)]
pub struct Cli {
    /// The command to run.
    #[command(subcommand)]
    pub command: Command,
}

/// Integrator choice.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum MethodArg {
    /// Dormand-Prince 8(5,3).
    Dop853,
    /// Rosenbrock RODAS4 (stiff friction, large mu0 c).
    Rodas4,
}

/// Friction law choice.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum FrictionArg {
    /// No friction (mu = 0).
    None,
    /// mu = -mu0 tanh(c xd) (Eqs. 26, 37): the paper's simulations.
    Tanh,
    /// Exact Coulomb friction (Eq. 25) with stick-slip.
    Coulomb,
}

impl From<FrictionArg> for Friction {
    fn from(f: FrictionArg) -> Self {
        match f {
            FrictionArg::None => Friction::None,
            FrictionArg::Tanh => Friction::Tanh,
            FrictionArg::Coulomb => Friction::Coulomb,
        }
    }
}

/// Impact law choice.
#[derive(clap::ValueEnum, Clone, Copy, Debug)]
pub enum ImpactArg {
    /// The paper's impact: only the striking foot's normal velocity is constrained.
    Frictionless,
    /// Plastic impact with Coulomb friction mu0 at the striking foot (docs/impacts.md).
    Coulomb,
}

impl From<ImpactArg> for ImpactLaw {
    fn from(f: ImpactArg) -> Self {
        match f {
            ImpactArg::Frictionless => ImpactLaw::Frictionless,
            ImpactArg::Coulomb => ImpactLaw::Coulomb,
        }
    }
}

/// Flags shared by the simulation commands.
#[derive(clap::Args, Debug)]
pub struct Common {
    /// `active-level`, `passive-slope` or a scene FILE.toml (a model scene, or the paper's
    /// scene format).
    #[arg(long, required_unless_present = "model", conflicts_with = "model")]
    pub scene: Option<String>,
    /// A model FILE.toml (docs/model-format.md), with its defaults; the shipped models run
    /// compiled kernels, any other file is derived when the command starts.
    #[arg(long)]
    pub model: Option<PathBuf>,
    /// Set a run-time parameter of the model: NAME=VALUE (repeat for others; each parameter
    /// once, also across --mu0, --c, --t-set and --phi), e.g. --set T_set=0.2.
    #[arg(long = "set")]
    pub set: Vec<String>,
    /// Friction law (default: the scene's; tanh for the built-in scenes).
    #[arg(long, value_enum)]
    pub friction: Option<FrictionArg>,
    /// Impact law at heel strike (default: the scene's; frictionless for the built-in scenes).
    #[arg(long, value_enum)]
    pub impact: Option<ImpactArg>,
    /// Friction law sharpness c (s/m), > 0.
    #[arg(value_parser = number::positive, long, allow_hyphen_values = true)]
    pub c: Option<f64>,
    /// Integrator.
    #[arg(long, value_enum, default_value = "dop853")]
    pub method: MethodArg,
    /// Relative tolerance of the integrator, in [2.2e-15, 1) (ten machine epsilons and more;
    /// default 1e-10; 1e-8 with rodas4).
    #[arg(value_parser = number::rtol, long, allow_hyphen_values = true)]
    pub rtol: Option<f64>,
    /// Absolute tolerance of the integrator, in [2.2e-308, 1) (a normal number; default
    /// 1e-12; 1e-10 with rodas4).
    #[arg(value_parser = number::atol, long, allow_hyphen_values = true)]
    pub atol: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long)]
    pub json: bool,
}

impl Common {
    /// The scene overrides of these flags and of a command's `mu0`, `T_set` and `phi`.
    ///
    /// # Errors
    /// A `--set` that is not `NAME=VALUE` with a number.
    pub fn overrides(
        &self,
        mu0: Option<f64>,
        t_set: Option<f64>,
        phi: Option<f64>,
    ) -> Result<Overrides, InputError> {
        Ok(Overrides {
            mu0,
            c: self.c,
            t_set,
            phi,
            set: assignments("set", &self.set)?,
            friction: self.friction.map(Friction::from),
            impact: self.impact.map(ImpactLaw::from),
        })
    }

    /// The integrator settings of the flags: the method's default tolerances, overridden by
    /// `--rtol` and `--atol`.
    ///
    /// # Errors
    /// `--rtol` or `--atol` is outside its range ([`walker::request::sim_config`]; the error
    /// names the flag).
    pub fn config(&self) -> Result<SimConfig, InputError> {
        let method = match self.method {
            MethodArg::Dop853 => Method::Dop853,
            MethodArg::Rodas4 => Method::Rodas4,
        };
        Ok(walker::request::sim_config(method, self.rtol, self.atol)?)
    }
}

/// The flags of one walk's parameters and start, shared by `simulate` and `animate`.
#[derive(clap::Args, Debug)]
pub struct WalkFlags {
    /// Friction coefficient mu0, >= 0.
    #[arg(value_parser = number::mu0, long, allow_hyphen_values = true)]
    pub mu0: Option<f64>,
    /// Ramp duration T_set (s), > 0 (active walker).
    #[arg(value_parser = number::positive, long = "t-set", allow_hyphen_values = true)]
    pub t_set: Option<f64>,
    /// Initial angular velocity omega0 (rad/s) of the paper's walkers (a parameter of their
    /// start).
    #[arg(value_parser = number::finite, long, allow_hyphen_values = true)]
    pub omega0: Option<f64>,
    /// Slope angle phi (rad), in [0, pi/2) (passive wheel).
    #[arg(value_parser = number::slope, long, allow_hyphen_values = true)]
    pub phi: Option<f64>,
    /// Start from this value of a coordinate or velocity instead of the model's start:
    /// NAME=VALUE (repeat for others; each once), e.g. --init th1d=0.7.
    #[arg(long = "init")]
    pub init: Vec<String>,
}

/// The commands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Simulate one walk.
    Simulate {
        /// The shared flags.
        #[command(flatten)]
        common: Common,
        /// The walker's parameters and start.
        #[command(flatten)]
        walk: WalkFlags,
        /// Stop after the step that passes this time (s), in (0, 1e9].
        #[arg(value_parser = number::duration, long, allow_hyphen_values = true)]
        duration: Option<f64>,
        /// Stop after this many steps: a whole number in [0, 1000000].
        #[arg(long = "max-steps", allow_hyphen_values = true, default_value = "100")]
        max_steps: String,
        /// Walk on the floor of FILE.toml (docs/floors.md): the friction mu0 and the slope phi
        /// of each step (a random floor's walk 0), or mu0 by position along the floor (a
        /// patches floor); not with --mu0, --mu0-steps or --phi-steps.
        #[arg(long)]
        floor: Option<PathBuf>,
        /// Walk on mu0 per step, comma separated, each > 0: step k on the k-th value, the last
        /// value after the list (e.g. 0.4,0.4,0.05,0.4); not with --mu0 or --floor.
        #[arg(long = "mu0-steps", allow_hyphen_values = true)]
        mu0_steps: Option<String>,
        /// Walk step k on the line of slope phi_k (rad) through its stance foot, comma
        /// separated, the last value after the list (e.g. 0.2,0.25,0.15); with --mu0-steps or
        /// alone; not with --phi or --floor (docs/floors.md, "A slope per step").
        #[arg(long = "phi-steps", allow_hyphen_values = true)]
        phi_steps: Option<String>,
    },
    /// Walk many times on a random floor: the steps before a failure, the survival curve, the
    /// mean first-passage time with its confidence interval and the failures by kind
    /// (docs/floors.md).
    Survive {
        /// The shared flags.
        #[command(flatten)]
        common: Common,
        /// The floor FILE.toml (docs/floors.md); walk i runs on the floor's stream i.
        #[arg(long)]
        floor: PathBuf,
        /// Ramp duration T_set (s), > 0 (active walker).
        #[arg(value_parser = number::positive, long = "t-set", allow_hyphen_values = true)]
        t_set: Option<f64>,
        /// Slope angle phi (rad), in [0, pi/2) (passive wheel).
        #[arg(value_parser = number::slope, long, allow_hyphen_values = true)]
        phi: Option<f64>,
        /// The number of walks: a whole number in [1, 100000].
        #[arg(long, allow_hyphen_values = true, default_value = "100")]
        walks: String,
        /// The step limit of each walk: a whole number in [1, 1000000] (at most 1e8 steps in
        /// all, walks times this).
        #[arg(long = "max-steps", allow_hyphen_values = true, default_value = "1000")]
        max_steps: String,
        /// The index of the first walk: the walks are first-walk .. first-walk + walks - 1,
        /// each on its own stream of the floor, so that a batch split into ranges gives the
        /// same walks. A whole number; the last walk's index at most 2^63 - 1.
        #[arg(long = "first-walk", allow_hyphen_values = true, default_value = "0")]
        first_walk: String,
        /// Print each walk's outcome too (JSON always has them).
        #[arg(long)]
        outcomes: bool,
    },
    /// Design a gait: the run-time parameters (within bounds) whose periodic gait minimises
    /// an objective, with the friction it needs, its multipliers and its normal force as
    /// constraints (docs/design.md).
    Design(crate::design::DesignArgs),
    /// The mean first-passage time on a random floor by the Markov-chain (mesh)
    /// approximation of Byl and Tedrake: the Poincare section meshed around the gait, one
    /// step per mesh point and floor sample, the chain's second eigenvalue (docs/floors.md).
    /// For walkers that fall too rarely for `survive`.
    Mfpt {
        /// The shared flags.
        #[command(flatten)]
        common: Common,
        /// The floor FILE.toml (docs/floors.md): random (or uniform), not steps, of friction only.
        #[arg(long)]
        floor: PathBuf,
        /// Ramp duration T_set (s), > 0 (active walker).
        #[arg(value_parser = number::positive, long = "t-set", allow_hyphen_values = true)]
        t_set: Option<f64>,
        /// Slope angle phi (rad), in [0, pi/2) (passive wheel).
        #[arg(value_parser = number::slope, long, allow_hyphen_values = true)]
        phi: Option<f64>,
        /// Mesh points per coordinate of the section: a whole number in [2, 129] (at most
        /// 2048 mesh states in all; odd puts the fixed point on a point).
        #[arg(long, allow_hyphen_values = true, default_value = "17")]
        mesh: String,
        /// Floor samples of a uniform or truncated-normal mu0: a whole number in [1, 256] (a
        /// Markov floor has its two values).
        #[arg(long, allow_hyphen_values = true, default_value = "16")]
        samples: String,
        /// The box: this many times the largest deviation from the fixed point seen in 32
        /// pilot walks of 200 steps, in (0, 100]; not with --half-widths.
        #[arg(long = "box-scale", allow_hyphen_values = true)]
        box_scale: Option<String>,
        /// The box's half-widths, one per coordinate of the section, comma separated, each
        /// > 0; not with --box-scale.
        #[arg(long = "half-widths", allow_hyphen_values = true)]
        half_widths: Option<String>,
        /// Also walk this many times from the fixed point (Monte Carlo, as `survive`), for
        /// a check of the mesh from the same start: a whole number in [1, 100000].
        #[arg(long, allow_hyphen_values = true)]
        walks: Option<String>,
        /// The step limit of each of those walks: a whole number in [1, 1000000] (at most
        /// 1e8 steps in all).
        #[arg(long = "max-steps", allow_hyphen_values = true, default_value = "1000")]
        max_steps: String,
    },
    /// Sweep a run-time parameter (mu0 by default: procedures P1a-P5a / P1b-P5b).
    Sweep {
        /// The shared flags.
        #[command(flatten)]
        common: Common,
        /// The parameter to sweep (default mu0, the friction coefficient); not also given by
        /// --set or as the chains.
        #[arg(long)]
        param: Option<String>,
        /// First value.
        #[arg(value_parser = number::finite, long, visible_alias = "mu0-from", allow_hyphen_values = true)]
        from: f64,
        /// Last value.
        #[arg(value_parser = number::finite, long, visible_alias = "mu0-to", allow_hyphen_values = true)]
        to: f64,
        /// Increment, > 0; at most 100000 points in all (values times chains).
        #[arg(value_parser = number::positive, long, visible_alias = "mu0-step", allow_hyphen_values = true)]
        step: f64,
        /// T_set values (active walker; repeat for several chains, at most 64).
        #[arg(value_parser = number::positive, long = "t-set", allow_hyphen_values = true)]
        t_set: Vec<f64>,
        /// Slope angles (passive wheel; repeat for several chains, at most 64).
        #[arg(value_parser = number::slope, long, allow_hyphen_values = true)]
        phi: Vec<f64>,
        /// Start every value from the initial condition instead of the previous steady state.
        #[arg(long)]
        restart: bool,
        /// Walk each value for this long (s), in (0, 1e9].
        #[arg(value_parser = number::duration, long, default_value_t = 100.0, allow_hyphen_values = true)]
        duration: f64,
        /// At most this many steps per value: a whole number in [0, 1000000].
        #[arg(long = "max-steps", allow_hyphen_values = true, default_value = "1000")]
        max_steps: String,
        /// Stop a value early once its gait is periodic: when the step-to-step change of T, dx
        /// and p, continued geometrically, adds up to at most this (relative; in (0, 1)). The
        /// last step then stands for the rest of the duration.
        #[arg(value_parser = number::fraction, long = "until-periodic", allow_hyphen_values = true)]
        until_periodic: Option<f64>,
    },
    /// Find the limit cycle (fixed point of the Poincare map) and its Floquet multipliers.
    FixedPoint {
        /// The shared flags.
        #[command(flatten)]
        common: Common,
        /// Friction coefficient mu0, >= 0.
        #[arg(value_parser = number::mu0, long, allow_hyphen_values = true)]
        mu0: Option<f64>,
        /// Ramp duration T_set (s), > 0 (active walker).
        #[arg(value_parser = number::positive, long = "t-set", allow_hyphen_values = true)]
        t_set: Option<f64>,
        /// Slope angle phi (rad), in [0, pi/2) (passive wheel).
        #[arg(value_parser = number::slope, long, allow_hyphen_values = true)]
        phi: Option<f64>,
        /// Initial angular velocity omega0 of the warm-up walk (rad/s; the paper's walkers).
        #[arg(value_parser = number::finite, long, allow_hyphen_values = true)]
        omega0: Option<f64>,
        /// Start the warm-up walk from this value of a coordinate or velocity: NAME=VALUE
        /// (repeat).
        #[arg(long = "init")]
        init: Vec<String>,
        /// Also the gait's sensitivities to these run-time parameters, comma-separated
        /// (`mu0,T_set`): d(state)/dp, dT/dp, dV/dp, d(dx)/dp and the multipliers'
        /// derivatives, each with an error estimate (docs/poincare.md).
        #[arg(long = "sensitivities", value_delimiter = ',')]
        sensitivities: Vec<String>,
    },
    /// Draw a walk to scale and play it: an animated SVG or GIF, or a stick diagram
    /// (`--strobe`, SVG or PNG).
    Animate {
        /// The shared flags.
        #[command(flatten)]
        common: Common,
        /// The walker's parameters and start.
        #[command(flatten)]
        walk: WalkFlags,
        /// Walk this many steps: a whole number in [1, 1000] (default 6).
        #[arg(long, allow_hyphen_values = true)]
        steps: Option<String>,
        /// Walk for this long instead (s), in (0, 600].
        #[arg(value_parser = number::animate_duration, long, allow_hyphen_values = true)]
        duration: Option<f64>,
        /// Playback speed: seconds of the walk per second of playback, in [0.01, 100].
        #[arg(value_parser = number::speed, long, allow_hyphen_values = true, default_value_t = 1.0)]
        speed: f64,
        /// Frames per second of playback, in [1, 50] (default 30; with --strobe, poses per
        /// second of playback, default 10: a pose every 0.1 s of the walk at --speed 1).
        #[arg(value_parser = number::fps, long, allow_hyphen_values = true)]
        fps: Option<f64>,
        /// The file to write: FILE.svg or FILE.gif (with --strobe, FILE.svg or FILE.png).
        #[arg(short = 'o', long)]
        output: PathBuf,
        /// Draw a stick diagram: the walker at equal time intervals in one picture.
        #[arg(long)]
        strobe: bool,
        /// Walk on the floor of FILE.toml (docs/floors.md), drawn as a patch of colour per step
        /// (per patch of a floor by position) from ice blue (its lowest mu0) to brown (its
        /// highest); a random floor's walk 0; not with --mu0 or --mu0-steps.
        #[arg(long)]
        floor: Option<PathBuf>,
        /// Walk step k on the k-th mu0 of this comma-separated list, drawn as --floor is, the
        /// last value after the list (e.g. 0.4,0.4,0.05,0.4); not with --mu0 or --floor.
        #[arg(long = "mu0-steps", allow_hyphen_values = true)]
        mu0_steps: Option<String>,
    },
    /// Follow a branch of periodic gaits as a parameter moves (pseudo-arclength
    /// continuation), stable or not, with its folds, period doublings and the boundaries where
    /// it stops being physical (docs/continuation.md).
    Continue {
        /// The shared flags.
        #[command(flatten)]
        common: Common,
        /// The parameter to move: any run-time parameter of the model (the paper's mu0, c,
        /// T_set, K_P, K_D, phi, m1, m2, l, I1, I2, g, alpha).
        #[arg(long)]
        param: String,
        /// Start of the range (within the parameter's valid range).
        #[arg(value_parser = number::value, long, allow_hyphen_values = true)]
        from: f64,
        /// End of the range (within the parameter's valid range, not equal to --from).
        #[arg(value_parser = number::value, long, allow_hyphen_values = true)]
        to: f64,
        /// Also place a point exactly at this parameter value (repeat; within the range).
        #[arg(value_parser = number::value, long, allow_hyphen_values = true)]
        at: Vec<f64>,
        /// Also follow the period-two branch born at each period doubling.
        #[arg(long = "period-two")]
        period_two: bool,
        /// Seek the branch's first gait from this start: the model's start with a coordinate
        /// or velocity replaced, NAME=VALUE (repeat for others; each once). The warm-up walk
        /// from it and the start itself are the guesses tried.
        #[arg(long = "init")]
        init: Vec<String>,
        /// Largest continuation step in the scaled arclength, in (0, 1] (default 0.2; the
        /// whole range has length 1).
        #[arg(value_parser = number::max_step, long = "max-step", allow_hyphen_values = true)]
        max_step: Option<f64>,
        /// Write the points as CSV to FILE.
        #[arg(long)]
        csv: Option<PathBuf>,
        /// Draw the bifurcation diagram (V against the parameter) to FILE.png or FILE.svg.
        #[arg(long)]
        plot: Option<PathBuf>,
    },
    /// Reproduce the paper's figures and claims.
    Reproduce {
        /// Output directory.
        #[arg(long, default_value = "reproduce-out")]
        out: PathBuf,
    },
    /// The shipped walkers on a slippery floor as mu0 falls: where they walk, how they fail
    /// and why (figures, CSV data and checked claims).
    Gallery {
        /// Output directory.
        #[arg(long, default_value = "gallery-out")]
        out: PathBuf,
    },
    /// The paper's question on floors that change from step to step: which T_set walks
    /// farthest on random floors, against uniform floors of the same range, and the longest
    /// ice patch each T_set crosses (figures, CSV data and checked claims; docs/floors.md).
    FloorStudy {
        /// Output directory.
        #[arg(long, default_value = "floor-study-out")]
        out: PathBuf,
        /// Seeded walks per contact law, random floor and T_set: a whole number in [1, 2000].
        #[arg(long, allow_hyphen_values = true, default_value = "100")]
        walks: String,
        /// The step limit of a walk on a random or uniform floor: a whole number in
        /// [1, 10000].
        #[arg(long = "max-steps", allow_hyphen_values = true, default_value = "200")]
        max_steps: String,
    },
}

#[cfg(test)]
mod tests {
    use clap::CommandFactory;

    use super::Cli;

    #[test]
    fn the_clap_definitions_are_consistent() {
        Cli::command().debug_assert();
    }
}
