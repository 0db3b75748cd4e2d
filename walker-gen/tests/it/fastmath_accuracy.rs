//! Accuracy of the float functions walker-gen writes into generated files
//! (`FloatFunctions::Inline`): `sin_cos` and `tanh`, compiled here from the very
//! files the emitter appends (`src/fastmath/*.rs`, `include!`d below; the test
//! `emitted_text_is_the_tested_text` checks that a rendered file contains them byte for byte).
//!
//! The oracle is independent of the code under test: double-double arithmetic (about 104 bits),
//! `x - n pi/2` as an *exact* floating-point expansion with `pi/2` in 24-bit parts taken from
//! the hexadecimal digits of pi, then Taylor series summed in double-double; `tanh x =
//! e/(e + 2)` with `e = expm1(2|x|)` from a Taylor series at `2|x|/2^k` and `k` doublings
//! `expm1(2a) = e (e + 2)` (no cancellation anywhere). The oracle itself is checked against
//! values computed with mpmath at 300 bits (`oracle_matches_mpmath`).
//!
//! Errors are in ulps of the exact value: `|computed - exact| / ulp(exact)`, with `ulp(v) =
//! 2^(e - 52)` for `2^e <= |v| < 2^(e+1)` (and `2^-1074` below the normal range). A correctly
//! rounded result has at most 0.5.
//!
//! Points come from a seeded generator (SplitMix64), so a failure reproduces; the maximum and
//! mean are printed (`cargo test -p walker-gen --test it fastmath_accuracy:: -- --nocapture`).

use std::path::PathBuf;

// The functions under test, byte for byte as emitted. They are private items of this crate
// root, named `sin_cos` and `tanh` as in a generated file.
include!("../../src/fastmath/sin_cos.rs");
include!("../../src/fastmath/tanh.rs");

const SIN_COS_SOURCE: &str = include_str!("../../src/fastmath/sin_cos.rs");
const TANH_SOURCE: &str = include_str!("../../src/fastmath/tanh.rs");

// ---------------------------------------------------------------------------------------------
// Double-double arithmetic (Dekker, Knuth; no FMA needed).

/// `hi + lo` with `|lo| <= ulp(hi)/2`.
#[derive(Clone, Copy, Debug)]
struct Dd {
    hi: f64,
    lo: f64,
}

/// `a + b = s + e` exactly.
fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// `a + b = s + e` exactly, for `|a| >= |b|` (or `a` zero).
fn quick_two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    (s, b - (s - a))
}

/// Dekker's split: `a = hi + lo` with 26 and 27 significant bits.
fn split(a: f64) -> (f64, f64) {
    let t = 134_217_729.0 * a; // 2^27 + 1
    let hi = t - (t - a);
    (hi, a - hi)
}

/// `a b = p + e` exactly (no overflow, no underflow).
fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let ((ah, al), (bh, bl)) = (split(a), split(b));
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

impl Dd {
    const fn from(v: f64) -> Dd {
        Dd { hi: v, lo: 0.0 }
    }

    fn norm(hi: f64, lo: f64) -> Dd {
        let (hi, lo) = quick_two_sum(hi, lo);
        Dd { hi, lo }
    }

    fn add(self, o: Dd) -> Dd {
        let (s, e) = two_sum(self.hi, o.hi);
        let (t, f) = two_sum(self.lo, o.lo);
        let (s, e) = quick_two_sum(s, e + t);
        Dd::norm(s, e + f)
    }

    fn neg(self) -> Dd {
        Dd {
            hi: -self.hi,
            lo: -self.lo,
        }
    }

    fn sub(self, o: Dd) -> Dd {
        self.add(o.neg())
    }

    fn mul(self, o: Dd) -> Dd {
        let (p, e) = two_prod(self.hi, o.hi);
        Dd::norm(p, e + (self.hi * o.lo + self.lo * o.hi))
    }

    fn mul_f64(self, b: f64) -> Dd {
        let (p, e) = two_prod(self.hi, b);
        Dd::norm(p, e + self.lo * b)
    }

