"""Independent symbolic derivation (SymPy) of the rimless wheel with torso on slippery ground.

Everything is derived from the physical description in docs/kernels.md (positions, kinetic and
potential energy, Euler-Lagrange, contact geometry); none of the paper's printed closed forms is
used.  The public entry point is `derive()`, which returns a `Model` holding the symbolic matrices
and the kernel table `KERNELS` (name -> inputs, outputs).

Symbols
-------
parameters : m1 m2 l I1 I2 g alpha phi   (PARAMS, in the canonical JSON order)
state      : x z th1 th2, velocities xd zd th1d th2d
inputs     : u (joint torque), mu (friction coefficient incl. direction),
             v (auxiliary input of the closed loop, yddot = v, Eq. 32)
stick phase: the stick_* kernels (foot at rest, not in the paper) output qdd and the ground
             force [lambda_t, lambda_n]: along the floor's unit tangent (cos phi, -sin phi)
             and along its unit normal (sin phi, cos phi)
"""
from __future__ import annotations

import functools
from dataclasses import dataclass, field

import sympy as sp

# ---------------------------------------------------------------- symbols
m1, m2, l, I1, I2, g, alpha = sp.symbols("m1 m2 l I1 I2 g alpha", positive=True)
phi = sp.Symbol("phi", real=True)
PARAMS = [m1, m2, l, I1, I2, g, alpha, phi]

x, z, th1, th2 = sp.symbols("x z th1 th2", real=True)
xd, zd, th1d, th2d = sp.symbols("xd zd th1d th2d", real=True)
xdd, zdd, th1dd, th2dd = sp.symbols("xdd zdd th1dd th2dd", real=True)
u, mu = sp.symbols("u mu", real=True)
v = sp.Symbol("v", real=True)

Q = [x, z, th1, th2]
QD = [xd, zd, th1d, th2d]
QDD = [xdd, zdd, th1dd, th2dd]
ALL_INPUT_SYMBOLS = Q + QD + [u, mu, v]

t = sp.Symbol("t", real=True)


# Polynomial stand-ins for the trigonometric functions.  All kernel algebra is done on rational
# functions of these symbols (fast, exact), reduced modulo the Pythagorean identities
# C^2 + S^2 = 1, and converted back to sin/cos at the end.
S1, C1, SA, CA, SP, CP = sp.symbols("S1 C1 SA CA SP CP", real=True)
TRIG_PAIRS = [(C1, S1, th1), (CA, SA, alpha), (CP, SP, phi)]
TO_POLY = {sp.sin(th1): S1, sp.cos(th1): C1, sp.sin(alpha): SA, sp.cos(alpha): CA,
           sp.sin(phi): SP, sp.cos(phi): CP, sp.tan(phi): SP / CP}
FROM_POLY = {S1: sp.sin(th1), C1: sp.cos(th1), SA: sp.sin(alpha), CA: sp.cos(alpha),
             SP: sp.sin(phi), CP: sp.cos(phi)}


def to_poly(e):
    """Rewrite sin/cos/tan of th1, alpha, phi (and of their sums) as rational functions of
    S1, C1, SA, CA, SP, CP.  Exact (angle-addition formulas only)."""
    e = sp.sympify(e)
    e = sp.expand_trig(e)
    e = e.subs(TO_POLY)
    assert not e.has(sp.sin, sp.cos, sp.tan), e
    return e


def reduce_pyth(p):
    """Normal form of a polynomial modulo C^2 + S^2 - 1 for the three angle pairs."""
    p = sp.expand(p)
    for c, s, _ in TRIG_PAIRS:
        if p.has(c):
            p = sp.rem(p, c ** 2 + s ** 2 - 1, c)
            p = sp.expand(p)
    return p


def rsimp(e):
    """Canonical rational simplification of a poly-form expression: cancel, reduce numerator and
    denominator modulo the Pythagorean identities, cancel again.  A rational function that
    vanishes identically always comes out as exactly 0."""
    e = sp.cancel(sp.together(e))
    n, d = sp.fraction(e)
    n = reduce_pyth(n)
    if n == 0:
        return sp.Integer(0)
    d = reduce_pyth(d)
    return sp.cancel(n / d)


