//! A blown-up ground reaction is named for its cause (issue 21): `lambda-denominator-zero` only
//! where the denominator of Eq. 23 vanishes, `lambda-numerator-huge` where it is regular and the
//! control input or the spin is huge. The denominator is computed here by hand from the printed
//! Eq. 23 (`docs/equations.md`, `lambda_level`), not from the kernels the simulator reads.
#![allow(clippy::panic, reason = "tests report failures by panicking")]

use crate::common;

use common::{start, table1, table1_total_mass};
use walker::model::{Contact, FrictionLaw, Model, Slide};
use walker::sim::{Failure, FailureKind, SimConfig, WalkLimits, walk};

/// At most two steps and one second of walking (as the CLI's fuzz test runs them).
fn limits() -> WalkLimits {
    WalkLimits {
        max_steps: 2,
        duration: 1.0,
        ..WalkLimits::default()
    }
}

/// The denominator of Eq. 23 on level ground with Table 1, `I1 + m_t l^2 (sin th1 - mu cos th1)
/// sin th1`, at the friction coefficient `mu`.
fn denominator(th1: f64, mu: f64) -> f64 {
    let l = table1("l");
    let (s, c) = th1.sin_cos();
    table1("I1") + table1_total_mass() * l * l * (s - mu * c) * s
}

/// The body weight `m_t g` of Table 1.
fn weight() -> f64 {
    table1_total_mass() * table1("g")
}

/// The walk's failure, or a test failure naming `what`.
fn failure_of(model: &Model, start: &[f64], what: &str) -> Failure {
    let w = walk(model, &SimConfig::default(), start, &limits());
    w.failure
        .unwrap_or_else(|| panic!("{what}: {} steps and no failure", w.steps.len()))
}

/// Ramps from `1e-4` down to `1e-100` s make `ydd_d = 60 alpha / T_set^2` and with it the
/// control input huge but finite (shorter ones overflow the kernels: `non-finite`,
/// `sim_extreme.rs`). With `mu0 = 0.4` the denominator of Eq. 23 has no zero at any angle
/// (`|mu| >= 0.882` is needed, `docs/stability.md`): it is at least `I1 - m_t l^2 (sqrt(1 +
/// mu0^2) - 1) / 2 = 0.384` (the minimum over `th1` of `sin^2 - mu0 |sin cos|` is `(1 -
/// sqrt(1 + mu0^2)) / 2`). So the blow-up is the numerator's, for the smooth law with Table 1
/// compiled in or at run time and for Coulomb friction alike. These were
/// `lambda-denominator-zero`.
#[test]
fn a_huge_control_input_is_a_huge_numerator_not_a_pole() {
    let mu0 = 0.4;
    for t_set in [1e-4, 1e-5, 1e-8, 1e-20, 1e-50, 1e-100] {
        let rt = [("mu0", mu0), ("T_set", t_set)];
        for model in [
            common::active(&rt),
            common::active_run_time(&rt),
            common::active_coulomb(&rt),
        ] {
            let what = format!("T_set = {t_set:e}, {:?}", model.friction_law());
            let f = failure_of(&model, &start(&model, 0.8), &what);
            let FailureKind::LambdaNumeratorHuge { lambda, u } = f.kind else {
                panic!("{what}: {f:?}");
            };
            // The guard `LambdaBlowUp` ends the stance phase where `|lambda|` rises through the
            // threshold `1e6 m_t g` (located to a few ulps).
            let threshold = 1e6 * weight();
            assert!(
                (lambda.abs() / threshold - 1.0).abs() < 1e-9,
                "{what}: {f:?}"
            );
            assert!(u.is_finite(), "{what}: {f:?}");
            let (th1, th1d) = (f.state[2], f.state[6]);
            let d_min = denominator(th1, mu0).min(denominator(th1, -mu0));
            assert!(d_min >= 0.384, "{what}: D = {d_min} at {f:?}");
            let smooth = model.friction_law() == FrictionLaw::Tanh;
            if smooth {
                // `|lambda D| = m_t |I1 (g - l th1d^2 cos th1) - l u sin th1|` is at least
                // `2.943e7 0.384 = 1.130e7`; with `|th1d| <= 100` and `|sin th1| <= sin(alpha /
                // 2) = 0.2588` (both asserted; the swing is fast, `th1d` reaches 52) gravity and
                // spin give at most `m_t I1 (g + l 100^2) = 1.5e4` of it, so the control input
                // is `|u| >= (1.130e7 - 1.5e4) / (m_t l 0.2588) = 1.45e7`. (A stuck Coulomb
                // foot's reaction is not Eq. 23; its `u` is only finite.)
                assert!(
                    th1d.abs() <= 100.0 && th1.sin().abs() <= 0.2589,
                    "{what}: {f:?}"
                );
                assert!(u.abs() >= 1.45e7, "{what}: {f:?}");
            }
            // The library's own measure of the denominator agrees: `m_t I1 g / D <= 0.5 / 0.384
            // m_t g = 1.302 m_t g` for either sign of `mu` (a stuck Coulomb foot has none).
            let contact = if smooth {
                Contact::Smooth
            } else {
                Contact::Sliding(Slide::of(f.state[4]))
            };
            if let Some(lg) = model.gravity_lambda(&f.state, contact) {
                assert!(lg.abs() <= 1.31 * weight(), "{what}: lambda_g = {lg}");
            }
        }
    }
}

