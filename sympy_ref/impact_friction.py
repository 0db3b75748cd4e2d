"""Reference of the whole plastic impact with Coulomb friction at the striking foot (not in the
paper): tests/data/impact_friction.json.

Impact model: W. J. Stronge, *Impact Mechanics*, Cambridge University Press, 2000, Ch. 5
(incremental impulse formulation with Coulomb friction, slip stop and slip reversal), with a
restitution coefficient of zero: the impact ends when the fore foot's normal velocity reaches
zero.  The torso lock of the active walker (level ground, th1d = th2d) is a frictionless
bilateral impulse applied first and kept during the foot's impulse; the passive wheel (slope)
has no lock.

Nothing here uses the Delassus matrix or the closed-form phases of the Rust code.  Every
quantity comes from the model's own M(q) (model.euler_lagrange) and the contact geometry (the
Jacobians of the fore foot and of the stance foot projected on the floor's unit tangent
tau = (cos phi, -sin phi) and unit normal n = (sin phi, cos phi)), through saddle-point (KKT)
systems [[M, -D], [C, 0]] [qd+; impulses] = [M qd-; 0] solved by mpmath's LU at dps 60.  Two
independent methods:

A. algebraic modes (the linear complementarity conditions, one mode at a time): stick (both foot
   velocities zero; valid if Lambda_n >= 0 and |Lambda_t| <= mu0 Lambda_n) and slide s = +-1
   (v_n+ = 0 with Lambda_t = -s mu0 Lambda_n; valid if Lambda_n >= 0 and s v_t+ > 0);
B. Stronge's incremental model integrated numerically in the normal impulse p: explicit steps of
   qd along dqd/dp = M_L^-1 (n + a t) (a = -s mu0 while the foot slips in direction s, the a
   that keeps v_t = 0 while it sticks, the rate itself solved from the KKT system with the lock),
   200 steps per phase (Euler; exact here because the rate is constant between events), the
   events v_t = 0 (slip stops) and v_n = 0 (end of compression, end of the plastic impact)
   located by bisection within the step to 1e-55 of the step.  When the slip stops, the foot
   sticks if the a that holds it has |a| <= mu0 (Stronge's condition on the ratio of the
   impulse increments), and slips the other way otherwise (reverse).

Where the slip does not reverse, A has exactly one valid mode and it must agree with B to 1e-45
(asserted).  For a reversal only B applies (A's slide modes then have the impulse on the cone's
edge against the final slip, a different law).

The rear (old stance) foot's test impulse (double support, Eqs. 11, 46): the normal impulse that
keeps the rear foot on the floor, the fore foot's contact in the impact's final mode (stuck, or
sliding with the final slip direction), from qd+ (a KKT solve with the rear row added).  For the
stick and slide regimes it is checked against the whole impact solved with the rear row from
qd- (the two must agree to 1e-45).  It is the normal impulse along the unit normal (on the
slope the paper's vertical component is this times cos phi).

Every case is chosen so that no regime decision is near its switching point: the margins
(cone slack, slip at the end relative to the velocity scale, the slip-stop impulse relative to
the end of compression, |a| against mu0, the normal rate) are all above MARGIN (asserted), so
that rounding in a double-precision implementation cannot change the regime.

Inputs are doubles, written as exact decimal expansions; outputs with 34 significant digits,
checked against a rerun at dps 90 (relative 1e-40).

Usage: python impact_friction.py [OUT.json]   (default ../tests/data/impact_friction.json)
"""
from __future__ import annotations

import json
import os
import sys

import mpmath as mp
import sympy as sp

import model as md
from kernels import exact_str, out_str

DPS = 60
DPS_CHECK = 90
STEPS = 200
MARGIN = 1e-2
HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_OUT = os.path.join(os.path.dirname(HERE), "tests", "data", "impact_friction.json")
PNAMES = ["m1", "m2", "l", "I1", "I2", "g", "alpha", "phi"]