def from_poly(e):
    return e.subs(FROM_POLY)


def pdiff(e, s):
    """Partial derivative of a poly-form rational function by the input symbol `s` (th1 through
    its stand-ins: d S1/d th1 = C1, d C1/d th1 = -S1).  Quotient rule on numerator/denominator
    in sympy's sparse polynomial arithmetic (much faster than expanding expressions), numerator
    reduced modulo C^2 + S^2 - 1 for every angle pair (these leading terms are coprime, so the
    reduction is a normal form and the zero test is exact); no cancellation."""
    if e == 0:
        return sp.Integer(0)
    n, d = sp.fraction(sp.together(e))
    gens = set(e.free_symbols) | {s}
    for c, sn, _ in TRIG_PAIRS:
        if c in gens or sn in gens or (s == th1 and c == C1):
            gens |= {c, sn}
    gens.discard(th1)
    gens = sorted(gens, key=str)
    N, D = sp.Poly(n, *gens), sp.Poly(d, *gens)
    if s == th1:
        cS, cC = sp.Poly(C1, *gens), sp.Poly(S1, *gens)
        der = lambda P: P.diff(S1) * cS - P.diff(C1) * cC
    else:
        der = lambda P: P.diff(s)
    num = der(N) * D - N * der(D)
    for c, sn, _ in TRIG_PAIRS:
        if c in gens and num.degree(c) >= 2:
            order = [c] + [y for y in num.gens if y != c]
            num = num.reorder(*order).rem(sp.Poly(c ** 2 + sn ** 2 - 1, *order))
    if num.is_zero:
        return sp.Integer(0)
    return num.as_expr() / d ** 2


def _grad(f):
    """Row vector d f / d q (the Jacobian of a contact-geometry function)."""
    return sp.Matrix([[sp.diff(f, qi) for qi in Q]])


def _time_derivative(f):
    """d/dt of a function of q along qd (chain rule)."""
    return sum(sp.diff(f, qi) * qdi for qi, qdi in zip(Q, QD))


@dataclass
class Model:
    M: sp.Matrix
    h: sp.Matrix
    S: sp.Matrix
    T: sp.Expr
    V: sp.Expr
    hip: tuple
    fore: tuple
    fore_vel: tuple
    J_level: sp.Matrix
    Jmu_level: sp.Matrix
    J_slope: sp.Matrix
    Jmu_slope: sp.Matrix
    JI: dict
    JC: dict = field(default_factory=dict)
    kernels: dict = field(default_factory=dict)


def euler_lagrange():
    """M(q), h(q, qd) from T and V by the Euler-Lagrange equations (time functions)."""
    qf = [sp.Function(n, real=True)(t) for n in ("x", "z", "th1", "th2")]
    xf, zf, t1f, t2f = qf
    # hip = torso centre of mass = wheel centre
    xh = xf + l * sp.sin(t1f)
    zh = zf + l * sp.cos(t1f)
    mt = m1 + m2
    Tk = (sp.Rational(1, 2) * mt * (sp.diff(xh, t) ** 2 + sp.diff(zh, t) ** 2)
          + sp.Rational(1, 2) * I1 * sp.diff(t1f, t) ** 2
          + sp.Rational(1, 2) * I2 * sp.diff(t2f, t) ** 2)
    Vp = mt * g * zh
    L = Tk - Vp
    eqs = []
    for qi in qf:
        eqs.append(sp.diff(sp.diff(L, sp.diff(qi, t)), t) - sp.diff(L, qi))
    # replace derivatives by plain symbols (second derivatives first)
    rep = {}
    for qi, a, b, c in zip(qf, Q, QD, QDD):
        rep[sp.diff(qi, t, 2)] = c
    for qi, a, b, c in zip(qf, Q, QD, QDD):
        rep[sp.diff(qi, t)] = b
    for qi, a, b, c in zip(qf, Q, QD, QDD):
        rep[qi] = a
    eqs = [sp.expand(e.subs(rep)) for e in eqs]
    M = sp.Matrix(4, 4, lambda i, j: sp.simplify(sp.diff(eqs[i], QDD[j])))
    h = sp.Matrix(4, 1, lambda i, j: sp.simplify(eqs[i].subs({a: 0 for a in QDD})))
    # check the split is exact: eqs = M qdd + h
    for i in range(4):
        r = sp.simplify(eqs[i] - (sum(M[i, j] * QDD[j] for j in range(4)) + h[i]))
        assert r == 0, r
    Tq = sp.expand(Tk.subs(rep))
    Vq = sp.expand(Vp.subs(rep))
    return M, h, Tq, Vq


