//! Limit cycles: the Poincare map on the post-impact section, its Jacobian by the variational
//! equations, fixed points by Newton's method, and their Floquet multipliers.
//!
//! # The map
//!
//! [`poincare_map`] takes the state right after an impact and reset (time 0 of a step) and
//! returns the state right after the next impact and reset: one step of the hybrid walker, the
//! same stance dynamics as [`crate::sim`] (`u` of Eq. 31, `qdd` from the model's kernels), the
//! same heel-strike event and the same impact and reset. The output is measured from the new
//! stance foot: `x` and `z` are cyclic (no acceleration, event or impact depends on them), so the
//! map sets them to zero (the reduction of the translation).
//!
//! # The Jacobian
//!
//! The 8x8 sensitivity matrix `Phi' = Df Phi`, `Phi(0) = I`, is integrated alongside the state
//! with the same integrator (64 extra components under the same error control). `Df` comes from
//! the generated Jacobian kernels (`closed_loop_level_jacobian`, `accel_slope_jacobian`) with the
//! chain rule through `mu(xd)` (`dmu/dxd = -mu0 c (1 - tanh^2)`, with `c / cos phi` on the slope)
//! and through `v(t, y, ydot)` of Eq. 32 (`dv/dy = -K_P`, `dv/dydot = -K_D`). The `T_set`
//! breakpoint splits the integration; `Phi` is continuous there. At the heel strike
//! (`g = th1 - alpha/2 - phi`) the saltation correction `Phi+ = (I - f g_y^T / (g_y . f)) Phi`
//! is applied, then the Jacobian of the impact map (generated `impact2_level_jacobian` /
//! `impact_slope_jacobian`) and of the reset. The reset's Jacobian is analytic from the
//! fore-foot geometry of `docs/kernels.md` (`xd_f = xd + l th1d (cos th1 - cos(th1 - alpha))`,
//! `zd_f = zd - l th1d (sin th1 - sin(th1 - alpha))`; positions: `th1+ = th1 - alpha`,
//! `x+ = z+ = 0` after the reduction); a test checks it against the `fore_foot` kernel.
//!
//! # Coordinates of the fixed-point problem
//!
//! The full 8x8 map has trivial multipliers: `x`, `z` (reduced to zero: multiplier 0), `th1`
//! (fixed by the event: 0), the impact constraints (`zd+ = 0` on level ground, `zd+ + xd+ tan phi
//! = 0` on the slope, the torso lock `th1d+ = th2d+` of the active walker: 0 each), and the torso
//! for the passive wheel (its centre of mass is at the hip, so nothing acts on it: `th2` and
//! `th2d` give a Jordan block at 1). For the active walker with `K_P = K_D = 0` (the paper) the
//! output offset `y + alpha/2` at the section is neutral (`yddot = yd_dd` exactly, so an offset
//! persists): a multiplier at 1 that belongs to the controller, not to the gait; with positive
//! gains it is the tracking error's contraction.
//!
//! Newton's method therefore works in the two independent coordinates `r = (xd+, th1d+)` of the
//! section restricted to the controller's invariant manifold `y = -alpha/2, ydot = 0`
//! (active walker: `th1 = -alpha/2`, `th2 = 0`, `th2d = th1d`, `z = zd = 0`; passive wheel:
//! `th1 = phi - alpha/2`, `th2 = th2d = 0`, `zd = -xd tan phi`), see [`embed`]. The reduced
//! Jacobian `D P_r = Pi DP E` (`E` = [`embed_tangent`], `Pi` picks `xd`, `th1d`) has the gait's
//! two Floquet multipliers; [`FixedPoint::full_multipliers`] lists all eight for reference.
//!
//! For `mu0 = 0` the horizontal momentum is conserved in stance and at the impacts (no horizontal
//! force and a frictionless impulse), so the active walker has a one-parameter family of cycles
//! (Fig. 4: the speed depends on `omega0`) and `D P_r` has an exact multiplier at 1 everywhere.
//! This is detected (a multiplier within [`UNIT_MULTIPLIER_TOL`] of 1) and Newton's method takes
//! least-norm steps (truncated SVD), which converge to the family member nearest to the guess.

use nalgebra::{DMatrix, Matrix2, Vector2};
use serde::Serialize;

