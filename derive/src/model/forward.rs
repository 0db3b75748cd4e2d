//! The Jacobian of a structured solve by forward-mode differentiation of its straight-line
//! program: the stance kernels' partial derivatives for the models whose stance has no closed
//! form (the compass gait's sliding stance, the three-link and five-link bipeds), where
//! `jacobians` has nothing to differentiate.
//!
//! A program ([`Staged`]) binds locals `s_k = e_k` in order, each `e_k` a small rational
//! function of the arguments, the parameters and the locals before it (`program`). Its
//! derivative in an argument `x` is the chain rule taken local by local, in the same order:
//!
//! `d s_k / dx = de_k/dx + sum_l (de_k / ds_l) (d s_l / dx)`,
//!
//! `de_k/dx` the explicit partial (an angle through its sine and cosine, [`RatFunc::diff`]) and
//! the sum over the locals `s_l` that `e_k` reads. Each partial `de_k / ds_l` is bound once and
//! shared by every argument; a tangent that is exactly zero is skipped, so the structure of the
//! solve carries over: `M`, its factors and every quantity of the coordinates alone have no
//! tangent in the velocities, `mu` or the auxiliary inputs, whose tangents run through the
//! right-hand sides and the substitutions only. The result is a program again (the original
//! locals, then the tangents), which the code generator lowers like any structured solve.
//!
//! Written here rather than taken from an automatic-differentiation crate: the program is
//! symbolic (exact rational functions over the model's symbols, differentiated at generation
//! time), and its output is code, not numbers.

use std::collections::HashMap;

use crate::error::Result;
use crate::kernels::Staged;
use crate::ratfunc::RatFunc;
use crate::symbol::{Sym, Symbols};

use super::program::Program;

/// `d outputs / d vars` of `program` (row `i` an output, column `j` a variable, row-major) as a
/// program: `program`'s locals, then the tangents (module documentation). The new locals are
/// added to `table` under `prefix`.
///
/// # Errors
/// A full symbol table, or an arithmetic error of the differentiation.
pub(super) fn differentiate(
    program: &Staged,
    vars: &[Sym],
    table: &mut Symbols,
    prefix: &str,
) -> Result<Staged> {
    let by_slot: HashMap<usize, Sym> = program.locals.iter().map(|(s, _)| (s.slot(), *s)).collect();
    let mut p = Program::new(table, prefix);
    // Each local's tangent, one entry per variable (bound, or an exact constant).
    let mut tangents: HashMap<Sym, Vec<RatFunc>> = HashMap::with_capacity(program.locals.len());
    for (s, e) in &program.locals {
        let t = tangent(&mut p, e, vars, &by_slot, &tangents, true)?;
        tangents.insert(*s, t);
    }
    let mut outputs = Vec::with_capacity(program.outputs.len() * vars.len());
    for e in &program.outputs {
        outputs.extend(tangent(&mut p, e, vars, &by_slot, &tangents, false)?);
    }
    let derived = p.finish(outputs);
    let mut locals = program.locals.clone();
    locals.extend(derived.locals);
    Ok(Staged {
        locals,
        outputs: derived.outputs,
    })
}

