"""High-precision reference values of every kernel of docs/kernels.md.

For each kernel: >= 200 random points plus edge points (`edge:...`) and Table 1 points
(`table1`), evaluated by substituting into the symbolic outputs of model.py with mpmath at
mp.dps = 40.  Every point is also evaluated

  * from the same expressions at mp.dps = 60 (rounding check), and
  * by a second, purely numeric route at mp.dps = 60: M, h, S, J, J_mu, J_I are evaluated as
    matrices and the formulas of the brief (lambda = -J M^-1 (S u - h) / (J M^-1 Jhat^T), ...)
    are applied with mpmath linear algebra (checks the symbolic simplification).  The Jacobian
    kernels (*_jacobian) are checked against the complex-step derivative of that numeric route
    (Im f(x + i h) / h with h = 1e-40 at dps 60: no cancellation, truncation error ~h^2).

Inputs are drawn as IEEE doubles (so a Rust test reads exactly the same input) and written as
their exact decimal expansion.  Outputs are written with OUT_DIGITS significant digits.

Usage: python kernels.py OUTDIR [KERNEL ...]   (all kernels when none is named)
"""
from __future__ import annotations

import json
import os
import random
import sys
import time
from decimal import Decimal

import mpmath as mp
import sympy as sp

import model as md
from model import (I1, I2, alpha, g, l, m1, m2, mu, phi, th1, th1d, th2d, u, x, xd, z, zd)

SEED = 20240601
N_RANDOM = 200
N_EDGE = 4          # points per edge tag
OUT_DIGITS = 34     # significant digits written
CLAIM_DIGITS = 30   # digits claimed in the JSON ("digits")
COND_MAX = 1e6      # reject points whose denominators have condition number above this
ALLARGS = md.Q + md.QD + [u, mu, md.v] + md.PARAMS
JAC_H = mp.mpf(10) ** -40   # complex step of the numeric Jacobian route
# Jacobian kernel -> (base kernel, slice of the base outputs that are differentiated)
JACOBIANS = {"closed_loop_level_jacobian": ("closed_loop_level", slice(0, 4)),
             "accel_slope_jacobian": ("accel_slope", slice(0, 4)),
             "impact2_level_jacobian": ("impact2_level", slice(2, 6)),
             "impact_slope_jacobian": ("impact_slope", slice(1, 5))}

TABLE1 = {m1: 2.0, m2: 1.0, l: 1.0, I1: 0.5, I2: 1.0, g: 9.81, alpha: float(mp.pi / 6),
          phi: 0.2}

# ------------------------------------------------------------------ deterministic sampling
mp.mp.dps = 30


class Sampler:
    """Deterministic doubles: random.Random is stable across Python versions; exp/log go through
    mpmath (pure Python, platform independent) and are rounded to double once."""

    def __init__(self, seed):
        self.r = random.Random(seed)

    def uni(self, a, b):
        return float(mp.mpf(a) + (mp.mpf(b) - mp.mpf(a)) * mp.mpf(self.r.random()))

    def logu(self, a, b):
        la, lb = mp.log(a), mp.log(b)
        return float(mp.exp(la + (lb - la) * mp.mpf(self.r.random())))

    def params(self):
        return {m1: self.logu(1e-2, 1e2), m2: self.logu(1e-2, 1e2), l: self.logu(0.1, 10.0),
                I1: self.logu(1e-2, 1e2), I2: self.logu(1e-2, 1e2), g: self.uni(1.0, 20.0),
                alpha: self.logu(1e-3, 2.5), phi: self.uni(0.0, 0.5)}

    def state(self, p):
        a, f = p[alpha], p[phi]
        return {x: self.uni(-10, 10), z: self.uni(-10, 10),
                th1: self.uni(-a / 2 - 0.3, a / 2 + f + 0.3),
                xd: self.uni(-50, 50), zd: self.uni(-50, 50),
                th1d: self.uni(-50, 50), th2d: self.uni(-50, 50),
                u: self.uni(-50, 50), mu: self.uni(-2, 2)}


def exact_str(v: float) -> str:
    """Exact decimal expansion of a double."""
    s = str(Decimal(v))
    return s.replace("E", "e")