use crate::jacobian::Jac;
use crate::model::{Contact, Kind, Model};
use crate::ode::{Direction, Event, Integrator, NoObserver, OdeSystem, Outcome, Tolerances};
use crate::sim::{SimConfig, WalkLimits, walk};

/// Size of the integrated state: 8 mechanical components and the 8x8 sensitivity matrix.
const NA: usize = 8 + 64;

/// A multiplier counts as the structural multiplier at 1 (family of cycles) when it is this
/// close to 1.
pub const UNIT_MULTIPLIER_TOL: f64 = 1e-6;

/// Why the map could not be evaluated.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("Poincare map failed at t = {t}: {reason}")]
pub struct MapError {
    /// Time since the impact where it happened.
    pub t: f64,
    /// What happened.
    pub reason: String,
}

fn map_err(t: f64, reason: impl Into<String>) -> MapError {
    MapError {
        t,
        reason: reason.into(),
    }
}

/// The stance phase with the variational equations appended.
struct Variational<'a> {
    model: &'a Model,
    jac: Jac,
}

impl Variational<'_> {
    fn mech_rhs(&self, t: f64, y: &[f64]) -> [f64; 8] {
        let (qdd, _) = self.model.stance(t, y, Contact::Smooth);
        [y[4], y[5], y[6], y[7], qdd[0], qdd[1], qdd[2], qdd[3]]
    }
}

impl OdeSystem<NA> for Variational<'_> {
    fn rhs(&mut self, t: f64, y: &[f64; NA], dy: &mut [f64; NA]) {
        dy[..8].copy_from_slice(&self.mech_rhs(t, y));
        let a = self.jac.accel(self.model, t, y);
        for j in 0..8 {
            for i in 0..4 {
                dy[8 + 8 * i + j] = y[8 + 8 * (i + 4) + j];
                let mut s = 0.0;
                for (k, aik) in a[i].iter().enumerate() {
                    s += aik * y[8 + 8 * k + j];
                }
                dy[8 + 8 * (i + 4) + j] = s;
            }
        }
    }

    fn next_breakpoint(&self, t: f64) -> Option<f64> {
        let ts = self.model.runtime.t_set;
        (self.model.is_active() && ts > t).then_some(ts)
    }
}

/// One evaluation of the Poincare map.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MapResult {
    /// The next post-impact state `[x, z, th1, th2, xd, zd, th1d, th2d]`, measured from the new
    /// stance foot (`x = z = 0`).
    pub state_plus: [f64; 8],
    /// The step period `T` (s).
    pub period: f64,
    /// The step length (Eq. 34; along the slope, Eq. 47) (m).
    pub dx: f64,
    /// `d state_plus_i / d state_j` (row `i`, column `j`).
    pub jacobian: [[f64; 8]; 8],
}

type M8 = [[f64; 8]; 8];