def contact_jacobians(slope_angle):
    """Constraint Jacobian J and friction Jacobian J_mu for a floor through the origin that
    descends towards +x with angle `slope_angle` (0 = level floor).

    The constraint is c(q) = z + x tan(phi) = 0 (the stance foot stays on the floor); J = dc/dq.
    lambda is the multiplier of J, i.e. the generalized constraint force is J^T lambda; in the
    (x, z) plane that force is (lambda tan phi, lambda): normal to the floor with magnitude
    N = lambda / cos phi.  Sliding friction mu * N acts along the unit tangent
    tau = (cos phi, -sin phi) (downslope = +x); its generalized force is Jp^T (mu N tau) with
    Jp = d(x, z)/dq, which defines J_mu through J_mu^T lambda.
    """
    cphi = z + x * sp.tan(slope_angle)
    J = _grad(cphi)
    Jp = sp.Matrix([_grad(x), _grad(z)])  # 2x4 Jacobian of the foot position
    normal_force = Jp.T * sp.Matrix([sp.tan(slope_angle), 1])  # = J^T, per unit lambda
    assert sp.simplify(normal_force - J.T) == sp.zeros(4, 1)
    nvec = sp.Matrix([sp.tan(slope_angle), 1])
    # |n| = sqrt(1 + tan^2 phi) = 1/cos phi for |phi| < pi/2 (the positive root)
    N_per_lambda = 1 / sp.cos(slope_angle)
    assert sp.simplify(N_per_lambda ** 2 - nvec.dot(nvec)) == 0
    tau = sp.Matrix([sp.cos(slope_angle), -sp.sin(slope_angle)])
    Jmu = (Jp.T * (mu * N_per_lambda * tau)).T
    Jmu = Jmu.applyfunc(sp.simplify)
    return J, Jmu


def _rs_mat(A):
    return A.applyfunc(rsimp)


def constrained_dynamics(Minv, h, S, J, Jmu, uval):
    """lambda, qdd, Y, A, B for one holonomic constraint J qdd = 0 (poly form, J constant).

    lambda = -J M^-1 (S u - h) / (J M^-1 Jhat^T),  qdd = M^-1 (S u - h + Jhat^T lambda),
    Y = I - Jhat^T (J M^-1 Jhat^T)^-1 J M^-1,  A = S^T M^-1 Y S,  B = S^T M^-1 Y h.
    """
    Jhat = J + Jmu
    den = rsimp((J * Minv * Jhat.T)[0, 0])
    lam = rsimp(-(J * Minv * (S * uval - h))[0, 0] / den)
    qdd = _rs_mat(Minv * (S * uval - h + Jhat.T * lam))
    Y = _rs_mat(sp.eye(4) - Jhat.T * (1 / den) * J * Minv)
    MY = _rs_mat(Minv * Y)
    A = rsimp((S.T * MY * S)[0, 0])
    B = rsimp((S.T * MY * h)[0, 0])
    # consistency: M qdd = Y (S u - h) and J qdd = 0 and ydd = A u - B
    M = Minv.inv()
    assert _rs_mat(M * qdd - Y * (S * uval - h)) == sp.zeros(4, 1)
    assert rsimp((J * qdd)[0, 0]) == 0
    assert rsimp((S.T * qdd)[0, 0] - (A * uval - B)) == 0
    return den, lam, qdd, Y, A, B