    fn div(self, o: Dd) -> Dd {
        let q1 = self.hi / o.hi;
        let r = self.sub(o.mul_f64(q1));
        let q2 = r.hi / o.hi;
        let r = r.sub(o.mul_f64(q2));
        let q3 = r.hi / o.hi;
        Dd::norm(q1, q2).add(Dd::from(q3))
    }

    fn div_f64(self, b: f64) -> Dd {
        self.div(Dd::from(b))
    }
}

// ---------------------------------------------------------------------------------------------
// The oracle.

/// The first 576 bits of the fraction of pi, in hexadecimal (the words are also Blowfish's
/// P-array; checked against mpmath).
const PI_FRACTION_HEX: [u32; 18] = [
    0x243F_6A88,
    0x85A3_08D3,
    0x1319_8A2E,
    0x0370_7344,
    0xA409_3822,
    0x299F_31D0,
    0x082E_FA98,
    0xEC4E_6C89,
    0x4528_21E6,
    0x38D0_1377,
    0xBE54_66CF,
    0x34E9_0C6C,
    0xC0AC_29B7,
    0xC97C_50DD,
    0x3F84_D5B5,
    0xB547_0917,
    0x9216_D5D9,
    0x8979_FB1B,
];

/// `pi/2` as a sum of doubles of at most 24 significant bits each (so that `n * part` is exact
/// for `|n| < 2^29`): 16 parts, `pi/2` to about `2^-383`.
fn pio2_parts() -> Vec<f64> {
    // The bits of pi/2 = 1.1001..., integer bit first: pi = 11.0010..., shifted by one.
    let mut bits: Vec<u8> = vec![1, 1];
    for w in PI_FRACTION_HEX {
        bits.extend((0..32).rev().map(|i| u8::from((w >> i) & 1 == 1)));
    }
    bits.chunks_exact(24)
        .take(16)
        .enumerate()
        .map(|(k, chunk)| {
            let m = chunk.iter().fold(0_u32, |m, &b| 2 * m + u32::from(b));
            // The chunk's first bit has weight 2^-(24 k).
            let exp = -(24 * i32::try_from(k).unwrap_or(0)) - 23;
            f64::from(m) * 2f64.powi(exp)
        })
        .collect()
}

/// Adds `b` to the nonoverlapping expansion `e` (increasing magnitude), exactly (Shewchuk's
/// Grow-Expansion).
fn grow_expansion(e: &mut Vec<f64>, b: f64) {
    let mut q = b;
    for c in e.iter_mut() {
        let (s, err) = two_sum(q, *c);
        *c = err;
        q = s;
    }
    e.push(q);
}

/// `x - n pi/2` as a double-double, `n` the integer nearest to `x 2/pi` (give or take one:
/// the series below converge on any `|r| < 1`), and `n mod 4`. Exact up to the final rounding
/// to double-double for `|x| < 2^29`.
fn reduce(x: f64, parts: &[f64]) -> (Dd, u32) {
    let n = (x / std::f64::consts::FRAC_PI_2).round();
    assert!(
        n.abs() < 2f64.powi(29),
        "the oracle reduces |x| < 2^29 only"
    );
    let mut e = vec![x];
    for &p in parts {
        grow_expansion(&mut e, -(n * p)); // exact: 24 + 29 bits
    }
    // Sum from the smallest component up: double-double rounding of an exact value.
    let r = e.iter().fold(Dd::from(0.0), |acc, &c| acc.add(Dd::from(c)));
    let quadrant = (n as i64).rem_euclid(4) as u32;
    (r, quadrant)
}