fn matmul(a: &M8, b: &M8) -> M8 {
    let mut c = [[0.0; 8]; 8];
    for i in 0..8 {
        for j in 0..8 {
            c[i][j] = (0..8).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}

/// One step of the hybrid walker from the post-impact state `s` (time 0), with its Jacobian
/// (see the module documentation). Failures of the stance phase (no heel strike within
/// [`SimConfig::max_step_time`], integrator failures, non-finite values) are errors; the
/// physical validity tests of [`crate::sim`] (lift-off, double support) are not applied here.
/// Models whose physical parameters are not Table 1 are refused (no Jacobian kernels).
pub fn poincare_map(model: &Model, cfg: &SimConfig, s: &[f64; 8]) -> Result<MapResult, MapError> {
    if !s.iter().all(|v| v.is_finite()) {
        return Err(map_err(0.0, "non-finite state"));
    }
    let mut y = [0.0; NA];
    y[..8].copy_from_slice(s);
    for i in 0..8 {
        y[8 + 9 * i] = 1.0;
    }
    let heel = model.heel_strike_angle();
    let mut events = [Event::terminal(
        Direction::Rising,
        move |_, y: &[f64; NA]| y[2] - heel,
    )];
    let mut sys = Variational {
        model,
        jac: Jac::new(model).map_err(|e| map_err(0.0, e.to_string()))?,
    };
    let mut integ = Integrator::<NA>::new(cfg.method, Tolerances::new(cfg.rtol, cfg.atol));
    let mut t = 0.0;
    let (te, ye) = loop {
        match integ.integrate(
            &mut sys,
            t,
            &y,
            cfg.max_step_time,
            &mut events,
            &mut NoObserver,
        ) {
            Outcome::Breakpoint { t: tb, y: yb } => {
                t = tb;
                y = yb;
            }
            Outcome::Event { t, y, .. } => break (t, y),
            Outcome::Reached { t, .. } => return Err(map_err(t, "no heel strike")),
            Outcome::NonFinite { t, .. } => return Err(map_err(t, "non-finite state")),
            Outcome::StepSizeTooSmall { t, .. } => return Err(map_err(t, "step size too small")),
            Outcome::MaxSteps { t, .. } => return Err(map_err(t, "too many steps")),
            Outcome::InvalidInput { t, reason, .. } => return Err(map_err(t, reason)),
        }
    };
    let mut pre = [0.0; 8];
    pre.copy_from_slice(&ye[..8]);
    let mut phi = [[0.0; 8]; 8];
    for (i, row) in phi.iter_mut().enumerate() {
        row.copy_from_slice(&ye[8 + 8 * i..16 + 8 * i]);
    }
    // Saltation: g = th1 - heel, g_y = e_2, g_y . f = th1d.
    let f = sys.mech_rhs(te, &ye);
    if f[2].abs() < 1e-12 {
        return Err(map_err(te, "grazing heel strike (th1d = 0)"));
    }
    let g_row = phi[2];
    for (i, row) in phi.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v -= f[i] * g_row[j] / f[2];
        }
    }
    // Impact: positions unchanged, velocities from the impact kernel.
    let imp = model.impact(&pre);
    let k = sys.jac.impact(&pre);
    let mut dimp = [[0.0; 8]; 8];
    for (i, row) in dimp.iter_mut().enumerate().take(4) {
        row[i] = 1.0;
    }
    const COLS: [usize; 5] = [2, 4, 5, 6, 7];
    for i in 0..4 {
        for (c, &col) in COLS.iter().enumerate() {
            dimp[4 + i][col] = k[i][c];
        }
    }
    // Reset to the new stance leg, measured from the new foot.
    let [x, z, th1, th2, ..] = pre;
    let [xd, zd, th1d, th2d] = imp.qd;
    let [xf, _, xdf, zdf] = model.fore_foot(x, z, th1, xd, zd, th1d);
    let (l, alpha) = (model.physical.l, model.physical.alpha);
    let cs = th1.cos() - (th1 - alpha).cos();
    let sn = th1.sin() - (th1 - alpha).sin();
    let mut dres = [[0.0; 8]; 8];
    dres[2][2] = 1.0;
    dres[3][3] = 1.0;
    dres[4] = [0.0, 0.0, -l * th1d * sn, 0.0, 1.0, 0.0, l * cs, 0.0];
    dres[5] = [0.0, 0.0, -l * th1d * cs, 0.0, 0.0, 1.0, -l * sn, 0.0];
    dres[6][6] = 1.0;
    dres[7][7] = 1.0;
    let jacobian = matmul(&dres, &matmul(&dimp, &phi));
    let state_plus = [0.0, 0.0, th1 - alpha, th2, xdf, zdf, th1d, th2d];
    let dx = (xf - s[0]) / model.runtime.phi.cos();
    let ok = state_plus
        .iter()
        .chain(jacobian.iter().flatten())
        .all(|v| v.is_finite());
    if !ok || !dx.is_finite() {
        return Err(map_err(te, "non-finite impact or reset"));
    }
    Ok(MapResult {
        state_plus,
        period: te,
        dx,
        jacobian,
    })
}

/// The state on the section with the reduced coordinates `r = (xd, th1d)` (see the module
/// documentation): the active walker's `[0, 0, -alpha/2, 0, xd, 0, th1d, th1d]`, the passive
/// wheel's `[0, 0, phi - alpha/2, 0, xd, -xd tan phi, th1d, 0]`.
pub fn embed(model: &Model, r: [f64; 2]) -> [f64; 8] {
    let th1 = model.rear_contact_angle();
    match model.kind() {
        Kind::ActiveLevel => [0.0, 0.0, th1, 0.0, r[0], 0.0, r[1], r[1]],
        Kind::PassiveSlope => [
            0.0,
            0.0,
            th1,
            0.0,
            r[0],
            -r[0] * model.runtime.phi.tan(),
            r[1],
            0.0,
        ],
    }
}

