//! The derivation against the paper (Asano, Kikuchi, Shibata), equation by equation.
//!
//! Where a printed form is simple, it is built with the engine and compared with the derived
//! one by semantic [`RatFunc`] equality (exact). Every printed closed form is also written out
//! by hand in `f64` below (`paper_*` functions, straight from the paper's text, with std's
//! `sin`/`cos`) and compared with the kernels evaluated in `f64` at random points, which checks
//! the substitutions of the impact posture independently of `paper::at_impact_posture`.
//! Where the paper is wrong, the test asserts the derived form and says what is printed;
//! `docs/errata.md` lists every such case with the name of its test.

use crate::common;

use common::{Rng, cos1, derivation, div, out, s, sin1};

use num_traits::ToPrimitive;
use walker_symbolic::paper::{
    self, Floor, cos, frac, int, sin, sin_half_alpha, tan_phi, total_inertia, total_mass,
};
use walker_symbolic::symbol::{Atom, BaseAngle, Point, Symbols, Valuation};
use walker_symbolic::{Error, Matrix, Poly, Q, RatFunc, Sym};

// ---------------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------------

fn mat(rows: Vec<Vec<RatFunc>>) -> Matrix {
    Matrix::from_rows(rows).expect("rectangular")
}

fn mul(a: &Matrix, b: &Matrix) -> Matrix {
    a.mul(b).expect("dimensions")
}

/// The paper's impact state on level ground: `th1 = alpha/2`, `zd- = 0`, `th2d- = th1d-`.
fn at_level(r: &RatFunc) -> RatFunc {
    let p = paper::at_impact_posture(r, Floor::Level).expect("posture");
    paper::paper_pre_impact(&p, Floor::Level).expect("pre-impact")
}

/// The paper's impact state on the slope: `th1 = alpha/2 + phi`, `zd- = -xd- tan phi`,
/// `th2d- = th1d-`.
fn at_slope(r: &RatFunc) -> RatFunc {
    let p = paper::at_impact_posture(r, Floor::Slope).expect("posture");
    paper::paper_pre_impact(&p, Floor::Slope).expect("pre-impact")
}

/// `m_t l^2 (1 - cos alpha)`, the left side of Eqs. 11 and 46.
fn k_alpha() -> RatFunc {
    let l = s(Sym::L);
    &(&(&total_mass() * &l) * &l) * &(&int(1) - &cos1(Sym::Alpha))
}

/// Values of the symbols at one point.
#[derive(Clone, Copy, Debug)]
struct Pt {
    m1: f64,
    m2: f64,
    l: f64,
    i1: f64,
    i2: f64,
    g: f64,
    alpha: f64,
    phi: f64,
    th1: f64,
    xd: f64,
    zd: f64,
    th1d: f64,
    th2d: f64,
    u: f64,
    mu: f64,
}

impl Pt {
    fn random(rng: &mut Rng) -> Pt {
        Pt {
            m1: rng.range(0.5, 3.0),
            m2: rng.range(0.5, 3.0),
            l: rng.range(0.5, 1.5),
            i1: rng.range(0.1, 2.0),
            i2: rng.range(0.1, 2.0),
            g: rng.range(5.0, 15.0),
            alpha: rng.range(0.2, 1.2),
            phi: rng.range(-0.3, 0.3),
            th1: rng.range(-0.8, 0.8),
            xd: rng.range(-1.0, 1.0),
            zd: rng.range(-1.0, 1.0),
            th1d: rng.range(-2.0, 2.0),
            th2d: rng.range(-2.0, 2.0),
            u: rng.range(-5.0, 5.0),
            mu: rng.range(-0.8, 0.8),
        }
    }

    /// Table 1 (`g = 9.81`), with the remaining values of `self`.
    fn table1(self) -> Pt {
        Pt {
            m1: 2.0,
            m2: 1.0,
            l: 1.0,
            i1: 2.0 * 0.5f64.powi(2),
            i2: 1.0,
            g: 9.81,
            alpha: std::f64::consts::PI / 6.0,
            ..self
        }
    }

    fn mt(&self) -> f64 {
        self.m1 + self.m2
    }

    fn it(&self) -> f64 {
        self.i1 + self.i2
    }

    fn atoms(&self) -> Point<f64> {
        let mut v = Point::zeros(&Symbols::paper());
        let set = |v: &mut Point<f64>, s: Sym, x: f64| v.set_sym(s, x);
        for (s, x) in [
            (Sym::M1, self.m1),
            (Sym::M2, self.m2),
            (Sym::L, self.l),
            (Sym::I1, self.i1),
            (Sym::I2, self.i2),
            (Sym::G, self.g),
            (Sym::Alpha, self.alpha),
            (Sym::Phi, self.phi),
            (Sym::Th1, self.th1),
            (Sym::Th2, 0.3),
            (Sym::Xd, self.xd),
            (Sym::Zd, self.zd),
            (Sym::Th1d, self.th1d),
            (Sym::Th2d, self.th2d),
            (Sym::U, self.u),
            (Sym::Mu, self.mu),
        ] {
            set(&mut v, s, x);
        }
        v
    }

    fn eval(&self, r: &RatFunc) -> f64 {
        r.eval(&self.atoms())
    }

    /// The paper's impact state on level ground (Eq. 3 and the text under it).
    fn level_impact(self) -> Pt {
        Pt {
            th1: self.alpha / 2.0,
            zd: 0.0,
            th2d: self.th1d,
            ..self
        }
    }

    /// The paper's impact state on the slope (Section 5.1).
    fn slope_impact(self) -> Pt {
        Pt {
            th1: self.alpha / 2.0 + self.phi,
            zd: -self.xd * self.phi.tan(),
            th2d: self.th1d,
            ..self
        }
    }
}

fn close(got: f64, want: f64, what: &str) {
    let tol = 1e-10 * (1.0 + want.abs());
    assert!(
        (got - want).abs() <= tol,
        "{what}: derived {got:.15e}, paper {want:.15e}"
    );
}

const POINTS: usize = 200;

fn points() -> impl Iterator<Item = Pt> {
    let mut rng = Rng(0x5eed_2024);
    (0..POINTS).map(move |_| Pt::random(&mut rng))
}

// ---------------------------------------------------------------------------------------------
// Eq. 2: the inertia matrix
// ---------------------------------------------------------------------------------------------

/// Eq. 2 as printed.
fn paper_mass_matrix() -> Matrix {
    let (mt, l, i1, i2) = (total_mass(), s(Sym::L), s(Sym::I1), s(Sym::I2));
    let (s1, c1) = (sin1(Sym::Th1), cos1(Sym::Th1));
    let mtl = &mt * &l;
    mat(vec![
        vec![mt.clone(), int(0), &mtl * &c1, int(0)],
        vec![int(0), mt.clone(), -(&mtl * &s1), int(0)],
        vec![&mtl * &c1, -(&mtl * &s1), &(&mtl * &l) + &i1, int(0)],
        vec![int(0), int(0), int(0), i2],
    ])
}

#[test]
fn eq02_mass_matrix_entry_by_entry() {
    let d = derivation();
    let paper = paper_mass_matrix();
    for i in 0..4 {
        for j in 0..4 {
            assert_eq!(
                d.quantities.dynamics.mass.get(i, j),
                paper.get(i, j),
                "M[{i}][{j}] differs from Eq. 2"
            );
        }
    }
    for p in points() {
        let a = p.atoms();
        let (mt, c, sn) = (p.mt(), p.th1.cos(), p.th1.sin());
        let want = [
            [mt, 0.0, mt * p.l * c, 0.0],
            [0.0, mt, -mt * p.l * sn, 0.0],
            [mt * p.l * c, -mt * p.l * sn, mt * p.l * p.l + p.i1, 0.0],
            [0.0, 0.0, 0.0, p.i2],
        ];
        for (i, row) in want.iter().enumerate() {
            for (j, w) in row.iter().enumerate() {
                close(d.quantities.dynamics.mass.get(i, j).eval(&a), *w, "Eq. 2");
            }
        }
    }
}

