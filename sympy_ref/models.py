"""Reference values for ANY model file (docs/model-format.md), derived independently with SymPy.

Why: the pipeline derives and generates kernels for every walker described by a model file
(`models/*.toml`).  This module reads the same files with `tomllib`, parses their expressions with
SymPy in a restricted namespace, derives the mechanics from the bodies' energies (Euler-Lagrange),
and evaluates every derived quantity at deterministic samples with mpmath, so that the Rust
derivation can be tested against values it had no part in.  Nothing here reads the Rust code.

Derivation (conventions of docs/kernels.md, generalised to n coordinates and p inputs/outputs)
-----------------------------------------------------------------------------------------------
* `T = sum 1/2 m |d com/dt|^2 + 1/2 I (d angle/dt)^2`, `V = sum m g com_z`;
  `M = d^2 T / d qd^2`, `h = (dM/dt) qd - dT/dq + dV/dq` (so that `EL = M qdd + h`).
* `S`: column k is input k's `force` (one expression per coordinate).
* Floor: level, or the slope `phi` descending towards +x; unit tangent `t = (cos phi, -sin phi)`,
  unit normal `n = (sin phi, cos phi)`; a point's signed distance `d = z cos phi + x sin phi`.
  The stance foot is `(q0, q1)`.
* Sliding stance, the paper's scaling: `J = grad(d(foot)) / cos phi = [tan phi, 1, 0, ...]`, so
  that `lambda` is the vertical reaction (the normal force times cos phi);
  `J_mu = (mu / cos phi) t^T d(x, z)/dq = [mu, -mu tan phi, 0, ...]` (friction `mu N` along t).
  `Jhat = J + J_mu`, `den = J M^-1 Jhat^T`, `lambda = -J M^-1 (S u - h) / den`,
  `qdd = M^-1 (S u - h + Jhat^T lambda)`, `Y = I - Jhat^T den^-1 J M^-1` (`M qdd = Y (S u - h)`).
* Outputs `y = h_y(q)` (p of them), `H = dy/dq`, `Hdot qd = d/dt(H) qd`:
  `yddot = A u - B` with `A = H M^-1 Y S`, `B = H M^-1 Y h - Hdot qd`; the closed loop
  `u = A^-1 (v + B)` and `qdd` with that `u` (so `yddot = v`).
* Stick phase: both foot coordinates held, `J_s = [grad(t . foot); grad(n . foot)]`;
  `[lambda_t, lambda_n] = -(J_s M^-1 J_s^T)^-1 J_s M^-1 (S u - h)` (tangential force along t,
  normal force), `qdd = M^-1 (S u - h + J_s^T [lambda_t, lambda_n])`; its closed loop with
  `A_s = H M^-1 Y_s S`, `B_s = H M^-1 Y_s h - Hdot qd`, `Y_s = I - J_s^T (J_s M^-1 J_s^T)^-1 J_s M^-1`.
* Impact, frictionless law: rows `J_I` = the striking point's normal constraint
  (`grad(d(strike)) / cos phi`, the paper's vertical scaling), then the rear (old stance) foot's
  (`J`, only in the double-support variant `_ds`), then the locks' gradients;
  `lambda_I = -(J_I M^-1 J_I^T)^-1 J_I qd-`, `qd+ = qd- + M^-1 J_I^T lambda_I`.
* Relabelling: the new foot is the striking point (`q0, q1` = its position, `qd0, qd1` = its
  velocity at `qd+`); every other coordinate by the `[relabel]` map (unlisted: unchanged), its
  velocity by the map's Jacobian times `qd+`.  Given for both impact variants.
* Impact with Coulomb friction at the striking point, its ingredients: rows
  `J_c = [grad(t . strike); grad(n . strike); grad(n . foot)]` (unit tangent and normal, no
  scaling), the locks `J_L` bilateral and frictionless, applied by the KKT system
  `[[M, J_L^T], [J_L, 0]] [x; l] = [b; 0]` whose `x` is `M_L^-1 b` (`M^-1 b` without locks):
  `qd_L` from `b = M qd-` (`qd-` itself without locks), `v = J_c qd_L`, `W = J_c M_L^-1 J_c^T`
  (upper triangle over t, n, r), `R = M_L^-1 [J_t; J_n]^T`.
* Input rates `w = S^T qd` (input k's power is `u_k w_k`); the total mass, the sum of the
  bodies' masses.
* Jacobians (only where the closed forms are derived and the model has at most `JAC_MAX_N`
  coordinates): sympy's derivatives of the closed forms, `d qdd / d (q, qd, mu)` of the sliding
  stance (no inputs), `d [qdd_cl; u_cl] / d (q, qd, mu, v)` of the closed loop, `d qd+ / d (q, qd)`
  of the impact; checked against complex-step derivatives (step `1e-40`, at 70 digits) of the
  numeric route (`checks.jacobians_vs_complex_step`, which must be below 1e-40).  For every
  model, sympy's derivatives by `(q, qd)` of the maps that need no solve: the relabelling
  `[q'; qd']` (qd the post-impact velocities), the outputs and rates `[y; H qd]`, the input
  rates `S^T qd`.

Evaluation: the numeric route applies the formulas above with mpmath linear algebra to the
symbolic `M, h, S, J, J_mu, J_s, J_I, H, Hdot qd` evaluated at the sample, at 50 and at 70
digits (they must agree to 1e-30 relative); values are written from the 70-digit run with 32
significant digits, `digits` (claimed) 30.  Where the closed forms were derived symbolically
(`derive(..., closed=True)`), they are evaluated too, at 70 digits, and must agree with the
numeric route to 1e-40 (`checks.closed_vs_numeric`, the maximum relative difference).
Relative differences are taken against max(|value|, 1e-20 * the sample's largest value).

JSON layout of tests/data/models/<name>.json
-------------------------------------------
```
{ "model": "compass-gait", "file": "models/compass-gait.toml",
  "generator": "python sympy_ref/generate.py --only models", "sympy": "1.14.0", "mpmath": "1.3.0",
  "dps": 70, "digits": 30,
  "coordinates": ["x", "z", ...], "parameters": ["m", ...], "inputs": ["u", ...],
  "outputs": ["y", ...], "aux": ["v", ...], "points": ["hip", ...],
  "names": [every output name, in the order below],
  "samples": [ { "tag": "strike" | "generic",
                 "params": {"m": "5.1...", ...},          # exact decimal expansions of doubles
                 "q": [...], "qd": [...], "u": [...], "mu": "...", "v": [...], "t": "...",
                 "out": {"M_0_0": "...", ...} } ],      # 32 significant digits
  "checks": {...} }
```
Output names (i, j over coordinates, k, l over inputs/outputs, r over impact rows):
`M_i_j`, `h_i`, `T`, `V`, `J_i`, `Jmu_i`; sliding stance with `u`, `mu`: `lambda`, `qdd_i`,
`Y_i_j`; with inputs: `A_k_l`, `B_k`, closed loop with `v`: `u_cl_k`, `qdd_cl_i`, `lambda_cl`;
stick with `u`: `stick_qdd_i`, `stick_lambda_t`, `stick_lambda_n`; with inputs, its closed loop
with `v`: `stick_A_k_l`, `stick_B_k`, `stick_u_cl_k`, `stick_qdd_cl_i`, `stick_lambda_t_cl`,
`stick_lambda_n_cl`; impact: `impact_lambda_r`, `impact_qdp_i`, `impact_ds_lambda_r`,
`impact_ds_qdp_i`, relabelled: `relabel_q_i`, `relabel_qd_i`, `relabel_ds_qd_i`; the Coulomb
impact: `coulomb_qdl_i`, `coulomb_v_t`, `coulomb_v_n`, `coulomb_v_r`, `coulomb_W_tt`, `_tn`,
`_tr`, `_nn`, `_nr`, `_rr`, `coulomb_R_i_j` (j = 0, 1); points:
`<point>_x`, `<point>_z`, `<point>_xd`, `<point>_zd`; outputs: `y_k`, `yd_k` (rate), the desired
trajectory at `t`: `ydes_k`, `yddes_k`, `ydddes_k`, and Eq. 32's `vpd_k`
(`ydddes + K_D (yddes - yd) + K_P (ydes - y)`); `guard` (the strike guard) and
`fall_<name>` (each fall's guard or point distance); with inputs `w_k`; `total_mass`; the
Jacobians `accel_jac_i_j`, `cl_jac_i_j` (rows: qdd, then u), `impact_jac_i_j` (column j over
q, qd, then mu, then v), `relabel_jac_i_j`, `yrates_jac_i_j` (rows: y, then the rates),
`w_jac_i_j` (column j over q, qd).  `impact` rows: strike, then locks; `impact_ds` rows: strike, rear foot, then locks.  New
outputs are appended after the old ones (and sampled from the same random stream), so adding
them leaves every existing value unchanged.

Usage: python models.py [MODEL.toml ...]   (default: every models/*.toml; writes the JSON)
"""
from __future__ import annotations

