// The polynomials and the argument reduction of `sin_cos` are fdlibm's (FreeBSD msun k_sin.c,
// k_cos.c, e_rem_pio2.c, as in musl and the Rust `libm` crate 0.2.16), under this notice:
//
// ====================================================
// Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved.
//
// Developed at SunPro, a Sun Microsystems, Inc. business.
// Permission to use, copy, modify, and distribute this
// software is freely granted, provided that this notice
// is preserved.
// ====================================================

/// `(sin x, cos x)` with one shared argument reduction, in place of `f64::sin_cos` (two library
/// calls, two reductions). Written by walker-gen (`FloatFunctions::Inline`).
///
/// Algorithm (fdlibm, see the notice above): for `|x| <= pi/4` the polynomials of
/// `__kernel_sin` (degree 13) and `__kernel_cos` (degree 14), whose approximation error is below
/// `2^-58`, are evaluated directly. For `pi/4 < |x| < 2^20 pi/2` the medium path of
/// `__ieee754_rem_pio2` subtracts `n pi/2`, `n` the nearest integer to `x 2/pi`, with `pi/2`
/// split into 33-bit parts (Cody-Waite; a second and a third part when cancellation needs
/// them) and leaves the remainder as a double-double `y0 + y1`, which the kernels take; `n mod 4`
/// swaps and negates the results (bit operations, no branch). Below `2^-27 sqrt(2)`, `(x, 1)`.
/// Larger `|x|`, infinities and NaN go to `f64::sin_cos` (a cold branch; NaN for infinities and
/// NaN). `sin(-0) = -0`.
///
/// Accuracy, measured by walker-gen's test `fastmath_accuracy` against a double-double oracle
/// over 1.3 million points (`|x| <= 2`, near multiples of `pi/4`, up to `2^20 pi/2`), in ulps
/// of the exact value: sin at most 0.78 (mean 0.25), cos at most 0.76 (mean 0.25); the test
/// asserts at most 1. `sin_cos(-x)` is exactly `(-sin x, cos x)`.
#[inline]
fn sin_cos(x: f64) -> (f64, f64) {
    // __kernel_sin: sin(y) ~ y + S1 y^3 + ... + S6 y^13 on [-pi/4, pi/4].
    const S1: f64 = f64::from_bits(0xBFC5_5555_5555_5549); // -1.66666666666666324348e-01
    const S2: f64 = f64::from_bits(0x3F81_1111_1110_F8A6); // 8.33333333332248946124e-03
    const S3: f64 = f64::from_bits(0xBF2A_01A0_19C1_61D5); // -1.98412698298579493134e-04
    const S4: f64 = f64::from_bits(0x3EC7_1DE3_57B1_FE7D); // 2.75573137070700676789e-06
    const S5: f64 = f64::from_bits(0xBE5A_E5E6_8A2B_9CEB); // -2.50507602534068634195e-08
    const S6: f64 = f64::from_bits(0x3DE5_D93A_5ACF_D57C); // 1.58969099521155010221e-10
    // __kernel_cos: cos(y) ~ 1 - y^2/2 + C1 y^4 + ... + C6 y^14 on [-pi/4, pi/4].
    const C1: f64 = f64::from_bits(0x3FA5_5555_5555_554C); // 4.16666666666666019037e-02
    const C2: f64 = f64::from_bits(0xBF56_C16C_16C1_5177); // -1.38888888888741095749e-03
    const C3: f64 = f64::from_bits(0x3EFA_01A0_19CB_1590); // 2.48015872894767294178e-05
    const C4: f64 = f64::from_bits(0xBE92_7E4F_809C_52AD); // -2.75573143513906633035e-07
    const C5: f64 = f64::from_bits(0x3E21_EE9E_BDB4_B1C4); // 2.08757232129817482790e-09
    const C6: f64 = f64::from_bits(0xBDA8_FAE9_BE88_38D4); // -1.13596475577881948265e-11
    // __ieee754_rem_pio2: 53 bits of 2/pi; pi/2 in 33-bit parts PIO2_k and tails PIO2_kT.
    const INV_PIO2: f64 = f64::from_bits(0x3FE4_5F30_6DC9_C883); // 6.36619772367581382433e-01
    const PIO2_1: f64 = f64::from_bits(0x3FF9_21FB_5440_0000); // 1.57079632673412561417e+00
    const PIO2_1T: f64 = f64::from_bits(0x3DD0_B461_1A62_6331); // 6.07710050650619224932e-11
    const PIO2_2: f64 = f64::from_bits(0x3DD0_B461_1A60_0000); // 6.07710050630396597660e-11
    const PIO2_2T: f64 = f64::from_bits(0x3BA3_198A_2E03_7073); // 2.02226624879595063154e-21
    const PIO2_3: f64 = f64::from_bits(0x3BA3_198A_2E00_0000); // 2.02226624871116645580e-21
    const PIO2_3T: f64 = f64::from_bits(0x397B_839A_2520_49C1); // 8.47842766036889956997e-32
    // 1.5 * 2^52: adding it rounds to an integer, which lands in the low bits of the sum.
    const TO_INT: f64 = f64::from_bits(0x4338_0000_0000_0000);

    /// `__kernel_sin(y0, y1)` and `__kernel_cos(y0, y1)` for `|y0 + y1| <~ pi/4`, sharing `y0^2`.
    #[inline]
    fn kernels(y0: f64, y1: f64) -> (f64, f64) {
        let z = y0 * y0;
        let z2 = z * z;
        let rs = S2 + z * (S3 + z * S4) + z * z2 * (S5 + z * S6);
        let y03 = z * y0;
        let sin = y0 - ((z * (0.5 * y1 - y03 * rs) - y1) - y03 * S1);
        let rc = z * (C1 + z * (C2 + z * C3)) + z2 * z2 * (C4 + z * (C5 + z * C6));
        let hz = 0.5 * z;
        let one_hz = 1.0 - hz;
        let cos = one_hz + (((1.0 - one_hz) - hz) + (z * rc - y0 * y1));
        (sin, cos)
    }

    // The high word of |x|, as fdlibm compares it.
    let hx = (x.to_bits() >> 32) & 0x7fff_ffff;
    if hx <= 0x3fe9_21fb {
        // |x| <~ pi/4: no reduction.
        if hx < 0x3e46_a09e {
            // |x| < 2^-27 sqrt(2): sin x = x and cos x = 1 after rounding (also +-0, subnormals).
            return (x, 1.0);
        }
        return kernels(x, 0.0);
    }
    if hx >= 0x4139_21fb {
        // |x| >~ 2^20 pi/2, infinite or NaN: std's reduction (NaN for infinities and NaN).
        return x.sin_cos();
    }
    // pi/4 <~ |x| <~ 2^20 pi/2: fdlibm's medium reduction.
    let tmp = x * INV_PIO2 + TO_INT;
    let f_n = tmp - TO_INT; // rint(x 2/pi), exact
    let quadrant = tmp.to_bits() & 3; // n mod 4, also for negative n
    let mut r = x - f_n * PIO2_1; // exact: f_n has at most 21 bits, PIO2_1 33
    let mut w = f_n * PIO2_1T; // first round, good to 85 bits
    let mut y0 = r - w;
    let ex = hx >> 20;
    if ex > ((y0.to_bits() >> 52) & 0x7ff) + 16 {
        // Cancellation of more than 16 bits: second round, good to 118 bits.
        let t = r;
        w = f_n * PIO2_2;
        r = t - w;
        w = f_n * PIO2_2T - ((t - r) - w);
        y0 = r - w;
        if ex > ((y0.to_bits() >> 52) & 0x7ff) + 49 {
            // Third round, good to 151 bits, covers all cases.
            let t = r;
            w = f_n * PIO2_3;
            r = t - w;
            w = f_n * PIO2_3T - ((t - r) - w);
            y0 = r - w;
        }
    }
    let (sin, cos) = kernels(y0, (r - y0) - w);
    // Quadrant n mod 4, without branches (unpredictable for spread-out arguments): odd
    // quadrants swap sin and cos; the sign of sin flips with n & 2, that of cos with (n + 1) & 2.
    let (sin, cos) = (sin.to_bits(), cos.to_bits());
    let swap = (quadrant & 1).wrapping_neg() & (sin ^ cos);
    (
        f64::from_bits(sin ^ swap ^ ((quadrant & 2) << 62)),
        f64::from_bits(cos ^ swap ^ (((quadrant + 1) & 2) << 62)),
    )
}