/// `(sin x, cos x)` in double-double, for `|x| < 2^29`.
fn oracle_sin_cos(x: f64, parts: &[f64]) -> (Dd, Dd) {
    let (r, quadrant) = reduce(x, parts);
    let r2 = r.mul(r);
    let (mut sin, mut term) = (r, r);
    for k in 1..60 {
        let k = f64::from(k);
        term = term.mul(r2).div_f64(-(2.0 * k) * (2.0 * k + 1.0));
        sin = sin.add(term);
        if term.hi.abs() <= sin.hi.abs() * 1e-40 {
            break;
        }
    }
    let (mut cos, mut term) = (Dd::from(1.0), Dd::from(1.0));
    for k in 1..60 {
        let k = f64::from(k);
        term = term.mul(r2).div_f64(-(2.0 * k - 1.0) * (2.0 * k));
        cos = cos.add(term);
        if term.hi.abs() <= 1e-40 {
            break;
        }
    }
    match quadrant {
        0 => (sin, cos),
        1 => (cos, sin.neg()),
        2 => (sin.neg(), cos.neg()),
        _ => (cos.neg(), sin),
    }
}

/// `tanh x` in double-double, for `|x| <= 300`.
fn oracle_tanh(x: f64) -> Dd {
    let y = 2.0 * x.abs();
    assert!(y <= 600.0, "the oracle takes |x| <= 300");
    // expm1(y) = expm1(a)(expm1(a) + 2) ... with a = y / 2^k <= 1/16, exact scaling.
    let (mut a, mut k) = (y, 0);
    while a > 0.0625 {
        a *= 0.5;
        k += 1;
    }
    let (mut em1, mut term) = (Dd::from(a), Dd::from(a));
    for j in 2..60 {
        term = term.mul_f64(a).div_f64(f64::from(j));
        em1 = em1.add(term);
        if term.hi <= em1.hi * 1e-40 {
            break;
        }
    }
    for _ in 0..k {
        em1 = em1.mul(em1.add(Dd::from(2.0)));
    }
    let t = em1.div(em1.add(Dd::from(2.0)));
    if x < 0.0 { t.neg() } else { t }
}

/// `|got - exact|` in ulps of `exact`.
fn ulps(got: f64, exact: Dd) -> f64 {
    let (s, e) = two_sum(exact.hi, -got);
    let diff = s + (e + exact.lo);
    let mag = exact.hi.abs();
    if mag < f64::MIN_POSITIVE {
        return diff.abs() / 2f64.powi(-1074);
    }
    let bits = mag.to_bits();
    let mut exp = i32::try_from(bits >> 52).unwrap_or(0) - 1023;
    // Just below a power of two, hi may have rounded up to it.
    if bits & ((1 << 52) - 1) == 0 && exact.lo != 0.0 && (exact.lo < 0.0) == (exact.hi > 0.0) {
        exp -= 1;
    }
    diff.abs() / 2f64.powi(exp - 52)
}

// ---------------------------------------------------------------------------------------------
// Points.

/// SplitMix64.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[0, 1)`.
    fn unit(&mut self) -> f64 {
        let m = (self.next_u64() >> 11) as f64;
        m * 2f64.powi(-53)
    }

    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// `|x|` log-uniform in `[lo, hi)`, random sign.
    fn log_uniform_signed(&mut self, lo: f64, hi: f64) -> f64 {
        let v = (lo.ln() + (hi.ln() - lo.ln()) * self.unit()).exp();
        if self.next_u64() & 1 == 0 { v } else { -v }
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n
    }
}

/// `x` moved by `k` units in the last place (`k` may be negative), through the bits.
fn step_ulps(x: f64, k: i64) -> f64 {
    let mut v = x;
    for _ in 0..k.unsigned_abs() {
        v = if k > 0 { v.next_up() } else { v.next_down() };
    }
    v
}

/// Maximum and mean of a stream of errors, with the argument of the maximum.
#[derive(Default)]
struct Stat {
    max: f64,
    arg: f64,
    sum: f64,
    n: u64,
}

impl Stat {
    fn add(&mut self, err: f64, x: f64) {
        if err > self.max || err.is_nan() {
            self.max = err;
            self.arg = x;
        }
        self.sum += err;
        self.n += 1;
    }

    fn mean(&self) -> f64 {
        let n = self.n as f64;
        self.sum / n
    }
}