import json
import os
import random
import sys
import time
import tomllib
from dataclasses import dataclass, field
from decimal import Decimal

import mpmath as mp
import sympy as sp
from sympy.matrices.utilities import dotprodsimp
from sympy.parsing.sympy_parser import (auto_number, convert_xor, parse_expr, rationalize)

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
MODELS = os.path.join(ROOT, "models")
OUTDIR = os.path.join(ROOT, "tests", "data", "models")
GENERATOR = "python sympy_ref/generate.py --only models"
DPS_LO, DPS_HI = 50, 70
OUT_DIGITS = 32
CLAIM_DIGITS = 30
N_STRIKE, N_GENERIC = 4, 4
SEED = 20261124


# ------------------------------------------------------------------------------------ parsing
class ModelError(ValueError):
    pass


_TRANSFORMS = (auto_number, rationalize, convert_xor)


def parse(text, names, where):
    """Parse a model expression: rationals exact (`0.163` -> 163/1000), `^` a power, only the
    given symbols and sin/cos (no Python builtins)."""
    glob = {"__builtins__": {}, "Integer": sp.Integer, "Float": sp.Float,
            "Rational": sp.Rational, "sin": sp.sin, "cos": sp.cos}
    try:
        e = parse_expr(str(text), local_dict=dict(names), global_dict=glob,
                       transformations=_TRANSFORMS, evaluate=True)
    except Exception as err:  # noqa: BLE001 - report which expression failed
        raise ModelError(f"{where}: cannot parse {text!r}: {err}") from err
    e = sp.sympify(e)
    bad = e.free_symbols - set(names.values())
    if bad:
        raise ModelError(f"{where}: unknown symbols {bad}")
    return e


def parse_range(text):
    """'(0, inf)', '[0, pi/2)' -> (lo, hi, lo_closed, hi_closed) as mpmath numbers."""
    text = text.strip()
    lo_c, hi_c = text[0] == "[", text[-1] == "]"
    lo, hi = (s.strip() for s in text[1:-1].split(","))

    def num(s):
        if s in ("inf", "-inf"):
            return mp.inf if s == "inf" else -mp.inf
        return mp.mpf(sp.N(sp.sympify(s), 40))
    return num(lo), num(hi), lo_c, hi_c


@dataclass
class Model:
    name: str
    path: str
    raw: dict
    q: list
    qd: list
    units: dict
    params: list                      # [(Symbol, default float, range tuple, unit)]
    sym: dict                         # name -> Symbol (coordinates, velocities, parameters, mu, t)
    mu: sp.Symbol
    t: sp.Symbol
    bodies: list = field(default_factory=list)     # (mass, (cx, cz), inertia, angle)
    points: dict = field(default_factory=dict)     # name -> (x, z)
    phi: object = 0                                # slope symbol or 0
    g: sp.Symbol = None
    strike_point: str = ""
    guard: object = None
    falls: list = field(default_factory=list)      # (name, expr)
    relabel: dict = field(default_factory=dict)    # coordinate index -> expr
    locks: list = field(default_factory=list)
    inputs: list = field(default_factory=list)     # (name, [force exprs])
    outputs: list = field(default_factory=list)    # (name, h expr, aux name, desired dict)
    kp: object = 0
    kd: object = 0


