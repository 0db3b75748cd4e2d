//! Helpers shared by the derivation's test files (`paper.rs`, `stick.rs`).

#![allow(dead_code, reason = "each test file uses a subset")]

use std::sync::OnceLock;

use walker_symbolic::paper::{cos, sin, sym};
use walker_symbolic::{Derivation, RatFunc, Sym};

/// The derivation, made once per test binary.
pub fn derivation() -> &'static Derivation {
    static D: OnceLock<Derivation> = OnceLock::new();
    D.get_or_init(|| Derivation::new().expect("the derivation succeeds"))
}

/// Output `name` of kernel `kernel`.
pub fn out(kernel: &str, name: &str) -> RatFunc {
    derivation()
        .kernel(kernel)
        .expect("kernel exists")
        .output(name)
        .expect("the kernel has this output")
        .clone()
}

/// A symbol as a rational function.
pub fn s(x: Sym) -> RatFunc {
    sym(x)
}

/// `sin x` of an angle symbol.
pub fn sin1(x: Sym) -> RatFunc {
    sin(&[(x, 1)]).expect("angle")
}

/// `cos x` of an angle symbol.
pub fn cos1(x: Sym) -> RatFunc {
    cos(&[(x, 1)]).expect("angle")
}

/// `a / b`.
pub fn div(a: &RatFunc, b: &RatFunc) -> RatFunc {
    a.div(b).expect("nonzero divisor")
}

/// A deterministic pseudo-random generator (SplitMix64): no dependency, same points each run.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }

    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}