/// The sin_cos test points: `|x| <= 2` uniformly, the neighbourhoods of `k pi/4`, the medium
/// range up to `2^20 pi/2` (with the doubles nearest to `n pi/2`, the worst cancellations).
fn sin_cos_points() -> Vec<f64> {
    let mut rng = Rng(0x5EED_0001);
    let mut xs: Vec<f64> = (0..1_000_000).map(|_| rng.uniform(-2.0, 2.0)).collect();
    for k in -8_i32..=8 {
        let centre = f64::from(k) * std::f64::consts::FRAC_PI_4;
        for m in -200..=200 {
            xs.push(step_ulps(centre, m));
        }
        for _ in 0..5_000 {
            // Offsets 2^-1 ... 2^-52 relative, both signs.
            let j = i32::try_from(rng.below(52)).unwrap_or(0) + 1;
            let off = rng.uniform(-1.0, 1.0) * 2f64.powi(-j);
            xs.push(if k == 0 { off } else { centre * (1.0 + off) });
        }
    }
    let top = 2f64.powi(20) * std::f64::consts::FRAC_PI_2;
    for _ in 0..200_000 {
        xs.push(rng.log_uniform_signed(2.0, top));
    }
    for _ in 0..20_000 {
        let n = (rng.below(1 << 20) + 1) as f64;
        let centre = n * std::f64::consts::FRAC_PI_2;
        let m = i64::try_from(rng.below(7)).unwrap_or(0) - 3;
        let x = step_ulps(centre, m);
        if x.abs() < top {
            xs.push(if rng.next_u64() & 1 == 0 { x } else { -x });
        }
    }
    xs
}

/// The tanh test points: `|x| <= 30` uniformly, dense near 0, near the switch at 0.625 and near
/// 22, both signs.
fn tanh_points() -> Vec<f64> {
    let mut rng = Rng(0x5EED_0002);
    let mut xs: Vec<f64> = Vec::new();
    xs.extend((0..300_000).map(|_| rng.uniform(-30.0, 30.0)));
    xs.extend((0..300_000).map(|_| rng.log_uniform_signed(2f64.powi(-30), 0.625)));
    xs.extend(
        (0..200_000).map(|_| rng.uniform(0.5, 0.75) * if rng.below(2) == 0 { 1.0 } else { -1.0 }),
    );
    xs.extend((0..100_000).map(|_| rng.uniform(0.625, 5.0)));
    xs.extend((0..100_000).map(|_| rng.uniform(21.0, 23.0)));
    for centre in [0.625, 22.0, 2f64.powi(-27)] {
        for m in -2_000..=2_000 {
            let x = step_ulps(centre, m);
            xs.push(x);
            xs.push(-x);
        }
    }
    xs
}

// ---------------------------------------------------------------------------------------------
// Tests.