class Geometry:
    """M(q) and the contact rows, lambdified from the model (mpmath)."""

    def __init__(self):
        M, _, _, _ = md.euler_lagrange()
        xf, zf = md.fore_foot_position()
        Jf = sp.Matrix([[sp.diff(c, q) for q in md.Q] for c in (xf, zf)])
        args = [md.th1] + md.PARAMS
        self.M = sp.lambdify(args, M, modules="mpmath")
        self.Jf = sp.lambdify(args, Jf, modules="mpmath")

    def at(self, th1, par, slope):
        a = [mp.mpf(th1)] + [mp.mpf(par[n]) for n in PNAMES]
        M = mp.matrix(self.M(*a))
        Jf = mp.matrix(self.Jf(*a))
        ph = mp.mpf(par["phi"]) if slope else mp.mpf(0)
        tau = mp.matrix([[mp.cos(ph), -mp.sin(ph)]])
        nrm = mp.matrix([[mp.sin(ph), mp.cos(ph)]])
        Jr = mp.matrix([[1, 0, 0, 0], [0, 1, 0, 0]])
        t, n, r = tau * Jf, nrm * Jf, nrm * Jr
        rows = dict(t=t, n=n, r=r)
        if not slope:
            rows["lock"] = mp.matrix([[0, 0, 1, -1]])
        return M, rows


def kkt(M, D, C, b):
    """Solves M x - D p = b, C x = 0 for (x, p): impulse directions D (list of 1x4 rows, used as
    columns), constraint rows C (same count)."""
    k = len(D)
    K = mp.zeros(4 + k, 4 + k)
    rhs = mp.zeros(4 + k, 1)
    for i in range(4):
        for j in range(4):
            K[i, j] = M[i, j]
        rhs[i] = b[i]
    for c in range(k):
        for i in range(4):
            K[i, 4 + c] = -D[c][0, i]
            K[4 + c, i] = C[c][0, i]
    sol = mp.lu_solve(K, rhs)
    return mp.matrix([sol[i] for i in range(4)]), [sol[4 + c] for c in range(k)]


def dot(row, v):
    return sum(row[0, i] * v[i] for i in range(4))


def lock_rows(rows):
    return [rows["lock"]] if "lock" in rows else []


def method_a(M, rows, qd, mu0):
    """Algebraic modes from qd- (lock included): list of valid (regime, Lambda, qd+)."""
    t, n = rows["t"], rows["n"]
    L = lock_rows(rows)
    b = M * qd
    out = []
    x, p = kkt(M, [t, n] + L, [t, n] + L, b)
    lt, ln = p[0], p[1]
    if ln >= 0 and abs(lt) <= mu0 * ln:
        out.append(("stick", [lt, ln], x))
    for s in (1, -1):
        d = t * (-s * mu0) + n
        x, p = kkt(M, [d] + L, [n] + L, b)
        ln = p[0]
        if ln >= 0 and s * dot(t, x) > 0:
            out.append(("slide-forward" if s > 0 else "slide-backward", [-s * mu0 * ln, ln], x))
    return out


def rate(M, rows, a):
    """dqd/dp for the fore-foot impulse increment (a, 1) along (t, n), the lock kept."""
    L = lock_rows(rows)
    d = (rows["t"] * a + rows["n"]).T
    if L:
        return kkt(M, L, L, d)[0]
    return mp.lu_solve(M, d)


def integrate_phase(qd, r, events, h):
    """Steps qd += h r until one of the events (row, sign) is reached: sign * (row . qd) falls
    from positive to zero or below.  The step where that happens is bisected to 1e-55 of its
    length (dps 60; 10^(5 - dps) in general).  Returns (qd at the event, p advanced, index of the event)."""
    p = mp.mpf(0)
    val = lambda i, q: events[i][1] * dot(events[i][0], q)
    vals = [val(i, qd) for i in range(len(events))]
    for _ in range(10 * STEPS):
        nq = qd + r * h
        nvals = [val(i, nq) for i in range(len(events))]
        hit = [i for i in range(len(events)) if vals[i] > 0 >= nvals[i]]
        if hit:
            lo, hi = mp.mpf(0), h
            while hi - lo > h * mp.mpf(10) ** (5 - mp.mp.dps):
                mid = (lo + hi) / 2
                if any(val(i, qd + r * mid) <= 0 for i in hit):
                    hi = mid
                else:
                    lo = mid
            first = min(hit, key=lambda i: val(i, qd + r * lo))
            return qd + r * hi, p + hi, first
        qd, vals, p = nq, nvals, p + h
    raise AssertionError("no event within 10 * STEPS steps")


