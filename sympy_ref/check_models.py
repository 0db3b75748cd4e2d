"""Cross-checks of the generic model derivation (models.py) inside SymPy.

1. The paper's two walkers: models/paper-active.toml and models/paper-passive.toml, derived by
   models.py from the model files, must agree with the hand-written derivation of the paper's
   model (model.py, its kernel tables of docs/kernels.md) on the samples of
   tests/data/models/<name>.json.  The hand-written kernels' symbolic outputs are evaluated at
   70 digits at those samples and compared with (a) the generic numeric route recomputed at 70
   digits (for the Jacobians: models.py's derivatives of its closed forms) and (b) the 32-digit
   values written in the JSON.  Among them the impact with Coulomb friction's ingredients and
   the Jacobians of the closed loop, the sliding stance and the impacts.
2. The compass gait: the angle block of M (the stance foot pinned) equals the inertia matrix
   printed by Goswami, Thuilot and Espiau (1998), Section 2 (the swing-phase equation of motion
   `M(theta) theta_dd + N(theta, theta_d) theta_d + g(theta) = 0`, theta = [theta_ns, theta_s]):
       M = [[m b^2, -m l b cos(theta_s - theta_ns)],
            [-m l b cos(theta_s - theta_ns), (m_H + m) l^2 + m a^2]],   l = a + b,
   exactly (the difference simplifies to 0), with theta_ns = th_sw and theta_s = th_st.

Usage: python check_models.py   (prints the maximum relative differences; takes about a minute:
model.derive() is the slow part)
"""
from __future__ import annotations

import json
import os
import sys

import mpmath as mp
import sympy as sp

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import models as ms  # noqa: E402

# hand-written kernel -> [(its output index, generic output name)]
def _vec(prefix, n):
    return [f"{prefix}_{i}" for i in range(n)]


# The impact with Coulomb friction's ingredients, in the hand-written kernels' order.
COULOMB = (_vec("coulomb_qdl", 4) + [f"coulomb_v_{c}" for c in "tnr"]
           + [f"coulomb_W_{ab}" for ab in ("tt", "tn", "tr", "nn", "nr", "rr")]
           + [f"coulomb_R_{i}_{j}" for i in range(4) for j in range(2)])


def _jac(prefix, columns):
    """A generic Jacobian's entries (columns over x, z, th1, th2, xd, zd, th1d, th2d, mu, v) in
    the order of a hand-written one over the given columns."""
    return [f"{prefix}_{i}_{j}" for i in range(4) for j in columns]


TH1, XD, ZD, TH1D, TH2D, MU, V = 2, 4, 5, 6, 7, 8, 9


PAPER = {
    "paper-active": {
        "mass_matrix": [f"M_{i}_{j}" for i in range(4) for j in range(4)],
        "bias": _vec("h", 4),
        "lambda_level": ["lambda"],
        "projection_level": [f"Y_{i}_{j}" for i in range(4) for j in range(4)],
        "control_level": ["A_0_0", "B_0"],
        "accel_level": _vec("qdd", 4),
        "closed_loop_level": _vec("qdd_cl", 4) + ["u_cl_0"],
        "stick_level": _vec("stick_qdd", 4) + ["stick_lambda_t", "stick_lambda_n"],
        "closed_loop_stick_level": _vec("stick_qdd_cl", 4) + ["stick_u_cl_0",
                                                              "stick_lambda_t_cl",
                                                              "stick_lambda_n_cl"],
        "impact3_level": _vec("impact_ds_lambda", 3) + _vec("impact_ds_qdp", 4),
        "impact2_level": _vec("impact_lambda", 2) + _vec("impact_qdp", 4),
        "impact_coulomb_level": COULOMB,
        "closed_loop_level_jacobian": _jac("cl_jac", (TH1, TH1D, MU, V)),
        "impact2_level_jacobian": _jac("impact_jac", (TH1, XD, ZD, TH1D, TH2D)),
        "fore_foot": ["fore_foot_x", "fore_foot_z", "fore_foot_xd", "fore_foot_zd"],
        "energy": ["T", "V"],
    },
    "paper-passive": {
        "mass_matrix": [f"M_{i}_{j}" for i in range(4) for j in range(4)],
        "bias": _vec("h", 4),
        "lambda_slope": ["lambda"],
        "accel_slope": _vec("qdd", 4),
        "stick_slope": _vec("stick_qdd", 4) + ["stick_lambda_t", "stick_lambda_n"],
        "impact_slope": _vec("impact_lambda", 1) + _vec("impact_qdp", 4),
        "impact2_slope": _vec("impact_ds_lambda", 2) + _vec("impact_ds_qdp", 4),
        "impact_coulomb_slope": COULOMB,
        "accel_slope_jacobian": _jac("accel_jac", (TH1, TH1D, MU)),
        "impact_slope_jacobian": _jac("impact_jac", (TH1, XD, ZD, TH1D, TH2D)),
        "fore_foot": ["fore_foot_x", "fore_foot_z", "fore_foot_xd", "fore_foot_zd"],
        "energy": ["T", "V"],
    },
}


def sample_of(row):
    """A JSON sample back to the dict models.Numeric.evaluate takes (exact decimal strings)."""
    return {"tag": row["tag"], "params": row["params"], "q": row["q"], "qd": row["qd"],
            "u": row["u"], "mu": row["mu"], "v": row["v"], "t": row["t"]}