#[test]
fn eq02_det_is_mt_squared_i1_i2_and_the_inverse_is_exact() {
    let d = derivation();
    let mt = total_mass();
    let det = d.quantities.dynamics.mass.det().expect("square");
    assert_eq!(det, &(&(&mt * &mt) * &s(Sym::I1)) * &s(Sym::I2));
    let product = mul(&d.quantities.dynamics.mass, &d.quantities.dynamics.mass_inv);
    assert_eq!(product, Matrix::identity(4), "M M^-1 = I exactly");
    let product = mul(&d.quantities.dynamics.mass_inv, &d.quantities.dynamics.mass);
    assert_eq!(product, Matrix::identity(4), "M^-1 M = I exactly");
}

// ---------------------------------------------------------------------------------------------
// Eq. 20: h and S
// ---------------------------------------------------------------------------------------------

/// Eq. 20 as printed has three entries; `h` is in R^4 and its fourth entry is 0 (the torso
/// has no Coriolis, centrifugal or gravity term: its centre of mass is on the hip).
fn paper_bias() -> Matrix {
    let (mt, l, g, th1d) = (total_mass(), s(Sym::L), s(Sym::G), s(Sym::Th1d));
    let (s1, c1) = (sin1(Sym::Th1), cos1(Sym::Th1));
    let l_w2 = &(&l * &th1d) * &th1d;
    Matrix::column(vec![
        -(&(&mt * &l_w2) * &s1),
        &mt * &(&g - &(&l_w2 * &c1)),
        -(&(&(&mt * &g) * &l) * &s1),
        int(0),
    ])
}

#[test]
fn eq20_bias_has_a_fourth_entry_zero_and_s_is_as_printed() {
    let d = derivation();
    let paper = paper_bias();
    assert_eq!(
        d.quantities.dynamics.bias.rows(),
        4,
        "h is in R^4, Eq. 20 prints 3 rows"
    );
    for i in 0..4 {
        assert_eq!(
            d.quantities.dynamics.bias.get(i, 0),
            paper.get(i, 0),
            "h[{i}]"
        );
    }
    assert!(
        d.quantities.dynamics.bias.get(3, 0).is_zero(),
        "the 4th entry is 0"
    );
    assert_eq!(
        d.quantities.dynamics.input_map,
        Matrix::column(vec![int(0), int(0), int(1), int(-1)])
    );
    for p in points() {
        let a = p.atoms();
        let w2 = p.th1d * p.th1d;
        let want = [
            -p.mt() * p.l * w2 * p.th1.sin(),
            p.mt() * (p.g - p.l * w2 * p.th1.cos()),
            -p.mt() * p.g * p.l * p.th1.sin(),
            0.0,
        ];
        for (i, w) in want.iter().enumerate() {
            close(d.quantities.dynamics.bias.get(i, 0).eval(&a), *w, "Eq. 20");
        }
    }
}

#[test]
fn section5_torso_decouples_when_u_is_zero() {
    // "By setting the control input to zero, we can divide the torso dynamics from the
    // passive RW": the 4th row and column of M are diag(I2) and h[3] = 0.
    let d = derivation();
    for k in 0..3 {
        assert!(d.quantities.dynamics.mass.get(3, k).is_zero());
        assert!(d.quantities.dynamics.mass.get(k, 3).is_zero());
    }
    assert_eq!(d.quantities.dynamics.mass.get(3, 3), &s(Sym::I2));
    assert!(d.quantities.dynamics.bias.get(3, 0).is_zero());
}

// ---------------------------------------------------------------------------------------------
// Eqs. 21-24: the ground reaction on level ground
// ---------------------------------------------------------------------------------------------

/// Eq. 23 as printed.
fn paper_lambda_eq23() -> RatFunc {
    let (mt, l, g, i1, u, mu, th1d) = (
        total_mass(),
        s(Sym::L),
        s(Sym::G),
        s(Sym::I1),
        s(Sym::U),
        s(Sym::Mu),
        s(Sym::Th1d),
    );
    let (s1, c1) = (sin1(Sym::Th1), cos1(Sym::Th1));
    let s2 = sin(&[(Sym::Th1, 2)]).expect("angle");
    let c2 = cos(&[(Sym::Th1, 2)]).expect("angle");
    let num = &(&int(2) * &mt)
        * &(&(&i1 * &(&g - &(&(&(&l * &th1d) * &th1d) * &c1))) - &(&(&u * &l) * &s1));
    let den = &(&int(2) * &i1) + &(&(&(&mt * &l) * &l) * &(&(&int(1) - &c2) - &(&mu * &s2)));
    div(&num, &den)
}

#[test]
fn eq23_lambda_level_is_exactly_the_printed_fraction() {
    let lambda = out("lambda_level", "lambda");
    let paper = paper_lambda_eq23();
    assert_eq!(lambda, paper, "lambda_level == Eq. 23");
    assert_eq!(lambda, derivation().quantities.level.lambda);
    // lambda times Eq. 23's denominator is Eq. 23's numerator.
    let (mt, l, g, i1, u, mu, th1d) = (
        total_mass(),
        s(Sym::L),
        s(Sym::G),
        s(Sym::I1),
        s(Sym::U),
        s(Sym::Mu),
        s(Sym::Th1d),
    );
    let (s1, c1) = (sin1(Sym::Th1), cos1(Sym::Th1));
    let s2 = sin(&[(Sym::Th1, 2)]).expect("angle");
    let c2 = cos(&[(Sym::Th1, 2)]).expect("angle");
    let num = &(&int(2) * &mt)
        * &(&(&i1 * &(&g - &(&(&(&l * &th1d) * &th1d) * &c1))) - &(&(&u * &l) * &s1));
    let den = &(&int(2) * &i1) + &(&(&(&mt * &l) * &l) * &(&(&int(1) - &c2) - &(&mu * &s2)));
    assert_eq!(&lambda * &den, num);
    for p in points() {
        let w2 = p.th1d * p.th1d;
        let want = 2.0 * p.mt() * (p.i1 * (p.g - p.l * w2 * p.th1.cos()) - p.u * p.l * p.th1.sin())
            / (2.0 * p.i1
                + p.mt() * p.l * p.l * (1.0 - (2.0 * p.th1).cos() - p.mu * (2.0 * p.th1).sin()));
        close(p.eval(&lambda), want, "Eq. 23");
    }
}

#[test]
fn eq22_from_the_printed_matrices_gives_the_same_lambda() {
    // Eq. 22 with the paper's own M (Eq. 2), h (Eq. 20, with its 4th entry 0), S, J (Eq. 21)
    // and J_mu (Eq. 24): an independent route to lambda.
    let m_inv = paper_mass_matrix().inverse("M").expect("regular");
    let j = Matrix::row(vec![int(0), int(1), int(0), int(0)]);
    let j_mu = Matrix::row(vec![s(Sym::Mu), int(0), int(0), int(0)]);
    let s_u = Matrix::column(vec![int(0), int(0), s(Sym::U), -s(Sym::U)]);
    let su_h = s_u.sub(&paper_bias()).expect("dims");
    let jm = mul(&j, &m_inv);
    let top = mul(&jm, &su_h).scalar().expect("1x1");
    let bottom = mul(&jm, &j.add(&j_mu).expect("dims").transpose())
        .scalar()
        .expect("1x1");
    let lambda = -div(&top, &bottom);
    assert_eq!(lambda, out("lambda_level", "lambda"));
    assert_eq!(bottom, derivation().quantities.level.lambda_den);
    // The derived contact Jacobians are Eqs. 21 and 24.
    assert_eq!(derivation().quantities.level.contact.jacobian, j);
    assert_eq!(derivation().quantities.level.contact.friction, j_mu);
}