def stuck_foot(Minv, h, S, uval, slope_angle):
    """The stance foot stuck to the floor (stick phase of Coulomb friction; not in the paper).

    Route, chosen to differ from the Rust derivation (which constrains the foot's coordinates
    along the floor's tangent and normal): the foot *position* (x, z) is held, c(q) = (x, z) -
    const, whatever the floor; its multipliers are the Cartesian ground force F = (F_x, F_z) on
    the foot, with M qdd + h = S u + Jp^T F and Jp qdd = 0 (Jp = d(x, z)/dq is constant, so this
    is the acceleration-level constraint).  The floor enters only when F is resolved into the
    reported components: lambda_t = F . tau along the unit tangent tau = (cos phi, -sin phi)
    (the floor's +x direction, down the slope) and lambda_n = F . n along the unit normal
    n = (sin phi, cos phi).  Returns (qdd, [lambda_t, lambda_n]) in poly form.
    """
    Jp = sp.Matrix([_grad(x), _grad(z)])
    assert all(sp.diff(e, q) == 0 for e in Jp for q in Q + QD)   # constant: Jdot = 0
    rhs = S * uval - h
    W = _rs_mat(Jp * Minv * Jp.T)
    detW = rsimp(W.det(method="berkowitz"))
    Winv = _rs_mat(W.adjugate() / detW)
    F = _rs_mat(-Winv * Jp * Minv * rhs)
    qdd = _rs_mat(Minv * (rhs + Jp.T * F))
    assert _rs_mat(Jp * qdd) == sp.zeros(2, 1)
    tau = sp.Matrix([sp.cos(slope_angle), -sp.sin(slope_angle)]).applyfunc(to_poly)
    nrm = sp.Matrix([sp.sin(slope_angle), sp.cos(slope_angle)]).applyfunc(to_poly)
    lam = [rsimp(F.dot(tau)), rsimp(F.dot(nrm))]
    return qdd, lam


def foot_rows(fore, slope_angle):
    """The three contact rows of the impact with friction (not in the paper), each the foot
    Jacobian Jp = d(x_p, z_p)/dq of a contact point projected on a unit vector of the floor:
    the fore foot along the unit tangent tau = (cos phi, -sin phi) (the floor's +x, down the
    slope) and along the unit normal n = (sin phi, cos phi), and the rear (stance) foot
    (x, z) along n.  Returns the 3x4 matrix with rows (t, n, r)."""
    xf, zf = fore
    tau = sp.Matrix([[sp.cos(slope_angle), -sp.sin(slope_angle)]])
    nrm = sp.Matrix([[sp.sin(slope_angle), sp.cos(slope_angle)]])
    Jf = sp.Matrix([_grad(xf), _grad(zf)])
    Jr = sp.Matrix([_grad(x), _grad(z)])
    return sp.Matrix.vstack(tau * Jf, nrm * Jf, nrm * Jr)


def coulomb_impact(Mp, JC, lock):
    """Ingredients of the impact with Coulomb friction at the fore foot (poly form).

    Route, chosen to differ from the Rust derivation (which subtracts the lock's Schur
    complement from M^-1): the torso lock th1d = th2d is a frictionless bilateral impulse
    applied first, and the locked walker is described by its own coordinates w = (x, z, th)
    with qd = P w, P = [[1,0,0],[0,1,0],[0,0,1],[0,0,1]].  Its inertia is M_r = P^T M P and its
    inverse mass in q is M_L^-1 = P M_r^-1 P^T.  The lock's impulse lies along (0, 0, 1, -1),
    orthogonal to the columns of P, so P^T M qd is conserved by it:
    qd_L = P M_r^-1 P^T M qd-.  Without the lock (slope) P = I.
    Then v = J qd_L, W = J M_L^-1 J^T, R = M_L^-1 [J_t; J_n]^T for the rows J of foot_rows.
    """
    qdm = sp.Matrix(QD)
    if lock:
        P = sp.Matrix([[1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 1]])
    else:
        P = sp.eye(4)
    Mr = _rs_mat(P.T * Mp * P)
    detMr = rsimp(Mr.det(method="berkowitz"))
    Mr_inv = _rs_mat(Mr.adjugate() / detMr)
    ML_inv = _rs_mat(P * Mr_inv * P.T)
    qdl = _rs_mat(P * (Mr_inv * (P.T * (Mp * qdm))))
    if lock:
        assert rsimp(qdl[2] - qdl[3]) == 0
    vc = _rs_mat(JC * qdl)
    W = _rs_mat(JC * ML_inv * JC.T)
    assert _rs_mat(W - W.T) == sp.zeros(3, 3)
    R = _rs_mat(ML_inv * JC[0:2, :].T)
    return qdl, vc, W, R