def rel(a, b, scale):
    return abs(a - b) / max(abs(b), mp.mpf(10) ** -20 * scale)


def check_paper(name, mdl):
    """Max relative differences (fresh generic route, JSON values) against model.py."""
    with open(os.path.join(ms.OUTDIR, f"{name}.json")) as fh:
        data = json.load(fh)
    m = ms.load(os.path.join(ms.MODELS, f"{name}.toml"))
    num = ms.Numeric(m, ms.derive(m, closed=True))     # closed: the Jacobians
    worst_fresh = worst_json = mp.mpf(0)
    count = 0
    fns = {}
    for kname, outs in PAPER[name].items():
        k = mdl.kernels[kname]
        args = list(k["inputs"]) + list(k["params"])
        fns[kname] = (args, sp.lambdify(args, [e for _, e in k["outputs"]], modules="mpmath"))
        assert len(k["outputs"]) == len(outs), kname
    for row in data["samples"]:
        s = sample_of(row)
        byname = dict(zip([c for c in data["coordinates"]], s["q"]))
        byname.update({c + "d": v for c, v in zip(data["coordinates"], s["qd"])})
        byname.update(s["params"])
        byname.update(dict(zip(data["inputs"], s["u"])))
        byname.update(dict(zip(data["aux"], s["v"])))
        byname["mu"] = s["mu"]
        with mp.workdps(ms.DPS_HI):
            mine = num.evaluate(s)
            scale = max(abs(v) for v in mine.values())
            for kname, (args, f) in fns.items():
                vals = f(*[mp.mpf(byname.get(a.name, "0")) for a in args])
                for ref, oname in zip(vals, PAPER[name][kname]):
                    worst_fresh = max(worst_fresh, rel(mine[oname], ref, scale))
                    worst_json = max(worst_json, rel(mp.mpf(row["out"][oname]), ref, scale))
                    count += 1
    return worst_fresh, worst_json, count


def check_goswami():
    """The compass gait's pinned-foot inertia matrix against Goswami et al. (1998)."""
    m = ms.load(os.path.join(ms.MODELS, "compass-gait.toml"))
    d = ms.derive(m)
    S = m.sym
    th_st, th_sw = S["th_st"], S["th_sw"]
    mm, mH, a, b = S["m"], S["m_H"], S["a"], S["b"]
    L = a + b
    c = sp.cos(th_st - th_sw)
    gos = sp.Matrix([[mm * b ** 2, -mm * L * b * c],
                     [-mm * L * b * c, (mH + mm) * L ** 2 + mm * a ** 2]])
    i_sw, i_st = m.q.index(th_sw), m.q.index(th_st)
    mine = d.M.extract([i_sw, i_st], [i_sw, i_st])
    diff = (mine - gos).applyfunc(lambda e: sp.simplify(sp.expand_trig(e)))
    return diff == sp.zeros(2, 2)


def start_of(m, P):
    """The model file's [start] values (coordinates and velocities) at the parameters P."""
    subs = {s: P[s.name] for s, *_ in m.params}
    return {k: float(ms.parse(v, m.sym, f"start {k}").subs(subs))
            for k, v in m.raw.get("start", {}).items()}


# the models whose files give a start posture (just after an impact, both feet on the floor)
START = ["three-link", "five-link"]


def check_start_A(name):
    """det A (Eq. 30, sliding stance with mu = 0) at the model's start posture and defaults."""
    m = ms.load(os.path.join(ms.MODELS, f"{name}.toml"))
    num = ms.Numeric(m, ms.derive(m))
    P = {s.name: dflt for s, dflt, *_ in m.params}
    q, qd = [0.0] * len(m.q), [0.0] * len(m.q)
    for k, v in start_of(m, P).items():
        names = [s.name for s in m.q]
        if k in names:
            q[names.index(k)] = v
        else:
            qd[[s.name for s in m.qd].index(k)] = v
    s = {"params": P, "q": q, "qd": qd, "u": [0.0] * len(m.inputs), "mu": 0.0,
         "v": [0.0] * len(m.outputs), "t": 0.0}
    with mp.workdps(30):
        out = num.evaluate(s)
        p = len(m.inputs)
        A = mp.matrix([[out[f"A_{i}_{j}"] for j in range(p)] for i in range(p)])
        return mp.det(A), out["swing_foot_z"], out["guard"]


def main():
    import model as md
    mdl = md.derive()
    res = {}
    for name in PAPER:
        fresh, js, count = check_paper(name, mdl)
        res[name] = (fresh, js, count)
        print(f"{name}: {count} values; max rel. difference to model.py: generic route "
              f"{mp.nstr(fresh, 3)}, JSON (32 digits) {mp.nstr(js, 3)}")
    ok = check_goswami()
    print(f"compass-gait: M (angle block) equals Goswami et al. 1998: {ok}")
    for name in START:
        det, zf, guard = check_start_A(name)
        print(f"{name}: at the start posture det A = {mp.nstr(det, 6)}, swing foot z = "
              f"{mp.nstr(zf, 3)}, strike guard = {mp.nstr(guard, 6)}")
    return res, ok


if __name__ == "__main__":
    main()
