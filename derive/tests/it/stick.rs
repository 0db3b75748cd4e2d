//! The stick phase (the stance foot stuck to the floor), checked against mechanics derived by
//! hand. Not in the paper: Asano, Kikuchi and Shibata model sliding only ("without considering
//! the static friction effect", Eq. 25); exact Coulomb friction with stick-slip needs these
//! kernels when the foot is at rest and the friction can hold it.
//!
//! Every check compares exact rational functions (modulo `sin^2 + cos^2 = 1`), so a wrong sign
//! or a missing term fails; the hand-built forms below are written from the physics, not taken
//! from the derivation:
//!
//! - with the foot pinned, the walker is a 2-DOF system `(th1, th2)` with
//!   `L = 1/2 (m_t l^2 + I1) th1d^2 + 1/2 I2 th2d^2 - m_t g l cos th1` (the hip, where both
//!   centres of mass are, moves on a circle of radius `l` about the foot; `th1` is measured
//!   from the vertical on the slope as well), and the torque `u` acts on `y = th1 - th2`, so
//!   Euler-Lagrange gives
//!   `(m_t l^2 + I1) th1dd = m_t g l sin th1 + u` and `I2 th2dd = -u`;
//! - Newton's law for the centre of mass (the hip): the ground force on the foot is
//!   `m_t (a_hip + g e_z)`, with `a_hip = l th1dd (cos th1, -sin th1) - l th1d^2 (sin th1,
//!   cos th1)`; `lambda_t` is its component along the unit tangent `(cos phi, -sin phi)`,
//!   `lambda_n` along the unit normal `(sin phi, cos phi)` (`phi = 0`: horizontal and vertical);
//! - the output control: `yddot = th1dd - th2dd = A_s u - B_s` with, from the two equations
//!   above, `A_s = 1 / (m_t l^2 + I1) + 1 / I2` and `B_s = -m_t g l sin th1 / (m_t l^2 + I1)`.

use crate::common;

use common::{Rng, cos1, derivation, div, out, s, sin1};

use walker_symbolic::paper::{self, int, total_mass};
use walker_symbolic::symbol::{Atom, BaseAngle, Point, Symbols};
use walker_symbolic::{RatFunc, Sym};

/// `m_t l^2 + I1`: the wheel's moment of inertia about the stuck foot.
fn inertia_about_foot() -> RatFunc {
    &(&(&total_mass() * &s(Sym::L)) * &s(Sym::L)) + &s(Sym::I1)
}

/// `th1dd` from the reduced Lagrangian, with torque `u`.
fn th1dd_by_hand(u: &RatFunc) -> RatFunc {
    let gravity = &(&(&total_mass() * &s(Sym::G)) * &s(Sym::L)) * &sin1(Sym::Th1);
    div(&(&gravity + u), &inertia_about_foot())
}

/// `[lambda_t, lambda_n]` from Newton's law for the centre of mass, for a given `th1dd`, on a
/// level floor or on the slope of angle `phi`.
fn forces_by_newton(th1dd: &RatFunc, slope: bool) -> [RatFunc; 2] {
    let (l, w) = (s(Sym::L), s(Sym::Th1d));
    let (s1, c1) = (sin1(Sym::Th1), cos1(Sym::Th1));
    let w2 = &w * &w;
    let ax = &(&(&l * th1dd) * &c1) - &(&(&l * &w2) * &s1);
    let az = -(&(&(&l * th1dd) * &s1) + &(&(&l * &w2) * &c1));
    let mt = total_mass();
    let fx = &mt * &ax;
    let fz = &mt * &(&az + &s(Sym::G));
    if !slope {
        return [fx, fz];
    }
    let (sp, cp) = (
        RatFunc::sin_of(BaseAngle::Phi),
        RatFunc::cos_of(BaseAngle::Phi),
    );
    [&(&fx * &cp) - &(&fz * &sp), &(&fx * &sp) + &(&fz * &cp)]
}