def load(path) -> Model:
    with open(path, "rb") as fh:
        raw = tomllib.load(fh)
    name = raw["name"]
    coords = raw["coordinate"]
    q = [sp.Symbol(c["name"], real=True) for c in coords]
    qd = [sp.Symbol(c["name"] + "d", real=True) for c in coords]
    sym = {s.name: s for s in q + qd}
    units = {c["name"]: c["unit"] for c in coords}
    params = []
    for p in raw.get("parameter", []):
        if p.get("stage") == "start":
            continue        # a value of [start] only: in no kernel
        s = sp.Symbol(p["name"], real=True)
        sym[p["name"]] = s
        params.append((s, float(p["default"]), parse_range(p["range"]), p["unit"]))
    mu, t = sp.Symbol("mu", real=True), sp.Symbol("t", real=True)
    sym["mu"], sym["t"] = mu, t
    m = Model(name=name, path=path, raw=raw, q=q, qd=qd, units=units, params=params, sym=sym,
              mu=mu, t=t)
    P = lambda text, where: parse(text, sym, f"{path}: {where}")
    fl = raw["floor"]
    m.g = sym[fl["gravity"]]
    m.phi = sym[fl["slope"]] if "slope" in fl else sp.Integer(0)
    for b in raw["body"]:
        inertia = P(b.get("inertia", "0"), f"body {b['name']} inertia")
        angle = P(b["angle"], f"body {b['name']} angle") if "angle" in b else sp.Integer(0)
        m.bodies.append((P(b["mass"], f"body {b['name']} mass"),
                         tuple(P(e, f"body {b['name']} com") for e in b["com"]), inertia, angle))
    for pt in raw.get("point", []):
        m.points[pt["name"]] = tuple(P(e, f"point {pt['name']}") for e in pt["at"])
    st = raw["strike"]
    m.strike_point = st["point"]
    m.guard = (P(st["guard"], "strike guard") if "guard" in st
               else signed_distance(m.points[st["point"]], m.phi))
    for f in raw.get("fall", []):
        e = (P(f["guard"], f"fall {f['name']}") if "guard" in f
             else signed_distance(m.points[f["point"]], m.phi))
        m.falls.append((f["name"], e))
    idx = {c.name: i for i, c in enumerate(q)}
    m.relabel = {idx[k]: P(v, f"relabel {k}") for k, v in raw.get("relabel", {}).items()}
    imp = raw.get("impact", {})
    m.locks = [P(e, "impact lock") for e in imp.get("locks", [])]
    for inp in raw.get("input", []):
        sym[inp["name"]] = sp.Symbol(inp["name"], real=True)
        m.inputs.append((inp["name"], [P(e, f"input {inp['name']} force") for e in inp["force"]]))
    if m.inputs:
        ctl = raw["control"]
        m.kp, m.kd = sym[ctl["kp"]], sym[ctl["kd"]]
    for o in raw.get("output", []):
        d = {k: (v if k == "shape" else
                 [P(e, f"output {o['name']} desired {k}[{i}]") for i, e in enumerate(v)]
                 if k == "points" else P(v, f"output {o['name']} desired {k}"))
             for k, v in o["desired"].items()}
        m.outputs.append((o["name"], P(o["h"], f"output {o['name']}"),
                          o.get("aux", "v_" + o["name"]), d))
    if len(m.outputs) != len(m.inputs):
        raise ModelError(f"{path}: {len(m.outputs)} outputs for {len(m.inputs)} inputs")
    return m


def signed_distance(pt, phi):
    """Signed distance of a point from the floor through the origin (level: its z)."""
    x, z = pt
    return z * sp.cos(phi) + x * sp.sin(phi)


# ------------------------------------------------------------------------------ derivation
def grad(e, q):
    return sp.Matrix([[sp.diff(e, s) for s in q]])


@dataclass
class Derived:
    """Symbolic matrices of one model (sin/cos form, expanded; no simplification)."""
    M: sp.Matrix
    h: sp.Matrix
    T: sp.Expr
    V: sp.Expr
    S: sp.Matrix
    J: sp.Matrix
    Jmu: sp.Matrix
    Js: sp.Matrix
    JI: sp.Matrix          # strike + locks
    JI_ds: sp.Matrix       # strike + rear foot + locks
    H: sp.Matrix
    Hdqd: sp.Matrix        # Hdot qd
    y: sp.Matrix
    Jc: sp.Matrix = None   # Coulomb impact: strike point along the floor, its gap, rear foot's gap
    JL: sp.Matrix = None   # the locks' gradients (0 x n without locks)
    mass: sp.Expr = None   # the bodies' total mass
    closed: dict = field(default_factory=dict)     # name -> symbolic closed forms (optional)
    jacobians: dict = field(default_factory=dict)  # name -> derivatives of closed forms (optional)
    timings: dict = field(default_factory=dict)


def energies(m: Model):
    q, qd = sp.Matrix(m.q), sp.Matrix(m.qd)
    T = sp.Integer(0)
    V = sp.Integer(0)
    for mass, (cx, cz), inertia, angle in m.bodies:
        v = sp.Matrix([cx, cz]).jacobian(q) * qd
        w = (grad(angle, m.q) * qd)[0, 0]
        T += sp.Rational(1, 2) * mass * (v[0] ** 2 + v[1] ** 2) + sp.Rational(1, 2) * inertia * w ** 2
        V += mass * m.g * cz
    return sp.expand(T), sp.expand(V)


def euler_lagrange(m: Model, T, V):
    """M = d^2T/dqd^2, h = (d/dt dT/dqd)|_{qdd=0} - dT/dq + dV/dq."""
    n = len(m.q)
    M = sp.Matrix(n, n, lambda i, j: sp.expand(sp.diff(T, m.qd[i], m.qd[j])))
    p = [sp.diff(T, s) for s in m.qd]
    h = sp.Matrix(n, 1, lambda i, _: sp.expand(
        sum(sp.diff(p[i], m.q[k]) * m.qd[k] for k in range(n))
        - sp.diff(T, m.q[i]) + sp.diff(V, m.q[i])))
    return M, h