def impact(Minv, JI):
    """lambda_I = -(J_I M^-1 J_I^T)^-1 J_I qd-, qd+ = qd- + M^-1 J_I^T lambda_I (poly form)."""
    qdm = sp.Matrix(QD)
    X = _rs_mat(JI * Minv * JI.T)
    detX = rsimp(X.det(method="berkowitz"))
    Xinv = _rs_mat(X.adjugate() / detX)
    lamI = _rs_mat(-Xinv * JI * qdm)
    qdp = _rs_mat(qdm + Minv * JI.T * lamI)
    assert _rs_mat(JI * qdp) == sp.zeros(JI.rows, 1)
    return detX, lamI, qdp


def fore_foot_position():
    """The fore-leg end: the hip (x + l sin th1, z + l cos th1) minus the leg at th1 - alpha."""
    xh = x + l * sp.sin(th1)
    zh = z + l * sp.cos(th1)
    return xh - l * sp.sin(th1 - alpha), zh - l * sp.cos(th1 - alpha)


@functools.lru_cache(maxsize=None)
def derive() -> Model:
    M, h, T, V = euler_lagrange()
    # control input: torque u between stance leg (wheel) and torso; its virtual work is
    # u (d th1 - d th2) = u d y with y = th1 - th2, hence S = dy/dq^T.
    y = th1 - th2
    S = _grad(y).T

    xh = x + l * sp.sin(th1)
    zh = z + l * sp.cos(th1)
    xf, zf = fore_foot_position()
    xfd = _time_derivative(xf)
    zfd = _time_derivative(zf)

    J_level, Jmu_level = contact_jacobians(sp.Integer(0))
    J_slope, Jmu_slope = contact_jacobians(phi)

    # impact constraint Jacobians, each row the gradient of a contact-geometry function
    fore_level = _grad(zf)                       # fore foot vertical velocity
    rear_level = _grad(z)                        # rear (old stance) foot vertical velocity
    lock = _grad(th1 - th2)                      # torso locked to the wheel
    fore_slope = _grad(zf + xf * sp.tan(phi))    # fore foot velocity along the slope normal
    rear_slope = _grad(z + x * sp.tan(phi))      # rear foot velocity along the slope normal
    JI = {
        "impact3_level": sp.Matrix.vstack(fore_level, rear_level, lock),
        "impact2_level": sp.Matrix.vstack(fore_level, lock),
        "impact_slope": fore_slope,
        "impact2_slope": sp.Matrix.vstack(fore_slope, rear_slope),
    }
    JC = {"impact_coulomb_level": foot_rows((xf, zf), sp.Integer(0)),
          "impact_coulomb_slope": foot_rows((xf, zf), phi)}
    mdl = Model(M=M, h=h, S=S, T=T, V=V, hip=(xh, zh), fore=(xf, zf), fore_vel=(xfd, zfd),
                J_level=J_level, Jmu_level=Jmu_level, J_slope=J_slope, Jmu_slope=Jmu_slope,
                JI=JI, JC=JC)
    mdl.kernels = build_kernels(mdl)
    return mdl