def out_str(v) -> str:
    if v == 0:
        return "0"
    return mp.nstr(v, OUT_DIGITS, strip_zeros=False, min_fixed=-4, max_fixed=6)


# ------------------------------------------------------------------ numeric cross-check route
class Numeric:
    """Second route: matrices evaluated numerically, formulas applied with mpmath linalg."""

    def __init__(self, mdl):
        args = ALLARGS
        self.args = args
        self.kernels = mdl.kernels
        L = lambda e: sp.lambdify(args, e, modules="mpmath")
        self.M = L(mdl.M)
        self.h = L(mdl.h)
        self.S = L(mdl.S)
        self.J = {"level": L(mdl.J_level), "slope": L(mdl.J_slope)}
        self.Jmu = {"level": L(mdl.Jmu_level), "slope": L(mdl.Jmu_slope)}
        self.JI = {k: L(v) for k, v in mdl.JI.items()}
        self.fore = L(sp.Matrix([*mdl.fore, *mdl.fore_vel]))
        self.energy = L(sp.Matrix([mdl.T, mdl.V]))
        # impact with friction: the gradients of the scalar contact coordinates (the fore foot's
        # coordinate along the floor and its signed distance from it, the rear foot's distance)
        xf, zf = mdl.fore
        coords = lambda a: sp.Matrix([[sp.diff(c, qi) for qi in md.Q] for c in (
            xf * sp.cos(a) - zf * sp.sin(a), zf * sp.cos(a) + xf * sp.sin(a),
            z * sp.cos(a) + x * sp.sin(a))])
        self.JC = {"impact_coulomb_level": L(coords(sp.Integer(0))),
                   "impact_coulomb_slope": L(coords(phi))}

    def __call__(self, name, vals):
        if name in JACOBIANS:
            # complex step: d out / d s = Im out(s + i h) / h, one column per variable
            base, rows = JACOBIANS[name]
            cols = [[mp.im(o) / JAC_H for o in
                     self(base, {**vals, s: mp.mpc(vals[s], JAC_H)})[rows]]
                    for s in self.kernels[name]["inputs"]]
            return [cols[j][i] for i in range(len(cols[0])) for j in range(len(cols))]
        a = [mp.mpmathify(vals.get(s, 0)) for s in self.args]
        M = mp.matrix(self.M(*a))
        h = mp.matrix(self.h(*a))
        S = mp.matrix(self.S(*a))
        U = a[self.args.index(u)]
        qd = mp.matrix([a[self.args.index(s)] for s in md.QD])
        flat = lambda A: [A[i, j] for i in range(A.rows) for j in range(A.cols)]
        if name == "mass_matrix":
            return flat(M)
        if name == "bias":
            return flat(h)
        if name in ("lambda_level", "projection_level", "control_level", "accel_level",
                    "lambda_slope", "accel_slope", "closed_loop_level"):
            kind = "level" if name.endswith("level") else "slope"
            if kind == "slope":
                U = 0
            J = mp.matrix(self.J[kind](*a))
            Jh = J + mp.matrix(self.Jmu[kind](*a))
            Minv = mp.inverse(M)
            rhs = S * U - h
            den = (J * Minv * Jh.T)[0, 0]
            Y = mp.eye(4) - Jh.T * (1 / den) * J * Minv
            A = (S.T * Minv * Y * S)[0, 0]
            B = (S.T * Minv * Y * h)[0, 0]
            if name == "closed_loop_level":
                U = (a[self.args.index(md.v)] + B) / A     # Eq. 31
                rhs = S * U - h
            lam = -(J * Minv * rhs)[0, 0] / den
            qdd = Minv * (rhs + Jh.T * lam)
            if name == "closed_loop_level":
                return flat(qdd) + [U]
            if name.startswith("lambda"):
                return [lam]
            if name.startswith("accel"):
                return flat(qdd)
            if name == "projection_level":
                return flat(Y)
            return [A, B]
        if name.startswith("stick") or name == "closed_loop_stick_level":
            # the foot held: KKT system [[M, -Jp^T], [Jp, 0]] [qdd; F] = [S u - h; 0] for the
            # Cartesian ground force F on the foot, solved by mpmath's LU, then F resolved
            # along the floor's unit tangent and normal
            ph = a[self.args.index(phi)] if name == "stick_slope" else mp.mpf(0)

            def solve(uu):
                K = mp.zeros(6, 6)
                r = S * uu - h
                b = mp.zeros(6, 1)
                for i in range(4):
                    for j in range(4):
                        K[i, j] = M[i, j]
                    b[i] = r[i]
                for c in range(2):       # Jp = [[1, 0, 0, 0], [0, 1, 0, 0]]
                    K[c, 4 + c] = -1
                    K[4 + c, c] = 1
                sol = mp.lu_solve(K, b)
                return [sol[i] for i in range(4)], (sol[4], sol[5])

            if name == "stick_slope":
                U = 0
            if name == "closed_loop_stick_level":
                ydd = lambda q: q[2] - q[3]
                y0 = ydd(solve(0)[0])
                A = ydd(solve(1)[0]) - y0
                U = (a[self.args.index(md.v)] - y0) / A      # yddot = A u + y0 = v
            qdd, (fx, fz) = solve(U)
            lam = [fx * mp.cos(ph) - fz * mp.sin(ph), fx * mp.sin(ph) + fz * mp.cos(ph)]
            return qdd + ([U] if name == "closed_loop_stick_level" else []) + lam
        if name.startswith("impact_coulomb"):
            # the lock (level) by its Schur complement: M_L^-1 = M^-1 - M^-1 j^T (j M^-1 j^T)^-1
            # j M^-1 with j = [0, 0, 1, -1], qd_L = qd - M^-1 j^T (j M^-1 j^T)^-1 j qd
            Minv = mp.inverse(M)
            qdl = qd
            if name.endswith("level"):
                jl = mp.matrix([[0, 0, 1, -1]])
                X = (jl * Minv * jl.T)[0, 0]
                qdl = qd - Minv * jl.T * ((jl * qd)[0, 0] / X)
                Minv = Minv - Minv * jl.T * jl * Minv / X
            JC = mp.matrix(self.JC[name](*a))
            vc = JC * qdl
            W = JC * Minv * JC.T
            R = Minv * JC.T
            return (flat(qdl) + flat(vc)
                    + [W[i, j] for i, j in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))]
                    + [R[i, j] for i in range(4) for j in range(2)])
        if name.startswith("impact"):
            JI = mp.matrix(self.JI[name](*a))
            Minv = mp.inverse(M)
            X = JI * Minv * JI.T
            lamI = -(mp.inverse(X) * (JI * qd))
            qdp = qd + Minv * JI.T * lamI
            return flat(lamI) + flat(qdp)
        if name == "fore_foot":
            return flat(mp.matrix(self.fore(*a)))
        if name == "energy":
            return flat(mp.matrix(self.energy(*a)))
        raise KeyError(name)