/// `d embed(r)_i / d r_j`.
pub fn embed_tangent(model: &Model) -> [[f64; 2]; 8] {
    let mut e = [[0.0; 2]; 8];
    e[4][0] = 1.0;
    e[6][1] = 1.0;
    match model.kind() {
        Kind::ActiveLevel => e[7][1] = 1.0,
        Kind::PassiveSlope => e[5][0] = -model.runtime.phi.tan(),
    }
    e
}

/// The reduced coordinates `(xd, th1d)` of a post-impact state.
pub fn reduce(s: &[f64; 8]) -> [f64; 2] {
    [s[4], s[6]]
}

/// The reduced map's Jacobian `Pi DP E` from the full one.
pub fn reduced_jacobian(model: &Model, full: &[[f64; 8]; 8]) -> [[f64; 2]; 2] {
    let e = embed_tangent(model);
    let mut out = [[0.0; 2]; 2];
    for (a, &row) in [4usize, 6].iter().enumerate() {
        for (b, o) in out[a].iter_mut().enumerate() {
            *o = (0..8).map(|k| full[row][k] * e[k][b]).sum();
        }
    }
    out
}

/// A Floquet multiplier (an eigenvalue of the map's Jacobian at the fixed point).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Multiplier {
    /// Real part.
    pub re: f64,
    /// Imaginary part.
    pub im: f64,
}

impl Multiplier {
    /// `|lambda|`.
    pub fn modulus(&self) -> f64 {
        self.re.hypot(self.im)
    }
}

/// Eigenvalues of a square matrix given row by row (real Schur form via nalgebra), sorted by
/// decreasing modulus. Rows of the wrong length give an empty list.
pub fn eigenvalues(rows: &[Vec<f64>]) -> Vec<Multiplier> {
    let n = rows.len();
    if rows.iter().any(|r| r.len() != n) {
        return Vec::new();
    }
    let m = DMatrix::from_fn(n, n, |i, j| rows[i][j]);
    let mut out: Vec<Multiplier> = m
        .complex_eigenvalues()
        .iter()
        .map(|c| Multiplier { re: c.re, im: c.im })
        .collect();
    out.sort_by(|a, b| b.modulus().total_cmp(&a.modulus()));
    out
}

/// Outcome of the fixed-point search.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Newton's method converged to an isolated cycle.
    Converged,
    /// Converged to a member of a family of cycles (structural multiplier at 1, `mu0 = 0`).
    Family,
    /// The residual did not reach the tolerance.
    NotConverged,
    /// The cycle was found but is not a valid gait (a failure of [`crate::sim::walk`] on it).
    InvalidGait,
}

/// A limit cycle: its post-impact state, descriptors and multipliers.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct FixedPoint {
    /// Outcome.
    pub status: Status,
    /// The fixed point `[x, z, th1, th2, xd, zd, th1d, th2d]` of the map (foot-relative).
    pub state_plus: [f64; 8],
    /// Step period (s).
    #[serde(rename = "T")]
    pub period: f64,
    /// Average walking speed `dx / T` (m/s).
    #[serde(rename = "V")]
    pub speed: f64,
    /// Step length (m).
    pub dx: f64,
    /// The gait's Floquet multipliers: eigenvalues of the reduced map in `(xd, th1d)`, by
    /// decreasing modulus.
    pub multipliers: Vec<Multiplier>,
    /// All eight eigenvalues of the full foot-relative map (the trivial ones explained in the
    /// module documentation).
    pub full_multipliers: Vec<Multiplier>,
    /// The reduced Jacobian `D P_r` at the fixed point.
    pub reduced_jacobian: [[f64; 2]; 2],
    /// A multiplier of the reduced map lies within [`UNIT_MULTIPLIER_TOL`] of 1: a family of
    /// cycles (conserved horizontal momentum for `mu0 = 0`), not a loss of stability.
    pub structural_unit_multiplier: bool,
    /// `|P_r(r) - r|` at the returned point.
    pub residual: f64,
    /// Newton iterations taken.
    pub iterations: usize,
    /// The failure of [`crate::sim::walk`] on the cycle, if any (see [`Status::InvalidGait`]).
    pub failure: Option<String>,
}