#[test]
fn oracle_matches_mpmath() {
    use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, FRAC_PI_4, PI, TAU};
    type Pair = (f64, f64);
    // x, (sin hi, lo), (cos hi, lo): mpmath 1.3.0 at 300 bits, rounded to double-double.
    const SIN_COS: [(f64, Pair, Pair); 14] = [
        (
            1.0,
            (0.8414709848078965, 1.776845092935536e-18),
            (0.5403023058681398, -4.760954612604417e-17),
        ),
        (
            0.5,
            (0.479425538604203, -5.103969860556013e-18),
            (0.8775825618903728, -4.2623149864279997e-17),
        ),
        (
            1e-05,
            (9.999999999833334e-06, 6.182336062862823e-22),
            (0.99999999995, 4.137435208440879e-18),
        ),
        (
            2.0,
            (0.9092974268256817, -1.4020906557816256e-17),
            (-0.4161468365471424, 1.990596398957495e-17),
        ),
        (
            FRAC_PI_2,
            (1.0, -1.874699728327322e-33),
            (6.123233995736766e-17, -1.4973849048591698e-33),
        ),
        (
            PI,
            (1.2246467991473532e-16, -2.99476980971834e-33),
            (-1.0, 7.498798913309288e-33),
        ),
        (
            FRAC_PI_4,
            (0.7071067811865475, 4.1036934489363755e-17),
            (FRAC_1_SQRT_2, -2.6687565161377232e-17),
        ),
        (
            -0.8,
            (-0.7173560908995228, -1.1851419720716684e-18),
            (0.6967067093471654, 1.9275818349860986e-18),
        ),
        (
            100.0,
            (-0.5063656411097588, -3.050947053792115e-18),
            (0.8623188722876839, 4.334809858136501e-17),
        ),
        (
            100000.0,
            (0.03574879797201651, 1.5429743706109861e-18),
            (-0.9993608074382124, -2.3447088905187402e-17),
        ),
        (
            1647099.3291652855,
            (-6.420676210313675e-11, 1.570165989482554e-27),
            (1.0, -2.0612541498843988e-21),
        ),
        (
            1647099.0,
            (-0.3232532403530771, -1.0971673396794272e-17),
            (0.9463124973290988, 3.103352546403623e-17),
        ),
        (
            TAU,
            (-2.4492935982947064e-16, 5.9895396194366814e-33),
            (1.0, -2.999519565323715e-32),
        ),
        (
            4.71238898038469,
            (-1.0, 1.6872297554945898e-32),
            (-1.8369701987210297e-16, -7.833796929500799e-33),
        ),
    ];
    const TANH: [(f64, Pair); 9] = [
        (1e-10, (1e-10, -3.3333333333333338e-31)),
        (0.3, (0.2913126124515909, -6.4602656586469586e-18)),
        (0.55, (0.5005202111902353, -2.2927568355840214e-17)),
        (0.625, (0.5545997223493823, 3.145617845100655e-17)),
        (1.0, (0.7615941559557649, 3.7090214482164924e-17)),
        (5.0, (0.9999092042625951, 2.298523750966507e-17)),
        (19.0, (0.9999999999999999, 4.823964662155506e-17)),
        (22.0, (1.0, -1.5562264482267593e-19)),
        (
            9.313225746154785e-10,
            (9.313225746154785e-10, -2.692645223154387e-28),
        ),
    ];
    // Relative agreement to 2^-95: far below the 2^-53 scale of the errors measured.
    let close = |got: Dd, want: (f64, f64), what: &str| {
        let d = got.sub(Dd {
            hi: want.0,
            lo: want.1,
        });
        assert!(
            d.hi.abs() <= want.0.abs() * 2f64.powi(-95),
            "{what}: oracle {got:?}, mpmath {want:?}"
        );
    };
    let parts = pio2_parts();
    let sum = parts
        .iter()
        .rev()
        .fold(Dd::from(0.0), |acc, &p| acc.add(Dd::from(p)));
    assert_eq!(
        sum.hi,
        std::f64::consts::FRAC_PI_2,
        "pi/2 from the hex digits"
    );
    for (x, s, c) in SIN_COS {
        let (os, oc) = oracle_sin_cos(x, &parts);
        close(os, s, &format!("sin({x:?})"));
        close(oc, c, &format!("cos({x:?})"));
        let (ns, nc) = oracle_sin_cos(-x, &parts);
        close(ns, (-s.0, -s.1), &format!("sin({:?})", -x));
        close(nc, c, &format!("cos({:?})", -x));
    }
    for (x, t) in TANH {
        close(oracle_tanh(x), t, &format!("tanh({x:?})"));
        close(oracle_tanh(-x), (-t.0, -t.1), &format!("tanh({:?})", -x));
    }
}

/// The measure is not blind: results one ulp off a correctly rounded value are reported as such.
#[test]
fn the_measure_can_fail() {
    let parts = pio2_parts();
    let mut rng = Rng(7);
    for _ in 0..1000 {
        let x = rng.uniform(-2.0, 2.0);
        let (s, _) = oracle_sin_cos(x, &parts);
        let rounded = s.hi; // correctly rounded (the lo part is below half an ulp)
        assert!(ulps(rounded, s) <= 0.5 + 1e-9);
        let off = if rng.below(2) == 0 {
            step_ulps(rounded, 2)
        } else {
            step_ulps(rounded, -2)
        };
        assert!(
            ulps(off, s) > 1.0,
            "{x:?}: two ulps off measured {}",
            ulps(off, s)
        );
        let t = oracle_tanh(x * 10.0);
        assert!(ulps(step_ulps(t.hi, 3), t) > 2.0, "tanh({:?})", x * 10.0);
    }
}