# ------------------------------------------------------------------ kernel evaluation
def kernel_edges(name, k):
    """Edge tags that apply to a kernel: (tag, function(vals) -> vals)."""
    ins = k["inputs"]
    slope = "slope" in name
    E = []

    def setv(**kw):
        def fn(v):
            v = dict(v)
            for key, f in kw.items():
                v[getattr(md, key)] = f(v)
            return v
        return fn

    if th1 in ins:
        if slope:
            E.append(("edge:th1=alpha/2+phi", setv(th1=lambda v: v[alpha] / 2 + v[phi])))
            E.append(("edge:th1=alpha/2-phi", setv(th1=lambda v: v[alpha] / 2 - v[phi])))
        E.append(("edge:th1=alpha/2", setv(th1=lambda v: v[alpha] / 2)))
        E.append(("edge:th1=-alpha/2", setv(th1=lambda v: -v[alpha] / 2)))
        E.append(("edge:th1=0", setv(th1=lambda v: 0.0)))
    if mu in ins:
        E.append(("edge:mu=0", setv(mu=lambda v: 0.0)))
    if md.v in ins:
        E.append(("edge:v=0", setv(v=lambda v: 0.0)))
    if "stick" in name:   # the foot at rest and the wheel momentarily still
        E.append(("edge:th1d=0", setv(th1d=lambda v: 0.0)))
    if phi in k["params"]:
        E.append(("edge:phi=0", setv(phi=lambda v: 0.0)))
        if name.startswith("impact"):
            E.append(("edge:phi=0,th1=alpha/2", setv(phi=lambda v: 0.0,
                                                     th1=lambda v: v[alpha] / 2)))
    if name in ("impact3_level", "impact2_level", "impact2_level_jacobian",
                "impact_coulomb_level"):
        E.append(("edge:pre_impact(th1=alpha/2,zd=0,th2d=th1d)",
                  setv(th1=lambda v: v[alpha] / 2, zd=lambda v: 0.0, th2d=lambda v: v[th1d])))
    if name in ("impact_slope", "impact2_slope", "impact_slope_jacobian",
                "impact_coulomb_slope"):
        E.append(("edge:pre_impact(th1=alpha/2+phi,zd=-xd*tan(phi))",
                  setv(th1=lambda v: v[alpha] / 2 + v[phi],
                       zd=lambda v: float(-mp.mpf(v[xd]) * mp.tan(v[phi])))))
    return E


