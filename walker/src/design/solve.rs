//! The nonlinear program of a design and its solution by SLSQP: the nested functions (the
//! objective and constraints of the periodic gait at `p`), their central-difference gradients
//! and the bookkeeping of the best feasible point.

use std::cell::RefCell;

use slsqp::{Func, StopTols, minimize};

use crate::setup::Setup;
use crate::sim::SimConfig;

use super::constraints::{CAP, Kind, kinds, program_value, row, stance_ks};
use super::error::DesignError;
use super::evaluate::{Evaluation, evaluate};
use super::kkt::kkt;
use super::request::{DesignRequest, Objective, Vary};
use super::result::{ConstraintSlack, Design, DesignStatus, VariedValue};

/// A constraint's value where there is no gait (every constraint reads as violated by this).
const NO_GAIT: f64 = 1.0;
/// A violation the solver sees as none (see the constraints' callbacks).
const SNAP: f64 = 1e-10;
/// A constraint holds with a slack of at least `-FEASIBLE`.
const FEASIBLE: f64 = 1e-8;
/// A design is optimal where the KKT residual is at most this times `1 + |grad f|`: the
/// central differences of nested functions solved to `rtol` carry errors of about `rtol /
/// STEP` (1e-6 at the defaults), and the solver stops on the objective's change.
const KKT_TOL: f64 = 1e-4;
/// The difference step, relative to each parameter's range.
const STEP: f64 = 1e-4;

/// The program: the walker, the request, and a cache of evaluations by parameter vector.
struct Program<'a> {
    setup: &'a Setup,
    cfg: &'a SimConfig,
    req: &'a DesignRequest,
    names: Vec<&'a str>,
    /// The number of varied parameters (the program's first variables).
    n: usize,
    /// Whether the objective is the friction the gait needs, in epigraph form: one more
    /// variable `s` (the program's last), minimised subject to both ratios `<= s`.
    epi: bool,
    /// The floor's friction coefficient, which the constraints hold the foot against.
    floor_mu0: f64,
    /// The design's constraints (the program's first ones), in order.
    kinds: Vec<Kind>,
    /// Evaluated points: the parameters and the evaluation (or why there was none).
    seen: RefCell<Vec<(Vec<f64>, Option<Evaluation>)>>,
    /// The last fixed point found, Newton's next guess.
    guess: RefCell<Option<Vec<f64>>>,
    /// The gradients at the last point asked (the solver asks for each constraint's).
    grads: RefCell<Option<Gradients>>,
}

/// A point and the gradients there: `df` and `dg[j][i] = d g_j / d x_i`.
type Gradients = (Vec<f64>, Vec<f64>, Vec<Vec<f64>>);