#[test]
fn the_foot_does_not_move() {
    for kernel in ["stick_level", "closed_loop_stick_level", "stick_slope"] {
        assert!(out(kernel, "qdd0").is_zero(), "{kernel}: xdd = 0");
        assert!(out(kernel, "qdd1").is_zero(), "{kernel}: zdd = 0");
    }
}

#[test]
fn the_stick_constraint_jacobians_are_the_unit_tangent_and_normal() {
    // Constant rows, so J_s qdd = 0 is the acceleration-level constraint (no Jdot qd term).
    let d = derivation();
    let (sp, cp) = (
        RatFunc::sin_of(BaseAngle::Phi),
        RatFunc::cos_of(BaseAngle::Phi),
    );
    let level = walker_symbolic::Matrix::from_rows(vec![
        vec![int(1), int(0), int(0), int(0)],
        vec![int(0), int(1), int(0), int(0)],
    ])
    .expect("rectangular");
    let slope = walker_symbolic::Matrix::from_rows(vec![
        vec![cp.clone(), -sp.clone(), int(0), int(0)],
        vec![sp, cp, int(0), int(0)],
    ])
    .expect("rectangular");
    assert_eq!(d.quantities.stick_level.jacobian, level);
    assert_eq!(d.quantities.stick_slope.jacobian, slope);
}

#[test]
fn th1dd_is_the_rimless_wheel_with_torso_about_a_pinned_foot() {
    let u = s(Sym::U);
    assert_eq!(out("stick_level", "qdd2"), th1dd_by_hand(&u));
    assert_eq!(out("stick_level", "qdd3"), -div(&u, &s(Sym::I2)));
    // On the slope th1 is measured from the vertical too, so the equation is the same (u = 0).
    assert_eq!(out("stick_slope", "qdd2"), th1dd_by_hand(&RatFunc::zero()));
    assert!(out("stick_slope", "qdd3").is_zero());
}

#[test]
fn the_ground_force_is_newtons_law_for_the_centre_of_mass() {
    let [t, n] = forces_by_newton(&th1dd_by_hand(&s(Sym::U)), false);
    assert_eq!(out("stick_level", "lambda_t"), t, "level lambda_t");
    assert_eq!(out("stick_level", "lambda_n"), n, "level lambda_n");
    let [t, n] = forces_by_newton(&th1dd_by_hand(&RatFunc::zero()), true);
    assert_eq!(out("stick_slope", "lambda_t"), t, "slope lambda_t");
    assert_eq!(out("stick_slope", "lambda_n"), n, "slope lambda_n");
    // At rest upright without torque on level ground the walker stands on its weight; on the
    // slope that weight splits into m_t g (sin phi, cos phi) along the tangent (down the
    // slope) and the normal: the friction must hold it up the slope, lambda_t = -m_t g sin phi.
    let rest = |r: &RatFunc| {
        let r = r
            .substitute(Atom::Sym(Sym::U), &RatFunc::zero())
            .expect("subst");
        let r = r
            .substitute(Atom::Sym(Sym::Th1d), &RatFunc::zero())
            .expect("subst");
        let r = r
            .substitute(Atom::Sin(BaseAngle::Th1), &RatFunc::zero())
            .expect("subst");
        r.substitute(Atom::Cos(BaseAngle::Th1), &int(1))
            .expect("subst")
    };
    let weight = &total_mass() * &s(Sym::G);
    assert!(rest(&out("stick_level", "lambda_t")).is_zero());
    assert_eq!(rest(&out("stick_level", "lambda_n")), weight);
    assert_eq!(
        rest(&out("stick_slope", "lambda_t")),
        -(&weight * &RatFunc::sin_of(BaseAngle::Phi))
    );
    assert_eq!(
        rest(&out("stick_slope", "lambda_n")),
        &weight * &RatFunc::cos_of(BaseAngle::Phi)
    );
}

