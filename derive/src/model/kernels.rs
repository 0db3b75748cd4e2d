//! A model's named kernels: what the code generator turns into Rust for any model file. The
//! names are the model-independent ones of `docs/model-format.md` (`mass_matrix`, `bias`,
//! `lambda`, `accel`, `control`, `closed_loop`, `stick`, `impact`, `impact_double`, `points`,
//! `energy`); a kernel's arguments are the non-parameter symbols its outputs contain, in the
//! table's order (coordinates, velocities, inputs, `mu`, auxiliary inputs, `t`), and the impact
//! kernels take every velocity.

use walker_scene::model::Model;

use super::mechanics::Mechanics;
use super::phases::{output_control, sliding, strike_impacts, stuck};
use super::table::ModelSymbols;
use crate::error::{Error, Result};
use crate::kernels::{Kernel, Shape, Staged};
use crate::matrix::Matrix;
use crate::ratfunc::RatFunc;
use crate::symbol::{Atom, Sym, SymKind, Symbols};

/// The largest closed-form `M^-1` (terms of its numerators and denominators) whose products the
/// stance and impact kernels are derived from: the paper's walkers have 34 and the rimless wheel
/// 21 (each model derived in under 0.05 s); the compass gait's 234 already take minutes in the
/// products and gcds that follow (BENCHMARKS.md, section 5b). Larger models are refused with
/// [`Error::TooLarge`] until the structured solve exists.
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

fn named(prefix: &str, m: &Matrix) -> Vec<(String, RatFunc)> {
    let c = m.cols();
    m.entries()
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let name = if m.rows() > 1 && c > 1 {
                format!("{prefix}{}{}", k / c, k % c)
            } else {
                format!("{prefix}{k}")
            };
            (name, r.clone())
        })
        .collect()
}

/// The non-parameter symbols the outputs contain (plus `always`), in table order.
fn args_of(symbols: &Symbols, outputs: &[(String, RatFunc)], always: &[Sym]) -> Vec<Sym> {
    let mut used = std::collections::BTreeSet::new();
    for (_, r) in outputs {
        for p in [r.num(), r.den()] {
            for slot in p.slots() {
                if let Some(s) = symbols.symbol_of_slot(slot)
                    && symbols.kind(s) != SymKind::Parameter
                {
                    used.insert(s);
                }
            }
        }
    }
    used.extend(always.iter().copied());
    used.into_iter().collect()
}

fn kernel(
    symbols: &Symbols,
    name: &'static str,
    doc: &'static str,
    equation: &'static str,
    outputs: Vec<(String, RatFunc)>,
    shape: Shape,
    always: &[Sym],
) -> Kernel {
    Kernel {
        name,
        doc,
        equation,
        args: args_of(symbols, &outputs, always),
        outputs,
        shape,
        staged: None,
    }
}

impl ModelDerivation {
    /// Derives every kernel of `model`.
    ///
    /// # Errors
    /// As [`Mechanics::new`], the phases' derivations, or a kernel that depends on a symbol it
    /// does not take.
    pub fn new(model: &Model) -> Result<ModelDerivation> {
        let m = Mechanics::new(model)?;
        let size: usize = m
            .mass_inv
            .entries()
            .iter()
            .map(|r| r.num().len() + r.den().len())
            .sum();
        if size > MAX_INVERSE_TERMS {
            return Err(Error::TooLarge {
                what: format!("model `{}`: M^-1", model.name),
                terms: size,
                limit: MAX_INVERSE_TERMS,
            });
        }
        let t = &m.syms.table;
        let n = m.syms.q.len();
        let slide = sliding(&m)?;
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
            kernel(
                t,
                "lambda",
                "Vertical ground reaction lambda of the sliding stance foot",
                "Eqs. 22-23",
                vec![("lambda".into(), slide.lambda.clone())],
                Shape::Scalar,
                &[],
            ),
            kernel(
                t,
                "accel",
                "Accelerations qddot of the sliding stance",
                "Eq. 27",
                named("qdd", &slide.accel),
                Shape::Vector(n),
                &[],
            ),
        ];
        if !model.outputs.is_empty() {
            let c = output_control(&m, model, &slide.projection)?;
            let mut parts = named("A", &c.a);
            parts.extend(named("B", &c.b));
            kernels.push(kernel(
                t,
                "control",
                "Matrix A and vector B of the output-following control, yddot = A u - B",
                "Eqs. 30-31",
                parts,
                Shape::Parts,
                &[],
            ));
            // Closed loop: u = A^-1 (v + B) once, then Eq. 27 with that u.
            let subst = |r: &RatFunc| -> Result<RatFunc> {
                let mut r = r.clone();
                for (u, value) in m.syms.inputs.iter().zip(c.u.entries()) {
                    r = r.substitute(Atom::Sym(*u), value)?;
                }
                Ok(r)
            };
            let closed = slide.accel.try_map(subst)?;
            let mut outputs = named("qdd", &closed);
            outputs.extend(named("u", &c.u));
            let mut staged_out: Vec<RatFunc> = slide.accel.entries().to_vec();
            staged_out.extend(m.syms.inputs.iter().map(|u| RatFunc::sym(*u)));
            let mut closed_loop = kernel(
                t,
                "closed_loop",
                "Accelerations qddot and inputs u under the output-following control, with yddot = v",
                "Eqs. 27, 31",
                outputs,
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
            kernels.push(closed_loop);
        }
        let st = stuck(&m)?;
        let mut stick = named("qdd", &st.accel);
        stick.push(("lambda_t".into(), st.forces.get(0, 0).clone()));
        stick.push(("lambda_n".into(), st.forces.get(1, 0).clone()));
        kernels.push(kernel(t, "stick", "Accelerations qddot and the ground force [lambda_t, lambda_n] with the stance foot stuck", "stick phase; Eq. 19 with both foot coordinates held", stick, Shape::Parts, &[]));
        let imp = strike_impacts(&m, model)?;
        let qd = m.syms.qd.clone();
        let mut single = named("lambdaI", &imp.single.impulse);
        single.extend(named("qdp", &imp.single.velocity));
        kernels.push(kernel(
            t,
            "impact",
            "Normal impulses and post-impact velocities: the striking point and the locks",
            "Eqs. 6-16, 39-42",
            single,
            Shape::Parts,
            &qd,
        ));
        if let Some(d) = &imp.double {
            let mut double = named("lambdaI", &d.impulse);
            double.extend(named("qdp", &d.velocity));
            kernels.push(kernel(t, "impact_double", "Normal impulses and post-impact velocities with the old stance foot held (double-support test)", "Eqs. 6-11, 46", double, Shape::Parts, &qd));
        }
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
        for k in &kernels {
            k.check_staged()?;
            let free = k.free_symbols(t);
            if !free.is_empty() {
                let names: Vec<&str> = free.iter().map(|s| t.name(*s)).collect();
                return Err(Error::CheckFailed {
                    what: format!(
                        "kernel {} depends on {names:?} which are not arguments",
                        k.name
                    ),
                });
            }
        }
        Ok(ModelDerivation {
            symbols: m.syms.table.clone(),
            syms: m.syms,
            kernels,
        })
    }

    /// A kernel by name.
    ///
    /// # Errors
    /// [`Error::UnknownKernel`].
    pub fn kernel(&self, name: &str) -> Result<&Kernel> {
        self.kernels
            .iter()
            .find(|k| k.name == name)
            .ok_or_else(|| Error::UnknownKernel {
                name: name.to_owned(),
            })
    }
}