def build_kernels(mdl: Model):
    """name -> dict(inputs, params, outputs=[(name, expr)], poly=[(name, poly-form expr)],
    den=[denominator factors]).  `outputs` are in sin/cos form, `poly` in S1, C1, ... form."""
    P = lambda A: A.applyfunc(to_poly) if hasattr(A, "applyfunc") else to_poly(A)
    Mp, hp, Sp = P(mdl.M), P(mdl.h), mdl.S
    detM = rsimp(Mp.det(method="berkowitz"))
    Minv = _rs_mat(Mp.adjugate() / detM)
    assert _rs_mat(Minv * Mp) == sp.eye(4)
    den_l, lam_l, qdd_l, Y_l, A_l, B_l = constrained_dynamics(
        Minv, hp, Sp, P(mdl.J_level), P(mdl.Jmu_level), u)
    den_s, lam_s, qdd_s, _, _, _ = constrained_dynamics(
        Minv, hp, Sp, P(mdl.J_slope), P(mdl.Jmu_slope), sp.Integer(0))
    mdl.detM = detM
    mdl.Minv_poly = Minv
    mdl.den_level, mdl.den_slope = den_l, den_s
    K = {}

    def add(name, inputs, outs):
        K[name] = dict(inputs=inputs, poly=[(n, rsimp(P(e))) for n, e in outs])

    add("mass_matrix", [th1], [(f"M{i}{j}", Mp[i, j]) for i in range(4) for j in range(4)])
    add("bias", [th1, th1d], [(f"h{i}", hp[i]) for i in range(4)])
    add("lambda_level", [th1, th1d, u, mu], [("lambda", lam_l)])
    add("projection_level", [th1, mu], [(f"Y{i}{j}", Y_l[i, j]) for i in range(4) for j in range(4)])
    add("control_level", [th1, th1d, mu], [("A", A_l), ("B", B_l)])
    add("accel_level", [th1, th1d, u, mu], [(f"qdd{i}", qdd_l[i]) for i in range(4)])
    add("lambda_slope", [th1, th1d, mu], [("lambda", lam_s)])
    add("accel_slope", [th1, th1d, mu], [(f"qdd{i}", qdd_s[i]) for i in range(4)])
    imp_in = [th1, xd, zd, th1d, th2d]
    mdl.detX = {}
    for name in ("impact3_level", "impact2_level", "impact_slope", "impact2_slope"):
        detX, lamI, qdp = impact(Minv, P(mdl.JI[name]))
        mdl.detX[name] = detX
        outs = [(f"lambdaI{i}", lamI[i]) for i in range(lamI.rows)]
        outs += [(f"qdp{i}", qdp[i]) for i in range(4)]
        add(name, imp_in, outs)
    # impact with Coulomb friction at the fore foot (not in the paper), see coulomb_impact
    for name, lock in (("impact_coulomb_level", True), ("impact_coulomb_slope", False)):
        qdl, vc, W, R = coulomb_impact(Mp, P(mdl.JC[name]), lock)
        outs = [(f"qdl{i}", qdl[i]) for i in range(4)]
        outs += [(n, vc[i]) for i, n in enumerate(("v_t", "v_n", "v_r"))]
        outs += [(n, W[i, j]) for n, i, j in (("W_tt", 0, 0), ("W_tn", 0, 1), ("W_tr", 0, 2),
                                              ("W_nn", 1, 1), ("W_nr", 1, 2), ("W_rr", 2, 2))]
        outs += [(f"R{i}{j}", R[i, j]) for i in range(4) for j in range(2)]
        add(name, imp_in, outs)
    xf, zf = mdl.fore
    xfd, zfd = mdl.fore_vel
    # closed loop (Eqs. 27, 31): u = (v + B) / A substituted into qdd, so that yddot = v
    u_cl = rsimp((v + B_l) / A_l)
    qdd_cl = [rsimp(qdd_l[i].subs(u, u_cl)) for i in range(4)]
    assert rsimp((Sp.T * sp.Matrix(qdd_cl))[0, 0] - v) == 0    # yddot = v
    add("closed_loop_level", [th1, th1d, mu, v],
        [(f"qdd{i}", qdd_cl[i]) for i in range(4)] + [("u", u_cl)])

    def jacobian(name, base, rows, wrt):
        """J<i><j> = d rows[i] / d wrt[j] (poly form, symbolic); the denominator factors for the
        rejection test are those of the base kernel (the Jacobian's are their squares)."""
        K[name] = dict(inputs=wrt, den_of=base,
                       poly=[(f"J{i}{j}", pdiff(r, s)) for i, r in enumerate(rows)
                             for j, s in enumerate(wrt)])

    poly = lambda name: [e for n, e in K[name]["poly"]]
    jacobian("closed_loop_level_jacobian", "closed_loop_level",
             poly("closed_loop_level")[:4], [th1, th1d, mu, v])
    jacobian("accel_slope_jacobian", "accel_slope", poly("accel_slope"), [th1, th1d, mu])
    for base in ("impact2_level", "impact_slope"):
        jacobian(base + "_jacobian", base, [e for n, e in K[base]["poly"] if n.startswith("qdp")],
                 imp_in)
    # Stick phase (not in the paper): the foot held, see stuck_foot.  Level floor with the
    # torque u; its closed loop with u from yddot = A_s u - B_s = v, where A_s and B_s are read
    # off S^T qdd, which is affine in u (no projection matrix); the passive wheel on the slope.
    qdd_st, lam_st = stuck_foot(Minv, hp, Sp, u, sp.Integer(0))
    add("stick_level", [th1, th1d, u],
        [(f"qdd{i}", qdd_st[i]) for i in range(4)]
        + [("lambda_t", lam_st[0]), ("lambda_n", lam_st[1])])
    ydd_st = rsimp((Sp.T * qdd_st)[0, 0])
    A_st = rsimp(sp.diff(ydd_st, u))
    B_st = rsimp(A_st * u - ydd_st)
    assert sp.diff(B_st, u) == 0
    u_st = rsimp((v + B_st) / A_st)
    qdd_stc = [rsimp(qdd_st[i].subs(u, u_st)) for i in range(4)]
    assert rsimp(qdd_stc[2] - qdd_stc[3] - v) == 0    # yddot = v
    add("closed_loop_stick_level", [th1, th1d, v],
        [(f"qdd{i}", qdd_stc[i]) for i in range(4)] + [("u", u_st)]
        + [("lambda_t", rsimp(lam_st[0].subs(u, u_st))),
           ("lambda_n", rsimp(lam_st[1].subs(u, u_st)))])
    qdd_ss, lam_ss = stuck_foot(Minv, hp, Sp, sp.Integer(0), phi)
    add("stick_slope", [th1, th1d],
        [(f"qdd{i}", qdd_ss[i]) for i in range(4)]
        + [("lambda_t", lam_ss[0]), ("lambda_n", lam_ss[1])])
    add("fore_foot", [x, z, th1, xd, zd, th1d],
        [("x_f", xf), ("z_f", zf), ("xd_f", xfd), ("zd_f", zfd)])
    add("energy", [z, th1, xd, zd, th1d, th2d], [("T", mdl.T), ("V", mdl.V)])

    for name, k in K.items():
        k["outputs"] = [(n, from_poly(e)) for n, e in k["poly"]]
        syms = set()
        for _, e in k["outputs"]:
            syms |= e.free_symbols
        extra = syms - set(k["inputs"]) - set(PARAMS)
        assert not extra, (name, extra)
        missing = [s for s in k["inputs"] if s not in syms]
        # a Jacobian keeps all its variables as inputs even where it is constant in one
        # (impact2_level_jacobian: qd+ - qd- does not involve xd-)
        assert not missing or "den_of" in k, (name, missing)
        k["params"] = [p for p in PARAMS if p in syms]
        # denominator factors (for rejecting near-singular points)
        if "den_of" in k:
            k["den"] = K[k["den_of"]]["den"]
            continue
        dens = set()
        for _, e in k["poly"]:
            _, d = sp.fraction(e)
            for f in sp.Mul.make_args(sp.factor(d)):
                b = f.base if f.is_Pow else f
                if b.free_symbols and not b.is_number:
                    dens.add(from_poly(b))
        k["den"] = sorted(dens, key=sp.default_sort_key)
    return K


if __name__ == "__main__":
    import time
    t0 = time.time()
    mdl = derive()
    print("M =", mdl.M)
    print("h =", mdl.h.T)
    print("J_level =", mdl.J_level, " J_mu_level =", mdl.Jmu_level)
    print("J_slope =", mdl.J_slope, " J_mu_slope =", mdl.Jmu_slope)
    for n, k in mdl.kernels.items():
        print(n, [str(s) for s in k["inputs"]], [str(p) for p in k["params"]],
              "den:", k["den"])
    print(f"derived in {time.time() - t0:.1f} s")