// ---------------------------------------------------------------------------------------------
// Eqs. 25-26: the sign of the friction coefficient
// ---------------------------------------------------------------------------------------------

#[test]
fn eq25_friction_must_oppose_sliding_energy_balance() {
    // Along the stance motion (zd = 0, qdd from Eq. 27), the mechanical energy changes by the
    // joint power and the friction power only (the constraint force does no work):
    //     dE/dt = u (th1d - th2d) + mu lambda xd.
    // With lambda > 0, friction dissipates iff mu xd <= 0, i.e. mu = -mu0 sign(xd): Eq. 26
    // (-mu0 tanh(c xd)) has this sign, Eq. 25 as printed (+mu0 sign(xd)) would feed energy in.
    let d = derivation();
    let energy = &out("energy", "T") + &out("energy", "V");
    let mut rate = paper::time_derivative(&energy);
    for (k, qdd) in paper::QDD_SYMS.iter().enumerate() {
        rate = rate
            .substitute(Atom::Sym(*qdd), d.quantities.level.accel.get(k, 0))
            .expect("substitution");
    }
    let rate = rate
        .substitute(Atom::Sym(Sym::Zd), &RatFunc::zero())
        .expect("substitution");
    let joint_power = &s(Sym::U) * &(&s(Sym::Th1d) - &s(Sym::Th2d));
    let friction_power = &(&s(Sym::Mu) * &d.quantities.level.lambda) * &s(Sym::Xd);
    assert_eq!(rate, &joint_power + &friction_power);
    // Numerically, with lambda > 0 and u = 0: Eq. 26 dissipates, the printed Eq. 25 does not.
    let (mu0, c) = (0.4, 100.0);
    for p in points() {
        let p = Pt { u: 0.0, ..p };
        let lambda = p.eval(&d.quantities.level.lambda);
        if lambda <= 0.0 || p.xd.abs() < 1e-3 {
            continue;
        }
        let eq26 = -mu0 * (c * p.xd).tanh();
        let eq25_printed = mu0 * p.xd.signum();
        assert!(eq26 * lambda * p.xd < 0.0);
        assert!(eq25_printed * lambda * p.xd > 0.0);
    }
}

// ---------------------------------------------------------------------------------------------
// Eqs. 27-31: Y, the accelerations, A and B
// ---------------------------------------------------------------------------------------------

#[test]
fn eq28_projection_identities() {
    // Y = I - Jh^T (J M^-1 Jh^T)^-1 J M^-1 with Jh = J + J_mu (Eqs. 28-29). Then
    //   J M^-1 Y = J M^-1 - (J M^-1 Jh^T)(J M^-1 Jh^T)^-1 J M^-1 = 0      (a row of zeros),
    // for every mu, not only applied to (S u - h): whatever the forces, Y removes the part
    // that would accelerate the foot into the floor, so J qdd = J M^-1 Y (S u - h) = 0.
    // Likewise Y Jh^T = Jh^T - Jh^T (J M^-1 Jh^T)^-1 (J M^-1 Jh^T) = 0 (Y annihilates the
    // contact force direction), and Y^2 = Y. M^-1 Y is symmetric only without friction
    // (Jh = J); with mu != 0 it is not, the projection is oblique.
    let d = derivation();
    let y = &d.quantities.level.projection;
    let j = &d.quantities.level.contact.jacobian;
    let jh = j.add(&d.quantities.level.contact.friction).expect("dims");
    let zero_row = Matrix::zeros(1, 4);
    assert_eq!(
        mul(&mul(j, &d.quantities.dynamics.mass_inv), y),
        zero_row,
        "J M^-1 Y = 0"
    );
    assert_eq!(mul(y, &jh.transpose()), Matrix::zeros(4, 1), "Y Jh^T = 0");
    assert_eq!(mul(y, y), *y, "Y^2 = Y");
    let m_inv_y = mul(&d.quantities.dynamics.mass_inv, y);
    let no_friction = m_inv_y
        .try_map(|r| r.substitute(Atom::Sym(Sym::Mu), &RatFunc::zero()))
        .expect("substitution");
    assert_eq!(
        no_friction,
        no_friction.transpose(),
        "M^-1 Y symmetric at mu = 0"
    );
    assert_ne!(m_inv_y, m_inv_y.transpose(), "and not with friction");
    // Eq. 28 from the paper's printed matrices.
    let m_inv = paper_mass_matrix().inverse("M").expect("regular");
    let jp = Matrix::row(vec![int(0), int(1), int(0), int(0)]);
    let jhp = Matrix::row(vec![s(Sym::Mu), int(1), int(0), int(0)]);
    let jm = mul(&jp, &m_inv);
    let k = mul(&jm, &jhp.transpose()).scalar().expect("1x1");
    let paper_y = Matrix::identity(4)
        .sub(&mul(&jhp.transpose(), &jm).scale(&k.recip().expect("nonzero")))
        .expect("dims");
    assert_eq!(*y, paper_y);
}

#[test]
fn eq27_m_qdd_equals_y_times_su_minus_h() {
    let d = derivation();
    let su_h = d
        .quantities
        .dynamics
        .input_map
        .scale(&s(Sym::U))
        .sub(&d.quantities.dynamics.bias)
        .expect("dims");
    let lhs = mul(&d.quantities.dynamics.mass, &d.quantities.level.accel);
    let rhs = mul(&d.quantities.level.projection, &su_h);
    assert_eq!(lhs, rhs, "M qdd = Y (S u - h)");
    // and the constraint: zdd = 0
    assert!(d.quantities.level.accel.get(1, 0).is_zero());
    // the kernel is the same vector
    for k in 0..4 {
        assert_eq!(
            &out("accel_level", &format!("qdd{k}")),
            d.quantities.level.accel.get(k, 0)
        );
    }
}

#[test]
fn eq30_31_output_acceleration_is_a_u_minus_b() {
    let d = derivation();
    let a = out("control_level", "A");
    let b = out("control_level", "B");
    // A and B as defined under Eq. 32.
    let st = d.quantities.dynamics.input_map.transpose();
    let st_minv_y = mul(
        &mul(&st, &d.quantities.dynamics.mass_inv),
        &d.quantities.level.projection,
    );
    assert_eq!(
        a,
        mul(&st_minv_y, &d.quantities.dynamics.input_map)
            .scalar()
            .expect("1x1")
    );
    assert_eq!(
        b,
        mul(&st_minv_y, &d.quantities.dynamics.bias)
            .scalar()
            .expect("1x1")
    );
    // Eq. 30: yddot = S^T qdd = A u - B.
    let ydd = &out("accel_level", "qdd2") - &out("accel_level", "qdd3");
    assert_eq!(ydd, &(&a * &s(Sym::U)) - &b);
    // Eq. 31: with u = A^-1 (v + B) the output obeys yddot = v.
    let ydd_closed = &out("closed_loop_level", "qdd2") - &out("closed_loop_level", "qdd3");
    assert_eq!(ydd_closed, s(Sym::V));
    assert_eq!(
        out("closed_loop_level", "u"),
        div(&(&s(Sym::V) + &b), &a),
        "u of Eq. 31"
    );
    // The torso's only torque is -u (S = [0, 0, 1, -1], Eqs. 19-20), so th2dd = -u / I2; the
    // simulator's Jacobian of the input power relies on it.
    assert_eq!(
        out("closed_loop_level", "qdd3"),
        -div(&out("closed_loop_level", "u"), &s(Sym::I2)),
        "th2dd = -u / I2"
    );
}

