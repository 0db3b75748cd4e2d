"""Independent reference for Garcia, Chatterjee, Ruina and Coleman's simplest walking model
(models/simplest-walker.toml): its period-one fixed point and Floquet multipliers.

Derived here from scratch with SymPy (nothing read from the Rust code or its kernels):

- Lagrange's equations of the walker with its foot free (the four coordinates), then the
  stance with the stance foot stuck (checked: the ground force stays inside the friction cone
  |F_t| <= mu0 F_n along the whole cycle): the two legs' angles a = th_st, b = th_sw from the
  vertical, the hip mass M at (l sin a, l cos a) from the foot, the swing foot's mass m at
  hip - l (sin b, cos b); Lagrange's equations;
- the strike: 2 phi - a - b falls through zero with the swing foot ahead of the stance foot;
- the plastic impact with the striking foot stuck (checked: the impulse lies in the friction
  cone, |P_t| <= mu0 P_n, P_n > 0), the old stance foot free (it leaves the floor): the full
  system (x, z, a, b) with the impulse at the striking foot only, M (qd+ - qd-) = J^T P,
  J qd+ = 0;
- relabelling: the legs swap, the new stance foot is at rest.

The map on the section r = (th_st, th_std, th_swd) (th_sw = 2 phi - th_st, the foot at rest);
its Jacobian by the variational equations (the field's Jacobian and the impact map's by
complex-step differentiation of their numerical evaluation: exact to rounding), the saltation
at the strike; the fixed point by Newton's method. Integration: SciPy's DOP853 at
rtol = 1e-13, atol = 1e-15. A Richardson-extrapolated central difference of the map checks
the Jacobian inside this script.

Writes sympy_ref/simplest_walker.json. Run: python3 sympy_ref/simplest_walker.py (the environment
variable RTOL changes the integration tolerance, for a convergence check: at RTOL=3e-14 the
multipliers move by 2e-12).
"""

import json
import os

import numpy as np
import sympy as sp
from scipy.integrate import solve_ivp

PARAMS = {"m": 1e-4, "M": 1.0, "l": 1.0, "g": 1.0, "phi": 0.009, "mu0": 5.0}
RTOL, ATOL = float(os.environ.get("RTOL", "1e-13")), 1e-15


def derive():
    """Lagrange's equations of the walker with the foot free, as `M(q) qdd + h(q, qd) = 0`
    (the floor's force on the stance foot is what makes the foot rows hold), and the swing
    foot's position: SymPy expressions, differentiated by SymPy."""
    m, M, l, g = sp.symbols("m M l g", positive=True)
    t = sp.symbols("t")
    names = ("x", "z", "a", "b")
    fs = [sp.Function(n)(t) for n in names]
    x, z, a, b = fs
    hip = sp.Matrix([x + l * sp.sin(a), z + l * sp.cos(a)])
    swing = hip - sp.Matrix([l * sp.sin(b), l * sp.cos(b)])
    stance = sp.Matrix([x, z])
    bodies = [(m, stance), (M, hip), (m, swing)]
    kinetic = sum(mass * (p.diff(t).T * p.diff(t))[0] for mass, p in bodies) / 2
    potential = sum(mass * g * p[1] for mass, p in bodies)
    lag = kinetic - potential
    q = sp.symbols("x z a b")
    qd = sp.symbols("xd zd ad bd")
    qdd = sp.symbols("xdd zdd add bdd")
    subs2 = {f.diff(t, 2): s for f, s in zip(fs, qdd)}
    subs1 = {f.diff(t): s for f, s in zip(fs, qd)}
    subs0 = dict(zip(fs, q))

    def gen(e):
        return e.subs(subs2).subs(subs1).subs(subs0)

    eqs = [sp.expand(gen(sp.diff(lag.diff(f.diff(t)), t) - lag.diff(f))) for f in fs]
    mass = sp.Matrix(4, 4, lambda i, j: eqs[i].coeff(qdd[j]))
    bias = sp.Matrix([eqs[i].subs({s: 0 for s in qdd}) for i in range(4)])
    swing_pos = gen(swing)
    jac_i = swing_pos.jacobian(q)
    args = [m, M, l, g, *q, *qd]
    lam = lambda e: sp.lambdify(args, e, "numpy")  # noqa: E731
    return {
        "mass": lam(mass),
        "bias": lam(bias),
        "swing": lam(swing_pos),
        "jac_i": lam(jac_i),
    }