def derive(m: Model, closed=False) -> Derived:
    """Energies -> M, h by Euler-Lagrange; S, the contact and impact rows, the outputs' Jacobian.
    With `closed`, also the closed forms of lambda, qdd, Y, A, B, u, qdd of the closed loop and
    the impact maps, built on adj(M) / det(M) (see closed_forms)."""
    tm = {}
    t0 = time.perf_counter()
    T, V = energies(m)
    M, h = euler_lagrange(m, T, V)
    n = len(m.q)
    tm["energies_M_h"] = time.perf_counter() - t0
    t1 = time.perf_counter()
    S = sp.Matrix.hstack(*[sp.Matrix(f) for _, f in m.inputs]) if m.inputs else sp.zeros(n, 0)
    phi = m.phi
    foot = (m.q[0], m.q[1])
    J = grad(signed_distance(foot, phi), m.q) / sp.cos(phi)
    tvec = sp.Matrix([[sp.cos(phi), -sp.sin(phi)]])
    Jp = sp.Matrix([grad(foot[0], m.q), grad(foot[1], m.q)])
    Jmu = (m.mu / sp.cos(phi)) * tvec * Jp
    J, Jmu = J.applyfunc(sp.simplify), Jmu.applyfunc(sp.simplify)
    Js = sp.Matrix.vstack(grad(foot[0] * sp.cos(phi) - foot[1] * sp.sin(phi), m.q),
                          grad(signed_distance(foot, phi), m.q))
    strike = grad(signed_distance(m.points[m.strike_point], phi), m.q) / sp.cos(phi)
    locks = [grad(e, m.q) for e in m.locks]
    JI = sp.Matrix.vstack(strike, *locks)
    JI_ds = sp.Matrix.vstack(strike, J, *locks)
    y = sp.Matrix([o[1] for o in m.outputs]) if m.outputs else sp.zeros(0, 1)
    H = y.jacobian(sp.Matrix(m.q)) if m.outputs else sp.zeros(0, n)
    qdv = sp.Matrix(m.qd)
    Hdqd = (H * qdv).jacobian(sp.Matrix(m.q)) * qdv if m.outputs else sp.zeros(0, 1)
    sx, sz = m.points[m.strike_point]
    Jc = sp.Matrix.vstack(grad(sx * sp.cos(phi) - sz * sp.sin(phi), m.q),
                          grad(signed_distance((sx, sz), phi), m.q),
                          grad(signed_distance(foot, phi), m.q))
    JL = sp.Matrix.vstack(*locks) if locks else sp.zeros(0, n)
    mass = sp.Add(*[b[0] for b in m.bodies])
    tm["contacts_outputs"] = time.perf_counter() - t1
    d = Derived(M=M, h=h, T=T, V=V, S=S, J=J, Jmu=Jmu, Js=Js, JI=JI, JI_ds=JI_ds, H=H,
                Hdqd=Hdqd, y=y, Jc=Jc, JL=JL, mass=mass, timings=tm)
    if closed:
        t2 = time.perf_counter()
        d.closed = closed_forms(m, d)
        tm["closed_forms"] = time.perf_counter() - t2
        if n <= JAC_MAX_N:
            t3 = time.perf_counter()
            d.jacobians = jacobians(m, d)
            tm["jacobians"] = time.perf_counter() - t3
    return d


JAC_MAX_N = 4   # the Jacobians of the closed forms up to this many coordinates


def jacobian_vars(m: Model):
    """The variables of each Jacobian: `accel_jac` (no inputs) over (q, qd, mu), `cl_jac` (with
    outputs) over (q, qd, mu, v), `impact_jac` over (q, qd)."""
    x = m.q + m.qd
    out = {"impact_jac": x}
    if m.inputs:
        out["cl_jac"] = x + [m.mu] + [m.sym[o[2]] for o in m.outputs]
    else:
        out["accel_jac"] = x + [m.mu]
    return out


def jacobians(m: Model, d: Derived):
    """The Jacobians by sympy's differentiation of the closed forms (sin/cos form, chain rule
    through sin and cos of the angles): `accel_jac` of the sliding `qdd` (no inputs), `cl_jac` of
    the closed loop's `[qdd; u]`, `impact_jac` of `qd+`."""
    of = {"accel_jac": ["qdd"], "cl_jac": ["qdd_cl", "u_cl"], "impact_jac": ["impact_qdp"]}
    return {k: sp.Matrix.vstack(*[d.closed[e] for e in of[k]]).jacobian(v)
            for k, v in jacobian_vars(m).items()}


def kinematic_jacobians(m: Model, d: Derived):
    """The Jacobians by (q, qd) of the maps that need no solve, differentiated symbolically for
    every model: `relabel_jac` of the relabelling `[q'; qd']` (the striking point becomes the
    stance foot, `qd' = dq'/dq qd` with qd the post-impact velocities), `yrates_jac` of the
    outputs and their rates `[y; H qd]`, `w_jac` of the input rates `S^T qd`."""
    x = sp.Matrix(m.q + m.qd)
    qv = sp.Matrix(m.qd)
    after = sp.Matrix([m.relabel.get(i, s) for i, s in enumerate(m.q)])
    after[0], after[1] = m.points[m.strike_point]
    out = {"relabel_jac": sp.Matrix.vstack(after, after.jacobian(sp.Matrix(m.q)) * qv)}
    if m.outputs:
        out["yrates_jac"] = sp.Matrix.vstack(d.y, d.H * qv)
    if m.inputs:
        out["w_jac"] = d.S.T * qv
    return {k: e.jacobian(x) for k, e in out.items()}


def trig_standins(m: Model):
    """Stand-in symbols S_a, C_a for sin and cos of every declared angle (coordinates and
    parameters in rad), and the maps to and from them."""
    angles = [s for s in m.q if m.units[s.name] == "rad"]
    angles += [s for s, _, _, unit in m.params if unit == "rad"]
    to, back, pairs = {}, {}, []
    for a in angles:
        S, C = sp.Symbol("S_" + a.name, real=True), sp.Symbol("C_" + a.name, real=True)
        to[sp.sin(a)], to[sp.cos(a)] = S, C
        back[S], back[C] = sp.sin(a), sp.cos(a)
        pairs.append((C, S))
    return to, back, pairs


def reduce_pyth(p, pairs):
    """Normal form of a polynomial in the stand-ins modulo C^2 + S^2 - 1 (each angle)."""
    p = sp.expand(p)
    for C, S in pairs:
        if p.has(C):
            p = sp.expand(sp.rem(p, C ** 2 + S ** 2 - 1, C))
    return p


def mm(*mats):
    """Matrix product built term by term (Add of Muls, nothing expanded or cancelled): sympy's
    own product may convert to a polynomial domain and cancel, which explodes here."""
    def two(A, B):
        return sp.Matrix(A.rows, B.cols, lambda i, j: sp.Add(*[A[i, k] * B[k, j]
                                                             for k in range(A.cols)]))
    out = mats[0]
    for B in mats[1:]:
        out = two(out, B)
    return out


def closed_forms(m: Model, d: Derived):
    """Closed forms (see _closed_forms) with sympy's intermediate simplification of matrix
    algebra (dotprodsimp, a cancel per entry) switched off: it does not finish here."""
    with dotprodsimp(False):
        return _closed_forms(m, d)