#[test]
fn the_staged_closed_loop_composes_to_its_definition_and_a_wrong_one_is_caught() {
    let k = derivation()
        .kernel("closed_loop_level")
        .expect("kernel exists");
    let staged = k
        .staged
        .as_ref()
        .expect("closed_loop_level has a staged form");
    assert_eq!(staged.locals.len(), 1, "u is the one local");
    k.check_staged().expect("u once, then Eq. 27 with it");
    // The same stages with the wrong sign of v in u must be rejected.
    let mut wrong = k.clone();
    if let Some(st) = wrong.staged.as_mut() {
        let u = st.locals[0].1.clone();
        st.locals[0].1 = u
            .substitute(Atom::Sym(Sym::V), &-s(Sym::V))
            .expect("substitute");
    }
    assert!(wrong.check_staged().is_err(), "a wrong staged form passes");
}

#[test]
fn yd_boundary_conditions_hold() {
    paper::check_desired_output().expect("boundary conditions of y_d");
    let [yd, ydd, yddd] = paper::desired_output().expect("y_d");
    let t_set = s(Sym::TSet);
    let half = &s(Sym::Alpha) * &frac(1, 2);
    let at = |f: &RatFunc, t: &RatFunc| f.substitute(Atom::Sym(Sym::T), t).expect("subst");
    assert_eq!(at(&yd, &RatFunc::zero()), -&half);
    assert_eq!(at(&yd, &t_set), half);
    for f in [&ydd, &yddd] {
        assert!(at(f, &RatFunc::zero()).is_zero());
        assert!(at(f, &t_set).is_zero());
    }
    // The printed polynomial: 6 a t^5/T^5 - 15 a t^4/T^4 + 10 a t^3/T^3 - a/2.
    let (a, t) = (s(Sym::Alpha), s(Sym::T));
    let term = |k: i64, n: i32| {
        let tn = t.powi(n).expect("power");
        let ts = t_set.powi(n).expect("power");
        div(&(&(&int(k) * &a) * &tn), &ts)
    };
    let printed = &(&(&term(6, 5) - &term(15, 4)) + &term(10, 3)) - &(&a * &frac(1, 2));
    assert_eq!(yd, printed);
}

// ---------------------------------------------------------------------------------------------
// Eqs. 3-18: the impact on level ground
// ---------------------------------------------------------------------------------------------

#[test]
fn eq03_fore_foot_velocity_and_eq07_12_jacobians() {
    let d = derivation();
    let (l, z) = (s(Sym::L), s(Sym::Z));
    // Eq. 3: z + l cos th1 - l cos(alpha - th1) is the height of the fore foot.
    let height = &(&z + &(&l * &cos1(Sym::Th1)))
        - &(&l * &cos(&[(Sym::Alpha, 1), (Sym::Th1, -1)]).expect("angle"));
    assert_eq!(out("fore_foot", "z_f"), height);
    assert_eq!(out("fore_foot", "zd_f"), paper::time_derivative(&height));
    // Eq. 7 (three rows) and Eq. 12 (rows 1 and 3), as printed.
    let row1 = vec![
        int(0),
        int(1),
        &(-(&l * &sin1(Sym::Th1)))
            + &(&l * &sin(&[(Sym::Th1, 1), (Sym::Alpha, -1)]).expect("angle")),
        int(0),
    ];
    let row2 = vec![int(0), int(1), int(0), int(0)];
    let row3 = vec![int(0), int(0), int(1), int(-1)];
    assert_eq!(
        d.quantities.impact3.jacobian,
        mat(vec![row1.clone(), row2, row3.clone()]),
        "J_I of Eq. 7"
    );
    assert_eq!(
        d.quantities.impact2.jacobian,
        mat(vec![row1, row3]),
        "J_I of Eq. 12"
    );
    // Eq. 12 says J_I in R^{2x3}; it is 2 x 4 (four generalized velocities).
    assert_eq!(
        (
            d.quantities.impact2.jacobian.rows(),
            d.quantities.impact2.jacobian.cols()
        ),
        (2, 4)
    );
}

#[test]
fn eq08_09_from_the_printed_matrices() {
    // lambda_I = -X_I^-1 J_I qd- and qd+ = (I - M^-1 J_I^T X_I^-1 J_I) qd- (Eqs. 8-9) with the
    // paper's M (Eq. 2) and J_I (Eq. 7): the same as the kernels, at any th1.
    let d = derivation();
    let m_inv = paper_mass_matrix().inverse("M").expect("regular");
    let qd = Matrix::column(paper::QD_SYMS.iter().map(|x| s(*x)).collect());
    for (imp, kernel) in [
        (&d.quantities.impact3, "impact3_level"),
        (&d.quantities.impact2, "impact2_level"),
    ] {
        let j = &imp.jacobian;
        let x = mul(&mul(j, &m_inv), &j.transpose());
        let x_inv = x.inverse("X_I").expect("regular");
        let lambda = mul(&x_inv, &mul(j, &qd)).scale(&int(-1));
        let proj = Matrix::identity(4)
            .sub(&mul(&mul(&mul(&m_inv, &j.transpose()), &x_inv), j))
            .expect("dims");
        let qd_plus = mul(&proj, &qd);
        for k in 0..lambda.rows() {
            assert_eq!(
                lambda.get(k, 0),
                &out(kernel, &format!("lambdaI{k}")),
                "{kernel} lambda_I[{k}]"
            );
        }
        for k in 0..4 {
            assert_eq!(
                qd_plus.get(k, 0),
                &out(kernel, &format!("qdp{k}")),
                "{kernel} qd+[{k}]"
            );
        }
        // J_I qd+ = 0 (Eq. 6).
        assert_eq!(mul(j, &qd_plus), Matrix::zeros(j.rows(), 1));
    }
}

#[test]
fn eq08_impulses_at_the_posture_and_the_third_entry() {
    let (it, l, w) = (total_inertia(), s(Sym::L), s(Sym::Th1d));
    let four_l_s = &(&int(4) * &l) * &sin_half_alpha();
    let k = k_alpha();
    let lambda1 = div(&(&(&(&int(2) * &it) + &k) * &w), &four_l_s);
    let lambda2 = -div(&(&(&(&int(2) * &it) - &k) * &w), &four_l_s);
    assert_eq!(
        at_level(&out("impact3_level", "lambdaI0")),
        lambda1,
        "Eq. 8 row 1"
    );
    assert_eq!(
        at_level(&out("impact3_level", "lambdaI1")),
        lambda2,
        "Eq. 8 row 2"
    );
    // Eq. 8 prints two entries of the 3-vector lambda_I; the third, the torso-lock impulse,
    // is I2 th1d-: the torso stops (th2d+ = 0) from th2d- = th1d-.
    assert_eq!(
        at_level(&out("impact3_level", "lambdaI2")),
        &s(Sym::I2) * &w,
        "lambda_I3 (not printed)"
    );
    for p in points() {
        let p = p.level_impact();
        let h = (p.alpha / 2.0).sin();
        let k = p.mt() * p.l * p.l * (1.0 - p.alpha.cos());
        let want1 = (2.0 * p.it() + k) / (4.0 * p.l * h) * p.th1d;
        let want2 = -(2.0 * p.it() - k) / (4.0 * p.l * h) * p.th1d;
        close(
            p.eval(&out("impact3_level", "lambdaI0")),
            want1,
            "Eq. 8 row 1",
        );
        close(
            p.eval(&out("impact3_level", "lambdaI1")),
            want2,
            "Eq. 8 row 2",
        );
        close(
            p.eval(&out("impact3_level", "lambdaI2")),
            p.i2 * p.th1d,
            "lambda_I3",
        );
    }
}