/// `de / d vars` by the chain rule through the locals `e` reads; each entry bound to a local
/// where `bind` (a local's tangent, read again later), left as an expression otherwise (an
/// output's).
fn tangent(
    p: &mut Program<'_>,
    e: &RatFunc,
    vars: &[Sym],
    by_slot: &HashMap<usize, Sym>,
    tangents: &HashMap<Sym, Vec<RatFunc>>,
    bind: bool,
) -> Result<Vec<RatFunc>> {
    let mut read: Vec<Sym> = [e.num(), e.den()]
        .iter()
        .flat_map(|poly| poly.slots())
        .filter_map(|slot| by_slot.get(&slot).copied())
        .collect();
    read.sort_unstable();
    read.dedup();
    // The partials in the locals whose tangents are not all zero, each bound once.
    let mut chain = Vec::with_capacity(read.len());
    for l in read {
        let t = &tangents[&l];
        if t.iter().all(RatFunc::is_zero) {
            continue;
        }
        let partial = e.diff(l);
        if !partial.is_zero() {
            chain.push((p.bind(partial)?, t));
        }
    }
    let mut out = Vec::with_capacity(vars.len());
    for (j, &x) in vars.iter().enumerate() {
        let mut d = e.diff(x);
        for (partial, t) in &chain {
            if !t[j].is_zero() {
                d = &d + &(partial * &t[j]);
            }
        }
        out.push(if bind { p.bind(d)? } else { d });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    //! The differentiated structured solve equals the closed-form Jacobian exactly, on the
    //! paper's walkers (which have both): each evaluated in exact rational arithmetic at points
    //! whose sines and cosines lie on the unit circle (`sin = 2 s / (1 + s^2)`, `cos = (1 -
    //! s^2) / (1 + s^2)`), where the two rational functions must agree if they are the same
    //! function of the angles.
    #![allow(clippy::unwrap_used, reason = "tests")]

    use num_bigint::BigInt;
    use walker_scene::model::Model;

    use super::differentiate;
    use crate::kernels::Staged;
    use crate::model::ModelDerivation;
    use crate::poly::Q;
    use crate::ratfunc::RatFunc;
    use crate::symbol::{Point, Sym, Symbols};

    fn q(n: i64, d: i64) -> Q {
        Q::new(BigInt::from(n), BigInt::from(d))
    }

    /// A point: every symbol at a small rational of its own, every base angle on the circle.
    fn point(table: &Symbols, seed: i64) -> Point<Q> {
        let mut p = Point::zeros(table);
        for i in 0..table.len() {
            let s = table.by_index(i).unwrap();
            let k = i64::try_from(i).unwrap();
            p.set(s.slot(), q(3 + (k * 7 + seed * 5) % 11, 8));
        }
        for (b, angle) in table.base_angles().enumerate() {
            let s = q(1 + (i64::try_from(b).unwrap() + seed) % 5, 7);
            let d = q(1, 1) + &s * &s;
            p.set(angle.sin_slot(), q(2, 1) * &s / &d);
            p.set(angle.cos_slot(), (q(1, 1) - &s * &s) / &d);
        }
        p
    }

    /// The outputs of a program at `p` (its locals set in `p` on the way).
    fn run(program: &Staged, p: &mut Point<Q>) -> Vec<Q> {
        for (s, e) in &program.locals {
            let v = e.eval_exact(p).unwrap();
            p.set(s.slot(), v);
        }
        program
            .outputs
            .iter()
            .map(|e| e.eval_exact(p).unwrap())
            .collect()
    }

    fn check(model: &str, of: &str, jacobian: &str, vars: impl Fn(&ModelDerivation) -> Vec<Sym>) {
        let path = format!("{}/../models/{model}.toml", env!("CARGO_MANIFEST_DIR"));
        let d =
            ModelDerivation::new(&Model::from_file(std::path::Path::new(&path)).unwrap()).unwrap();
        let mut table = d.symbols.clone();
        let solve = d.kernel(of).unwrap().solve.clone().unwrap();
        let derived = differentiate(&solve, &vars(&d), &mut table, "test").unwrap();
        let closed: Vec<RatFunc> = d
            .kernel(jacobian)
            .unwrap()
            .outputs
            .iter()
            .map(|(_, r)| r.clone())
            .collect();
        assert_eq!(derived.outputs.len(), closed.len());
        assert!(table.len() > d.symbols.len(), "no tangent was bound");
        for seed in 0..3 {
            let mut p = point(&table, seed);
            let want: Vec<Q> = closed.iter().map(|r| r.eval_exact(&p).unwrap()).collect();
            let got = run(&derived, &mut p);
            for (k, (g, w)) in got.iter().zip(&want).enumerate() {
                assert_eq!(g, w, "{model} {jacobian}[{k}] at point {seed}");
            }
        }
        // Not trivially: some entry is not zero.
        let p = point(&table, 0);
        assert!(closed.iter().any(|r| r.eval_exact(&p).unwrap() != q(0, 1)));
    }

    #[test]
    fn the_active_walkers_closed_loop_jacobian() {
        check("paper-active", "closed_loop", "closed_loop_jacobian", |d| {
            let s = &d.syms;
            let mut v: Vec<Sym> = s.q.iter().chain(&s.qd).copied().collect();
            v.push(s.mu);
            v.extend(&s.aux);
            v
        });
    }

    #[test]
    fn the_passive_walkers_accel_jacobian() {
        check("paper-passive", "accel", "accel_jacobian", |d| {
            let s = &d.syms;
            let mut v: Vec<Sym> = s.q.iter().chain(&s.qd).copied().collect();
            v.push(s.mu);
            v
        });
    }
}
