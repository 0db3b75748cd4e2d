//! The derivation's budget: a bound on the work of one model's derivation, so that a model file
//! whose expressions blow up in the canonical form (a squared trigonometric factor in every
//! centre of mass, a long chain of coordinates) ends with [`Error::Budget`] in seconds instead
//! of running for minutes.
//!
//! Work is counted in *term products*: each product of two terms of polynomials (the inner loop
//! of [`Poly::mul_raw`](crate::Poly::mul_raw), which dominates every product, gcd and
//! inverse) and each term a product by one term or a trigonometric reduction writes. The count
//! lives in a thread-local cell, so that the polynomial arithmetic, whose operations return
//! values and not `Result`s, needs no extra argument: [`within`] opens a budget for one
//! derivation on the current thread and reads it at the end. Once the budget is spent, every
//! further product returns zero at once, so the derivation runs out quickly on values that it
//! then throws away: [`within`] reports the budget's error whatever the derivation returned.
//!
//! Outside [`within`] (the paper's derivation, the engine's own tests) work is not bounded.

use std::cell::RefCell;

use crate::error::{Error, Result};

/// The derivation budget of one model file, in term products (each weighed by the 64-bit words
/// of its coefficients): ten times the largest shipped model's derivation. Measured
/// (`cargo run --release -p walker-symbolic --example derive_cost -- models/*.toml`): the
/// paper's passive walker 193 thousand, the active one 89 thousand, the rimless wheel 64
/// thousand, the five-link biped 18.5 thousand (its stance and impact kernels are structured
/// solves), the compass gait 10 thousand and the three-link biped 9 thousand. A derivation
/// that spends it takes 2 to 5 s on one core of the reference machine (optimised build, the
/// machine shared), a few microseconds per term product.
pub const DERIVATION_BUDGET: u64 = 2_000_000;

/// The budget's state on one thread.
struct State {
    /// Term products so far.
    used: u64,
    /// The limit, or `None` outside [`within`].
    limit: Option<u64>,
    /// What is being derived, for the error.
    stage: String,
    /// The stage at which the limit was passed.
    spent_at: Option<String>,
}

thread_local! {
    static STATE: RefCell<State> = const {
        RefCell::new(State {
            used: 0,
            limit: None,
            stage: String::new(),
            spent_at: None,
        })
    };
}

/// Charges `work` term products. `false` when the budget is spent (the caller then returns a
/// cheap value: the derivation's result is discarded).
pub(crate) fn charge(work: usize) -> bool {
    STATE.with(|s| {
        let mut s = s.borrow_mut();
        if s.spent_at.is_some() {
            return false;
        }
        s.used = s.used.saturating_add(work as u64);
        match s.limit {
            Some(limit) if s.used > limit => {
                s.spent_at = Some(s.stage.clone());
                false
            }
            _ => true,
        }
    })
}

/// Whether the budget is spent (loops that make progress by products stop).
pub(crate) fn spent() -> bool {
    STATE.with(|s| s.borrow().spent_at.is_some())
}

/// Names what the derivation derives now (for [`Error::Budget`]).
pub(crate) fn stage(what: impl FnOnce() -> String) {
    STATE.with(|s| {
        let mut s = s.borrow_mut();
        if s.limit.is_some() && s.spent_at.is_none() {
            s.stage = what();
        }
    });
}

/// The work of a computation: its result and the term products it took.
pub struct Measured<T> {
    /// The result.
    pub result: Result<T>,
    /// Term products.
    pub work: u64,
}

/// Runs `f` (one derivation of the model called `model`) within `limit` term products.
///
/// # Errors
/// [`Error::Budget`] if `f` spent the budget (whatever `f` returned), else `f`'s own.
pub fn within<T>(model: &str, limit: u64, f: impl FnOnce() -> Result<T>) -> Measured<T> {
    let saved = STATE.with(|s| {
        let mut s = s.borrow_mut();
        let saved = (
            s.used,
            s.limit,
            std::mem::take(&mut s.stage),
            s.spent_at.take(),
        );
        s.used = 0;
        s.limit = Some(limit);
        saved
    });
    let result = f();
    let (work, spent_at) = STATE.with(|s| {
        let mut s = s.borrow_mut();
        let out = (s.used, s.spent_at.take());
        (s.used, s.limit, s.stage, s.spent_at) =
            (saved.0.saturating_add(out.0), saved.1, saved.2, saved.3);
        out
    });
    let result = match spent_at {
        Some(stage) => Err(Error::Budget {
            model: model.to_owned(),
            stage,
            budget: limit,
        }),
        None => result,
    };
    Measured { result, work }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn work_past_the_limit_is_the_budget_error_naming_the_stage() {
        let m = within("m", 10, || {
            stage(|| "the mass matrix".to_owned());
            assert!(charge(6));
            assert!(!charge(6));
            assert!(spent());
            Ok(1)
        });
        assert_eq!(
            m.result,
            Err(Error::Budget {
                model: "m".into(),
                stage: "the mass matrix".into(),
                budget: 10
            })
        );
        assert!(!spent(), "the budget ends with its derivation");
    }

    #[test]
    fn work_within_the_limit_keeps_the_result_and_counts_it() {
        let m = within("m", 10, || {
            charge(4);
            charge(6);
            Ok(1)
        });
        assert_eq!((m.result, m.work), (Ok(1), 10));
        assert!(charge(usize::MAX), "no limit outside a budget");
    }
}