def method_b(M, rows, qd_minus, mu0, margins, steps=STEPS, growing=None):
    """Stronge's incremental model from qd_L; returns (regime, Lambda, qd+, phases) or
    ('jam', None, None, phases) when the normal velocity can never reach zero.  The slip
    directions of phases in which more normal impulse made the approach faster are appended to
    `growing`."""
    growing = [] if growing is None else growing
    t, n = rows["t"], rows["n"]
    L = lock_rows(rows)
    qd = kkt(M, L, L, M * qd_minus)[0] if L else qd_minus
    scale = max(abs(e) for e in qd)
    tiny = mp.mpf(10) ** (15 - mp.mp.dps) * scale   # 1e-45 |qd_L| at dps 60
    lam = [mp.mpf(0), mp.mpf(0)]
    phases = []
    vn0 = dot(n, qd)
    assert vn0 < 0, "the fore foot must approach the floor"
    # a foot that starts (nearly) at rest along the floor is a knife edge in double precision
    margins.append(("|v_t-| / |qd_L|", abs(dot(t, qd)) / scale))
    while True:
        vt, vn = dot(t, qd), dot(n, qd)
        if vn >= -tiny:
            break
        if abs(vt) > tiny:
            s = 1 if vt > 0 else -1
            a = -s * mu0
        else:
            r0, r1 = rate(M, rows, 0), rate(M, rows, 1)
            astar = -dot(t, r0) / (dot(t, r1) - dot(t, r0))
            if abs(astar) <= mu0:
                margins.append(("stick-hold |a*|/mu0 slack", 1 - abs(astar) / mu0))
                s, a = 0, astar
            else:
                margins.append(("slip |a*|/mu0 excess",
                                abs(astar) / mu0 - 1 if mu0 > 0 else abs(astar)))
                ok = [s for s in (1, -1) if s * dot(t, rate(M, rows, -s * mu0)) > 0]
                assert len(ok) == 1, ok
                s = ok[0]
                a = -s * mu0
        r = rate(M, rows, a)
        dn, dt = dot(n, r), dot(t, r)
        margins.append(("|normal rate| / W_nn", abs(dn) / dot(n, rate(M, rows, 0))))
        # the end of compression comes in this phase only if dn > 0; with dn <= 0 (more
        # normal impulse, faster approach) the phase can still end where the slip stops
        p_end = -vn / dn if dn > 0 else None
        p_stop = -vt / dt if s != 0 and s * dt < 0 else None
        if dn <= 0:
            growing.append(s)
        if p_end is None and p_stop is None:
            return "jam", None, None, phases
        events = [(n, -1)] + ([(t, s)] if s != 0 else [])
        h = min(e for e in (p_end, p_stop) if e is not None) / steps
        qd_new, dp, which = integrate_phase(qd, r, events, h)
        if s != 0 and which == 1:
            margins.append(("slip stop before the end", 1 - dp / p_end if p_end else 1))
        elif s != 0:
            margins.append(("slip at the end / |v-|", s * dot(t, qd_new) / scale))
        lam = [lam[0] + a * dp, lam[1] + dp]
        phases.append(s)
        qd = qd_new
    if phases[-1] == 0:
        regime = "stick"
    elif len(phases) == 1 or (len(phases) == 2 and phases[0] == 0):
        regime = "slide-forward" if phases[-1] > 0 else "slide-backward"
    else:
        assert len(phases) == 2 and phases[0] == -phases[1], phases
        regime = "reverse-forward" if phases[0] > 0 else "reverse-backward"
    return regime, lam, qd, phases


def rear_impulse(M, rows, qd_plus, mu0, final_slip):
    """The rear foot's normal impulse that keeps it on the floor with the fore foot in its final
    mode (stuck if final_slip == 0, else sliding that way), from qd+."""
    t, n, r = rows["t"], rows["n"], rows["r"]
    L = lock_rows(rows)
    if final_slip == 0:
        D, C = [t, n, r] + L, [t, n, r] + L
        idx = 2
    else:
        d = t * (-final_slip * mu0) + n
        D, C = [d, r] + L, [n, r] + L
        idx = 1
    _, p = kkt(M, D, C, M * qd_plus)
    return p[idx]


