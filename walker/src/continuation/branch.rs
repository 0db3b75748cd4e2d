//! The typed results of a continuation, after AUTO and COCO: a [`Branch`] is a list of
//! [`Point`]s in arclength order; a point that is special carries a [`Label`] (its
//! [`LabelKind`], a running number and how tightly it was located); each end of the branch
//! says why it ends ([`EndReason`]).

use serde::Serialize;

use crate::poincare::Multiplier;

use super::problem::{Cycle, ProblemError, Tests};

/// The kind of a special point (the AUTO/COCO abbreviation in [`LabelKind::tag`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum LabelKind {
    /// `FP`: a fold (turning point in the parameter; a multiplier passes through +1).
    Fold,
    /// `BP`: a branch point (a multiplier passes through +1, the branch does not turn).
    BranchPoint,
    /// `PD`: period doubling (a multiplier passes through -1).
    PeriodDoubling,
    /// `NS`: Neimark-Sacker (a complex pair of multipliers crosses the unit circle).
    NeimarkSacker,
    /// `LO`: lift-off: the smallest normal force over the stance phase touches zero.
    LiftOff,
    /// `DS`: the double-support test changes sign (the rear leg stays on the floor beyond).
    DoubleSupport,
    /// `IT`: the heel strike reaches `T_set` (beyond, it strikes before the ramp ends).
    ImpactBeforeTSet,
    /// `SC`: the stick-slip structure changes (exact Coulomb friction or impact).
    SlipChange,
    /// `FAM`: the branch meets a family of cycles (a structural multiplier at 1, the paper's
    /// `mu0 = 0`); the point is the family's member that the corrector reached.
    Family,
    /// `UZ`: a parameter value asked for by the user.
    UserPoint,
    /// `EP`: an end of the branch ([`EndReason`] says why).
    EndPoint,
}

impl LabelKind {
    /// The short tag printed in tables and diagrams (`FP`, `PD`, `LO`, ...).
    #[must_use]
    pub fn tag(self) -> &'static str {
        match self {
            LabelKind::Fold => "FP",
            LabelKind::BranchPoint => "BP",
            LabelKind::PeriodDoubling => "PD",
            LabelKind::NeimarkSacker => "NS",
            LabelKind::LiftOff => "LO",
            LabelKind::DoubleSupport => "DS",
            LabelKind::ImpactBeforeTSet => "IT",
            LabelKind::SlipChange => "SC",
            LabelKind::Family => "FAM",
            LabelKind::UserPoint => "UZ",
            LabelKind::EndPoint => "EP",
        }
    }

    /// Whether the kind is a boundary of the walking region rather than a bifurcation.
    #[must_use]
    pub fn is_boundary(self) -> bool {
        matches!(
            self,
            LabelKind::LiftOff
                | LabelKind::DoubleSupport
                | LabelKind::ImpactBeforeTSet
                | LabelKind::SlipChange
        )
    }
}

/// The label of a special point.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Label {
    /// What is special.
    pub kind: LabelKind,
    /// Its short tag ([`LabelKind::tag`]: `FP`, `PD`, `LO`, ...).
    pub tag: &'static str,
    /// The running number of the label along the branch (1, 2, ...), as AUTO's `LAB`.
    pub number: usize,
    /// The width of the final bracket of the location in the parameter (0 for end points and
    /// user points, which are placed exactly).
    pub bracket: f64,
}

/// Whether a period-one cycle attracts nearby motions.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Stability {
    /// Every multiplier strictly inside the unit circle.
    Stable,
    /// A multiplier outside the unit circle.
    Unstable,
    /// A multiplier on the unit circle to within
    /// [`UNIT_MULTIPLIER_TOL`](crate::poincare::UNIT_MULTIPLIER_TOL) and none outside (a
    /// family, or a bifurcation point).
    Neutral,
}

/// One point of a branch: a fixed point of the map with what describes it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Point {
    /// The free parameter's value.
    pub parameter: f64,
    /// The fixed point in the section's independent coordinates (the paper's walkers:
    /// `(xd+, th1d+)`).
    pub state: Vec<f64>,
    /// The cycle's descriptors (for a period-two branch, of both steps together).
    #[serde(flatten)]
    pub cycle: Cycle,
    /// The Floquet multipliers, by decreasing modulus.
    pub multipliers: Vec<Multiplier>,
    /// Stable, unstable or neutral.
    pub stability: Stability,
    /// The physical test functions (the smallest over both steps for a period-two branch).
    pub tests: Tests,
    /// Whether every physical test holds (a gait the walker can walk).
    pub physical: bool,
    /// `|P(r, p) - r|` (infinity norm) at the point.
    pub residual: f64,
    /// The label, if the point is special.
    pub label: Option<Label>,
}

/// Why a branch ends on one side.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "reason")]
pub enum EndReason {
    /// The parameter reached the end of the asked range.
    ParameterBound,
    /// The map failed ahead and the step size fell below the minimum.
    MapFailed {
        /// The last failure (its text).
        error: String,
        /// Where the walker itself failed in the step beyond this end, after the step began
        /// ([`ProblemError::physical_at`]: a lift-off, a fall, a contact without a solution):
        /// the time since the step's start. `None` for a numerical failure or one at the
        /// step's start. Not in the JSON (the text says it).
        #[serde(skip)]
        physical_at: Option<f64>,
    },
    /// The corrector did not converge and the step size fell below the minimum.
    NoConvergence,
    /// The branch met a family of cycles (structural multiplier at 1).
    Family,
    /// The largest number of points was reached.
    MaxPoints,
    /// A coordinate of the state left the box of
    /// [`ContinuationOptions::max_state`](super::ContinuationOptions::max_state).
    StateBound,
    /// The branch starts at the period doubling of a period-one branch (a period-two branch).
    BranchSwitch,
}

impl EndReason {
    /// The end reason of a map failure.
    #[must_use]
    pub fn map_failed(e: &ProblemError) -> Self {
        EndReason::MapFailed {
            error: e.to_string(),
            physical_at: e.physical_at(),
        }
    }
}

/// A branch of fixed points of the map (period one) or of its second iterate (period two).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Branch {
    /// The free parameter's name.
    pub parameter: String,
    /// 1 for fixed points of `P`, 2 for fixed points of `P o P` that are not fixed points of
    /// `P` (a period-two gait; its points describe both steps).
    pub period: usize,
    /// The points in arclength order, from the `from` end of the range to the `to` end.
    pub points: Vec<Point>,
    /// Why the branch ends at its first and at its last point.
    pub ends: [EndReason; 2],
}

impl Branch {
    /// The labelled points, in order.
    pub fn special(&self) -> impl Iterator<Item = &Point> {
        self.points.iter().filter(|p| p.label.is_some())
    }

    /// The labelled points of one kind, in order.
    pub fn labelled(&self, kind: LabelKind) -> impl Iterator<Item = &Point> {
        self.points
            .iter()
            .filter(move |p| p.label.is_some_and(|l| l.kind == kind))
    }
}