def table1_states(name, k):
    a = TABLE1[alpha]
    f = TABLE1[phi]
    slope = "slope" in name
    th_list = [a / 2 + f, a / 2 - f, 0.0, 0.3] if slope else [-a / 2, a / 2, 0.0, 0.1]
    # mu as the scene would give it: -mu0 tanh(c xd) with mu0 = 0.4 (level) / 0.2 (slope)
    out = []
    for i, t1 in enumerate(th_list):
        xdv = [0.0, 0.05, -0.003, 0.4][i]
        m0 = 0.2 if slope else 0.4
        muv = float(-m0 * mp.tanh(100 * mp.mpf(xdv) / (mp.cos(f) if slope else 1)))
        s = {x: [0.0, 0.25, -0.1, 1.5][i], z: 0.0 if not slope else float(-0.0), th1: t1,
             xd: xdv, zd: 0.0 if not slope else float(-mp.mpf(xdv) * mp.tan(f)),
             th1d: [0.8, 1.1, 0.5, 1.3][i], th2d: [0.8, 0.0, 0.0, -0.2][i],
             u: [0.0, 2.5, -1.0, 7.0][i], mu: muv, md.v: [0.0, 2.5, -1.0, 7.0][i]}
        out.append(s)
    return out


def make_evaluators(mdl, name, k):
    args = list(k["inputs"]) + list(k["params"])
    exprs = [e for _, e in k["outputs"]]
    f = sp.lambdify(args, exprs, modules="mpmath", cse=True)
    # condition number of each denominator factor w.r.t. componentwise relative perturbations
    allargs = ALLARGS
    dens = []
    for d in k["den"]:
        grads = [sp.diff(d, s) for s in allargs]
        dens.append((sp.lambdify(allargs, d, modules="mpmath"),
                     sp.lambdify(allargs, grads, modules="mpmath")))
    return args, f, dens


def cond_ok(dens, vals, allargs):
    a = [mp.mpf(vals.get(s, 0)) for s in allargs]
    for fd, fg in dens:
        d = fd(*a)
        gr = fg(*a)
        num = sum(abs(gi * ai) for gi, ai in zip(gr, a))
        if d == 0 or num / abs(d) > COND_MAX:
            return False
    return True