def rear_whole(M, rows, qd_minus, mu0, regime):
    """The rear impulse of the whole impact solved with the rear row from qd- (stick/slide)."""
    t, n, r = rows["t"], rows["n"], rows["r"]
    L = lock_rows(rows)
    if regime == "stick":
        _, p = kkt(M, [t, n, r] + L, [t, n, r] + L, M * qd_minus)
        return p[2]
    s = 1 if regime == "slide-forward" else -1
    d = t * (-s * mu0) + n
    _, p = kkt(M, [d, r] + L, [n, r] + L, M * qd_minus)
    return p[1]


def solve_case(geo, c, steps=STEPS, check=True):
    slope = c["floor"] == "slope"
    M, rows = geo.at(c["th1"], c["params"], slope)
    qd = mp.matrix([mp.mpf(v) for v in c["qd_minus"]])
    mu0 = mp.mpf(c["mu0"])
    margins, growing = [], []
    regime, lam, qdp, phases = method_b(M, rows, qd, mu0, margins, steps, growing)
    res = dict(regime=regime, margins=margins, growing=bool(growing))
    if regime == "jam" or not check:
        return res
    final = 0 if regime == "stick" else (1 if regime.endswith("forward") else -1)
    if regime.startswith("reverse"):
        final = -final
    algebraic = method_a(M, rows, qd, mu0)
    if not regime.startswith("reverse"):
        assert len(algebraic) == 1 and algebraic[0][0] == regime, (c, regime, algebraic)
        _, la, xa = algebraic[0]
        tol = mp.mpf(10) ** -45 * (1 + max(abs(e) for e in qd))
        assert all(abs(u - w) <= tol for u, w in zip(la, lam)), (la, lam)
        assert all(abs(xa[i] - qdp[i]) <= tol for i in range(4))
    rear = rear_impulse(M, rows, qdp, mu0, final)
    if not regime.startswith("reverse"):
        rw = rear_whole(M, rows, qd, mu0, regime)
        assert abs(rw - rear) <= mp.mpf(10) ** -45 * (1 + abs(rear)), (rw, rear)
    res.update(impulse=lam, qd_plus=[qdp[i] for i in range(4)], rear=rear,
               algebraic_modes=[m[0] for m in algebraic])
    return res


# ------------------------------------------------------------------ cases
TABLE1 = dict(m1=2.0, m2=1.0, l=1.0, I1=0.5, I2=1.0, g=9.81, alpha=float(mp.pi / 6))
OTHER = dict(m1=1.3, m2=0.7, l=0.8, I1=0.2, I2=0.35, g=9.81, alpha=0.7)


def state(par, floor, xd, th1d, th2d):
    """A pre-impact state at the heel strike: th1 = alpha/2 (+ phi), the stance foot on the
    floor (zd = 0, or -xd tan phi on the slope), rounded to doubles."""
    if floor == "level":
        th1, zd = par["alpha"] / 2, 0.0
    else:
        th1 = float(mp.mpf(par["alpha"]) / 2 + mp.mpf(par["phi"]))
        zd = float(-mp.mpf(xd) * mp.tan(mp.mpf(par["phi"])))
        if zd == 0:
            zd = 0.0
    return th1, [xd, zd, th1d, th2d]


WANTED = ["stick", "slide-forward", "slide-backward", "reverse-forward", "reverse-backward",
          "jam", "stick-growing-approach", "slide-forward-growing-approach",
          "slide-backward-growing-approach"]


def find_cases(geo):
    """Deterministic scan: per floor and parameter set, the first (mu0, xd) on a fixed grid
    that gives each regime with every margin above MARGIN; plus mu0 = 0 cases."""
    cases = []
    sets = [("level", "table1", dict(TABLE1, phi=0.0), 1.0, 0.6),
            ("slope", "table1", dict(TABLE1, phi=0.2), 1.0, 0.3),
            ("level", "other", dict(OTHER, phi=0.0), 1.4, 2.0),
            ("slope", "other", dict(OTHER, phi=0.1), 1.4, -0.5)]
    mus = [0.05, 0.1, 0.15, 0.3, 0.6, 1.0, 2.0, 2.9]
    xds = [k / 8 for k in range(-16, 17)]
    for floor, pname, par, th1d, th2d in sets:
        found = {}
        for mu0 in mus:
            for xd in xds:
                th1, qd = state(par, floor, xd, th1d, th2d)
                c = dict(floor=floor, params=par, th1=th1, qd_minus=qd, mu0=mu0)
                with mp.workdps(20):
                    res = solve_case(geo, c, steps=4, check=False)
                reg = res["regime"] + ("-growing-approach" if res["growing"] else "")
                if reg in found or not all(m > MARGIN for _, m in res["margins"]):
                    continue
                found[reg] = dict(c, name=f"{floor}-{pname}-{reg}")
        for reg in WANTED:
            if reg in found:
                cases.append(found[reg])
        th1, qd = state(par, floor, 0.25, th1d, th2d)
        cases.append(dict(floor=floor, params=par, th1=th1, qd_minus=qd, mu0=0.0,
                          name=f"{floor}-{pname}-mu0=0"))
    return cases


