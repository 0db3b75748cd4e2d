//! A model's named kernels: what the code generator turns into Rust for any model file. The
//! names are the model-independent ones of `docs/model-format.md` (`mass_matrix`, `bias`,
//! `lambda`, `accel`, `control`, `closed_loop`, `stick`, `closed_loop_stick`, `impact`,
//! `impact_double`, `impact_coulomb`, `accel_jacobian`, `closed_loop_jacobian`,
//! `impact_jacobian`, `stick_jacobian`, `closed_loop_stick_jacobian`, `input_map`, `impact_rows`,
//! `impact_double_rows`, `outputs`, `events`,
//! `relabel`, `points`, `energy`, `output_rates`, `input_rates`, `total_mass`); a kernel's
//! arguments are the non-parameter symbols its outputs contain, in the
//! table's order (coordinates, velocities, inputs, `mu`, auxiliary inputs, `t`), and the impact
//! kernels take every velocity.

use walker_scene::model::Model;

use super::assemble::{kernel, kernel_args, named, names, solve_only, with_solve};
use super::control_check::check_control;
use super::coulomb::impact_coulomb;
use super::descriptors::descriptor_kernels;
use super::events::event_kernels;
use super::jacobians::{
    Differentiated, jacobian_kernels, stick_jacobian, structured_jacobian_kernels,
};
use super::located::singular;
use super::maps::map_kernels;
use super::mechanics::{MAX_CLOSED_COORDINATES, Mechanics};
use super::multiples::check_angle_multiples;
use super::phases::{output_control, sliding, strike_impacts, strike_rows, stuck};
use super::stick_control::closed_loop_stick;
use super::structured::structured_kernels;
use super::table::ModelSymbols;
use crate::budget::{DERIVATION_BUDGET, Measured, stage, within};
use crate::error::Result;
use crate::kernels::{Kernel, Shape, Staged, find_kernel};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, Symbols};

/// The largest closed-form `M^-1` (terms of its numerators and denominators) whose products the
/// stance and impact kernels are derived from: the paper's walkers have 34 and the rimless wheel
/// 21 (each model derived in under 0.05 s); the compass gait's 234 already take minutes in the
/// products and gcds that follow (BENCHMARKS.md, section 5b). A model with a larger inverse gets
/// its stance and impact kernels as structured solves only.
pub const MAX_INVERSE_TERMS: usize = 100;

/// A model's derivation: its mechanics and its kernels.
#[derive(Clone, Debug)]
pub struct ModelDerivation {
    /// The symbol table of every expression.
    pub symbols: Symbols,
    /// The model's symbols by role.
    pub syms: ModelSymbols,
    /// The kernels.
    pub kernels: Vec<Kernel>,
}

/// The size of the closed-form `M^-1` (terms of its numerators and denominators), if derived.
fn inverse_terms(m: &Mechanics) -> Option<usize> {
    m.mass_inv.as_ref().map(|inv| {
        inv.entries()
            .iter()
            .map(|r| r.num().len() + r.den().len())
            .sum()
    })
}

impl ModelDerivation {
    /// Derives every kernel of `model`: the stance and impact kernels as closed forms where the
    /// closed-form `M^-1` is small (at most [`MAX_INVERSE_TERMS`]; the stuck stance's where the
    /// angles' block is at most [`MAX_CLOSED_COORDINATES`] square), and as structured solves
    /// always; the code generator evaluates the cheaper. The Jacobians differentiate the closed
    /// forms where they exist, and otherwise the stance's structured solves (forward mode,
    /// `forward.rs`; models of at most
    /// [`MAX_STRUCTURED_JACOBIAN_COORDINATES`](crate::model::MAX_STRUCTURED_JACOBIAN_COORDINATES)
    /// coordinates).
    ///
    /// The work is bounded by [`DERIVATION_BUDGET`]; the angles' multiples by
    /// [`MAX_ANGLE_MULTIPLE`](crate::model::MAX_ANGLE_MULTIPLE), checked before any work.
    ///
    /// # Errors
    /// As [`Mechanics::new`], the phases' derivations, or a kernel that depends on a symbol it
    /// does not take; [`crate::Error::Budget`] for a derivation past the budget.
    pub fn new(model: &Model) -> Result<ModelDerivation> {
        ModelDerivation::measured(model, DERIVATION_BUDGET).result
    }