impl Program<'_> {
    /// The floor's `mu0` at `x` (varied or the request's).
    fn mu0(&self, x: &[f64]) -> f64 {
        self.names
            .iter()
            .position(|n| *n == "mu0")
            .map_or(self.floor_mu0, |i| x[i])
    }

    /// The evaluation at `x`, from the cache or computed (warm-started from the last gait).
    fn at(&self, x: &[f64]) -> Option<Evaluation> {
        if let Some((_, e)) = self.seen.borrow().iter().rev().find(|(y, _)| y == x) {
            return e.clone();
        }
        let guess = self.guess.borrow().clone();
        let ramp_inputs = !self.req.max_input.is_empty();
        let e = evaluate(
            self.setup,
            self.cfg,
            &self.names,
            x,
            guess.as_deref(),
            ramp_inputs,
            self.req.bounds.clearance.is_some(),
        )
        .ok();
        if let Some(e) = &e {
            *self.guess.borrow_mut() = Some(e.reduced.clone());
        }
        self.seen.borrow_mut().push((x.to_vec(), e.clone()));
        e
    }

    /// The program's constraints: the design's ([`Program::kinds`]), and with
    /// [`Program::epi`] the epigraph's two (the stance's aggregate and the strike's ratio
    /// `<= s`).
    fn count(&self) -> usize {
        self.kinds.len() + if self.epi { 2 } else { 0 }
    }

    /// The epigraph's level at an evaluation: the larger of the stance's aggregate and the
    /// strike's ratio, the least `s` meeting both epigraph constraints.
    fn level(e: &Evaluation) -> f64 {
        stance_ks(e).max(e.impact_friction.min(CAP))
    }

    /// The objective at an evaluation as the program minimises it: the design's objective
    /// ([`Program::reported`]) times [`Objective::sign`] (`-V` for the speed, maximised).
    fn objective(&self, e: &Evaluation) -> f64 {
        self.req.objective.sign() * self.reported(e)
    }

    /// The design's objective at an evaluation, as the result reports it.
    fn reported(&self, e: &Evaluation) -> f64 {
        match self.req.objective {
            Objective::SpecificResistance => e.specific_resistance,
            Objective::Power => e.power,
            Objective::Friction => e.required_friction().min(CAP),
            Objective::Speed => e.fixed_point.speed,
        }
    }

    /// The design's constraints `g <= 0` at `x` (all [`NO_GAIT`] without a gait), in the
    /// order of [`Program::kinds`] ([`program_value`]).
    fn constraints(&self, x: &[f64], e: Option<&Evaluation>) -> Vec<f64> {
        let mu0 = self.mu0(x);
        match e {
            None => vec![NO_GAIT; self.kinds.len()],
            Some(e) => self
                .kinds
                .iter()
                .map(|&k| program_value(k, e, mu0, self.req))
                .collect(),
        }
    }

    /// The program's constraints at the program's point `x` (the parameters, then `s` with
    /// [`Program::epi`]).
    fn program_constraints(&self, x: &[f64], e: Option<&Evaluation>) -> Vec<f64> {
        let mut g = self.constraints(&x[..self.n], e);
        if self.epi {
            let s = x[self.n];
            match e {
                None => g.extend([NO_GAIT, NO_GAIT]),
                Some(e) => g.extend([stance_ks(e) - s, e.impact_friction.min(CAP) - s]),
            }
        }
        g
    }

    /// The program's objective and constraints at its point `x`; without a gait the objective
    /// of the nearest point with one (so that only the constraints tell the solver it has
    /// left the gaits). In epigraph form the objective is `s` itself.
    fn values(&self, x: &[f64]) -> (f64, Vec<f64>) {
        let p = &x[..self.n];
        let e = self.at(p);
        let f = match &e {
            _ if self.epi => x[self.n],
            Some(e) => self.objective(e),
            None => self
                .seen
                .borrow()
                .iter()
                .filter_map(|(y, e)| e.as_ref().map(|e| (dist(p, y), self.objective(e))))
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .map_or(0.0, |(_, f)| f),
        };
        (f, self.program_constraints(x, e.as_ref()))
    }

    /// Central differences of the objective and the constraints at the program's point `x` in
    /// the parameters (one-sided at a bound or where one side has no gait), cached for the
    /// last point; in epigraph form the column of `s` is exact (`1` in the objective, `-1` in
    /// the epigraph's constraints).
    fn gradients(&self, x: &[f64]) -> (Vec<f64>, Vec<Vec<f64>>) {
        if let Some((y, df, dg)) = self.grads.borrow().as_ref()
            && y == x
        {
            return (df.clone(), dg.clone());
        }
        let n = x.len();
        // The objective and the constraints in one vector, as `difference` takes them.
        let flat = |(f, g): (f64, Vec<f64>)| [vec![f], g].concat();
        let base = flat(self.values(x));
        let mut df = vec![0.0; n];
        let mut dg = vec![vec![0.0; n]; self.count()];
        for (i, v) in self.req.vary.iter().enumerate() {
            let column = difference(x, i, v, Some(&base), |y| {
                self.at(&y[..self.n])
                    .is_some()
                    .then(|| flat(self.values(y)))
            });
            let Some(column) = column else { continue };
            df[i] = column[0];
            for (j, row) in dg.iter_mut().enumerate() {
                row[i] = column[j + 1];
            }
        }
        if self.epi {
            let c = self.kinds.len();
            df[self.n] = 1.0;
            dg[c][self.n] = -1.0;
            dg[c + 1][self.n] = -1.0;
        }
        *self.grads.borrow_mut() = Some((x.to_vec(), df.clone(), dg.clone()));
        (df, dg)
    }

    /// Whether every constraint of the design holds at the parameters `p`.
    fn feasible(&self, p: &[f64]) -> bool {
        let e = self.at(p);
        e.is_some()
            && self
                .constraints(p, e.as_ref())
                .iter()
                .all(|g| *g <= FEASIBLE)
    }

    /// The visited parameters with a gait whose largest constraint violation is the least
    /// (the earliest among equals).
    fn least_violating(&self) -> Option<Vec<f64>> {
        let seen = self.seen.borrow();
        seen.iter()
            .filter_map(|(y, e)| {
                let worst = self
                    .constraints(y, Some(e.as_ref()?))
                    .into_iter()
                    .fold(f64::NEG_INFINITY, f64::max);
                Some((y.clone(), worst))
            })
            .min_by(|a, b| a.1.total_cmp(&b.1))
            .map(|(y, _)| y)
    }

    /// Central differences of the design's own objective in the parameters at `p` (as
    /// [`Program::gradients`] takes them), for the report in epigraph form, where the
    /// program's objective is `s`.
    fn objective_gradient(&self, p: &[f64]) -> Vec<f64> {
        let f = |y: &[f64]| self.at(y).map(|e| vec![self.objective(&e)]);
        let base = f(p);
        self.req
            .vary
            .iter()
            .enumerate()
            .map(|(i, v)| difference(p, i, v, base.as_deref(), f).map_or(0.0, |c| c[0]))
            .collect()
    }
}