def fmt(v):
    with mp.workdps(40):
        return out_str(v)


def main(out=DEFAULT_OUT):
    mp.mp.dps = DPS
    geo = Geometry()
    cases = find_cases(geo)
    lines, summary = [], []
    for c in cases:
        with mp.workdps(DPS):
            res = solve_case(geo, c)
        with mp.workdps(DPS_CHECK):
            chk = solve_case(geo, c)
        assert chk["regime"] == res["regime"]
        entry = {"name": c["name"], "floor": c["floor"],
                 "params": {k: exact_str(c["params"][k]) for k in PNAMES
                            if c["floor"] == "slope" or k != "phi"},
                 "th1": exact_str(c["th1"]),
                 "qd_minus": [exact_str(v) for v in c["qd_minus"]],
                 "mu0": exact_str(c["mu0"]), "regime": res["regime"]}
        if res["regime"] != "jam":
            for key in ("impulse", "qd_plus"):
                for u, w in zip(res[key], chk[key]):
                    assert abs(u - w) <= mp.mpf(10) ** -40 * (1 + abs(w)), (c["name"], key)
            assert abs(res["rear"] - chk["rear"]) <= mp.mpf(10) ** -40 * (1 + abs(chk["rear"]))
            entry.update(impulse=[fmt(v) for v in res["impulse"]],
                         qd_plus=[fmt(v) for v in res["qd_plus"]],
                         rear_impulse=fmt(res["rear"]),
                         algebraic_modes=res["algebraic_modes"])
        entry["approach_grows_while_slipping"] = res["growing"]
        entry["min_margin"] = mp.nstr(min(m for _, m in res["margins"]), 3)
        summary.append((c["name"], res["regime"], entry["min_margin"]))
        lines.append(json.dumps(entry))
        print(c["name"], res["regime"], entry["min_margin"], flush=True)
    head = {
        "reference": "plastic impact with Coulomb friction at the fore foot, Stronge's "
                     "incremental model (W. J. Stronge, Impact Mechanics, CUP 2000, Ch. 5) "
                     "with restitution 0; see sympy_ref/impact_friction.py",
        "method": "stick/slide: the complementarity modes solved directly (KKT systems with "
                  "M) and, independently, Stronge's model integrated numerically in the normal "
                  "impulse (200 Euler steps per phase, events by bisection), agreeing to "
                  "1e-45; reverse: the numerical integration only; mpmath dps 60, rechecked at "
                  "dps 90",
        "conventions": "qd = [xd, zd, th1d, th2d] in the old coordinates; impulse = "
                       "[Lambda_t, Lambda_n] along the floor's unit tangent (cos phi, -sin phi) "
                       "and unit normal at the fore foot; level: torso lock th1d = th2d applied "
                       "first (frictionless); rear_impulse: the rear foot's normal impulse of "
                       "the double-support test, the fore foot in the final mode; regime "
                       "reverse-<d>: slips towards d first, then back; "
                       "approach_grows_while_slipping: a slip phase had W_nn - s mu0 W_tn <= 0 "
                       "(more normal impulse, faster approach) and ended where the slip "
                       "stopped; min_margin: the smallest relative distance of a regime "
                       "decision from its switching point",
        "digits": 30,
    }
    text = ["{"] + [f"  {json.dumps(k)}: {json.dumps(v)}," for k, v in head.items()]
    text.append('  "cases": [')
    text.append(",\n".join("    " + x for x in lines))
    text += ["  ]", "}"]
    with open(out, "w") as fh:
        fh.write("\n".join(text) + "\n")
    json.load(open(out))
    return {"cases": len(cases), "min_margin": min(float(m) for _, _, m in summary),
            "regimes": {name: regime for name, regime, _ in summary}}


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else DEFAULT_OUT)