#[test]
fn eq10_velocities_after_the_three_constraint_impact() {
    let want = [
        &s(Sym::Xd) + &(&(&s(Sym::L) * &s(Sym::Th1d)) * &RatFunc::cos_of(BaseAngle::HalfAlpha)),
        int(0),
        int(0),
        int(0),
    ];
    for (k, w) in want.iter().enumerate() {
        assert_eq!(
            at_level(&out("impact3_level", &format!("qdp{k}"))),
            *w,
            "Eq. 10 row {k}"
        );
    }
    for p in points() {
        let p = p.level_impact();
        let x = p.xd + p.l * p.th1d * (p.alpha / 2.0).cos();
        close(p.eval(&out("impact3_level", "qdp0")), x, "Eq. 10");
        for k in 1..4 {
            close(
                p.eval(&out("impact3_level", &format!("qdp{k}"))),
                0.0,
                "Eq. 10",
            );
        }
    }
}

#[test]
fn eq11_rear_impulse_sign_is_the_printed_inequality() {
    // lambda_I2 >= 0 (the rear foot pushes on the floor, double support persists) exactly when
    // m_t l^2 (1 - cos alpha) >= 2 I_t, for th1d- > 0:
    //     lambda_I2 * 4 l sin(alpha/2) / th1d- = m_t l^2 (1 - cos alpha) - 2 I_t.
    let margin = div(
        &(&at_level(&out("impact3_level", "lambdaI1"))
            * &(&(&int(4) * &s(Sym::L)) * &sin_half_alpha())),
        &s(Sym::Th1d),
    );
    let paper = &k_alpha() - &(&int(2) * &total_inertia());
    assert_eq!(margin, paper);
}

#[test]
fn eq12_16_two_constraint_impact_at_the_posture() {
    let (it, i2, l, w, xd) = (
        total_inertia(),
        s(Sym::I2),
        s(Sym::L),
        s(Sym::Th1d),
        s(Sym::Xd),
    );
    let (mt, sh) = (total_mass(), sin_half_alpha());
    let k = k_alpha();
    let plus = &(&int(2) * &it) + &k;
    let minus = &(&int(2) * &it) - &k;
    // Eq. 13
    let factor = div(&(&(&(&(&int(4) * &mt) * &l) * &sh) * &w), &plus);
    assert_eq!(at_level(&out("impact2_level", "lambdaI0")), &factor * &it);
    assert_eq!(
        at_level(&out("impact2_level", "lambdaI1")),
        &factor * &(&(&i2 * &l) * &sh),
        "Eq. 13 second element"
    );
    // Eq. 14
    let dx = div(
        &(&(&(&(&(&(&int(2) * &mt) * &l) * &l) * &l) * &sh) * &sin1(Sym::Alpha)),
        &plus,
    );
    assert_eq!(at_level(&out("impact2_level", "qdp0")), &xd + &(&dx * &w));
    // Eq. 15
    let dz = div(&(&(&(&int(2) * &l) * &sh) * &minus), &plus);
    assert_eq!(at_level(&out("impact2_level", "qdp1")), &dz * &w);
    // Eq. 16
    let ratio = div(&minus, &plus);
    assert_eq!(at_level(&out("impact2_level", "qdp2")), &ratio * &w);
    assert_eq!(at_level(&out("impact2_level", "qdp3")), &ratio * &w);
    for p in points() {
        let p = p.level_impact();
        let h = (p.alpha / 2.0).sin();
        let k = p.mt() * p.l * p.l * (1.0 - p.alpha.cos());
        let (plus, minus) = (2.0 * p.it() + k, 2.0 * p.it() - k);
        let f = 4.0 * p.mt() * p.l * h * p.th1d / plus;
        close(
            p.eval(&out("impact2_level", "lambdaI0")),
            f * p.it(),
            "Eq. 13",
        );
        close(
            p.eval(&out("impact2_level", "lambdaI1")),
            f * p.i2 * p.l * h,
            "Eq. 13",
        );
        let x = p.xd + 2.0 * p.mt() * p.l.powi(3) * h * p.alpha.sin() / plus * p.th1d;
        close(p.eval(&out("impact2_level", "qdp0")), x, "Eq. 14");
        let z = 2.0 * p.l * h * minus / plus * p.th1d;
        close(p.eval(&out("impact2_level", "qdp1")), z, "Eq. 15");
        close(
            p.eval(&out("impact2_level", "qdp2")),
            minus / plus * p.th1d,
            "Eq. 16",
        );
        close(
            p.eval(&out("impact2_level", "qdp3")),
            minus / plus * p.th1d,
            "Eq. 16",
        );
    }
}

#[test]
fn eq15_sign_of_zd_plus_and_the_equivalence_of_c1_and_c2() {
    // Eq. 15: zd+ = 2 l sin(alpha/2) (2 I_t - K) / (2 I_t + K) th1d- with K = m_t l^2 (1 - cos
    // alpha). If Eq. 11 holds (K >= 2 I_t), zd+ <= 0: the rear foot would move into the floor
    // (condition C1), the same case as lambda_I2 >= 0 (C2). The text under Eq. 16 says zd+
    // "becomes positive if the condition of Eq. (11) holds"; it becomes negative.
    //     zd+ (two constraints) * lambda_I2 (three constraints)
    //       = -(2 I_t - K)^2 th1d^2 / (2 (2 I_t + K)) <= 0.
    let it2 = &int(2) * &total_inertia();
    let k = k_alpha();
    let w = s(Sym::Th1d);
    let zd_plus = at_level(&out("impact2_level", "qdp1"));
    let rear = at_level(&out("impact3_level", "lambdaI1"));
    let minus = &it2 - &k;
    let want = -div(
        &(&(&(&minus * &minus) * &w) * &w),
        &(&int(2) * &(&it2 + &k)),
    );
    assert_eq!(&zd_plus * &rear, want);
    // th1d+ (Eq. 16) has the sign of 2 I_t - K as well: negative iff Eq. 11 holds (the text is
    // right there).
    let th_plus = at_level(&out("impact2_level", "qdp2"));
    assert_eq!(
        div(&(&th_plus * &(&it2 + &k)), &w),
        minus,
        "th1d+ (2 I_t + K) / th1d- = 2 I_t - K"
    );
}

#[test]
fn eq17_18_reset_on_level_ground() {
    // The fore foot at the posture: x_f - x = 2 l sin(alpha/2), z_f = z (Eq. 17, z+- = 0), and
    // the new stance leg, the spoke at th1 - alpha, has th1+ = -alpha/2 (Eq. 18).
    let d = derivation();
    let g = &d.quantities.dynamics.geometry;
    let posture = |r: &RatFunc| paper::at_impact_posture(r, Floor::Level).expect("posture");
    let two_l_s = &(&int(2) * &s(Sym::L)) * &sin_half_alpha();
    assert_eq!(posture(&(&g.fore_foot[0] - &s(Sym::X))), two_l_s, "Eq. 17");
    assert_eq!(posture(&g.fore_foot[1]), s(Sym::Z), "z+ = z-");
    // hip - fore foot = l (sin th1+, cos th1+) with th1+ = -alpha/2
    let l = s(Sym::L);
    let sin_new = -sin_half_alpha();
    let cos_new = RatFunc::cos_of(BaseAngle::HalfAlpha);
    assert_eq!(
        posture(&(&g.hip[0] - &g.fore_foot[0])),
        &l * &sin_new,
        "Eq. 18"
    );
    assert_eq!(
        posture(&(&g.hip[1] - &g.fore_foot[1])),
        &l * &cos_new,
        "Eq. 18"
    );
}