def _closed_forms(m: Model, d: Derived):
    """The structured quantities in closed form on M^-1 = adj(M) / det(M): M in polynomial form
    in the sines and cosines of the angles (angle sums expanded), M, det(M) and the adjugate
    (Berkowitz) reduced modulo sin^2 + cos^2 = 1; the formulas of the module docstring are then
    built on them without further simplification (no cancellation: quotients of reduced
    polynomials, shared subexpressions left to cse; small inverses by adjugate and
    determinant).  The result is in sin/cos form."""
    to, back, pairs = trig_standins(m)
    P = lambda A: A.applyfunc(lambda e: reduce_pyth(sp.expand_trig(e).xreplace(to), pairs))
    M, h, S = P(d.M), P(d.h), d.S
    X_ = lambda A: A.applyfunc(lambda e: sp.expand_trig(e).xreplace(to))   # rows with 1/cos phi
    J, Jmu, JI, JI_ds = X_(d.J), X_(d.Jmu), X_(d.JI), X_(d.JI_ds)
    H, Hdqd = P(d.H), P(d.Hdqd)
    n = len(m.q)
    det = reduce_pyth(M.det(method="berkowitz"), pairs)
    adj = M.adjugate(method="berkowitz").applyfunc(lambda e: reduce_pyth(e, pairs))
    Minv = adj.applyfunc(lambda e: e / det)
    T = lambda A: A.T
    u = sp.Matrix([m.sym[nm] for nm, _ in m.inputs]) if m.inputs else sp.zeros(0, 1)
    rhs = (mm(S, u) - h) if m.inputs else -h
    Jh = J + Jmu
    JM = mm(J, Minv)
    den = mm(JM, T(Jh))[0, 0]
    lam = -mm(JM, rhs)[0, 0] / den
    qdd = mm(Minv, rhs + T(Jh) * lam)
    Y = sp.eye(n) - mm(T(Jh), JM).applyfunc(lambda e: e / den)
    out = {"lambda": lam, "qdd": qdd, "Y": Y}
    if m.inputs:
        MY = mm(Minv, Y)
        A = mm(H, MY, S)
        B = mm(H, MY, h) - Hdqd
        v = sp.Matrix([m.sym.setdefault(o[2], sp.Symbol(o[2], real=True)) for o in m.outputs])
        dA = A.det(method="berkowitz")
        ucl = mm(A.adjugate(method="berkowitz"), v + B).applyfunc(lambda e: e / dA)
        r = mm(S, ucl) - h
        lcl = -mm(JM, r)[0, 0] / den
        out.update(A=A, B=B, u_cl=ucl, lambda_cl=lcl, qdd_cl=mm(Minv, r + T(Jh) * lcl))
    qdm = sp.Matrix(m.qd)
    for tag, JJ in (("impact", JI), ("impact_ds", JI_ds)):
        X = mm(JJ, Minv, T(JJ))
        dX = X.det(method="berkowitz")
        lamI = -mm(X.adjugate(method="berkowitz"), mm(JJ, qdm)).applyfunc(lambda e: e / dX)
        out[tag + "_lambda"] = lamI
        out[tag + "_qdp"] = qdm + mm(Minv, T(JJ), lamI)
    return {k: v.xreplace(back) for k, v in out.items()}


def kernel_exprs(d: Derived):
    """The expressions whose size is reported: M, h and the closed forms (when derived), else the
    structured ingredients (M, h, J, J_mu, S, J_s, J_I, H, Hdot qd)."""
    ex = list(d.M) + list(d.h)
    if d.closed:
        for v in d.closed.values():
            ex += list(v) if isinstance(v, sp.MatrixBase) else [v]
    else:
        for A in (d.J, d.Jmu, d.S, d.Js, d.JI, d.JI_ds, d.H, d.Hdqd):
            ex += list(A)
    return ex