#[test]
fn sin_cos_is_within_one_ulp() {
    // Bound: fdlibm's kernels are documented (and here measured) below 1 ulp. The reduction is
    // good to 85 bits, or 118 and 151 when cancellation triggers the refinement steps, so it
    // adds far less than 2^-53 relative; the polynomial error is below 2^-58; the final
    // additions `y0 - (...)` and `w + (...)` round once (0.5 ulp) onto a value whose other terms
    // are at most about y0/6 and y0^2/2 in size, so their few roundings add under 0.4 ulp.
    const BOUND: f64 = 1.0;
    let parts = pio2_parts();
    let xs = sin_cos_points();
    let (mut sin_in, mut cos_in, mut sin_std, mut cos_std) = (
        Stat::default(),
        Stat::default(),
        Stat::default(),
        Stat::default(),
    );
    for &x in &xs {
        let (os, oc) = oracle_sin_cos(x, &parts);
        let (s, c) = sin_cos(x);
        sin_in.add(ulps(s, os), x);
        cos_in.add(ulps(c, oc), x);
        let (s_std, c_std) = x.sin_cos();
        sin_std.add(ulps(s_std, os), x);
        cos_std.add(ulps(c_std, oc), x);
        // Exact symmetry: every step of the reduction and the kernels is odd or even.
        let (ns, nc) = sin_cos(-x);
        assert!(
            ns.to_bits() == (-s).to_bits() && nc.to_bits() == c.to_bits(),
            "sin_cos({x:?}) = ({s:?}, {c:?}) but sin_cos(-x) = ({ns:?}, {nc:?})"
        );
    }
    println!(
        "sin_cos over {} points (|x| <= 2, near k pi/4, up to 2^20 pi/2):\n  \
         inline sin: max {:.3} ulp at x = {:?}, mean {:.4}\n  \
         inline cos: max {:.3} ulp at x = {:?}, mean {:.4}\n  \
         std sin:    max {:.3} ulp, mean {:.4}\n  std cos:    max {:.3} ulp, mean {:.4}",
        xs.len(),
        sin_in.max,
        sin_in.arg,
        sin_in.mean(),
        cos_in.max,
        cos_in.arg,
        cos_in.mean(),
        sin_std.max,
        sin_std.mean(),
        cos_std.max,
        cos_std.mean()
    );
    assert!(xs.len() >= 1_000_000);
    assert!(
        sin_in.max <= BOUND,
        "sin: {} ulp at x = {:?}",
        sin_in.max,
        sin_in.arg
    );
    assert!(
        cos_in.max <= BOUND,
        "cos: {} ulp at x = {:?}",
        cos_in.max,
        cos_in.arg
    );
}

#[test]
fn sin_cos_special_values() {
    let same = |a: (f64, f64), b: (f64, f64)| {
        a.0.to_bits() == b.0.to_bits() && a.1.to_bits() == b.1.to_bits()
    };
    assert!(same(sin_cos(0.0), (0.0, 1.0)));
    assert!(same(sin_cos(-0.0), (-0.0, 1.0)), "sin(-0) must be -0");
    // Tiny and subnormal: sin x = x, cos x = 1 (the correctly rounded values).
    let mut rng = Rng(11);
    for _ in 0..10_000 {
        let x = rng.log_uniform_signed(f64::from_bits(1), 2f64.powi(-27));
        assert!(
            same(sin_cos(x), (x, 1.0)),
            "sin_cos({x:?}) = {:?}",
            sin_cos(x)
        );
    }
    for x in [
        f64::from_bits(1),
        -f64::from_bits(1),
        f64::MIN_POSITIVE,
        -f64::MIN_POSITIVE,
    ] {
        assert!(same(sin_cos(x), (x, 1.0)), "sin_cos({x:?})");
    }
    for x in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let (s, c) = sin_cos(x);
        assert!(s.is_nan() && c.is_nan(), "sin_cos({x:?}) = ({s:?}, {c:?})");
    }
    // Above 2^20 pi/2 the cold branch is std's sin_cos, exactly.
    let top = f64::from_bits(0x4139_21FB_0000_0000);
    let mut huge = vec![top, -top, 1e7, 1e22, 1e300, f64::MAX, -f64::MAX];
    for _ in 0..10_000 {
        huge.push(rng.log_uniform_signed(top, 1e300));
    }
    for x in huge {
        assert!(same(sin_cos(x), x.sin_cos()), "sin_cos({x:?})");
    }
    // The branch boundaries, both sides, against the oracle.
    let parts = pio2_parts();
    for hi in [0x3E46_A09E_u64, 0x3FE9_21FB, 0x3FE9_21FC, 0x4139_21FA] {
        for x in [f64::from_bits(hi << 32), f64::from_bits((hi << 32) - 1)] {
            let (os, oc) = oracle_sin_cos(x, &parts);
            let (s, c) = sin_cos(x);
            assert!(ulps(s, os) <= 1.0 && ulps(c, oc) <= 1.0, "sin_cos({x:?})");
        }
    }
}

