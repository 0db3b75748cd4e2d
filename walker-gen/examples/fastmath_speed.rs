//! Speed of the inline float functions walker-gen writes into generated files
//! (`FloatFunctions::Inline`) against std's, on the same seeded inputs in one run.
//!
//! ```text
//! cargo run -p walker-gen --release --example fastmath_speed
//! ```
//!
//! For each input set (1024 seeded points) and each candidate, one timed pass evaluates every
//! point 64 times into an output array (independent calls: throughput, as in a kernel where
//! `sin_cos` and `tanh` do not depend on each other); the candidates of a set are interleaved
//! round by round, and the median over 41 rounds is printed in ns per call.

use std::hint::black_box;
use std::time::Instant;

// The functions exactly as emitted.
include!("../src/fastmath/sin_cos.rs");
include!("../src/fastmath/tanh.rs");

const POINTS: usize = 1024;
const REPS: usize = 64;
const ROUNDS: usize = 41;

/// SplitMix64, uniform in `[lo, hi)`.
fn points(seed: u64, lo: f64, hi: f64) -> Vec<f64> {
    let mut state = seed;
    (0..POINTS)
        .map(|_| {
            state = state.wrapping_add(0x9E37_79B9_7F4A_7C15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
            z ^= z >> 31;
            let unit = (z >> 11) as f64 * 2f64.powi(-53);
            lo + (hi - lo) * unit
        })
        .collect()
}

/// ns per call of one pass of `f` over `xs`, `REPS` times (generic, so `f` is inlined as in a
/// generated kernel).
fn pass<T: Copy, F: Fn(f64) -> T>(xs: &[f64], out: &mut [T], f: &F) -> f64 {
    let start = Instant::now();
    for _ in 0..REPS {
        for (o, &x) in out.iter_mut().zip(black_box(xs)) {
            *o = f(x);
        }
        black_box(&mut *out);
    }
    start.elapsed().as_secs_f64() * 1e9 / (REPS * xs.len()) as f64
}

fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// Interleaved rounds of std's function and the inline one on `xs`; prints a row for each.
fn compare<T: Copy + Default, S: Fn(f64) -> T, I: Fn(f64) -> T>(
    set: &str,
    xs: &[f64],
    (std_name, std_f): (&str, S),
    (inline_name, inline_f): (&str, I),
) {
    let mut out = vec![T::default(); xs.len()];
    let (mut std_t, mut inline_t) = (Vec::new(), Vec::new());
    pass(xs, &mut out, &std_f); // warm-up
    pass(xs, &mut out, &inline_f);
    for _ in 0..ROUNDS {
        std_t.push(pass(xs, &mut out, &std_f));
        inline_t.push(pass(xs, &mut out, &inline_f));
    }
    let (s, i) = (median(std_t), median(inline_t));
    println!("| {set} | {std_name} | {s:.2} | 1.00x |");
    println!("| {set} | {inline_name} | {i:.2} | {:.2}x |", s / i);
}

fn main() {
    println!(
        "# ns per call, median of {ROUNDS} interleaved rounds, {POINTS} seeded points x {REPS}"
    );
    println!("| inputs | candidate | ns/call | std / this |");
    println!("|---|---|---:|---:|");
    for (set, lo, hi, seed) in [
        ("sin_cos, |x| <= pi/4 (no reduction)", -0.78, 0.78, 1),
        ("sin_cos, |x| <= 2", -2.0, 2.0, 2),
        ("sin_cos, 2 <= x <= 100", 2.0, 100.0, 3),
    ] {
        let xs = points(seed, lo, hi);
        compare(
            set,
            &xs,
            ("std x.sin_cos()", |x: f64| x.sin_cos()),
            ("inline sin_cos(x)", sin_cos),
        );
    }
    for (set, lo, hi, seed) in [
        ("tanh, |x| < 0.625 (rational)", -0.62, 0.62, 4),
        ("tanh, 0.625 <= x <= 5 (exp)", 0.625, 5.0, 5),
        ("tanh, |x| <= 3 (both branches)", -3.0, 3.0, 6),
    ] {
        let xs = points(seed, lo, hi);
        compare(
            set,
            &xs,
            ("std x.tanh()", |x: f64| x.tanh()),
            ("inline tanh(x)", tanh),
        );
    }
}
