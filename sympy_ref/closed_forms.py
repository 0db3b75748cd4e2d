"""Closed forms for the errata: simplified SymPy results of model.py compared with the paper's
printed equations.  Output goes to stdout (run.sh writes it to closed_forms.txt).

The paper's expressions are typed in here ONLY to compare them with the derivation; nothing in
model.py, kernels.py or steps.py uses them.
"""
from __future__ import annotations

import sys

import sympy as sp

import model as md
from model import (C1, CA, CP, I1, I2, S1, SA, SP, alpha, g, l, m1, m2, mu, phi, th1, th1d,
                   th2d, u, x, xd, z, zd)

# half-angle symbols: sh = sin(alpha/2), ch = cos(alpha/2)
sh, ch = sp.symbols("sh ch", real=True)
mt_, It_ = sp.symbols("m_t I_t", positive=True)
HALF = {SA: 2 * sh * ch, CA: ch ** 2 - sh ** 2}
PAIRS = [(ch, sh), (CP, SP), (C1, S1)]
BACK = {sh: sp.sin(alpha / 2), ch: sp.cos(alpha / 2), SP: sp.sin(phi), CP: sp.cos(phi),
        S1: sp.sin(th1), C1: sp.cos(th1)}
NICE = {m1 + m2: mt_}


def red(p):
    p = sp.expand(p)
    for c, s in PAIRS:
        if p.has(c):
            p = sp.expand(sp.rem(p, c ** 2 + s ** 2 - 1, c))
    return p


def rs(e):
    """Rational simplification modulo the Pythagorean identities (exact zero test)."""
    e = sp.cancel(sp.together(e))
    n, d = sp.fraction(e)
    n = red(n)
    if n == 0:
        return sp.Integer(0)
    return sp.cancel(n / red(d))


def poly_at(e, where):
    """Poly-form expression with th1 (and alpha) expressed through half-angle symbols."""
    if where == "level":       # th1 = alpha/2
        sub = {S1: sh, C1: ch, **HALF}
    elif where == "slope":     # th1 = alpha/2 + phi
        sub = {S1: sh * CP + ch * SP, C1: ch * CP - sh * SP, **HALF}
    else:
        sub = dict(HALF)
    return rs(sp.sympify(e).subs(sub))


def to_paper(e):
    """Readable form: half-angle symbols back to sin/cos, m1 + m2 -> m_t, factored."""
    e = sp.factor(e)
    e = e.subs(BACK)
    e = e.subs(m1, mt_ - m2)
    e = sp.factor(sp.simplify(e))
    return e


def paper_poly(e):
    """Paper expression (in alpha, m_t, I_t) to the half-angle poly form."""
    e = e.subs({mt_: m1 + m2, It_: I1 + I2})
    e = sp.expand_trig(e.subs({sp.cos(alpha): 1 - 2 * sp.sin(alpha / 2) ** 2}))
    e = e.subs({sp.sin(alpha / 2): sh, sp.cos(alpha / 2): ch, sp.sin(alpha): 2 * sh * ch})
    e = sp.expand_trig(e).subs({sp.sin(alpha / 2): sh, sp.cos(alpha / 2): ch,
                               sp.sin(phi): SP, sp.cos(phi): CP, sp.tan(phi): SP / CP})
    return rs(e)


OUT = []


def say(*a):
    OUT.append(" ".join(str(v) for v in a))


def compare(label, ours, paper):
    """ours: poly form; paper: expression in alpha, m_t, I_t (or None = not printed)."""
    say(f"  {label}:")
    say(f"    derived: {to_paper(ours)}")
    if paper is None:
        say("    paper:   (not printed)")
        return
    d = rs(ours - paper_poly(paper))
    say(f"    paper:   {paper}")
    if d == 0:
        say("    => AGREES")
    else:
        say(f"    => DISAGREES; derived - paper = {to_paper(d)}")
        # is it a sign error?
        if rs(ours + paper_poly(paper)) == 0:
            say("       (the printed expression has the opposite sign)")


def nice(e):
    """sin/cos form with m1 + m2 written as m_t, factored."""
    return sp.factor(sp.simplify(md.from_poly(e).subs(m1, mt_ - m2)))