def run_kernel(mdl, name, k, numeric, stats):
    args, f, dens = make_evaluators(mdl, name, k)
    allargs = ALLARGS
    smp = Sampler(SEED + sum(map(ord, name)))
    points = []
    rejected = 0

    def draw(modify=None):
        nonlocal rejected
        while True:
            p = smp.params()
            vals = {**p, **smp.state(p)}
            if md.v in k["inputs"]:   # drawn only here: the other kernels' streams are unchanged
                vals[md.v] = smp.uni(-50, 50)
            if modify is not None:
                vals = modify(vals)
            if cond_ok(dens, vals, allargs):
                return vals
            rejected += 1

    tagged = [("random", draw()) for _ in range(N_RANDOM)]
    for tag, fn in kernel_edges(name, k):
        for _ in range(N_EDGE):
            tagged.append((tag, draw(fn)))
    for s in table1_states(name, k):
        tagged.append(("table1", {**TABLE1, **s}))

    worst_round = 0
    worst_route = 0
    escalated = 0
    zeros = 0
    tol = mp.mpf(10) ** -(CLAIM_DIGITS + 1)
    for tag, vals in tagged:
        a_in = [vals[s] for s in args]
        with mp.workdps(40):
            v40 = f(*[mp.mpf(v) for v in a_in])
        with mp.workdps(60):
            v60 = f(*[mp.mpf(v) for v in a_in])
            vn = numeric(name, vals)
            scale = max([abs(v) for v in v60] + [mp.mpf(0)])
        outs = []
        hi = None
        for i, (e40, e60, en, (oname, expr)) in enumerate(zip(v40, v60, vn, k["outputs"])):
            if expr == 0:   # identically zero (exact rational simplification)
                assert abs(en) <= mp.mpf(10) ** -50 * (1 + scale), (name, oname, en)
                outs.append("0")
                continue
            with mp.workdps(60):
                r2 = abs(e60 - en) / max(abs(e60), mp.mpf(10) ** -10 * scale)
            worst_route = max(worst_route, r2)
            if r2 > mp.mpf(10) ** -40:
                raise AssertionError(f"{name} {oname} {tag}: symbolic vs numeric route {r2}")
            with mp.workdps(60):
                r1 = abs(mp.mpf(e40) - e60) / abs(e60) if e60 != 0 else (0 if e40 == 0 else 1)
            if r1 <= tol:
                worst_round = max(worst_round, r1)
                with mp.workdps(40):
                    outs.append(out_str(e40))
                continue
            # cancellation: escalate the working precision
            escalated += 1
            if hi is None:
                with mp.workdps(80):
                    v80 = f(*[mp.mpf(v) for v in a_in])
                with mp.workdps(100):
                    v100 = f(*[mp.mpf(v) for v in a_in])
                hi = (v80, v100)
            e80, e100 = hi[0][i], hi[1][i]
            with mp.workdps(100):
                tiny = mp.mpf(10) ** -50 * scale
                if abs(e80) < tiny and abs(e100) < tiny:
                    zeros += 1
                    outs.append("0")   # exact zero at these (double) inputs
                    continue
                r = abs(e80 - e100) / abs(e100)
                if r > tol:
                    raise AssertionError(f"{name} {oname} {tag}: 80/100 rel {r}")
                outs.append(out_str(e100))
        points.append({"tag": tag, "in": [exact_str(v) for v in a_in], "out": outs})
    stats[name] = dict(points=len(points), rejected=rejected,
                       worst_rel_40_vs_60=mp.nstr(worst_round, 3),
                       worst_rel_symbolic_vs_numeric_route=mp.nstr(worst_route, 3),
                       escalated_outputs=escalated, exact_zero_at_point=zeros)
    return {"kernel": name, "inputs": [str(s) for s in args],
            "outputs": [n for n, _ in k["outputs"]], "digits": CLAIM_DIGITS, "points": points}


def write_json(path, data):
    """JSON with one point per line (readable diffs)."""
    head = {k: v for k, v in data.items() if k != "points"}
    lines = ["{"]
    for k, v in head.items():
        lines.append(f"  {json.dumps(k)}: {json.dumps(v)},")
    lines.append('  "points": [')
    pts = [json.dumps(p) for p in data["points"]]
    lines.append(",\n".join("    " + p for p in pts))
    lines.append("  ]")
    lines.append("}")
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")
    json.load(open(path))  # well-formed


_NUMERIC = None


def write_kernel(name, outdir):
    """Evaluate one kernel, write tests/data/<name>.json, return its accuracy statistics."""
    global _NUMERIC
    mdl = md.derive()
    if _NUMERIC is None:
        _NUMERIC = Numeric(mdl)
    stats = {}
    data = run_kernel(mdl, name, mdl.kernels[name], _NUMERIC, stats)
    write_json(os.path.join(outdir, f"{name}.json"), data)
    return stats[name]


def main(outdir, names=None):
    t0 = time.time()
    mdl = md.derive()
    t1 = time.time()
    os.makedirs(outdir, exist_ok=True)
    for name in names or mdl.kernels:
        t2 = time.time()
        print(f"{name:18s} {write_kernel(name, outdir)} {time.time() - t2:.1f} s", flush=True)
    print(f"derivation {t1 - t0:.1f} s, evaluation {time.time() - t1:.1f} s")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..",
                                                             "tests", "data"),
         sys.argv[2:])
