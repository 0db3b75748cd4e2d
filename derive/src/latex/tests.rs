//! Tests of the printer through its public entry points.

use super::*;
use crate::matrix::Matrix;
use crate::paper::Derivation;
use crate::paper::{self, cos, frac, int, sin, sym};
use crate::ratfunc::RatFunc;
use crate::symbol::{BaseAngle, Sym};

fn s(x: Sym) -> RatFunc {
    sym(x)
}

#[test]
fn atoms_in_the_papers_notation() {
    assert_eq!(
        ratfunc(&sin(&[(Sym::Th1, 1)]).expect("sin")),
        "\\sin\\theta_1"
    );
    assert_eq!(
        ratfunc(&RatFunc::cos_of(BaseAngle::HalfAlpha)),
        "\\cos\\frac{\\alpha}{2}"
    );
    assert_eq!(ratfunc(&RatFunc::sin_of(BaseAngle::Phi)), "\\sin\\phi");
    let s1 = sin(&[(Sym::Th1, 1)]).expect("sin");
    assert_eq!(ratfunc(&(&s1 * &s1)), "\\sin^2\\theta_1");
    assert_eq!(
        ratfunc(&(&s(Sym::Th1d) * &s(Sym::Th1d))),
        "\\dot{\\theta}_1^2"
    );
}

#[test]
fn constants_and_signs() {
    assert_eq!(ratfunc(&RatFunc::zero()), "0");
    assert_eq!(ratfunc(&int(-3)), "-3");
    assert_eq!(ratfunc(&frac(1, 2)), "\\frac{1}{2}");
    assert_eq!(ratfunc(&(&frac(-3, 4) * &s(Sym::L))), "-\\frac{3}{4} l");
}

#[test]
fn total_mass_is_abbreviated_by_division_and_by_substitution() {
    let mt = paper::total_mass();
    let l = s(Sym::L);
    // divisible: m_t^2 I_1 I_2 (det M)
    let det = &(&(&mt * &mt) * &s(Sym::I1)) * &s(Sym::I2);
    assert_eq!(ratfunc(&det), "m_t^2 I_1 I_2");
    // not divisible, but depends on the masses only through their sum
    let p = &s(Sym::I1) + &(&(&mt * &l) * &l);
    assert_eq!(ratfunc(&p), "I_1 + m_t l^2");
    // neither: m_1 alone stays
    let q = &s(Sym::M1) + &(&s(Sym::M2) * &l);
    assert_eq!(ratfunc(&q), "m_1 + m_2 l");
    // I_t
    let it = paper::total_inertia();
    assert_eq!(ratfunc(&(&int(2) * &it)), "2 I_t");
}

#[test]
fn fraction_with_content_split_above_and_below() {
    let it = paper::total_inertia();
    let den = &(&int(4) * &s(Sym::L)) * &paper::sin_half_alpha();
    let r = (&int(2) * &it).div(&den).expect("nonzero");
    assert_eq!(ratfunc(&r), "\\frac{I_t}{2 l \\sin\\frac{\\alpha}{2}}");
    let neg = r.neg();
    assert_eq!(ratfunc(&neg), "-\\frac{I_t}{2 l \\sin\\frac{\\alpha}{2}}");
}

#[test]
fn grouping_recovers_eq_23() {
    let d = Derivation::new().expect("derivation");
    let text = ratfunc(&d.quantities.level.lambda);
    assert_eq!(
        text,
        "\\frac{m_t \\left(I_1 \\left(g - l \\dot{\\theta}_1^2 \\cos\\theta_1\\right) - l u \\sin\\theta_1\\right)}\
         {I_1 + m_t l^2 \\left(\\sin\\theta_1 - \\mu \\cos\\theta_1\\right) \\sin\\theta_1}"
    );
}

#[test]
fn cosine_stays_after_the_group() {
    // l cos(th1) (a + b): the group comes before the cosine
    let c = cos(&[(Sym::Th1, 1)]).expect("cos");
    let p = &(&s(Sym::L) * &c) * &(&s(Sym::G) + &s(Sym::U));
    assert_eq!(ratfunc(&p), "l \\left(g + u\\right) \\cos\\theta_1");
}

#[test]
fn lowest_degree_term_leads_positive() {
    // -m_t (l thdot^2 cos - g) is printed m_t (g - l thdot^2 cos), as Eq. 20
    let d = Derivation::new().expect("derivation");
    assert_eq!(
        ratfunc(d.quantities.dynamics.bias.get(1, 0)),
        "m_t \\left(g - l \\dot{\\theta}_1^2 \\cos\\theta_1\\right)"
    );
}

#[test]
fn hidden_cosine_factors_are_pulled_out() {
    // I_1 - I_1 sin^2(phi) is I_1 cos^2(phi); over cos(phi) it is I_1 cos(phi)
    let sp = RatFunc::sin_of(BaseAngle::Phi);
    let cp = RatFunc::cos_of(BaseAngle::Phi);
    let p = &s(Sym::I1) - &(&(&s(Sym::I1) * &sp) * &sp);
    assert_eq!(ratfunc(&p), "I_1 \\cos^2\\phi");
    let r = p.div(&cp).expect("nonzero");
    assert_eq!(ratfunc(&r), "I_1 \\cos\\phi");
}

#[test]
fn shorter_in_a_shifted_angle() {
    // sin(th1 - phi) expands to two terms in th1 and phi; the printer shifts it back
    let r = sin(&[(Sym::Th1, 1), (Sym::Phi, -1)]).expect("sin");
    assert_eq!(ratfunc(&r), "\\sin\\left(\\theta_1 - \\phi\\right)");
    let c = cos(&[(Sym::Th1, 1), (Sym::Alpha, -1)]).expect("cos");
    let c2 = &c * &c;
    assert_eq!(ratfunc(&c2), "\\cos^2\\left(\\theta_1 - \\alpha\\right)");
}

#[test]
fn large_outputs_are_refused_by_the_bounded_printer() {
    let d = Derivation::new().expect("derivation");
    let k = d.kernel("impact_slope_jacobian").expect("kernel");
    let (_, big) = &k.outputs[0];
    assert!(ratfunc_at_most(big, MAX_PRINTED_TERMS).is_none());
    assert!(ratfunc_at_most(&d.quantities.level.lambda, MAX_PRINTED_TERMS).is_some());
}

#[test]
fn matrices_use_bmatrix() {
    let m =
        Matrix::from_rows(vec![vec![int(1), s(Sym::L)], vec![int(0), frac(1, 2)]]).expect("rows");
    assert_eq!(
        matrix(&m),
        "\\begin{bmatrix} 1 & l \\\\ 0 & \\frac{1}{2} \\end{bmatrix}"
    );
}

#[test]
fn output_is_deterministic() {
    let d = Derivation::new().expect("derivation");
    let k = d.kernel("impact2_level").expect("kernel");
    let a: Vec<String> = k.outputs.iter().map(|(_, r)| ratfunc(r)).collect();
    let b: Vec<String> = k.outputs.iter().map(|(_, r)| ratfunc(r)).collect();
    assert_eq!(a, b);
}