/// The difference quotient of `f` in component `i` of `x`, the varied parameter `v`: central,
/// `(f(x + h e_i) - f(x - h e_i)) / 2h` with `h = STEP (hi - lo)`, or one-sided against `base`
/// (`f(x)`) where one side leaves `v`'s bounds or `f` has no value there; `None` where neither
/// side has one, or one has and there is no `base`. The side `+h` is evaluated first (the
/// evaluations warm-start each other's fixed point).
fn difference(
    x: &[f64],
    i: usize,
    v: &Vary,
    base: Option<&[f64]>,
    f: impl Fn(&[f64]) -> Option<Vec<f64>>,
) -> Option<Vec<f64>> {
    let h = STEP * (v.hi - v.lo);
    let side = |s: f64| {
        let mut y = x.to_vec();
        y[i] += s;
        if y[i] >= v.lo && y[i] <= v.hi {
            f(&y)
        } else {
            None
        }
    };
    let (plus, minus) = (side(h), side(-h));
    let (a, b, w) = match (plus, minus) {
        (Some(p), Some(m)) => (p, m, 2.0 * h),
        (Some(p), None) => (p, base?.to_vec(), h),
        (None, Some(m)) => (base?.to_vec(), m, h),
        (None, None) => return None,
    };
    Some(a.iter().zip(&b).map(|(a, b)| (a - b) / w).collect())
}

/// The friction coefficient of the held walker: far above any ratio a gait needs (the
/// constraints cap ratios at [`CAP`]), so that under Coulomb friction no sample slips.
pub const HELD_MU0: f64 = 1e4;

/// `setup` with its foot held: under Coulomb friction `mu0 = HELD_MU0` (the stuck stance and
/// the sticking impact do not depend on `mu0`, so the gait is the one the floor's `mu0` walks
/// wherever the constraints hold); under a smooth law the setup itself (its foot always
/// creeps; the constraints bound the ratio it draws).
fn held_setup(setup: &Setup) -> Setup {
    let mut held = setup.clone();
    if setup.friction == crate::model::Friction::Coulomb && held.set("mu0", HELD_MU0).is_err() {
        return setup.clone();
    }
    held
}