#[test]
fn tanh_is_within_two_ulps() {
    // Bound, |x| < 0.625: x is exact and the correction x z P/Q is at most 0.12 x; its relative
    // error (Cephes' fit, about 2e-17, plus about six roundings) is under 8 u, so it adds at most
    // about 0.12 * 8 * 0.625 = 0.6 ulp (results in [0.5, 0.56) have ulp 2^-53; below 0.5 the
    // correction is smaller in proportion) to the final rounding of 0.5 ulp: about 1.1 ulp.
    // 0.625 <= |x| <= 22: t = 2/(exp(2|x|) + 1) <= 0.446 carries exp's error (glibc: under one
    // ulp) and two roundings, relative at most 3 u, so absolute 1.34 * 2^-53 next to a result in
    // [0.55, 1) whose ulp is 2^-53; with the final rounding at most 1.84 ulp. Hence 2.
    const BOUND: f64 = 2.0;
    let xs = tanh_points();
    let (mut small, mut large, mut std_stat) = (Stat::default(), Stat::default(), Stat::default());
    for &x in &xs {
        let exact = oracle_tanh(x);
        let t = tanh(x);
        if x.abs() < 0.625 {
            small.add(ulps(t, exact), x);
        } else {
            large.add(ulps(t, exact), x);
        }
        std_stat.add(ulps(x.tanh(), exact), x);
        assert_eq!(
            tanh(-x).to_bits(),
            (-t).to_bits(),
            "tanh(-x) != -tanh(x) at {x:?}"
        );
        if x.abs() > 22.0 {
            assert_eq!(t, 1.0_f64.copysign(x), "tanh({x:?}) must be exactly +-1");
        }
    }
    let all = small.n + large.n;
    println!(
        "tanh over {all} points (|x| <= 30; near 0, 0.625, 22):\n  \
         inline, |x| < 0.625 (rational): max {:.3} ulp at x = {:?}, mean {:.4} ({} points)\n  \
         inline, |x| >= 0.625 (exp):     max {:.3} ulp at x = {:?}, mean {:.4} ({} points)\n  \
         std:                            max {:.3} ulp at x = {:?}, mean {:.4}",
        small.max,
        small.arg,
        small.mean(),
        small.n,
        large.max,
        large.arg,
        large.mean(),
        large.n,
        std_stat.max,
        std_stat.arg,
        std_stat.mean()
    );
    assert!(all >= 1_000_000);
    assert!(
        small.max <= BOUND,
        "tanh: {} ulp at x = {:?}",
        small.max,
        small.arg
    );
    assert!(
        large.max <= BOUND,
        "tanh: {} ulp at x = {:?}",
        large.max,
        large.arg
    );
}

