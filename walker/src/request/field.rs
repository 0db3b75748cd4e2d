//! [`Field`]: which input of a request an error is about, in the library's own words. A front
//! end names it its own way (the command line `--t-set`, Python `t_set`) through
//! [`Field::name`]'s counterpart of its own.

use std::fmt;

/// A parameter given by its role in the model rather than by its name: the front ends have a
/// flag or keyword for each (`--mu0`, `--c`, `--t-set`, `--phi`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Role {
    /// The friction coefficient (the model's `[stance] mu0` parameter).
    Mu0,
    /// The tanh law's sharpness (the model's `[stance] c` parameter).
    C,
    /// The paper's ramp duration, the parameter called `T_set`.
    TSet,
    /// The slope angle (the model's `[floor] slope` parameter).
    Slope,
}

impl Role {
    /// The role's name in the library's words (`mu0`, `c`, `T_set`, `phi`).
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Role::Mu0 => "mu0",
            Role::C => "c",
            Role::TSet => "T_set",
            Role::Slope => "phi",
        }
    }
}

/// One input of a request.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum Field {
    /// The integration method (`dop853`, `rodas4`).
    Method,
    /// The friction law (`none`, `tanh`, `coulomb`).
    Friction,
    /// The impact law (`frictionless`, `coulomb`).
    Impact,
    /// The integrator's relative tolerance.
    Rtol,
    /// The integrator's absolute tolerance.
    Atol,
    /// The most steps of a walk.
    MaxSteps,
    /// How long a walk lasts (s).
    Duration,
    /// The tolerance of the periodic-gait stop.
    UntilPeriodic,
    /// The time between the samples of a trajectory (s).
    TrajectoryDt,
    /// The most samples of a trajectory.
    MaxFrames,
    /// The first value of a sweep.
    From,
    /// The last value of a sweep.
    To,
    /// The increment of a sweep.
    Step,
    /// The swept parameter.
    Param,
    /// A parameter given by its role.
    Role(Role),
    /// A parameter given by its name (the front ends' `set`), or a grid column of that name.
    Parameter(String),
    /// A start parameter by its name (the paper's `omega0`).
    StartParameter(String),
    /// A component of the start (a coordinate or velocity) by its name (the front ends'
    /// `init`).
    Init(String),
    /// The number of walks of a batch (`survive`).
    Walks,
    /// The index of the first walk of a batch (`survive`): walk `first_walk + i` runs on the
    /// floor's stream `first_walk + i`.
    FirstWalk,
    /// A floor file.
    Floor,
    /// A floor given as a list of `mu0` per step.
    Mu0Steps,
}

impl Field {
    /// The field's name in the library's words: `max_steps`, `trajectory_dt`, the parameter's
    /// name for a parameter (`T_set` for the role, `K_P` by name), `init th1d` for a start
    /// component. Names a user typed are echoed as [`super::shown::name`] shows them.
    #[must_use]
    pub fn name(&self) -> String {
        match self {
            Field::Method => "method".into(),
            Field::Friction => "friction".into(),
            Field::Impact => "impact".into(),
            Field::Rtol => "rtol".into(),
            Field::Atol => "atol".into(),
            Field::MaxSteps => "max_steps".into(),
            Field::Duration => "duration".into(),
            Field::UntilPeriodic => "until_periodic".into(),
            Field::TrajectoryDt => "trajectory_dt".into(),
            Field::MaxFrames => "max_frames".into(),
            Field::From => "from".into(),
            Field::To => "to".into(),
            Field::Step => "step".into(),
            Field::Param => "param".into(),
            Field::Role(r) => r.name().into(),
            Field::Parameter(n) | Field::StartParameter(n) => super::shown::name(n),
            Field::Init(n) => format!("init {}", super::shown::name(n)),
            Field::Walks => "walks".into(),
            Field::FirstWalk => "first_walk".into(),
            Field::Floor => "floor".into(),
            Field::Mu0Steps => "mu0_steps".into(),
        }
    }
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.name())
    }
}