# ------------------------------------------------------------------------------ numerics
class Numeric:
    """mpmath evaluation of the symbolic ingredients and the formulas of the module docstring."""

    def __init__(self, m: Model, d: Derived):
        self.m, self.d = m, d
        self.args = (m.q + m.qd + [s for s, *_ in m.params] + [m.mu, m.t])
        L = lambda e: sp.lambdify(self.args, e, modules="mpmath")
        self.f = {k: L(getattr(d, k)) for k in ("M", "h", "S", "J", "Jmu", "Js", "JI", "JI_ds",
                                                "H", "Hdqd", "y", "Jc")}
        if m.locks:
            self.f["JL"] = L(d.JL)
        self.f["TV"] = L(sp.Matrix([d.T, d.V, d.mass]))
        aux = [m.sym.setdefault(o[2], sp.Symbol(o[2], real=True)) for o in m.outputs]
        self.jac = {k: sp.lambdify(self.args + aux, e, modules="mpmath", cse=True)
                    for k, e in d.jacobians.items()}
        self.kin_jac = {k: L(e) for k, e in kinematic_jacobians(m, d).items()}
        qv = sp.Matrix(m.qd)
        pts = {}
        for nm, (px, pz) in m.points.items():
            Jp = sp.Matrix([px, pz]).jacobian(sp.Matrix(m.q))
            pts[nm] = (L(sp.Matrix([px, pz])), L(Jp))
        self.pts = pts
        self.guard = L(m.guard)
        self.falls = [(nm, L(e)) for nm, e in m.falls]
        rq = sp.Matrix([m.relabel.get(i, s) for i, s in enumerate(m.q)])
        self.relabel = (L(rq), L(rq.jacobian(sp.Matrix(m.q))))
        des = []
        for o in m.outputs:
            des.append({k: (v if k == "shape" else [L(e) for e in v] if k == "points"
                             else L(v)) for k, v in o[3].items()})
        self.des = des
        self.kp, self.kd = (L(m.kp), L(m.kd)) if m.inputs else (None, None)

    def evaluate(self, s):
        """All outputs (name -> mpf) at the sample s (dict with q, qd, params, u, mu, v, t)."""
        m = self.m
        n = len(m.q)
        a = ([mp.mpf(x) for x in s["q"]] + [mp.mpf(x) for x in s["qd"]]
             + [mp.mpf(s["params"][p.name]) for p, *_ in m.params] + [mp.mpf(s["mu"]),
                                                                       mp.mpf(s["t"])])
        E = lambda k: mp.matrix(self.f[k](*a))
        M, h, J, Jmu, Js = E("M"), E("h"), E("J"), E("Jmu"), E("Js")
        qd = mp.matrix(a[n:2 * n])
        out = {}
        put = lambda nm, A: out.update({f"{nm}_{i}_{j}": A[i, j] for i in range(A.rows)
                                        for j in range(A.cols)})
        vec = lambda nm, A: out.update({f"{nm}_{i}": A[i] for i in range(len(A))})
        put("M", M)
        vec("h", h)
        T, V, total_mass = E("TV")
        out["T"], out["V"] = T, V
        vec("J", J)
        vec("Jmu", Jmu)
        Minv = mp.inverse(M)
        p = len(m.inputs)
        S = E("S") if p else mp.zeros(n, 1)
        u = mp.matrix([mp.mpf(x) for x in s["u"]]) if p else mp.zeros(1, 1)
        rhs = S * u - h
        Jh = J + Jmu
        den = (J * Minv * Jh.T)[0, 0]
        lam = -(J * Minv * rhs)[0, 0] / den
        out["lambda"] = lam
        vec("qdd", Minv * (rhs + Jh.T * lam))
        Y = mp.eye(n) - Jh.T * (1 / den) * J * Minv
        put("Y", Y)
        Ws = Js * Minv * Js.T
        lst = -(mp.inverse(Ws) * (Js * Minv * rhs))
        out["stick_lambda_t"], out["stick_lambda_n"] = lst[0], lst[1]
        vec("stick_qdd", Minv * (rhs + Js.T * lst))
        if p:
            H, Hdqd = E("H"), E("Hdqd")
            v = mp.matrix([mp.mpf(x) for x in s["v"]])
            A = H * Minv * Y * S
            B = H * Minv * Y * h - Hdqd
            put("A", A)
            vec("B", B)
            ucl = mp.lu_solve(A, v + B)
            vec("u_cl", ucl)
            r = S * ucl - h
            lcl = -(J * Minv * r)[0, 0] / den
            out["lambda_cl"] = lcl
            vec("qdd_cl", Minv * (r + Jh.T * lcl))
            Ys = mp.eye(n) - Js.T * mp.inverse(Ws) * Js * Minv
            As = H * Minv * Ys * S
            Bs = H * Minv * Ys * h - Hdqd
            put("stick_A", As)
            vec("stick_B", Bs)
            us = mp.lu_solve(As, v + Bs)
            vec("stick_u_cl", us)
            r = S * us - h
            ls = -(mp.inverse(Ws) * (Js * Minv * r))
            vec("stick_qdd_cl", Minv * (r + Js.T * ls))
            out["stick_lambda_t_cl"], out["stick_lambda_n_cl"] = ls[0], ls[1]
        # impacts and relabelling
        sx, sJ = self.pts[m.strike_point]
        spos, sjac = mp.matrix(sx(*a)), mp.matrix(sJ(*a))
        rq, rjac = mp.matrix(self.relabel[0](*a)), mp.matrix(self.relabel[1](*a))
        for tag in ("impact", "impact_ds"):
            JI = E("JI" if tag == "impact" else "JI_ds")
            X = JI * Minv * JI.T
            lamI = -mp.lu_solve(X, JI * qd)
            qdp = qd + Minv * JI.T * lamI
            vec(tag + "_lambda", lamI)
            vec(tag + "_qdp", qdp)
            newqd = rjac * qdp
            foot_v = sjac * qdp
            newqd[0], newqd[1] = foot_v[0], foot_v[1]
            vec("relabel_qd" if tag == "impact" else "relabel_ds_qd", newqd)
        newq = rq.copy()
        newq[0], newq[1] = spos[0], spos[1]
        vec("relabel_q", newq)
        for nm, (fx, fJ) in self.pts.items():
            pos, jac = mp.matrix(fx(*a)), mp.matrix(fJ(*a))
            vel = jac * qd
            out[f"{nm}_x"], out[f"{nm}_z"] = pos[0], pos[1]
            out[f"{nm}_xd"], out[f"{nm}_zd"] = vel[0], vel[1]
        if p:
            yv = E("y")
            ydv = E("H") * qd
            tt = mp.mpf(s["t"])
            kp, kd = self.kp(*a), self.kd(*a)
            for k, des in enumerate(self.des):
                yd, ydd, yddd = desired(des, a, tt)
                out[f"y_{k}"], out[f"yd_{k}"] = yv[k], ydv[k]
                out[f"ydes_{k}"], out[f"yddes_{k}"], out[f"ydddes_{k}"] = yd, ydd, yddd
                out[f"vpd_{k}"] = yddd + kd * (ydd - ydv[k]) + kp * (yd - yv[k])
        out["guard"] = self.guard(*a)
        for nm, f in self.falls:
            out[f"fall_{nm}"] = f(*a)
        # the impact with Coulomb friction's ingredients, the input rates, the total mass
        coulomb(out, M, E("Jc"), E("JL") if m.locks else None, qd)
        if p:
            vec("w", S.T * qd)
        out["total_mass"] = total_mass
        # the Jacobians, from sympy's derivatives of the closed forms
        v = [mp.mpf(x) for x in s["v"]]
        for k, f in self.jac.items():
            put(k, mp.matrix(f(*a, *v)))
        for k, f in self.kin_jac.items():
            put(k, mp.matrix(f(*a)))
        return out

    def maps(self, a, v):
        """The maps the Jacobians differentiate, by the numeric route at the argument list `a`
        (complex entries allowed, for complex-step derivatives): the sliding `qdd` (no inputs) or
        the closed loop's `[qdd; u]` at `v`, and the impact's `qd+`."""
        m = self.m
        n = len(m.q)
        E = lambda k: mp.matrix(self.f[k](*a))
        M, h, J, Jmu = E("M"), E("h"), E("J"), E("Jmu")
        Minv = mp.inverse(M)
        Jh = J + Jmu
        den = (J * Minv * Jh.T)[0, 0]

        def slide(rhs):
            lam = -(J * Minv * rhs)[0, 0] / den
            return Minv * (rhs + Jh.T * lam)
        out = {}
        if m.inputs:
            S, H, Hdqd = E("S"), E("H"), E("Hdqd")
            Y = mp.eye(n) - Jh.T * (1 / den) * J * Minv
            A = H * Minv * Y * S
            B = H * Minv * Y * h - Hdqd
            u = mp.lu_solve(A, mp.matrix(v) + B)
            qdd = slide(S * u - h)
            out["cl_jac"] = mp.matrix(list(qdd) + list(u))
        else:
            out["accel_jac"] = slide(-h)
        JI = E("JI")
        qd = mp.matrix(a[n:2 * n])
        out["impact_jac"] = qd + Minv * JI.T * (-mp.lu_solve(JI * Minv * JI.T, JI * qd))
        return out

    def complex_step(self, s):
        """The Jacobians by complex-step differentiation of `maps` (no subtraction, so no
        cancellation; truncation error about `step^2` relative), name -> mpf."""
        m = self.m
        n = len(m.q)
        a = ([mp.mpf(x) for x in s["q"]] + [mp.mpf(x) for x in s["qd"]]
             + [mp.mpf(s["params"][p.name]) for p, *_ in m.params] + [mp.mpf(s["mu"]),
                                                                       mp.mpf(s["t"])])
        v = [mp.mpf(x) for x in s["v"]]
        step = mp.mpf(10) ** -40
        # each variable: (list, index) in (a, v)
        where = {x: ("a", i) for i, x in enumerate(m.q + m.qd)}
        where[m.mu] = ("a", 2 * n + len(m.params))
        where.update({m.sym[o[2]]: ("v", k) for k, o in enumerate(m.outputs)})
        out = {}
        for k, xs in jacobian_vars(m).items():
            if k not in self.jac:
                continue
            for j, x in enumerate(xs):
                which, i = where[x]
                aa, vv = list(a), list(v)
                (aa if which == "a" else vv)[i] += mp.mpc(0, step)
                col = self.maps(aa, vv)[k]
                for r in range(col.rows):
                    out[f"{k}_{r}_{j}"] = mp.im(col[r]) / step
        return out