impl FixedPoint {
    /// The largest multiplier modulus of the gait (0 if none).
    pub fn max_modulus(&self) -> f64 {
        self.multipliers
            .iter()
            .map(Multiplier::modulus)
            .fold(0.0, f64::max)
    }
}

/// Settings of [`fixed_point`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FixedPointOptions {
    /// Initial angular velocity of the warm-up walk (Eq. 33 / (P2b)).
    pub omega0: f64,
    /// Steps simulated from the initial condition to obtain Newton's initial guess.
    pub warmup_steps: usize,
    /// Largest number of Newton iterations.
    pub max_iter: usize,
    /// Newton stops when `|P_r(r) - r| <= tol`.
    pub tol: f64,
}

impl FixedPointOptions {
    /// Defaults for a model: its default `omega0`, 30 warm-up steps, 30 iterations, `1e-11`.
    pub fn for_model(model: &Model) -> Self {
        Self {
            omega0: model.default_omega0(),
            warmup_steps: 30,
            max_iter: 30,
            tol: 1e-11,
        }
    }
}

/// Why no fixed point could be searched for.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum FixedPointError {
    /// The warm-up walk failed before completing a step.
    #[error("the warm-up walk failed before the first impact: {0}")]
    Warmup(String),
    /// The map failed at the guess or at every damped Newton step.
    #[error(transparent)]
    Map(#[from] MapError),
}

/// Least-norm solution of `a d = b` by the SVD with singular values below
/// `UNIT_MULTIPLIER_TOL * max(1, sigma_max)` dropped; also whether any was dropped.
fn least_norm(a: [[f64; 2]; 2], b: [f64; 2]) -> ([f64; 2], bool) {
    let m = Matrix2::new(a[0][0], a[0][1], a[1][0], a[1][1]);
    let svd = m.svd(true, true);
    let smax = svd.singular_values.max();
    let eps = UNIT_MULTIPLIER_TOL * smax.max(1.0);
    let singular = svd.singular_values.iter().any(|&s| s <= eps);
    let d = svd
        .solve(&Vector2::new(b[0], b[1]), eps)
        .map(|v| [v[0], v[1]])
        .unwrap_or([0.0, 0.0]);
    (d, singular)
}

/// Find the limit cycle reached from the model's initial condition with `opts.omega0`:
/// simulate `opts.warmup_steps` steps, then Newton's method on `P_r(r) - r` in the reduced
/// coordinates (least-norm steps when `D P_r - I` is singular, damped when the map fails),
/// then the multipliers at the result and a validity check of one step of
/// [`crate::sim::walk`] from it.
pub fn fixed_point(
    model: &Model,
    cfg: &SimConfig,
    opts: &FixedPointOptions,
) -> Result<FixedPoint, FixedPointError> {
    let limits = WalkLimits {
        max_steps: opts.warmup_steps.max(1),
        ..WalkLimits::default()
    };
    let w = walk(model, cfg, model.initial_state(opts.omega0), &limits);
    let s0 = w.last_state().ok_or_else(|| {
        FixedPointError::Warmup(
            w.failure
                .as_ref()
                .map_or("no step", |f| f.name())
                .to_owned(),
        )
    })?;
    newton(model, cfg, reduce(&s0), opts)
}