#[test]
fn tanh_special_values() {
    assert_eq!(tanh(0.0).to_bits(), 0.0_f64.to_bits());
    assert_eq!(
        tanh(-0.0).to_bits(),
        (-0.0_f64).to_bits(),
        "tanh(-0) must be -0"
    );
    assert!(tanh(f64::NAN).is_nan());
    assert!(tanh(-f64::NAN).is_nan());
    for (x, t) in [
        (f64::INFINITY, 1.0),
        (f64::NEG_INFINITY, -1.0),
        (f64::MAX, 1.0),
        (-f64::MAX, -1.0),
        (22.0_f64.next_up(), 1.0),
        (-(22.0_f64.next_up()), -1.0),
        (1e300, 1.0),
    ] {
        assert_eq!(tanh(x), t, "tanh({x:?})");
    }
    // Tiny and subnormal: tanh x = x (x^3/3 is below half an ulp).
    let mut rng = Rng(13);
    for _ in 0..10_000 {
        let x = rng.log_uniform_signed(f64::from_bits(1), 2f64.powi(-27));
        assert_eq!(tanh(x).to_bits(), x.to_bits(), "tanh({x:?})");
    }
    for x in [f64::from_bits(1), -f64::from_bits(1), f64::MIN_POSITIVE] {
        assert_eq!(tanh(x).to_bits(), x.to_bits(), "tanh({x:?})");
    }
}

/// A rendered file carries exactly the source tested above, and only what its kernels call.
#[test]
fn emitted_text_is_the_tested_text() {
    use walker_gen::{Config, Float, FloatFunctions};
    let scene = |name: &str| {
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../walker/scenes")
            .join(format!("{name}.toml"))
    };
    let render = |name: &str, f: &dyn Fn(&mut Config)| {
        let mut config = Config::new();
        config.scene_file(scene(name));
        f(&mut config);
        config.render().expect("the scene renders")
    };
    // Both functions, verbatim, once each, at the end.
    let src = render("active-level", &|_| {});
    assert_eq!(src.matches(SIN_COS_SOURCE).count(), 1);
    assert_eq!(src.matches(TANH_SOURCE).count(), 1);
    assert!(src.ends_with(TANH_SOURCE));
    assert!(src.contains("sin_cos(th1)") && src.contains("tanh(p.c * xd)"));
    // std's methods remain only in sin_cos's cold branch for huge arguments.
    assert_eq!(src.matches(".sin_cos()").count(), 1);
    assert_eq!(src.matches(".tanh()").count(), 0);
    // No friction: no tanh anywhere.
    let src = render("active-level-frictionless", &|_| {});
    assert!(src.contains(SIN_COS_SOURCE));
    assert!(
        !src.contains("tanh"),
        "a file without tanh must not contain fn tanh"
    );
    // Std, f32 and no-std: neither function.
    for (what, src) in [
        (
            "std",
            render("active-level", &|c| {
                c.float_functions(FloatFunctions::Std);
            }),
        ),
        (
            "f32",
            render("active-level", &|c| {
                c.float(Float::F32);
            }),
        ),
        (
            "no_std",
            render("active-level", &|c| {
                c.no_std(true);
            }),
        ),
    ] {
        assert!(
            !src.contains("fn sin_cos(") && !src.contains("fn tanh("),
            "{what}"
        );
        assert!(!src.contains("SunPro"), "{what}");
    }
}

/// The helper files are formatted as `rustfmt` would (they are appended verbatim).
#[test]
fn helper_sources_are_rustfmt_clean() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("src/fastmath");
    let out = std::process::Command::new("rustfmt")
        .args(["--check", "--edition", "2024"])
        .arg(dir.join("sin_cos.rs"))
        .arg(dir.join("tanh.rs"))
        .output()
        .expect("this test needs rustfmt (`rustup component add rustfmt`)");
    assert!(
        out.status.success(),
        "rustfmt --check src/fastmath/*.rs:\n{}",
        String::from_utf8_lossy(&out.stdout)
    );
    for (name, src) in [("sin_cos", SIN_COS_SOURCE), ("tanh", TANH_SOURCE)] {
        assert!(
            src.lines().all(|l| l.len() <= 100 && l.trim_end() == l),
            "{name}"
        );
    }
}