def numeric(d):
    """The stuck stance's field, the ground force, the impact with the striking foot stuck,
    each as a function of the state s = (a, b, ad, bd); complex arguments pass through (the
    Jacobians below are complex-step derivatives: exact to rounding, no difference step)."""
    par = [PARAMS[k] for k in ("m", "M", "l", "g")]
    phi, mu0 = PARAMS["phi"], PARAMS["mu0"]
    tangent = np.array([np.cos(phi), -np.sin(phi)])
    normal = np.array([np.sin(phi), np.cos(phi)])

    def full(s, xd=0.0, zd=0.0):
        return [*par, 0.0, 0.0, s[0], s[1], xd, zd, s[2], s[3]]

    def mass(s):
        return np.array(d["mass"](*full(s)), dtype=complex)

    def bias(s):
        return np.array(d["bias"](*full(s)), dtype=complex).ravel()

    def field(s):
        mm, h = mass(s), bias(s)
        acc = np.linalg.solve(mm[2:, 2:], -h[2:])
        return np.array([s[2], s[3], acc[0], acc[1]])

    def forces(s):
        mm, h = mass(s), bias(s)
        acc = np.linalg.solve(mm[2:, 2:], -h[2:])
        f = mm[:2, 2:] @ acc + h[:2]  # the floor's force on the foot (world frame)
        return np.array([tangent @ f, normal @ f])

    def impact(s):
        mm = mass(s)
        jac = np.array(d["jac_i"](*full(s)), dtype=complex)
        jr = np.vstack([tangent @ jac, normal @ jac])
        qdm = np.array([0.0, 0.0, s[2], s[3]], dtype=complex)
        minv_jt = np.linalg.solve(mm, jr.T)
        p = -np.linalg.solve(jr @ minv_jt, jr @ qdm)
        qdp = qdm + minv_jt @ p
        return p, qdp

    def post(s):
        _, qdp = impact(s)
        return np.array([s[1], s[0], qdp[3], qdp[2]])

    def swing_x(s):
        return float(np.real(np.array(d["swing"](*full(s)), dtype=complex).ravel()[0]))

    def cjac(fun, s):
        h = 1e-30
        cols = []
        for k in range(4):
            e = np.array(s, dtype=complex)
            e[k] += 1j * h
            cols.append(np.imag(fun(e)) / h)
        return np.array(cols).T

    return {
        "f": lambda s: np.real(field(np.asarray(s, dtype=complex))),
        "fj": lambda s: cjac(field, s),
        "forces": lambda s: np.real(forces(np.asarray(s, dtype=complex))),
        "impulse": lambda s: np.real(impact(np.asarray(s, dtype=complex))[0]),
        "post": lambda s: np.real(post(np.asarray(s, dtype=complex))),
        "post_jac": lambda s: cjac(post, s),
        "swing_x": lambda s: swing_x(np.asarray(s, dtype=complex)),
        "mu0": mu0,
    }


def rhs(fn):
    def f(_, y):
        s = y[:4]
        phi = y[4:].reshape(4, 4)
        ds = fn["f"](s)
        dphi = fn["fj"](s) @ phi
        return np.concatenate([ds, dphi.ravel()])

    return f