/// Newton's method of [`fixed_point`] from the reduced guess `r0 = (xd+, th1d+)` (no warm-up
/// walk): for continuation from a neighbouring cycle.
pub fn newton(
    model: &Model,
    cfg: &SimConfig,
    r0: [f64; 2],
    opts: &FixedPointOptions,
) -> Result<FixedPoint, FixedPointError> {
    let mut r = r0;
    let mut m = poincare_map(model, cfg, &embed(model, r))?;
    let mut iterations = 0;
    let mut singular = false;
    let (mut res, mut jr) = residual(model, &m, r);
    while res > opts.tol && iterations < opts.max_iter {
        iterations += 1;
        let fr = [
            reduce(&m.state_plus)[0] - r[0],
            reduce(&m.state_plus)[1] - r[1],
        ];
        let a = [[jr[0][0] - 1.0, jr[0][1]], [jr[1][0], jr[1][1] - 1.0]];
        let (d, sing) = least_norm(a, [-fr[0], -fr[1]]);
        singular |= sing;
        let mut step = 1.0;
        let mut next = None;
        for _ in 0..8 {
            let rn = [r[0] + step * d[0], r[1] + step * d[1]];
            if let Ok(mn) = poincare_map(model, cfg, &embed(model, rn)) {
                let (rs, jn) = residual(model, &mn, rn);
                if rs < res || step < 0.01 {
                    next = Some((rn, mn, rs, jn));
                    break;
                }
            }
            step *= 0.5;
        }
        let Some((rn, mn, rs, jn)) = next else {
            break;
        };
        r = rn;
        m = mn;
        res = rs;
        jr = jn;
    }
    let multipliers = eigenvalues(&jr.map(|row| row.to_vec()));
    let full_multipliers = eigenvalues(&m.jacobian.map(|row| row.to_vec()));
    let structural = singular
        || multipliers
            .iter()
            .any(|l| (l.re - 1.0).hypot(l.im) < UNIT_MULTIPLIER_TOL);
    let state_plus = embed(model, r);
    let check = walk(
        model,
        cfg,
        state_plus,
        &WalkLimits {
            max_steps: 1,
            ..WalkLimits::default()
        },
    );
    let failure = check.failure.as_ref().map(|f| f.name().to_owned());
    let status = if failure.is_some() {
        Status::InvalidGait
    } else if res > opts.tol {
        Status::NotConverged
    } else if structural {
        Status::Family
    } else {
        Status::Converged
    };
    Ok(FixedPoint {
        status,
        state_plus,
        period: m.period,
        speed: m.dx / m.period,
        dx: m.dx,
        multipliers,
        full_multipliers,
        reduced_jacobian: jr,
        structural_unit_multiplier: structural,
        residual: res,
        iterations,
        failure,
    })
}

fn residual(model: &Model, m: &MapResult, r: [f64; 2]) -> (f64, [[f64; 2]; 2]) {
    let p = reduce(&m.state_plus);
    (
        (p[0] - r[0]).hypot(p[1] - r[1]),
        reduced_jacobian(model, &m.jacobian),
    )
}

/// One point of a continuation in `mu0`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ContinuationPoint {
    /// The chain's parameter: `T_set` (active walker) or `phi` (passive wheel).
    pub chain: f64,
    /// Friction coefficient.
    pub mu0: f64,
    /// The cycle, or `None` when the search failed (no step from the initial condition).
    pub cycle: Option<FixedPoint>,
}

impl ContinuationPoint {
    /// A converged, valid gait whose multipliers are all strictly inside the unit circle.
    pub fn is_stable(&self) -> bool {
        self.cycle
            .as_ref()
            .is_some_and(|c| c.status == Status::Converged && c.max_modulus() < 1.0)
    }
}

/// Continuation in `mu0` along `mu0s` for every chain value (`T_set` for the active walker,
/// `phi` for the passive wheel; `model_for(chain, mu0)` builds the model): each cycle starts
/// Newton's method from the previous one on the chain, and falls back to the warm-up walk of
/// [`fixed_point`] when that does not give a converged cycle.
pub fn continuation(
    model_for: impl Fn(f64, f64) -> Model,
    chains: &[f64],
    mu0s: &[f64],
    cfg: &SimConfig,
) -> Vec<ContinuationPoint> {
    let ok = |c: &FixedPoint| matches!(c.status, Status::Converged | Status::Family);
    let mut out = Vec::new();
    for &chain in chains {
        let mut prev: Option<[f64; 2]> = None;
        for &mu0 in mu0s {
            let model = model_for(chain, mu0);
            let opts = FixedPointOptions::for_model(&model);
            let from_prev = prev
                .and_then(|r| newton(&model, cfg, r, &opts).ok())
                .filter(ok);
            let cycle = from_prev.or_else(|| fixed_point(&model, cfg, &opts).ok());
            prev = cycle
                .as_ref()
                .filter(|c| ok(c))
                .map(|c| reduce(&c.state_plus));
            out.push(ContinuationPoint { chain, mu0, cycle });
        }
    }
    out
}