#[test]
fn eq33_torso_locked_impact_leaves_ydot_zero() {
    // "PD feedback is not necessary because y+ = -alpha/2 and yd+ = 0": the torso lock makes
    // th1d+ = th2d+ for any pre-impact state.
    assert_eq!(out("impact2_level", "qdp2"), out("impact2_level", "qdp3"));
    assert_eq!(out("impact3_level", "qdp2"), out("impact3_level", "qdp3"));
}

// ---------------------------------------------------------------------------------------------
// Section 5: the slope (Eqs. 35-47)
// ---------------------------------------------------------------------------------------------

#[test]
fn eq36_38_slope_contact_is_the_printed_one_times_cos_phi() {
    // The derivation constrains the signed distance along the unit normal; the paper's rows are
    // that divided by cos(phi), so that lambda is the vertical reaction. Same force either way.
    let d = derivation();
    let (tp, cp, mu) = (
        tan_phi().expect("tan"),
        RatFunc::cos_of(BaseAngle::Phi),
        s(Sym::Mu),
    );
    let j = Matrix::row(vec![tp.clone(), int(1), int(0), int(0)]);
    let j_mu = Matrix::row(vec![mu.clone(), -(&mu * &tp), int(0), int(0)]);
    assert_eq!(
        d.quantities.slope.contact.jacobian,
        j.scale(&cp),
        "Eq. 36 times cos(phi)"
    );
    assert_eq!(
        d.quantities.slope.contact.friction,
        j_mu.scale(&cp),
        "Eq. 38 times cos(phi)"
    );
    // Eq. 38: [cos phi, -sin phi] mu lambda / cos phi = [mu, -mu tan phi] lambda
    let lhs = Matrix::row(vec![
        cp.clone(),
        -RatFunc::sin_of(BaseAngle::Phi),
        int(0),
        int(0),
    ])
    .scale(&div(&mu, &cp));
    assert_eq!(lhs, j_mu);
    // lambda on the slope (u = 0) from Eq. 22 with the printed J, J_mu, M, h.
    let m_inv = paper_mass_matrix().inverse("M").expect("regular");
    let jm = mul(&j, &m_inv);
    let top = mul(&jm, &paper_bias().scale(&int(-1)))
        .scalar()
        .expect("1x1");
    let bottom = mul(&jm, &j.add(&j_mu).expect("dims").transpose())
        .scalar()
        .expect("1x1");
    assert_eq!(-div(&top, &bottom), out("lambda_slope", "lambda"));
    // the normal force is lambda / cos phi
    assert_eq!(
        div(&out("lambda_slope", "lambda"), &cp),
        d.quantities
            .slope
            .normal_force
            .substitute(Atom::Sym(Sym::U), &RatFunc::zero())
            .expect("subst")
    );
}

#[test]
fn eq37_tangential_speed_is_xd_over_cos_phi() {
    // On z = -x tan phi, |(xd, zd)| = |xd| / cos phi.
    let xd = s(Sym::Xd);
    let zd = -(&xd * &tan_phi().expect("tan"));
    let cp = RatFunc::cos_of(BaseAngle::Phi);
    assert_eq!(&(&xd * &xd) + &(&zd * &zd), div(&(&xd * &xd), &(&cp * &cp)));
}

#[test]
fn eq37_38_slope_friction_dissipates() {
    // The passive wheel on the slope (u = 0, zd = -xd tan phi, qdd of `accel_slope`): the
    // energy changes by the friction power only, the force [mu, -mu tan phi] lambda (Eq. 38)
    // times the foot velocity (xd, -xd tan phi):
    //     dE/dt = mu lambda xd (1 + tan^2 phi) = mu lambda xd / cos^2 phi,
    // dissipative iff mu xd <= 0, which Eq. 37's -mu0 tanh(c xd / cos phi) is.
    let energy = &out("energy", "T") + &out("energy", "V");
    let mut rate = paper::time_derivative(&energy);
    for (k, qdd) in paper::QDD_SYMS.iter().enumerate() {
        rate = rate
            .substitute(Atom::Sym(*qdd), &out("accel_slope", &format!("qdd{k}")))
            .expect("substitution");
    }
    let zd = -(&s(Sym::Xd) * &tan_phi().expect("tan"));
    let rate = rate
        .substitute(Atom::Sym(Sym::Zd), &zd)
        .expect("substitution");
    let cp = RatFunc::cos_of(BaseAngle::Phi);
    let friction_power = div(
        &(&(&s(Sym::Mu) * &out("lambda_slope", "lambda")) * &s(Sym::Xd)),
        &(&cp * &cp),
    );
    assert_eq!(rate, friction_power);
}

#[test]
fn eq39_fore_foot_velocity_as_printed() {
    let (l, w) = (s(Sym::L), s(Sym::Th1d));
    let a_minus_th = [(Sym::Alpha, 1), (Sym::Th1, -1)];
    let xd = &(&s(Sym::Xd) + &(&(&l * &w) * &cos1(Sym::Th1)))
        - &(&(&l * &w) * &cos(&a_minus_th).expect("angle"));
    let zd = &(&s(Sym::Zd) - &(&(&l * &w) * &sin1(Sym::Th1)))
        - &(&(&l * &w) * &sin(&a_minus_th).expect("angle"));
    assert_eq!(out("fore_foot", "xd_f"), xd);
    assert_eq!(out("fore_foot", "zd_f"), zd);
}

/// Eq. 42 as printed: J_I = [tan phi, 1, l (sin(phi - th1) - sin(phi - th1 + alpha)) / cos phi, 0].
fn paper_slope_fore_row() -> Vec<RatFunc> {
    let l = s(Sym::L);
    let cp = RatFunc::cos_of(BaseAngle::Phi);
    let a = sin(&[(Sym::Phi, 1), (Sym::Th1, -1)]).expect("angle");
    let b = sin(&[(Sym::Phi, 1), (Sym::Th1, -1), (Sym::Alpha, 1)]).expect("angle");
    vec![
        tan_phi().expect("tan"),
        int(1),
        div(&(&l * &(&a - &b)), &cp),
        int(0),
    ]
}

#[test]
fn eq42_slope_impact_row_and_the_vertical_impulse() {
    let d = derivation();
    let cp = RatFunc::cos_of(BaseAngle::Phi);
    let row = Matrix::row(paper_slope_fore_row());
    assert_eq!(
        d.quantities.impact_slope.jacobian,
        row.scale(&cp),
        "Eq. 42 times cos(phi)"
    );
    // With the printed row, lambda_I = -(J M^-1 J^T)^-1 J qd- is the kernel's impulse: the
    // kernels report the paper's (vertical) scaling.
    let m_inv = paper_mass_matrix().inverse("M").expect("regular");
    let qd = Matrix::column(paper::QD_SYMS.iter().map(|x| s(*x)).collect());
    let x = mul(&mul(&row, &m_inv), &row.transpose())
        .scalar()
        .expect("1x1");
    let lambda = -div(&mul(&row, &qd).scalar().expect("1x1"), &x);
    assert_eq!(lambda, out("impact_slope", "lambdaI0"));
    // Same for the two-constraint slope impact (rear row [tan phi, 1, 0, 0]).
    let rear = vec![tan_phi().expect("tan"), int(1), int(0), int(0)];
    let j2 = mat(vec![paper_slope_fore_row(), rear]);
    let x2 = mul(&mul(&j2, &m_inv), &j2.transpose());
    let lambda2 = mul(&x2.inverse("X_I").expect("regular"), &mul(&j2, &qd)).scale(&int(-1));
    assert_eq!(lambda2.get(0, 0), &out("impact2_slope", "lambdaI0"));
    assert_eq!(lambda2.get(1, 0), &out("impact2_slope", "lambdaI1"));
    for p in points() {
        let p = p.slope_impact();
        let row = [
            p.phi.tan(),
            1.0,
            p.l * ((p.phi - p.th1).sin() - (p.phi - p.th1 + p.alpha).sin()) / p.phi.cos(),
            0.0,
        ];
        for (k, w) in row.iter().enumerate() {
            close(
                p.eval(d.quantities.impact_slope.jacobian.get(0, k)) / p.phi.cos(),
                *w,
                "Eq. 42",
            );
        }
        // at th1 = alpha/2 + phi the third entry is -2 l sin(alpha/2) / cos(phi)
        close(
            row[2],
            -2.0 * p.l * (p.alpha / 2.0).sin() / p.phi.cos(),
            "Eq. 42 at the posture",
        );
    }
}