def step(fn, s0, check):
    """One step from the full post-impact state s0 = (a, b, ad, bd): the next post-impact
    state, the period, the 4x4 Jacobian of the full map, the worst friction ratios."""
    phi = PARAMS["phi"]
    y0 = np.concatenate([s0, np.eye(4).ravel()])
    f = rhs(fn)
    # Leave the strike posture first (the guard is zero at the start and falls at once).
    early = solve_ivp(f, (0.0, 0.5), y0, method="DOP853", rtol=RTOL, atol=ATOL)
    guard = lambda _, y: 2 * phi - y[0] - y[1]  # noqa: E731
    guard.terminal = False
    guard.direction = -1
    sol = solve_ivp(
        f, (0.5, 20.0), early.y[:, -1], method="DOP853", rtol=RTOL, atol=ATOL,
        events=guard, dense_output=True,
    )
    for te in sol.t_events[0]:
        ye = sol.sol(te)
        if fn["swing_x"](ye[:4]) > 0:
            break
    else:
        raise RuntimeError("no strike")
    # Re-integrate to the strike exactly (the dense output is less accurate than a step).
    end = solve_ivp(f, (0.5, te), early.y[:, -1], method="DOP853", rtol=RTOL, atol=ATOL)
    ye = end.y[:, -1]
    s, ph = ye[:4], ye[4:].reshape(4, 4)
    fv = fn["f"](s)
    gy = np.array([-1.0, -1.0, 0.0, 0.0])
    salt = np.eye(4) - np.outer(fv, gy) / (gy @ fv)
    post = fn["post"](s)
    jac = fn["post_jac"](s) @ salt @ ph
    ratios = {}
    if check:
        mu0 = PARAMS["mu0"]
        ts = np.linspace(0.0, te, 400)
        full = solve_ivp(f, (0.0, te), y0, method="DOP853", rtol=1e-10, atol=1e-12,
                         dense_output=True)
        worst = 0.0
        min_normal = np.inf
        for tt in ts:
            ft, fnrm = fn["forces"](full.sol(tt)[:4])
            worst = max(worst, abs(ft) / fnrm)
            min_normal = min(min_normal, fnrm)
        pt, pn = fn["impulse"](s)
        ratios = {
            "stance_max_ft_over_fn": worst,
            "stance_min_fn": min_normal,
            "impact_pt_over_pn": abs(pt) / pn,
            "impact_pn": pn,
            "mu0": mu0,
        }
    return post, te, jac, ratios


def embed(r):
    phi = PARAMS["phi"]
    return np.array([r[0], 2 * phi - r[0], r[1], r[2]])


E = np.array([[1.0, 0, 0], [-1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]])
PI = [0, 2, 3]


def reduced(fn, r, check=False):
    post, te, jac, ratios = step(fn, embed(r), check)
    return post[PI], te, jac[np.ix_(PI, range(4))] @ E, ratios


def main():
    d = derive()
    fn = numeric(d)
    phi = PARAMS["phi"]
    theta, thetad = 0.2003109, -0.1998325
    r = np.array([phi - theta, -thetad, -thetad * np.cos(2 * theta)])
    for _ in range(20):
        p, _, j, _ = reduced(fn, r)
        res = p - r
        if np.linalg.norm(res) < 1e-13:
            break
        r = r + np.linalg.solve(np.eye(3) - j, res)
    p, period, j, ratios = reduced(fn, r, check=True)
    # A check of the Jacobian inside this script: Richardson-extrapolated central differences.
    fd = np.zeros((3, 3))
    for k in range(3):
        cols = []
        for h in (1e-4, 5e-5):
            e = np.zeros(3)
            e[k] = h
            cols.append((reduced(fn, r + e)[0] - reduced(fn, r - e)[0]) / (2 * h))
        fd[:, k] = (4 * cols[1] - cols[0]) / 3
    eig = np.linalg.eigvals(j)
    eig = sorted(eig, key=lambda c: -abs(c))
    out = {
        "model": "models/simplest-walker.toml",
        "params": PARAMS,
        "integration": {"method": "DOP853", "rtol": RTOL, "atol": ATOL},
        "section": ["th_st", "th_std", "th_swd"],
        "fixed_point": list(map(float, r)),
        "residual": float(np.linalg.norm(p - r)),
        "period": float(period),
        "garcia_theta_thetadot": [float(phi - r[0]), float(-r[1])],
        "reduced_jacobian": [list(map(float, row)) for row in j],
        "jacobian_vs_richardson_fd": float(np.max(np.abs(j - fd))),
        "multipliers": [[float(c.real), float(c.imag)] for c in eig],
        "friction": {k: float(v) for k, v in ratios.items()},
    }
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "simplest_walker.json"), "w") as fh:
        json.dump(out, fh, indent=2)
        fh.write("\n")
    print(json.dumps(out, indent=2))


if __name__ == "__main__":
    main()