def text():
    OUT.clear()
    mdl = md.derive()
    K = mdl.kernels
    mt = m1 + m2
    It = I1 + I2
    say("Closed forms derived by sympy_ref/model.py, compared with the printed equations of")
    say("Asano, Kikuchi, Shibata, 'Modeling, control and analysis of limit cycle walking on")
    say("slippery road surface'.  m_t = m1 + m2, I_t = I1 + I2.")
    say("")
    # ------------------------------------------------------------------ M, det M, h
    say("== Eq. 2: inertia matrix M(q) ==")
    say("  derived:", md.from_poly(mdl.M.applyfunc(md.to_poly)).subs(m1, mt_ - m2).applyfunc(
        sp.simplify).tolist())
    M_paper = sp.Matrix([[mt_, 0, mt_ * l * sp.cos(th1), 0],
                         [0, mt_, -mt_ * l * sp.sin(th1), 0],
                         [mt_ * l * sp.cos(th1), -mt_ * l * sp.sin(th1), mt_ * l ** 2 + I1, 0],
                         [0, 0, 0, I2]]).subs(mt_, mt)
    say("  => AGREES" if (mdl.M - M_paper).applyfunc(sp.simplify) == sp.zeros(4, 4)
        else "  => DISAGREES")
    say("")
    say("== det M ==")
    say("  derived:", sp.factor(md.from_poly(mdl.detM)).subs(m1 + m2, mt_))
    say("  (never zero for positive masses and inertias: M^-1 always exists)")
    say("")
    say("== Eq. 20: h(q, qd) ==")
    say("  derived:", [sp.factor(e).subs(m1 + m2, mt_) for e in mdl.h])
    h_paper = sp.Matrix([-mt * l * th1d ** 2 * sp.sin(th1),
                         mt * (g - l * th1d ** 2 * sp.cos(th1)),
                         -mt * g * l * sp.sin(th1)])
    ok = all(sp.simplify(mdl.h[i] - h_paper[i]) == 0 for i in range(3))
    say("  paper prints 3 entries:", "the 3 AGREE" if ok else "DISAGREE",
        "; the 4th entry (torso row) is", mdl.h[3], "and is missing from the print")
    say("")
    # ------------------------------------------------------------------ lambda level
    say("== Eq. 23: lambda on level ground (u, mu inputs) ==")
    lam = K["lambda_level"]["poly"][0][1]
    say("  derived:", nice(lam))
    lam_paper_p = (2 * mt_ * (I1 * (g - l * th1d ** 2 * sp.cos(th1)) - u * l * sp.sin(th1))
                   / (2 * I1 + mt_ * l ** 2 * (1 - sp.cos(2 * th1) - mu * sp.sin(2 * th1))))
    lam_paper = lam_paper_p.subs(mt_, mt)
    d = md.rsimp(lam - md.to_poly(lam_paper))
    say("  paper:  ", lam_paper_p)
    if d == 0:
        say("  => AGREES")
    else:
        say("  => DISAGREES; derived - paper =", nice(d))
        # identify which term is off
        for nm, alt in [("u term with + sign",
                         (2 * mt * (I1 * (g - l * th1d ** 2 * sp.cos(th1)) + u * l * sp.sin(th1))
                          / (2 * I1 + mt * l ** 2 * (1 - sp.cos(2 * th1)
                                                     - mu * sp.sin(2 * th1)))))]:
            if md.rsimp(lam - md.to_poly(alt)) == 0:
                say(f"     the derived lambda equals the printed one with the {nm}")
    say("  denominator J M^-1 (J + J_mu)^T =", nice(mdl.den_level))
    say("")
    # ------------------------------------------------------------------ Y, A, B
    say("== Eqs. 27-31: control_level A and B (ydd = A u - B) ==")
    for n, e in K["control_level"]["poly"]:
        say(f"  {n} =", nice(e))
    say("")
    # ------------------------------------------------------------------ impacts
    qd_minus = {zd: 0, th2d: th1d}
    say("== Eqs. 6-10: impact with three constraints (impact3_level) at th1 = alpha/2,")
    say("   zd- = 0, th2d- = th1d- ==")
    outs = {n: poly_at(e.subs(qd_minus), "level") for n, e in K["impact3_level"]["poly"]}
    s2 = sp.sin(alpha / 2)
    c_ = 1 - sp.cos(alpha)
    paper8 = [(2 * It_ + mt_ * l ** 2 * c_) / (4 * l * s2) * th1d,
              -(2 * It_ - mt_ * l ** 2 * c_) / (4 * l * s2) * th1d, None]
    names = ["lambdaI0 (fore foot, Eq. 8 row 1)", "lambdaI1 (rear foot, Eq. 8 row 2)",
             "lambdaI2 (torso lock, Eq. 8 row 3)"]
    for i in range(3):
        compare(names[i], outs[f"lambdaI{i}"], paper8[i])
    paper10 = [xd + l * th1d * sp.cos(alpha / 2), sp.Integer(0), sp.Integer(0), sp.Integer(0)]
    for i, n in enumerate(["xd+", "zd+", "th1d+", "th2d+"]):
        compare(f"{n} (Eq. 10)", outs[f"qdp{i}"], paper10[i])
    lam_rear = outs["lambdaI1"]
    say("  DLS test (Eq. 11): lambdaI1 >= 0 <=>",
        "th1d- * (", to_paper(rs(lam_rear * 4 * l * sh / th1d)), ") >= 0")
    say("")
    say("== Eqs. 12-16: impact with two constraints (impact2_level) at th1 = alpha/2,")
    say("   zd- = 0, th2d- = th1d- ==")
    outs = {n: poly_at(e.subs(qd_minus), "level") for n, e in K["impact2_level"]["poly"]}
    D = 2 * It_ + mt_ * l ** 2 * c_
    N = 2 * It_ - mt_ * l ** 2 * c_
    paper13 = [4 * mt_ * l * s2 * th1d / D * It_, 4 * mt_ * l * s2 * th1d / D * I2 * l * s2]
    compare("lambdaI0 (fore foot, Eq. 13 row 1)", outs["lambdaI0"], paper13[0])
    compare("lambdaI1 (torso lock, Eq. 13 row 2)", outs["lambdaI1"], paper13[1])
    paper14 = xd + 2 * mt_ * l ** 3 * s2 * sp.sin(alpha) / D * th1d
    paper15 = 2 * l * s2 * N / D * th1d
    paper16 = N / D * th1d
    compare("xd+ (Eq. 14)", outs["qdp0"], paper14)
    compare("zd+ (Eq. 15)", outs["qdp1"], paper15)
    compare("th1d+ (Eq. 16)", outs["qdp2"], paper16)
    compare("th2d+ (Eq. 16)", outs["qdp3"], paper16)
    say("  (C1)/(C2) equivalence: zd+ of this impact and lambdaI1 of impact3_level:")
    say("    zd+ / lambdaI1(impact3) =",
        to_paper(rs(outs["qdp1"] / lam_rear)))
    say("")
    # ------------------------------------------------------------------ slope
    say("== Eqs. 39-42: slope impact (impact_slope), fore-foot Jacobian ==")
    JI = mdl.JI["impact_slope"]
    J3 = sp.simplify(JI[0, 2] * sp.cos(phi))
    paper42 = l * (sp.sin(phi - th1) - sp.sin(phi - th1 + alpha))
    say("  J_I[2] * cos(phi) derived:", J3)
    say("  Eq. 42 third entry * cos(phi):", paper42,
        "=> AGREES" if sp.simplify(sp.expand_trig(J3 - paper42)) == 0 else "=> DISAGREES")
    say("  J_I derived:", JI.applyfunc(sp.simplify).tolist())
    xf, zf = mdl.fore
    xfd, zfd = mdl.fore_vel
    say("  Eq. 39 fore-foot velocity: derived xd_f =", sp.simplify(xfd), "; zd_f =",
        sp.simplify(zfd))
    p39x = xd + l * th1d * sp.cos(th1) - l * th1d * sp.cos(alpha - th1)
    p39z = zd - l * th1d * sp.sin(th1) - l * th1d * sp.sin(alpha - th1)
    say("  Eq. 39:", "AGREES" if (sp.simplify(xfd - p39x) == 0 and
                                  sp.simplify(sp.expand_trig(zfd - p39z)) == 0)
        else "DISAGREES")
    say("")
    say("== Eqs. 43-45: reset on the slope at th1- = alpha/2 + phi ==")
    dxf = poly_at(md.to_poly(xf - x), "slope")
    dzf = poly_at(md.to_poly(zf - z), "slope")
    compare("x+ - x- (Eq. 43)", dxf, 2 * l * s2 * sp.cos(phi))
    compare("z+ - z- (Eq. 44)", dzf, -2 * l * s2 * sp.sin(phi))
    say("  th1+ = th1- - alpha = (alpha/2 + phi) - alpha = phi - alpha/2;"
        " Eq. 45 prints alpha/2 - phi (sign error)")
    say("")
    say("== Eq. 46: DLS test on the slope (impact2_slope) at th1 = alpha/2 + phi with the")
    say("   pre-impact stance constraint zd- = -xd- tan(phi) ==")
    outs = {n: poly_at(e.subs({zd: -xd * SP / CP}), "slope")
            for n, e in K["impact2_slope"]["poly"]}
    lr = outs["lambdaI1"]
    say("  lambdaI1 (rear foot) =", to_paper(lr))
    ratio = rs(rs(lr / th1d) / paper_poly(mt_ * l ** 2 * (1 - sp.cos(alpha)) - 2 * I1))
    say("  lambdaI1 / (th1d- (m_t l^2 (1 - cos alpha) - 2 I1)) =", to_paper(ratio))
    free = ratio.free_symbols & {xd, zd, th1d, th2d, I2}
    say("  => the ratio does not depend on the velocities nor on I2; if it is positive, the")
    say("     rear-foot impulse is >= 0 exactly when m_t l^2 (1 - cos alpha) >= 2 I1 (th1d- > 0),")
    say("     i.e. Eq. 46", "is CONFIRMED" if not free else f"depends on {free}")
    say("  lambdaI0 (fore foot) =", to_paper(outs["lambdaI0"]))
    for i, n in enumerate(["xd+", "zd+", "th1d+", "th2d+"]):
        say(f"  {n} =", to_paper(outs[f"qdp{i}"]))
    say("")
    say("== impact_slope (one constraint) at th1 = alpha/2 + phi, zd- = -xd- tan(phi) ==")
    outs = {n: poly_at(e.subs({zd: -xd * SP / CP}), "slope")
            for n, e in K["impact_slope"]["poly"]}
    for n, e in outs.items():
        say(f"  {n} =", to_paper(e))
    say("")
    # ------------------------------------------------------------------ Table 1 numbers
    say("== Table 1 numbers (m1=2, m2=1, l=1, alpha=pi/6, I1=0.5, I2=1) ==")
    t1 = {m1: 2, m2: 1, l: 1, alpha: sp.pi / 6, I1: sp.Rational(1, 2), I2: 1}
    lhs = (mt * l ** 2 * (1 - sp.cos(alpha))).subs(t1)
    say("  Eq. 11 left  m_t l^2 (1 - cos alpha) =", sp.nsimplify(lhs), "=", sp.N(lhs, 12),
        "(paper: 0.402)")
    say("  Eq. 11 right 2 I_t                    =", (2 * It).subs(t1), "(paper: 3.0)")
    say("  Eq. 46 right 2 I1                     =", (2 * I1).subs(t1), "(paper: 1.0)")
    v = (2 * l * sp.sin(alpha / 2)).subs(t1)
    say("  2 l sin(alpha/2)                      =", sp.nsimplify(sp.simplify(v)), "=",
        sp.N(v, 12), "(paper: 0.517638)")
    say("  I1 = m1 (l/2)^2 =", (m1 * (l / 2) ** 2).subs(t1), "; I2 = m2 r^2 = 1 needs r = 1 m")
    return "\n".join(OUT) + "\n"


def main():
    sys.stdout.write(text())


if __name__ == "__main__":
    main()