#[test]
fn eq43_45_reset_on_the_slope() {
    let d = derivation();
    let g = &d.quantities.dynamics.geometry;
    let posture = |r: &RatFunc| paper::at_impact_posture(r, Floor::Slope).expect("posture");
    let (l, sh) = (s(Sym::L), sin_half_alpha());
    let two_l_s = &(&int(2) * &l) * &sh;
    let (sp, cp) = (
        RatFunc::sin_of(BaseAngle::Phi),
        RatFunc::cos_of(BaseAngle::Phi),
    );
    assert_eq!(
        posture(&(&g.fore_foot[0] - &s(Sym::X))),
        &two_l_s * &cp,
        "Eq. 43"
    );
    assert_eq!(
        posture(&(&g.fore_foot[1] - &s(Sym::Z))),
        -(&two_l_s * &sp),
        "Eq. 44"
    );
    // Eq. 47: the step along the slope is 2 l sin(alpha/2).
    assert_eq!(div(&posture(&(&g.fore_foot[0] - &s(Sym::X))), &cp), two_l_s);
    // Eq. 45: the new stance leg is the spoke at th1- - alpha = phi - alpha/2:
    // hip - fore foot = l (sin(phi - alpha/2), cos(phi - alpha/2)). The paper prints
    // alpha/2 - phi, the negative.
    let sin_new = &(&sp * &RatFunc::cos_of(BaseAngle::HalfAlpha)) - &(&cp * &sh);
    let cos_new = &(&cp * &RatFunc::cos_of(BaseAngle::HalfAlpha)) + &(&sp * &sh);
    let hip_minus_fore = [
        posture(&(&g.hip[0] - &g.fore_foot[0])),
        posture(&(&g.hip[1] - &g.fore_foot[1])),
    ];
    assert_eq!(
        hip_minus_fore[0],
        &l * &sin_new,
        "sin th1+ = sin(phi - alpha/2)"
    );
    assert_eq!(
        hip_minus_fore[1],
        &l * &cos_new,
        "cos th1+ = cos(phi - alpha/2)"
    );
    let printed_sin = -&sin_new; // sin(alpha/2 - phi)
    assert_ne!(hip_minus_fore[0], &l * &printed_sin, "Eq. 45 as printed");
    for p in points() {
        let p = p.slope_impact();
        let a = p.atoms();
        let dx = g.hip[0].eval(&a) - g.fore_foot[0].eval(&a);
        let dz = g.hip[1].eval(&a) - g.fore_foot[1].eval(&a);
        let th_plus = dx.atan2(dz);
        close(th_plus, p.phi - p.alpha / 2.0, "Eq. 45 derived");
        close(
            g.fore_foot[0].eval(&a) - 0.0,
            2.0 * p.l * (p.alpha / 2.0).sin() * p.phi.cos(),
            "Eq. 43",
        );
        close(
            g.fore_foot[1].eval(&a) - 0.0,
            -2.0 * p.l * (p.alpha / 2.0).sin() * p.phi.sin(),
            "Eq. 44",
        );
    }
}

#[test]
fn eq46_rear_impulse_on_the_slope() {
    // impact2_slope's rear impulse (vertical) at the posture:
    //     lambda_I2 * 4 l sin(alpha/2) / (th1d- cos phi) = m_t l^2 (1 - cos alpha) - 2 I_1:
    // the torso (decoupled, no lock) drops out, as the paper notes under Eq. 46.
    let rear = at_slope(&out("impact2_slope", "lambdaI1"));
    let scale = div(
        &(&(&int(4) * &s(Sym::L)) * &sin_half_alpha()),
        &(&s(Sym::Th1d) * &RatFunc::cos_of(BaseAngle::Phi)),
    );
    assert_eq!(&rear * &scale, &k_alpha() - &(&int(2) * &s(Sym::I1)));
    // The slope impact in the slope's frame is the level one with I_t -> I_1 and no torso
    // lock: th1d+ = (2 I_1 - K) / (2 I_1 + K) th1d- (compare Eq. 16).
    let it2 = &int(2) * &s(Sym::I1);
    let k = k_alpha();
    assert_eq!(
        at_slope(&out("impact_slope", "qdp2")),
        &div(&(&it2 - &k), &(&it2 + &k)) * &s(Sym::Th1d)
    );
    for p in points() {
        let p = p.slope_impact();
        let k = p.mt() * p.l * p.l * (1.0 - p.alpha.cos());
        let got = p.eval(&out("impact2_slope", "lambdaI1")) * 4.0 * p.l * (p.alpha / 2.0).sin()
            / (p.th1d * p.phi.cos());
        close(got, k - 2.0 * p.i1, "Eq. 46");
    }
}

// ---------------------------------------------------------------------------------------------
// Table 1 and the numbers in the text
// ---------------------------------------------------------------------------------------------

/// Table 1 as exact rationals where they are rational: m1 = 2, m2 = 1, l = 1, r = 1,
/// I1 = m1 (l/2)^2 = 1/2, I2 = m2 r^2 = 1.
fn table1_q() -> [(Sym, Q); 5] {
    let q = |n: i64, d: i64| Q::new(n.into(), d.into());
    let (m1, l, r, m2) = (q(2, 1), q(1, 1), q(1, 1), q(1, 1));
    let half_l = &l / q(2, 1);
    let i1 = &m1 * &half_l * &half_l;
    let i2 = &m2 * &r * &r;
    [
        (Sym::M1, m1),
        (Sym::M2, m2),
        (Sym::L, l),
        (Sym::I1, i1),
        (Sym::I2, i2),
    ]
}

#[test]
fn table1_numbers_of_the_text() {
    let t = table1_q();
    let value = |s: Sym| {
        t.iter()
            .find(|(x, _)| *x == s)
            .map(|(_, v)| v.clone())
            .expect("in Table 1")
    };
    assert_eq!(value(Sym::I1), Q::new(1.into(), 2.into()), "I1 = 0.5");
    assert_eq!(value(Sym::I2), Q::new(1.into(), 1.into()), "I2 = 1.0");
    // Right-hand sides, exact: 2 I_t = 3.0 (Eq. 11; the text calls it "the total inertia
    // moment", it is twice that), 2 I_1 = 1.0 (Eq. 46).
    let two = Q::new(2.into(), 1.into());
    assert_eq!(
        &two * (value(Sym::I1) + value(Sym::I2)),
        Q::new(3.into(), 1.into())
    );
    assert_eq!(&two * value(Sym::I1), Q::new(1.into(), 1.into()));
    // Left-hand side of Eqs. 11 and 46 from the derived rear impulse: margin + 2 I_t with
    // alpha = 30 deg (irrational cosine: f64).
    let p = Pt {
        th1d: 1.0,
        ..Pt::random(&mut Rng(1)).table1()
    }
    .level_impact();
    let rear = p.eval(&out("impact3_level", "lambdaI1"));
    let margin = rear * 4.0 * p.l * (p.alpha / 2.0).sin() / p.th1d;
    let left = margin + 2.0 * p.it();
    assert_eq!(format!("{left:.3}"), "0.402", "left side of Eq. 11: {left}");
    assert!(
        margin < 0.0,
        "Eq. 11 does not hold: the rear leg leaves the ground"
    );
    let ps = Pt { phi: 0.1, ..p }.slope_impact();
    let rear_s = ps.eval(&out("impact2_slope", "lambdaI1"));
    let margin_s = rear_s * 4.0 * ps.l * (ps.alpha / 2.0).sin() / (ps.th1d * ps.phi.cos());
    assert_eq!(
        format!("{:.3}", margin_s + 2.0 * ps.i1),
        "0.402",
        "left of Eq. 46"
    );
    assert!(margin_s < 0.0, "Eq. 46 does not hold either");
    // Step length of Fig. 8 (b): 2 l sin(alpha/2) from the fore foot at the posture.
    let a = p.atoms();
    let step = out("fore_foot", "x_f").eval(&a) - 0.0;
    assert_eq!(
        format!("{step:.6}"),
        "0.517638",
        "2 l sin(alpha/2) = {step}"
    );
}