    /// [`ModelDerivation::new`] within `budget` term products, and the work it took.
    pub fn measured(model: &Model, budget: u64) -> Measured<ModelDerivation> {
        check_angle_multiples(model).map_or_else(
            |e| Measured {
                result: Err(e),
                work: 0,
            },
            |()| {
                let mut m = within(&model.name, budget, || ModelDerivation::derive(model));
                m.result = m.result.map_err(|e| singular(model, e));
                m
            },
        )
    }

    fn derive(model: &Model) -> Result<ModelDerivation> {
        let m = Mechanics::new(model)?;
        let closed = inverse_terms(&m).is_some_and(|terms| terms <= MAX_INVERSE_TERMS);
        let mut table = m.syms.table.clone();
        stage(|| "the structured solves of the stance and impact kernels".to_owned());
        let solves = structured_kernels(&m, model, &mut table)?;
        let n = m.syms.q.len();
        // The stuck foot's closed form needs no M^-1 (it is solved by blocks), only the inverse
        // of the angles' block: derived while that block is small.
        let stick_closed = n - 2 < MAX_CLOSED_COORDINATES;
        stage(|| "the stuck stance in closed form".to_owned());
        let st = if stick_closed { Some(stuck(&m)?) } else { None };
        // The stuck closed loop in closed form where both its neighbours have theirs (`stick`
        // and `closed_loop`): the three-link biped's stuck stance is closed, but substituting
        // its 2x2 control into it did not finish in 9 minutes.
        let loop_stick = if model.outputs.is_empty() {
            None
        } else {
            stage(|| "the stuck stance's output control".to_owned());
            let stuck_closed = st.as_ref().filter(|_| closed);
            Some(closed_loop_stick(&m, model, stuck_closed, &mut table)?)
        };
        stage(|| "the impact with Coulomb friction".to_owned());
        let coulomb = impact_coulomb(&m, model, closed, &mut table)?;
        // The closed forms: the sliding stance, its control and closed loop, the impacts, and
        // the Jacobians of the closed loop's (or, without inputs, the stance's) accelerations
        // and of the impact.
        stage(|| "the sliding stance in closed form".to_owned());
        let slide = if closed { Some(sliding(&m)?) } else { None };
        stage(|| "the impact maps in closed form".to_owned());
        let imp = if closed {
            Some(strike_impacts(&m, model)?)
        } else {
            None
        };
        stage(|| "the output control in closed form".to_owned());
        let control = match &slide {
            Some(s) if !model.outputs.is_empty() => {
                let c = output_control(&m, model, &s.projection)?;
                // Closed loop: u = A^-1 (v + B) once, then Eq. 27 with that u.
                let subst = |r: &RatFunc| -> Result<RatFunc> {
                    let mut r = r.clone();
                    for (u, value) in m.syms.inputs.iter().zip(c.u.entries()) {
                        r = r.substitute(Atom::Sym(*u), value)?;
                    }
                    Ok(r)
                };
                let closed_accel = s.accel.try_map(subst)?;
                let closed_outputs = Matrix::column(
                    closed_accel
                        .entries()
                        .iter()
                        .chain(c.u.entries())
                        .cloned()
                        .collect(),
                );
                Some((c, closed_accel, closed_outputs))
            }
            _ => None,
        };
        stage(|| "the Jacobians of the closed forms".to_owned());
        let jacobians = match (&slide, &imp) {
            (Some(s), Some(imp)) => {
                let of = Differentiated {
                    accel: model.inputs.is_empty().then_some(&s.accel),
                    closed_loop: control.as_ref().map(|(_, _, outputs)| outputs),
                    impact: &imp.single.velocity,
                };
                jacobian_kernels(&m, &of, &mut table)?
            }
            // Without closed forms, the stance's by differentiating its structured solve.
            _ => structured_jacobian_kernels(&m, &solves, loop_stick.as_ref(), &mut table)?,
        };
        // The stuck stance's Jacobian wherever its closed form is (its own block, no `M^-1`:
        // the compass gait has it though its sliding stance has no closed form).
        let stick_jac = match &st {
            Some(st) if model.inputs.is_empty() => {
                let column = Matrix::column(
                    st.accel
                        .entries()
                        .iter()
                        .chain(st.forces.entries())
                        .cloned()
                        .collect(),
                );
                Some(stick_jacobian(&m, &column, &mut table)?)
            }
            _ => None,
        };
        let t = &table;
        let inputs = m.syms.inputs.len();
        let outputs = model.outputs.len();
        let finish = |k: Kernel, solve: Staged| with_solve(k, solve, closed, t);
        let mut kernels = vec![
            kernel(
                t,
                "mass_matrix",
                "Inertia matrix M(q)",
                "Eq. 2",
                named("M", &m.mass),
                Shape::Matrix(n, n),
                &[],
            ),
            kernel(
                t,
                "bias",
                "Coriolis, centrifugal and gravity vector h(q, qdot)",
                "Eq. 20",
                named("h", &m.bias),
                Shape::Vector(n),
                &[],
            ),
        ];
        let (lambda_doc, lambda_eq) = (
            "Vertical ground reaction lambda of the sliding stance foot",
            "Eqs. 22-23",
        );
        kernels.push(finish(
            match &slide {
                Some(s) => kernel(
                    t,
                    "lambda",
                    lambda_doc,
                    lambda_eq,
                    vec![("lambda".into(), s.lambda.clone())],
                    Shape::Scalar,
                    &[],
                ),
                None => solve_only(
                    "lambda",
                    lambda_doc,
                    lambda_eq,
                    vec!["lambda".into()],
                    Shape::Scalar,
                ),
            },
            solves.lambda,
        ));
        let (accel_doc, accel_eq) = ("Accelerations qddot of the sliding stance", "Eq. 27");
        kernels.push(finish(
            match &slide {
                Some(s) => kernel(
                    t,
                    "accel",
                    accel_doc,
                    accel_eq,
                    named("qdd", &s.accel),
                    Shape::Vector(n),
                    &[],
                ),
                None => solve_only(
                    "accel",
                    accel_doc,
                    accel_eq,
                    names("qdd", n, 1),
                    Shape::Vector(n),
                ),
            },
            solves.accel,
        ));
        if let (Some(control_solve), Some(closed_loop_solve)) = (solves.control, solves.closed_loop)
        {
            let (control_doc, control_eq) = (
                "Matrix A and vector B of the output-following control, yddot = A u - B",
                "Eqs. 30-31",
            );
            let (loop_doc, loop_eq) = (
                "Accelerations qddot and inputs u under the output-following control, with yddot = v",
                "Eqs. 27, 31",
            );
            match (&slide, &control) {
                (Some(s), Some((c, closed_accel, _))) => {
                    let mut parts = named("A", &c.a);
                    parts.extend(named("B", &c.b));
                    kernels.push(finish(
                        kernel(
                            t,
                            "control",
                            control_doc,
                            control_eq,
                            parts,
                            Shape::Parts,
                            &[],
                        ),
                        control_solve,
                    ));
                    // Closed loop: u = A^-1 (v + B) once, then Eq. 27 with that u.
                    let mut loop_outputs = named("qdd", closed_accel);
                    loop_outputs.extend(named("u", &c.u));
                    let mut staged_out: Vec<RatFunc> = s.accel.entries().to_vec();
                    staged_out.extend(m.syms.inputs.iter().map(|u| RatFunc::sym(*u)));
                    let mut closed_loop = kernel(
                        t,
                        "closed_loop",
                        loop_doc,
                        loop_eq,
                        loop_outputs,
                        Shape::Parts,
                        &[],
                    );
                    closed_loop.staged = Some(Staged {
                        locals: m
                            .syms
                            .inputs
                            .iter()
                            .copied()
                            .zip(c.u.entries().iter().cloned())
                            .collect(),
                        outputs: staged_out,
                    });
                    kernels.push(finish(closed_loop, closed_loop_solve));
                }
                _ => {
                    let mut parts = names("A", outputs, inputs);
                    parts.extend(names("B", outputs, 1));
                    kernels.push(finish(
                        solve_only("control", control_doc, control_eq, parts, Shape::Parts),
                        control_solve,
                    ));
                    let mut parts = names("qdd", n, 1);
                    parts.extend(names("u", inputs, 1));
                    kernels.push(finish(
                        solve_only("closed_loop", loop_doc, loop_eq, parts, Shape::Parts),
                        closed_loop_solve,
                    ));
                }
            }
        }
        let (stick_doc, stick_eq) = (
            "Accelerations qddot and the ground force `[lambda_t, lambda_n]` with the stance foot stuck",
            "stick phase; Eq. 19 with both foot coordinates held",
        );
        let stick = if let Some(st) = &st {
            let mut outputs = named("qdd", &st.accel);
            outputs.push(("lambda_t".into(), st.forces.get(0, 0).clone()));
            outputs.push(("lambda_n".into(), st.forces.get(1, 0).clone()));
            kernel(t, "stick", stick_doc, stick_eq, outputs, Shape::Parts, &[])
        } else {
            let mut parts = names("qdd", n, 1);
            parts.extend(["lambda_t".to_owned(), "lambda_n".to_owned()]);
            solve_only("stick", stick_doc, stick_eq, parts, Shape::Parts)
        };
        kernels.push(with_solve(stick, solves.stick, stick_closed, t));
        kernels.extend(loop_stick);
        let qd = m.syms.qd.clone();
        stage(|| "the impact's constraint rows".to_owned());
        let rows = strike_rows(&m, model)?;
        let (impact_doc, impact_eq) = (
            "Normal impulses and post-impact velocities: the striking point and the locks",
            "Eqs. 6-16, 39-42",
        );
        let impact = match &imp {
            Some(imp) => {
                let mut single = named("lambdaI", &imp.single.impulse);
                single.extend(named("qdp", &imp.single.velocity));
                kernel(
                    t,
                    "impact",
                    impact_doc,
                    impact_eq,
                    single,
                    Shape::Parts,
                    &qd,
                )
            }
            None => {
                let mut parts = names("lambdaI", rows.single.len(), 1);
                parts.extend(names("qdp", n, 1));
                solve_only("impact", impact_doc, impact_eq, parts, Shape::Parts)
            }
        };
        let mut impact = finish(impact, solves.impact);
        impact.args = kernel_args(t, &impact, &qd);
        kernels.push(impact);
        if let (Some(double_rows), Some(double_solve)) = (&rows.double, solves.impact_double) {
            let (doc, eq) = (
                "Normal impulses and post-impact velocities with the old stance foot held (double-support test)",
                "Eqs. 6-11, 46",
            );
            let double = match imp.as_ref().and_then(|i| i.double.as_ref()) {
                Some(d) => {
                    let mut double = named("lambdaI", &d.impulse);
                    double.extend(named("qdp", &d.velocity));
                    kernel(t, "impact_double", doc, eq, double, Shape::Parts, &qd)
                }
                None => {
                    let mut parts = names("lambdaI", double_rows.len(), 1);
                    parts.extend(names("qdp", n, 1));
                    solve_only("impact_double", doc, eq, parts, Shape::Parts)
                }
            };
            let mut double = finish(double, double_solve);
            double.args = kernel_args(t, &double, &qd);
            kernels.push(double);
        }
        kernels.push(coulomb);
        kernels.extend(jacobians);
        kernels.extend(stick_jac);
        stage(|| "the events, relabelling and descriptors".to_owned());
        kernels.extend(map_kernels(&m, model, &rows, t)?);
        kernels.extend(event_kernels(&m, model, t)?);
        let mut points = Vec::new();
        for (name, [x, z]) in &m.points {
            points.push((format!("x_{name}"), x.clone()));
            points.push((format!("z_{name}"), z.clone()));
        }
        kernels.push(kernel(
            t,
            "points",
            "Positions of the model's named points",
            "model file",
            points,
            Shape::Parts,
            &[],
        ));
        kernels.push(kernel(
            t,
            "energy",
            "Kinetic and potential energy",
            "Section 2.1",
            vec![
                ("T".into(), m.kinetic.clone()),
                ("V".into(), m.potential.clone()),
            ],
            Shape::Vector(2),
            &[],
        ));
        kernels.extend(descriptor_kernels(&m, model, t)?);
        if let Some(control) = kernels.iter().find(|k| k.name == "control") {
            check_control(model, &m.syms, t, control)?;
        }
        for k in &kernels {
            k.check(t)?;
        }
        Ok(ModelDerivation {
            symbols: table,
            syms: m.syms,
            kernels,
        })
    }

    /// A kernel by name.
    ///
    /// # Errors
    /// [`crate::Error::UnknownKernel`].
    pub fn kernel(&self, name: &str) -> Result<&Kernel> {
        find_kernel(&self.kernels, name)
    }
}