def coulomb(out, M, Jc, JL, qd):
    """The ingredients of the impact with Coulomb friction (module docstring): the locks by the
    KKT system `[[M, JL^T], [JL, 0]] [x; l] = [b; 0]`, whose `x` is `M_L^-1 b`."""
    n = M.rows
    k = JL.rows if JL is not None else 0
    K = mp.zeros(n + k, n + k)
    for i in range(n):
        for j in range(n):
            K[i, j] = M[i, j]
        for r in range(k):
            K[i, n + r] = JL[r, i]
            K[n + r, i] = JL[r, i]

    def restricted(b):
        x = mp.lu_solve(K, mp.matrix(list(b) + [0] * k))
        return mp.matrix([x[i] for i in range(n)])
    qdl = restricted(M * qd) if k else qd
    cols = [restricted(Jc[r, :].T) for r in range(3)]
    for i in range(n):
        out[f"coulomb_qdl_{i}"] = qdl[i]
    v = Jc * qdl
    for r, nm in enumerate("tnr"):
        out[f"coulomb_v_{nm}"] = v[r]
    for a, b in ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2)):
        out[f"coulomb_W_{'tnr'[a]}{'tnr'[b]}"] = (Jc[a, :] * cols[b])[0, 0]
    for i in range(n):
        for j in range(2):
            out[f"coulomb_R_{i}_{j}"] = cols[j][i]


def desired(des, a, t):
    """The desired trajectory and its two derivatives at t (Section 3.2's quintic, a hold, or a
    Bezier polynomial in s = t / duration, held at its last point after the duration)."""
    if des["shape"] == "hold":
        return mp.mpf(des["value"](*a)), mp.mpf(0), mp.mpf(0)
    if des["shape"] == "bezier":
        pts = [mp.mpf(f(*a)) for f in des["points"]]
        T = des["duration"](*a)
        if t >= T:
            return pts[-1], mp.mpf(0), mp.mpf(0)
        s = t / T

        def bern(c):    # sum_k c_k C(M, k) s^k (1 - s)^(M - k), M = len(c) - 1
            M = len(c) - 1
            return sum(ck * mp.binomial(M, k) * s ** k * (1 - s) ** (M - k)
                       for k, ck in enumerate(c))
        M = len(pts) - 1
        d1 = [pts[k + 1] - pts[k] for k in range(M)]
        d2 = [d1[k + 1] - d1[k] for k in range(M - 1)]
        return (bern(pts), M * bern(d1) / T,
                M * (M - 1) * bern(d2) / T ** 2 if M >= 2 else mp.mpf(0))
    y0, y1, T = des["from"](*a), des["to"](*a), des["duration"](*a)
    if t >= T:
        return mp.mpf(y1), mp.mpf(0), mp.mpf(0)
    s = t / T
    dy = y1 - y0
    return (y0 + dy * (10 * s ** 3 - 15 * s ** 4 + 6 * s ** 5),
            dy * (30 * s ** 2 - 60 * s ** 3 + 30 * s ** 4) / T,
            dy * (60 * s - 180 * s ** 2 + 120 * s ** 3) / T ** 2)


# ------------------------------------------------------------------------------ sampling
def exact(x):
    """The exact decimal expansion of a double."""
    return str(Decimal(float(x)))


class Sampler:
    """Deterministic doubles (random.Random is stable across Python versions)."""

    def __init__(self, name):
        self.r = random.Random(SEED + sum(map(ord, name)))

    def uni(self, a, b):
        return float(a + (b - a) * self.r.random())


def sample_params(m: Model, smp: Sampler):
    """Parameters near their defaults (within +-10 %, or [0, 0.2] rad / [0, 1] for a zero
    default), inside their ranges."""
    out = {}
    for s, dflt, (lo, hi, loc, hic), unit in m.params:
        if dflt != 0:
            v = dflt * smp.uni(0.9, 1.1)
        else:
            v = smp.uni(0.0, 0.2 if unit == "rad" else 1.0)
        v = float(min(max(mp.mpf(v), lo), hi))
        if (v == lo and not loc) or (v == hi and not hic):
            v = dflt
        out[s.name] = v
    return out


def make_samples(m: Model):
    """N_STRIKE samples at the strike posture (the guard's zero, solved for the first angle it
    depends on, from a generic start) and N_GENERIC generic ones; the stance foot on the floor
    and its velocity along it."""
    smp = Sampler(m.name)
    n = len(m.q)
    angles = [i for i in range(2, n) if m.units[m.q[i].name] == "rad"]
    gl = sp.lambdify(m.q + [s for s, *_ in m.params], m.guard, modules="mpmath")
    solve_for = next((i for i in angles if m.guard.has(m.q[i])), None)
    samples = []
    tries = 0
    while len(samples) < N_STRIKE + N_GENERIC:
        tries += 1
        assert tries < 200, f"{m.name}: cannot draw samples"
        tag = "strike" if len(samples) < N_STRIKE else "generic"
        prm = sample_params(m, smp)
        phi = prm.get(m.phi.name, 0.0) if m.phi != 0 else 0.0
        x = smp.uni(-1, 1)
        q = [x, float(-mp.mpf(x) * mp.tan(phi))] + [smp.uni(-0.5, 0.5) for _ in range(2, n)]
        xd = smp.uni(-1, 1)
        qd = [xd, float(-mp.mpf(xd) * mp.tan(phi))] + [smp.uni(-2, 2) for _ in range(2, n)]
        if tag == "strike":
            if solve_for is None:
                continue
            pv = [mp.mpf(prm[s.name]) for s, *_ in m.params]

            def f(th):
                qq = list(map(mp.mpf, q))
                qq[solve_for] = th
                return gl(*qq, *pv)
            try:
                with mp.workdps(40):
                    root = mp.findroot(f, mp.mpf(q[solve_for]))
            except (ValueError, ZeroDivisionError):
                continue
            if abs(root) > 1.5:
                continue
            q[solve_for] = float(root)
        u = [smp.uni(-5, 5) for _ in m.inputs]
        v = [smp.uni(-5, 5) for _ in m.outputs]
        mu = smp.uni(-1, 1)
        t = smp.uni(0, 1.0)      # across the ramps (T_set 0.3-0.4 s) and the holds after them
        s = {"tag": tag, "params": prm, "q": q, "qd": qd, "u": u, "mu": mu, "v": v, "t": t}
        samples.append(s)
    return samples