// ---------------------------------------------------------------------------------------------
// Exact rational evaluation against f64
// ---------------------------------------------------------------------------------------------

/// A rational point: rational parameters, and every angle at a rational point of the unit
/// circle (`sin = 2t/(1+t^2)`, `cos = (1-t^2)/(1+t^2)`), so that `sin^2 + cos^2 = 1` holds
/// exactly and the reduced form evaluates to the function's exact value.
fn rational_point(seed: u64) -> (Point<Q>, Point<f64>) {
    let mut rng = Rng(seed);
    let table = Symbols::paper();
    let mut q: Point<Q> = Point::zeros(&table);
    let mut rat = |lo: i64, hi: i64| {
        let n = lo + (rng.next() * (hi - lo) as f64) as i64;
        Q::new(n.into(), 16.into())
    };
    for s in table.syms() {
        q.set(s.slot(), rat(4, 40));
    }
    for s in [
        Sym::Mu,
        Sym::U,
        Sym::Xd,
        Sym::Zd,
        Sym::Th1d,
        Sym::Th2d,
        Sym::V,
    ] {
        q.set(s.slot(), rat(-20, 20));
    }
    for a in table.base_angles() {
        let t = rat(-6, 6);
        let one = Q::from_integer(1.into());
        let two = Q::from_integer(2.into());
        let den = &one + &t * &t;
        q.set(a.sin_slot(), &two * &t / &den);
        q.set(a.cos_slot(), (&one - &t * &t) / &den);
    }
    let mut f = Point::zeros(&table);
    for s in table.syms() {
        f.set(s.slot(), q.value(s.slot()).to_f64().unwrap_or(f64::NAN));
    }
    for a in table.base_angles() {
        for slot in [a.sin_slot(), a.cos_slot()] {
            f.set(slot, q.value(slot).to_f64().unwrap_or(f64::NAN));
        }
    }
    (q, f)
}

/// Sum of the absolute values of the terms at a point.
fn abs_sum(p: &Poly, v: &Point<f64>) -> f64 {
    p.terms()
        .iter()
        .map(|(m, c)| {
            let mut t = c.to_f64().unwrap_or(f64::NAN).abs();
            for (slot, e) in m.factors() {
                t *= v.value(slot).abs().powi(i32::from(e));
            }
            t
        })
        .sum()
}

#[test]
fn exact_rational_evaluation_agrees_with_f64() {
    let d = derivation();
    let mut checked = 0;
    for seed in [11, 12, 13] {
        let (q, f) = rational_point(seed);
        for k in &d.kernels {
            // the Jacobian kernels have thousands of terms: one point is enough for them
            if k.name.ends_with("_jacobian") && seed != 11 {
                continue;
            }
            for (name, r) in &k.outputs {
                let Ok(exact) = r.eval_exact(&q) else {
                    continue; // a pole at this point
                };
                let exact = exact.to_f64().unwrap_or(f64::NAN);
                let got = r.eval(&f);
                let (n, dn) = (r.num().eval(&f), r.den().eval(&f));
                let cond = abs_sum(r.num(), &f) / n.abs().max(f64::MIN_POSITIVE)
                    + abs_sum(r.den(), &f) / dn.abs().max(f64::MIN_POSITIVE);
                let terms = (r.num().len() + r.den().len()) as f64;
                let bound = 8.0 * terms * f64::EPSILON * cond * exact.abs() + f64::MIN_POSITIVE;
                assert!(
                    (got - exact).abs() <= bound,
                    "{} {name}: f64 {got:e}, exact {exact:e}, bound {bound:e}",
                    k.name
                );
                checked += 1;
            }
        }
    }
    assert!(checked > 100);
}

// ---------------------------------------------------------------------------------------------
// Engine edge cases: errors, not panics
// ---------------------------------------------------------------------------------------------

#[test]
fn singular_matrix_is_an_error() {
    let m = mat(vec![
        vec![s(Sym::M1), s(Sym::L)],
        vec![&s(Sym::M1) * &int(2), &s(Sym::L) * &int(2)],
    ]);
    assert_eq!(
        m.inverse("S"),
        Err(Error::SingularMatrix { name: "S".into() })
    );
    // A matrix singular only through sin^2 + cos^2 = 1.
    let (s1, c1) = (sin1(Sym::Th1), cos1(Sym::Th1));
    let m = mat(vec![
        vec![s1.clone(), &int(1) - &(&c1 * &c1)],
        vec![int(1), s1],
    ]);
    assert!(matches!(m.inverse("T"), Err(Error::SingularMatrix { .. })));
    // Non-square: a dimension error.
    let r = Matrix::row(vec![int(1), int(2)]);
    assert!(matches!(r.inverse("R"), Err(Error::Dimension { .. })));
    assert!(matches!(r.mul(&r), Err(Error::Dimension { .. })));
}

#[test]
fn division_by_zero_is_an_error() {
    assert_eq!(
        RatFunc::one().div(&RatFunc::zero()),
        Err(Error::DivisionByZero)
    );
    // zero only after the trigonometric reduction
    let (s1, c1) = (sin1(Sym::Th1), cos1(Sym::Th1));
    let zero = &(&(&s1 * &s1) + &(&c1 * &c1)) - &int(1);
    assert_eq!(s(Sym::L).div(&zero), Err(Error::DivisionByZero));
    assert_eq!(RatFunc::zero().recip(), Err(Error::DivisionByZero));
    assert_eq!(
        RatFunc::new(Poly::one(), Poly::zero()).map(|_| ()),
        Err(Error::DivisionByZero)
    );
    // exact evaluation at a pole
    let r = div(&int(1), &s(Sym::M1));
    let zeros: Point<Q> = Point::zeros(&Symbols::paper());
    assert_eq!(r.eval_exact(&zeros), Err(Error::DivisionByZero));
}

#[test]
fn unknown_names_are_errors() {
    assert_eq!(
        Symbols::paper().lookup("theta1"),
        Err(Error::UnknownSymbol {
            name: "theta1".into()
        })
    );
    // A name turns into its symbol and so into an expression of the canonical form; a near
    // miss is an error, not a fresh symbol.
    let table = Symbols::paper();
    for x in table.syms() {
        assert_eq!(table.lookup(table.name(x)).map(paper::sym), Ok(s(x)));
    }
    assert_eq!(
        table.lookup("m3").map(paper::sym),
        Err(Error::UnknownSymbol { name: "m3".into() })
    );
    assert!(matches!(
        derivation().kernel("no_such_kernel"),
        Err(Error::UnknownKernel { .. })
    ));
}
