//! What the mesh reports ([`MeshReport`]).

use serde::Serialize;

/// The Markov-chain approximation of a walker on a floor: the mesh, the chain, and the mean
/// first-passage time by its two formulas. Times count the steps **completed before a
/// failure**, as `walker survive` does (Byl and Tedrake's `1 / (1 - lambda_2)` counts the
/// failing step too: it is `mfpt.eigen + 1`). `None` (JSON `null`): infinite, the chain
/// never falls from the states the walker reaches.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MeshReport {
    /// The section's coordinates, in the mesh's order.
    pub section: Vec<String>,
    /// The gait's fixed point in them: the centre of the box and the walker's start.
    pub centre: Vec<f64>,
    /// The box's half-widths.
    pub half_widths: Vec<f64>,
    /// Points per coordinate.
    pub points: usize,
    /// The coordinates held at the fixed point's value (one mesh point) on a floor that sets
    /// the slope: those no pilot walk moved (absent from the JSON when none is).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub held: Vec<String>,
    /// The floor's values of `mu0` the steps were simulated on (empty when the floor sets no
    /// `mu0`: the walker's own then).
    pub samples: Vec<f64>,
    /// The floor's values of `phi` the steps were simulated on, where the floor sets the
    /// slope (absent from the JSON otherwise).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slopes: Option<Vec<f64>>,
    /// The floor states the mesh state carries (`any`; `dry`, `icy`; on a floor that sets the
    /// slope, the slope sample the step before walked on, `phi[3]` or `dry, phi[3]`).
    pub floor_states: Vec<String>,
    /// The chain's transient states (mesh points times floor states).
    pub states: usize,
    /// Those reachable from the fixed point.
    pub reachable: usize,
    /// The steps simulated (mesh points times floor samples, times the slopes a step can
    /// start from on a floor that sets the slope).
    pub steps_simulated: usize,
    /// The largest distance of a step's end from the section (the components the section
    /// gives as functions of the free ones, recomputed from the step's free components): how
    /// far the reduction to the section's coordinates is from exact.
    pub off_section: f64,
    /// The second eigenvalue of the chain on the reachable states (1: infinite MFPT).
    pub lambda2: f64,
    /// Its bracket (Collatz-Wielandt bounds of the last inverse iteration).
    pub lambda2_bounds: [f64; 2],
    /// The mean first-passage time.
    pub mfpt: MeshMfpt,
    /// The probability that the walk from the fixed point ends by a fall rather than by a
    /// step out of the box (which the chain also counts as a fall): near 1 when the box is
    /// large enough to hold the walker's wanderings.
    pub fall_share: f64,
}

/// The mean first-passage time of the chain, in steps completed before a failure.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct MeshMfpt {
    /// From the second eigenvalue, `1 / (1 - lambda_2) - 1`: the walker's steps once it has
    /// forgotten its start (the quasi-stationary regime), the number Byl and Tedrake report.
    pub eigen: Option<f64>,
    /// Its bracket from `lambda2_bounds`.
    pub eigen_bounds: [Option<f64>; 2],
    /// The expected steps to absorption from the fixed point minus the failing one,
    /// `t(x*) - 1` with `(I - Q) t = 1`: exact for the chain, start included.
    pub from_fixed_point: Option<f64>,
}