def fmt(x):
    if x == 0:
        return "0"
    return mp.nstr(x, OUT_DIGITS, strip_zeros=False, min_fixed=-5, max_fixed=8)


def closed_eval(m: Model, d: Derived, s):
    """The closed forms evaluated at a sample (for the closed-vs-numeric check)."""
    subs_syms = (m.q + m.qd + [p for p, *_ in m.params] + [m.mu]
                 + [m.sym[nm] for nm, _ in m.inputs]
                 + [m.sym[o[2]] for o in m.outputs])
    vals = (s["q"] + s["qd"] + [s["params"][p.name] for p, *_ in m.params] + [s["mu"]]
            + s["u"] + s["v"])
    out = {}
    if not hasattr(d, "_closed_f"):
        d._closed_f = {k: sp.lambdify(subs_syms, e, modules="mpmath", cse=True)
                       for k, e in d.closed.items()}
    for k, e in d.closed.items():
        r = d._closed_f[k](*[mp.mpf(x) for x in vals])
        if isinstance(e, sp.MatrixBase):
            r = mp.matrix(r)
            if k in ("Y", "A"):
                for i in range(r.rows):
                    for j in range(r.cols):
                        out[f"{k}_{i}_{j}"] = r[i, j]
            else:
                for i in range(r.rows):
                    out[f"{k}_{i}"] = r[i]
        else:
            out[k] = r
    return out


def reference(m: Model, d: Derived):
    """Evaluate every sample at DPS_LO and DPS_HI; return (samples JSON, names, checks)."""
    num = Numeric(m, d)
    samples = make_samples(m)
    worst = mp.mpf(0)
    worst_closed = mp.mpf(0)
    worst_jac = mp.mpf(0)
    rows = []
    names = None
    for s in samples:
        with mp.workdps(DPS_LO):
            lo = num.evaluate(s)
        with mp.workdps(DPS_HI):
            hi = num.evaluate(s)
            scale = max(abs(v) for v in hi.values())
            for k, vh in hi.items():
                den = max(abs(vh), mp.mpf(10) ** -20 * scale)
                if den:
                    worst = max(worst, abs(lo[k] - vh) / den)
        if d.closed:
            with mp.workdps(DPS_HI):
                c = closed_eval(m, d, s)
                for k, vc in c.items():
                    vh = hi[k]
                    den = max(abs(vh), mp.mpf(10) ** -20 * scale)
                    if den:
                        worst_closed = max(worst_closed, abs(vc - vh) / den)
        if d.jacobians:
            with mp.workdps(DPS_HI):
                for k, vc in num.complex_step(s).items():
                    vh = hi[k]
                    den = max(abs(vh), mp.mpf(10) ** -20 * scale)
                    if den:
                        worst_jac = max(worst_jac, abs(vc - vh) / den)
        names = list(hi)
        with mp.workdps(DPS_HI):
            out = {k: fmt(v) for k, v in hi.items()}
        rows.append({"tag": s["tag"],
                     "params": {k: exact(v) for k, v in s["params"].items()},
                     "q": [exact(v) for v in s["q"]], "qd": [exact(v) for v in s["qd"]],
                     "u": [exact(v) for v in s["u"]], "mu": exact(s["mu"]),
                     "v": [exact(v) for v in s["v"]], "t": exact(s["t"]), "out": out})
    assert worst < mp.mpf(10) ** -CLAIM_DIGITS, (m.name, worst)
    if d.closed:
        assert worst_closed < mp.mpf(10) ** -(CLAIM_DIGITS + 10), (m.name, worst_closed)
    if d.jacobians:
        assert worst_jac < mp.mpf(10) ** -(CLAIM_DIGITS + 10), (m.name, worst_jac)
    checks = {"rel_dps50_vs_dps70": mp.nstr(worst, 3),
              "closed_vs_numeric": mp.nstr(worst_closed, 3) if d.closed else None}
    if d.jacobians:
        checks["jacobians_vs_complex_step"] = mp.nstr(worst_jac, 3)
    return rows, names, checks


def write(m: Model, d: Derived, outdir=OUTDIR):
    rows, names, checks = reference(m, d)
    data = {"model": m.name, "file": os.path.relpath(m.path, ROOT), "generator": GENERATOR,
            "sympy": sp.__version__, "mpmath": mp.__version__, "dps": DPS_HI,
            "digits": CLAIM_DIGITS,
            "coordinates": [s.name for s in m.q],
            "parameters": [s.name for s, *_ in m.params],
            "inputs": [nm for nm, _ in m.inputs], "outputs": [o[0] for o in m.outputs],
            "aux": [o[2] for o in m.outputs], "points": list(m.points),
            "names": names, "checks": checks}
    os.makedirs(outdir, exist_ok=True)
    path = os.path.join(outdir, f"{m.name}.json")
    lines = ["{"] + [f"  {json.dumps(k)}: {json.dumps(v)}," for k, v in data.items()]
    lines.append('  "samples": [')
    lines.append(",\n".join("    " + json.dumps(r) for r in rows))
    lines += ["  ]", "}"]
    with open(path, "w") as fh:
        fh.write("\n".join(lines) + "\n")
    with open(path) as fh:
        json.load(fh)
    return path, checks


def model_files():
    return sorted(os.path.join(MODELS, f) for f in os.listdir(MODELS) if f.endswith(".toml"))


CLOSED_MAX_N = 5     # closed forms on the symbolic inverse of M up to this many coordinates


def main(paths=None):
    """Write tests/data/models/<name>.json for the given model files (default: all); return
    each model's accuracy checks (for sympy_ref/report.json)."""
    res = {}
    for path in paths or model_files():
        t0 = time.time()
        m = load(path)
        d = derive(m, closed=len(m.q) <= CLOSED_MAX_N)
        t1 = time.time()
        out, checks = write(m, d)
        print(f"{m.name}: derive {t1 - t0:.1f} s, evaluate {time.time() - t1:.1f} s, {checks}",
              flush=True)
        res[m.name] = checks
    return res


if __name__ == "__main__":
    main(sys.argv[1:])