/// Spin whose square is huge but finite (`omega0` from `1e5` to `1e150`, as `walker simulate
/// --omega0 1e12` gives) blows up the spin term `l th1d^2 cos th1` of the numerator at `t = 0`
/// (the reaction is negative: the wheel is flung off the floor); the denominator is regular
/// there (`th1 = -alpha/2` or 0, `mu0 = 0.4`). `omega0 = 1e12` was `lambda-denominator-zero`.
/// Beyond `1e154` the square overflows: `non-finite` (`sim_start.rs`).
#[test]
fn a_huge_spin_is_a_huge_numerator_not_a_pole() {
    for omega0 in [1e5, 1e8, 1e12, 1e150] {
        // The walkers of the paper's Table 1 with `mu0 = 0.4` (the passive wheel on level
        // ground, `phi = 0`: a regular denominator at `th1 = 0`), not the built-in scenes'
        // `phi = 0.2`, `mu0 = 0.2`.
        for model in [
            common::active(&[("mu0", 0.4)]),
            common::passive(&[("mu0", 0.4), ("phi", 0.0)]),
        ] {
            let what = format!("omega0 = {omega0:e}, {}", model.spec().name());
            let start = start(&model, omega0);
            let f = failure_of(&model, &start, &what);
            assert_eq!((f.step, f.t, f.state), (0, 0.0, start), "{what}");
            let FailureKind::LambdaNumeratorHuge { lambda, u } = f.kind else {
                panic!("{what}: {f:?}");
            };
            assert!(
                lambda.is_finite() && lambda < -1e6 * weight(),
                "{what}: {f:?}"
            );
            assert!(u.is_finite(), "{what}: {f:?}");
            assert!(denominator(start[2], 0.4).abs() >= 0.384, "{what}");
        }
    }
}

/// The passive wheel on level ground (`general_slope`, `phi = 0`, so `u = 0` and Eq. 23 holds)
/// with `mu0 >= 0.9`, sliding backwards (`xd = -1`, so `mu = mu0`), started where the
/// denominator `D` of Eq. 23, computed here by hand, is `rel I1` on the way to its first zero,
/// spinning at `th1d = omega`. The spin makes `|lambda|` huge at the start whatever `rel`
/// (`m_t I1 l omega^2 cos th1 / |D| >= 1.5e12 0.97 / 0.05 = 3e13`, above the threshold `1e6
/// m_t g = 2.9e7`); the failure names the pole where `D` vanished against its constant term,
/// `|D| <= 1e-3 I1` (`sim/blowup.rs`), and the numerator elsewhere: `rel = 0.1` and `0.01` are
/// the numerator's, `1e-4` to `1e-9` the pole's, modest spin (`omega = 1`) at `1e-9` too (as
/// the walk of `docs/stability.md` started `1e-9` before the zero). Bracketing the thousandth
/// by a factor 10 on either side keeps the hand-computed `D` (a few ulps from the kernel's)
/// far from the edge.
#[test]
fn a_pole_is_named_only_where_the_denominator_of_eq23_vanishes() {
    let i1 = table1("I1");
    for mu0 in [0.9, 1.0, 2.0] {
        let model = common::passive_run_time(&[("mu0", mu0), ("phi", 0.0)]);
        let th_star = first_zero(mu0);
        assert!(denominator(th_star, mu0).abs() < 1e-12, "mu0 = {mu0}");
        for (rel, omegas, pole) in [
            (1e-1, &[1e6, 1e50][..], false),
            (1e-2, &[1e6, 1e50], false),
            (1e-4, &[1e6, 1e50], true),
            (1e-6, &[1e6, 1e50], true),
            (1e-9, &[1.0, 1e6, 1e50], true),
        ] {
            let th1 = angle_of(mu0, rel, th_star);
            assert!(
                (denominator(th1, mu0) / (rel * i1) - 1.0).abs() < 1e-3,
                "mu0 = {mu0}, rel = {rel:e}"
            );
            for &omega in omegas {
                let what = format!("mu0 = {mu0}, D = {rel:e} I1, omega = {omega:e}");
                let start = [0.0, 0.0, th1, 0.0, -1.0, 0.0, omega, omega];
                let f = failure_of(&model, &start, &what);
                assert_eq!((f.step, f.t), (0, 0.0), "{what}: {f:?}");
                if pole {
                    assert!(
                        matches!(f.kind, FailureKind::LambdaDenominatorZero { .. }),
                        "{what}: {f:?}"
                    );
                } else {
                    assert!(
                        matches!(f.kind, FailureKind::LambdaNumeratorHuge { .. }),
                        "{what}: {f:?}"
                    );
                }
            }
        }
    }
}

/// The smaller zero of `cos 2 th1 + mu0 sin 2 th1 - (1 + 2 I1 / (m_t l^2))` (the denominator
/// of Eq. 23 times `2 / (m_t l^2)`, Table 1) by bisection between 0 and the angle `atan(mu0) /
/// 2` where its left side is largest.
fn first_zero(mu0: f64) -> f64 {
    let l = table1("l");
    let k = 1.0 + 2.0 * table1("I1") / (table1_total_mass() * l * l);
    bisect(0.0, 0.5 * mu0.atan(), |th| {
        (2.0 * th).cos() + mu0 * (2.0 * th).sin() - k
    })
}

/// The angle in `[0, th_star]` where the denominator at `mu = mu0` is `rel I1` (it falls from
/// `I1` at 0 to 0 at `th_star`: its derivative `m_t l^2 (sin 2 th1 - mu0 cos 2 th1)` is
/// negative below `atan(mu0) / 2`).
fn angle_of(mu0: f64, rel: f64, th_star: f64) -> f64 {
    let i1 = table1("I1");
    bisect(0.0, th_star, |th| denominator(th, mu0) - rel * i1)
}

/// A root of `f` in `[a, b]`, where `f` changes sign, by 200 bisections.
fn bisect(mut a: f64, mut b: f64, f: impl Fn(f64) -> f64) -> f64 {
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if f(a) * f(m) <= 0.0 {
            b = m;
        } else {
            a = m;
        }
    }
    0.5 * (a + b)
}