/// Euclidean distance.
fn dist(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// Run the design `req` on `setup`'s walker with the integrator settings `cfg` (module
/// documentation). An infeasible design is a result ([`DesignStatus::Infeasible`]).
///
/// # Errors
/// An invalid request ([`DesignRequest::check`]), or no periodic gait at the start.
pub fn design(setup: &Setup, cfg: &SimConfig, req: &DesignRequest) -> Result<Design, DesignError> {
    req.check(setup, cfg)?;
    let x0: Vec<f64> = req.vary.iter().map(|v| v.start).collect();
    solve_from(setup, cfg, req, &x0)
}

/// The design of a checked request `req` from the parameters `x0` (within the bounds) in
/// place of the request's starts: [`design`] and each restart of
/// [`super::design_with_restarts`].
///
/// # Errors
/// No periodic gait at `x0`.
pub(super) fn solve_from(
    setup: &Setup,
    cfg: &SimConfig,
    req: &DesignRequest,
    x0: &[f64],
) -> Result<Design, DesignError> {
    // The gait with the foot held: under Coulomb friction the design's walker has a friction
    // coefficient no gait reaches, so its stance foot sticks and its strikes stick; the
    // constraints then ask that the friction the held gait needs stay below the floor's.
    let floor_mu0 = setup.params.get("mu0").unwrap_or(0.0);
    let held = held_setup(setup);
    let setup = &held;
    let names: Vec<&str> = req.vary.iter().map(|v| v.name.as_str()).collect();
    let n = x0.len();
    let swing = req.bounds.clearance.is_some();
    let start = evaluate(
        setup,
        cfg,
        &names,
        x0,
        None,
        !req.max_input.is_empty(),
        swing,
    )
    .map_err(|message| DesignError::NoGaitAtStart {
        at: names
            .iter()
            .zip(x0)
            .map(|(n, v)| format!("{n}={v}"))
            .collect::<Vec<_>>()
            .join(", "),
        message,
    })?;
    let prog = Program {
        setup,
        cfg,
        req,
        names: names.clone(),
        n,
        epi: req.objective == Objective::Friction,
        floor_mu0,
        kinds: kinds(req, start.ramps_end.is_some(), start.max_input.len()),
        seen: RefCell::new(Vec::new()),
        guess: RefCell::new(None),
        grads: RefCell::new(None),
    };
    *prog.guess.borrow_mut() = Some(start.reduced.clone());
    prog.seen
        .borrow_mut()
        .push((x0.to_vec(), Some(start.clone())));
    let start_value = prog.reported(&start);
    // The program's start: the parameters, and in epigraph form the least `s` there.
    let mut x0 = x0.to_vec();
    if prog.epi {
        x0.push(Program::level(&start));
    }

    let objective = |x: &[f64], grad: Option<&mut [f64]>, _: &mut ()| -> f64 {
        if let Some(g) = grad {
            g.copy_from_slice(&prog.gradients(x).0);
        }
        prog.values(x).0
    };
    let cons: Vec<Box<dyn Func<()> + '_>> = (0..prog.count())
        .map(|j| {
            let p = &prog;
            Box::new(
                move |x: &[f64], grad: Option<&mut [f64]>, _: &mut ()| -> f64 {
                    if let Some(g) = grad {
                        g.copy_from_slice(&p.gradients(x).1[j]);
                    }
                    // NLopt's SLSQP counts a point feasible only at `g <= 0` exactly, and stops
                    // only at a feasible one; iterates that converge onto an active constraint
                    // miss it by rounding, so a violation below `SNAP` reads as 0.
                    let g = p.values(x).1[j];
                    if g > 0.0 && g <= SNAP { 0.0 } else { g }
                },
            ) as Box<dyn Func<()> + '_>
        })
        .collect();
    let cons_ref: Vec<&dyn Func<()>> = cons.iter().map(|c| c.as_ref()).collect();
    let mut bounds: Vec<(f64, f64)> = req.vary.iter().map(|v| (v.lo, v.hi)).collect();
    if prog.epi {
        bounds.push((0.0, CAP));
    }
    let stop = StopTols {
        ftol_rel: req.tol,
        xtol_rel: req.tol,
        ..StopTols::default()
    };
    let outcome = minimize(
        objective,
        &x0,
        &bounds,
        &cons_ref,
        (),
        req.max_evaluations,
        Some(stop),
    );
    let (solver, converged, x_solver) = match outcome {
        Ok((s, x, _)) => (
            format!("{s:?}"),
            !matches!(s, slsqp::SuccessStatus::MaxEvalReached),
            x,
        ),
        Err((e, x, _)) => (format!("{e:?}"), false, x),
    };
    // The solver's point if it meets every constraint (to [`FEASIBLE`]), else the best point
    // visited that does (the solver's point is its best feasible one to [`SNAP`], or its last
    // one where it found none), else the solver's point, infeasible.
    let candidates: Vec<(Vec<f64>, f64)> = {
        let seen = prog.seen.borrow();
        seen.iter()
            .filter_map(|(y, e)| e.as_ref().map(|e| (y.clone(), prog.objective(e))))
            .collect()
    };
    let best_feasible = candidates
        .into_iter()
        .filter(|(y, _)| prog.feasible(y))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    let p_solver = x_solver[..n].to_vec();
    // In epigraph form the solver's point is its best one meeting the epigraph's constraints
    // too, which iterates converging from outside them miss (by 1e-3 on the three-link
    // biped): the best point visited that meets the design's constraints is taken instead.
    let p = if prog.epi {
        best_feasible.map_or(p_solver, |(y, _)| y)
    } else if prog.feasible(&p_solver) {
        p_solver
    } else {
        best_feasible.map_or(p_solver, |(y, _)| y)
    };
    // An infeasible design whose solver ended where there is no gait is reported at the point
    // visited with a gait whose largest violation is the least (the start at worst), so that
    // the parameters and the gait reported belong together.
    let p = if prog.at(&p).is_some() {
        p
    } else {
        prog.least_violating().unwrap_or_else(|| x0[..n].to_vec())
    };
    let e = prog.at(&p).unwrap_or(start);
    // The program's point: the parameters, and in epigraph form the least `s` there (so the
    // larger of the two ratios is exactly active in the KKT measure).
    let mut x = p.clone();
    if prog.epi {
        x.push(Program::level(&e));
    }
    let (f, g) = prog.values(&x);
    let f = if prog.epi {
        prog.objective(&e)
    } else {
        req.objective.sign() * f
    };
    let (df, dg) = prog.gradients(&x);
    let near = |y: f64, b: f64, v: &super::request::Vary| (y - b).abs() <= 1e-9 * (v.hi - v.lo);
    let at_lo: Vec<bool> = req
        .vary
        .iter()
        .zip(&x)
        .map(|(v, y)| near(*y, v.lo, v))
        .chain(prog.epi.then_some(false))
        .collect();
    let at_hi: Vec<bool> = req
        .vary
        .iter()
        .zip(&x)
        .map(|(v, y)| near(*y, v.hi, v))
        .chain(prog.epi.then_some(false))
        .collect();
    let (kkt_residual, lagrange) = kkt(&df, &g, &dg, &at_lo, &at_hi);
    let mu = prog.mu0(&p);
    let constraints: Vec<ConstraintSlack> = prog
        .kinds
        .iter()
        .zip(&lagrange)
        .map(|(&kind, &l)| {
            let (value, limit, sense) = row(kind, &e, mu, req);
            let slack = if sense == "<=" {
                limit - value
            } else {
                value - limit
            };
            ConstraintSlack {
                name: kind.name(),
                value,
                limit,
                sense,
                slack,
                holds: slack >= -FEASIBLE,
                lagrange: l,
            }
        })
        .collect();
    let feasible = constraints.iter().all(|c| c.holds);
    let violated = (!feasible).then(|| {
        constraints
            .iter()
            .min_by(|a, b| a.slack.total_cmp(&b.slack))
            .map_or_else(|| "multipliers".to_owned(), |c| c.name.clone())
    });
    let scale = 1.0 + df.iter().fold(0.0_f64, |m, d| m.max(d.abs()));
    let stationary = kkt_residual <= KKT_TOL * scale;
    let status = match (feasible, converged && stationary) {
        (false, _) => DesignStatus::Infeasible,
        (true, true) => DesignStatus::Optimal,
        (true, false) => DesignStatus::Feasible,
    };
    // The objective's derivatives reported: the program's own, or in epigraph form (where the
    // program's objective is `s`) the friction's.
    let reported = if prog.epi {
        prog.objective_gradient(&p)
    } else {
        df.iter().map(|d| req.objective.sign() * d).collect()
    };
    let evaluations = prog.seen.borrow().len();
    Ok(Design {
        status,
        violated,
        solver,
        objective: req.objective.name(),
        value: f,
        start_value,
        parameters: req
            .vary
            .iter()
            .zip(&p)
            .zip(&reported)
            .map(|((v, &value), &gradient)| VariedValue {
                name: v.name.clone(),
                value,
                lo: v.lo,
                hi: v.hi,
                gradient,
            })
            .collect(),
        mu0: mu,
        gait: e,
        constraints,
        kkt_residual,
        evaluations,
        restarts: Vec::new(),
    })
}
