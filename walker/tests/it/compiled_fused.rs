//! The compiled variants' fused paths against the kernel interface's defaults: every compiled
//! variant (`walker/build.rs`) writes `Kernels::stance_rhs`, `power_sign`, `sliding_lambda` and
//! `tracking` as straight functions of its kernels; the trait's defaults assemble the same
//! quantities from `Kernels::eval` calls. Both do the same floating-point operations in the same order, so they
//! must agree bit for bit (a mismatch is a wrong argument or output slot in the generator, not
//! rounding), at any state, in both contacts and both sliding directions.

#![allow(clippy::panic, reason = "tests")]

use std::path::Path;
use std::sync::{Arc, LazyLock};

use proptest::prelude::*;
use walker::compiled::MODELS;
use walker::model::{Args, Desired, KernelId, Kernels, Ramp, Tracking};
use walker::setup::{Overrides, Setup};
use walker::vector::MAX_COORDINATES;

/// Forwards `has` and `eval` only, so that every other method is the trait's default.
struct Assembled(Arc<dyn Kernels>);

impl Kernels for Assembled {
    fn has(&self, k: KernelId) -> bool {
        self.0.has(k)
    }
    fn eval(&self, k: KernelId, args: &Args<'_>, out: &mut [f64]) {
        self.0.eval(k, args, out);
    }
}

/// One compiled variant: its name, kernels, and the model's `n` and `m`.
struct Case {
    name: String,
    kernels: Arc<dyn Kernels>,
    n: usize,
    m: usize,
}

/// Every variant of every compiled model, prepared at the model file's default parameters.
static CASES: LazyLock<Vec<Case>> = LazyLock::new(|| {
    let mut cases = Vec::new();
    for c in MODELS {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("../models/{}.toml", c.name));
        let setup = Setup::from_model_file(&path, &Overrides::default(), None)
            .unwrap_or_else(|e| panic!("{}: {e}", c.name));
        let spec = setup.walker.spec();
        for (i, v) in c.variants.iter().enumerate() {
            let value = |name: &str| setup.params.get(name).unwrap_or(f64::NAN);
            cases.push(Case {
                name: format!("{} variant {i} ({:?})", c.name, v.friction),
                kernels: (v.prepare)(&value),
                n: spec.n,
                m: spec.inputs,
            });
        }
    }
    cases
});

/// Equal bits, or both NaN (a kernel a variant lacks gives NaN either way).
fn same(a: f64, b: f64) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn the_fused_paths_are_the_assembled_ones_bit_for_bit(
        y in prop::collection::vec(-2.0..2.0f64, 2 * MAX_COORDINATES),
        t in 0.0..0.6f64,
        stuck: bool,
        sliding_back: bool,
        gains in (0.0..200.0f64, 0.0..40.0f64),
    ) {
        let sigma = if sliding_back { -1.0 } else { 1.0 };
        let desired = [Desired::Quintic(Ramp::new(-0.3, 0.25, 0.4)); MAX_COORDINATES];
        for case in CASES.iter() {
            let (n, m) = (case.n, case.m);
            let control = Tracking { desired: &desired[..m], t, gains };
            let y = &y[..2 * n];
            let assembled = Assembled(Arc::clone(&case.kernels));

            let (mut fused, mut reference) = ([0.0; 2 * MAX_COORDINATES], [0.0; 2 * MAX_COORDINATES]);
            let p = case.kernels.stance_rhs(stuck, sigma, y, &control, &mut fused[..2 * n]);
            let q = assembled.stance_rhs(stuck, sigma, y, &control, &mut reference[..2 * n]);
            prop_assert!(same(p, q), "{}: power {p} against {q}", case.name);
            for i in 0..2 * n {
                prop_assert!(
                    same(fused[i], reference[i]),
                    "{}: dy[{i}] = {} against {}", case.name, fused[i], reference[i]
                );
            }

            let (p, q) = (
                case.kernels.power_sign(stuck, sigma, y, &control),
                assembled.power_sign(stuck, sigma, y, &control),
            );
            prop_assert!(same(p, q), "{}: power sign {p} against {q}", case.name);
            let (p, q) = (
                case.kernels.sliding_lambda(sigma, y, &control),
                assembled.sliding_lambda(sigma, y, &control),
            );
            prop_assert!(same(p, q), "{}: lambda {p} against {q}", case.name);

            if m > 0 {
                let args = Args { sigma, ..Args::state(&y[..n], &y[n..]) };
                let k = if stuck { KernelId::ClosedLoopStick } else { KernelId::ClosedLoop };
                let len = n + m + if stuck { 2 } else { 0 };
                let (mut out, mut w) = ([0.0; 3 * MAX_COORDINATES], [0.0; MAX_COORDINATES]);
                let (mut out_ref, mut w_ref) = ([0.0; 3 * MAX_COORDINATES], [0.0; MAX_COORDINATES]);
                case.kernels.tracking(k, &args, &control, &mut out[..len], &mut w[..m]);
                assembled.tracking(k, &args, &control, &mut out_ref[..len], &mut w_ref[..m]);
                for i in 0..len {
                    prop_assert!(same(out[i], out_ref[i]), "{}: tracking out[{i}]", case.name);
                }
                for i in 0..m {
                    prop_assert!(same(w[i], w_ref[i]), "{}: tracking w[{i}]", case.name);
                }
            }
        }
    }
}

#[test]
fn every_compiled_model_is_covered_with_and_without_inputs() {
    assert_eq!(
        CASES.len(),
        MODELS.iter().map(|c| c.variants.len()).sum::<usize>()
    );
    assert!(CASES.iter().any(|c| c.m == 0) && CASES.iter().any(|c| c.m > 0));
}