#[test]
fn the_stuck_closed_loop_follows_yddot_equals_v() {
    let d = derivation();
    let k = "closed_loop_stick_level";
    let ydd = &out(k, "qdd2") - &out(k, "qdd3");
    assert_eq!(ydd, s(Sym::V), "yddot = v");
    // A_s and B_s by hand (Eqs. 30-31 with the foot held).
    let a = &inertia_about_foot().recip().expect("nonzero") + &s(Sym::I2).recip().expect("nonzero");
    let b = -div(
        &(&(&(&total_mass() * &s(Sym::G)) * &s(Sym::L)) * &sin1(Sym::Th1)),
        &inertia_about_foot(),
    );
    assert_eq!(d.quantities.stick_control.a, a, "A_s");
    assert_eq!(d.quantities.stick_control.b, b, "B_s");
    let u = div(&(&s(Sym::V) + &b), &a);
    assert_eq!(out(k, "u"), u, "u = (v + B_s) / A_s");
    // The rest is stick_level at that u.
    for name in ["qdd2", "qdd3", "lambda_t", "lambda_n"] {
        let want = out("stick_level", name)
            .substitute(Atom::Sym(Sym::U), &u)
            .expect("subst");
        assert_eq!(out(k, name), want, "{name}");
    }
}

#[test]
fn the_staged_stuck_closed_loop_composes_and_a_wrong_one_is_caught() {
    let k = derivation()
        .kernel("closed_loop_stick_level")
        .expect("kernel exists");
    let staged = k.staged.as_ref().expect("a staged form");
    assert_eq!(staged.locals.len(), 1, "u is the one local");
    assert_eq!(staged.locals[0].0, Sym::U);
    k.check_staged().expect("u once, then stick_level with it");
    let mut wrong = k.clone();
    if let Some(st) = wrong.staged.as_mut() {
        // lambda_t and lambda_n swapped: the composition must notice.
        st.outputs.swap(5, 6);
    }
    assert!(wrong.check_staged().is_err(), "a wrong staged form passes");
}

#[test]
fn constraint_forces_do_no_work_while_stuck() {
    // With xd = zd = 0 the energy changes by the joint power only: dE/dt = u (th1d - th2d).
    let energy = &out("energy", "T") + &out("energy", "V");
    let rate = paper::time_derivative(&energy);
    let at_rest_foot = |r: RatFunc, kernel: &str| {
        let mut r = r;
        for (k, qdd) in paper::QDD_SYMS.iter().enumerate() {
            r = r
                .substitute(Atom::Sym(*qdd), &out(kernel, &format!("qdd{k}")))
                .expect("subst");
        }
        for v in [Sym::Xd, Sym::Zd] {
            r = r.substitute(Atom::Sym(v), &RatFunc::zero()).expect("subst");
        }
        r
    };
    let joint = &s(Sym::U) * &(&s(Sym::Th1d) - &s(Sym::Th2d));
    assert_eq!(at_rest_foot(rate.clone(), "stick_level"), joint);
    assert!(at_rest_foot(rate, "stick_slope").is_zero());
}

#[test]
fn sliding_with_mu_equal_to_the_force_ratio_is_sticking() {
    // The sign conventions of lambda_t and of mu agree: the sliding kernels with the friction
    // coefficient mu = lambda_t / lambda_n apply exactly the stick force, so they give the
    // stick accelerations, and their vertical reaction is lambda_n (times cos phi on the
    // slope, where the sliding kernels report the vertical component).
    let ratio = |kernel: &str| div(&out(kernel, "lambda_t"), &out(kernel, "lambda_n"));
    let cases = [
        (
            "stick_level",
            "accel_level",
            "lambda_level",
            ratio("stick_level"),
        ),
        (
            "stick_slope",
            "accel_slope",
            "lambda_slope",
            ratio("stick_slope"),
        ),
    ];
    for (stick, accel, lambda, mu) in cases {
        for k in 0..4 {
            let name = format!("qdd{k}");
            let sliding = out(accel, &name)
                .substitute(Atom::Sym(Sym::Mu), &mu)
                .expect("subst");
            assert_eq!(
                sliding,
                out(stick, &name),
                "{accel} {name} at mu = lambda_t/lambda_n"
            );
        }
        let vertical = if stick == "stick_slope" {
            &out(stick, "lambda_n") * &RatFunc::cos_of(BaseAngle::Phi)
        } else {
            out(stick, "lambda_n")
        };
        let sliding = out(lambda, "lambda")
            .substitute(Atom::Sym(Sym::Mu), &mu)
            .expect("subst");
        assert_eq!(sliding, vertical, "{lambda} at mu = lambda_t/lambda_n");
    }
}

fn atoms(values: &[(Sym, f64)]) -> Point<f64> {
    let mut v = Point::zeros(&Symbols::paper());
    for &(s, x) in values {
        v.set_sym(s, x);
    }
    v
}

#[test]
fn when_the_friction_cannot_hold_the_foot_slides_against_lambda_t() {
    // The contract for the simulator (docs/kernels.md): when |lambda_t| > mu0 lambda_n the
    // foot starts to slide in the direction sigma = -sign(lambda_t), and the sliding kernels
    // with mu = -mu0 sigma accelerate it that way (sigma xdd > 0). Checked at random states
    // of walkers near Table 1 where the sliding contact is regular (lambda_den > 0 between
    // mu and lambda_t / lambda_n), with mu0 a fraction of the ratio the foot would need.
    let d = derivation();
    let mut rng = Rng(0x57_1c4);
    let mut checked = 0;
    for _ in 0..400 {
        let slope = rng.next() < 0.5;
        let phi = if slope { rng.range(0.0, 0.3) } else { 0.0 };
        let values = [
            (Sym::M1, rng.range(0.5, 3.0)),
            (Sym::M2, rng.range(0.5, 3.0)),
            (Sym::L, rng.range(0.5, 1.5)),
            (Sym::I1, rng.range(0.1, 2.0)),
            (Sym::I2, rng.range(0.1, 2.0)),
            (Sym::G, 9.81),
            (Sym::Alpha, 0.5),
            (Sym::Phi, phi),
            (Sym::Th1, rng.range(-0.6, 0.6)),
            (Sym::Th1d, rng.range(-2.0, 2.0)),
            (Sym::U, if slope { 0.0 } else { rng.range(-5.0, 5.0) }),
        ];
        let (stick, accel, stance) = if slope {
            ("stick_slope", "accel_slope", &d.quantities.slope)
        } else {
            ("stick_level", "accel_level", &d.quantities.level)
        };
        let v = atoms(&values);
        let lt = out(stick, "lambda_t").eval(&v);
        let ln = out(stick, "lambda_n").eval(&v);
        if ln <= 0.0 || lt == 0.0 {
            continue;
        }
        let needed = lt / ln;
        let mu0 = rng.range(0.1, 0.9) * needed.abs();
        let sigma = -lt.signum();
        let mu = -mu0 * sigma;
        let den_at = |m: f64| {
            let mut w = values.to_vec();
            w.push((Sym::Mu, m));
            stance.lambda_den.eval(&atoms(&w))
        };
        if den_at(mu) <= 0.0 || den_at(needed) <= 0.0 {
            continue;
        }
        let mut w = values.to_vec();
        w.push((Sym::Mu, mu));
        let xdd = out(accel, "qdd0").eval(&atoms(&w));
        assert!(
            sigma * xdd > 0.0,
            "{stick}: lambda_t {lt:e}, lambda_n {ln:e}, mu0 {mu0:e}: sigma {sigma} but xdd {xdd:e}"
        );
        checked += 1;
    }
    assert!(checked > 100, "only {checked} regular points");
}
