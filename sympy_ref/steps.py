"""High-precision references of one whole step (tests/data/step_active.json, step_passive.json).

Method: explicit Taylor series integration of the 8-dimensional stance dynamics (plus
quadratures) with exact Taylor coefficients from automatic differentiation (taylor.py) of the
symbolic kernels of model.py, at mpmath precision DPS.  The step size is chosen from the last two
Taylor coefficients so that the truncation error per step is about TOL; the Taylor polynomial of
each step is the dense output, on which the heel-strike time is found by Newton's method to full
precision.  The active walker's control switches at T_set, so a step is forced to end exactly at
T_set.  The impact and the reset use the symbolic impact/fore-foot kernels.

Each case is computed twice (a coarse and a fine setting of order, tolerance and precision) and
the number of correct digits claimed is derived from the difference of the two runs.

Usage: python steps.py OUTDIR
"""
from __future__ import annotations

import json
import os
import sys
import time

import mpmath as mp
import sympy as sp

import model as md
from model import (C1, CP, I1, I2, S1, SP, alpha, g, l, m1, m2, mu, phi, th1d, u)
from taylor import (ONE, ZERO, Program, div_coeff, mul_coeff, poly_deriv, poly_eval, poly_integral,
                    sincos_coeff, tanh_coeff)

# Table 1 (exact) and the scene parameters of the paper
P_TABLE1 = {m1: sp.Integer(2), m2: sp.Integer(1), l: sp.Integer(1), I1: sp.Rational(1, 2),
            I2: sp.Integer(1), g: sp.Rational(981, 100)}
ALPHA = sp.pi / 6

CASES = {
    "active": dict(phi=sp.Integer(0), mu0=sp.Rational(2, 5), c=sp.Integer(100),
                   T_set=sp.Rational(3, 10), K_P=0, K_D=0, omega0=sp.Rational(4, 5)),
    "passive": dict(phi=sp.Rational(1, 5), mu0=sp.Rational(1, 5), c=sp.Integer(100)),
}

# (dps, Taylor order, local tolerance): the published run and the check run
SETTINGS = [(40, 30, mp.mpf(10) ** -33), (50, 40, mp.mpf(10) ** -43)]
# independent cross-check: GBS extrapolation (dps, tolerance)
GBS_SETTING = (30, mp.mpf(10) ** -24)
OUT_DIGITS = 32
ZERO_BELOW = mp.mpf(10) ** -40


def mpv(e):
    """Numeric value of a SymPy constant at the current mpmath precision."""
    return mp.mpf(sp.N(e, mp.mp.dps + 10))


class Case:
    """Stance dynamics of one case as Taylor-mode programs, at the current precision."""

    def __init__(self, name):
        self.name = name
        cfg = CASES[name]
        self.cfg = cfg
        mdl = md.derive()
        K = mdl.kernels
        sub = dict(P_TABLE1)
        self.active = name == "active"
        phiv = cfg["phi"]
        consts = {SP: mpv(sp.sin(phiv)), CP: mpv(sp.cos(phiv))}
        poly = lambda kn: [sp.sympify(e).subs(sub) for _, e in K[kn]["poly"]]
        if self.active:
            ins = [S1, C1, th1d, mu]
            self.prog_AB = Program(poly("control_level"), ins, consts)
            self.prog_acc = Program(poly("accel_level") + poly("lambda_level"),
                                    [S1, C1, th1d, mu, u], consts)
        else:
            self.prog_acc = Program(poly("accel_slope") + poly("lambda_slope"),
                                    [S1, C1, th1d, mu], consts)
        self.alpha = mpv(ALPHA)
        self.phi = mpv(phiv)
        self.mu0 = mpv(cfg["mu0"])
        self.c = mpv(cfg["c"])
        self.mt = mpv(P_TABLE1[m1] + P_TABLE1[m2])
        self.g = mpv(P_TABLE1[g])
        self.l = mpv(P_TABLE1[l])
        # friction argument c xd (level) or c xd / cos(phi) (slope, Eq. 37)
        self.fric_scale = self.c / mp.cos(self.phi)
        if self.active:
            self.T_set = mpv(cfg["T_set"])
            # y_d'' (t) = alpha/T^2 (120 s^3 - 180 s^2 + 60 s), s = t / T_set  (polynomial in t)
            a, T = self.alpha, self.T_set
            self.ydd_poly = [ZERO, 60 * a / T ** 3, -180 * a / T ** 4, 120 * a / T ** 5]
            self.yd_poly = [-a / 2, ZERO, ZERO, 10 * a / T ** 3, -15 * a / T ** 4,
                            6 * a / T ** 5]
        # kernels for impact and reset, at this precision
        params = {m1: P_TABLE1[m1], m2: P_TABLE1[m2], l: P_TABLE1[l], I1: P_TABLE1[I1],
                  I2: P_TABLE1[I2], g: P_TABLE1[g], alpha: ALPHA, phi: phiv}
        self.kern = {}
        for kn in ("impact2_level", "impact_slope", "fore_foot", "energy", "lambda_level",
                   "lambda_slope"):
            k = K[kn]
            exprs = [e.subs(params) for _, e in k["outputs"]]
            self.kern[kn] = sp.lambdify(k["inputs"], exprs, modules="mpmath")
        self.th_event = self.alpha / 2 + self.phi

    # ---------------------------------------------------------------- one Taylor expansion
    def expand(self, t0, y0, p, phase):
        """Taylor coefficients (degree p) at t0 of the state y = [x z th1 th2 xd zd th1d th2d]
        and of auxiliary series.  phase: 0 = t < T_set (quintic), 1 = after T_set."""
        Y = [[v] for v in y0]
        x_, z_, t1, t2, xd_, zd_, t1d, t2d = Y
        s, c = [], []
        T, D = [], []
        w = []        # friction argument
        muS = []
        series_acc = [s, c, t1d, muS] + ([[]] if self.active else [])
        if self.active:
            uS = series_acc[4]
            A, B, num = None, None, []
            runAB = self.prog_AB.run([s, c, t1d, muS])
            vS = self._shift(self.ydd_poly, t0) if phase == 0 else [ZERO]
        run = self.prog_acc.run(series_acc)
        acc = [[] for _ in range(4)]
        lam = []
        for k in range(p):
            sincos_coeff(t1, s, c, k)
            w.append(self.fric_scale * xd_[k])
            tanh_coeff(w, T, D, k)
            muS.append(-self.mu0 * T[k])
            if self.active:
                Ak, Bk = runAB.coeff(k)
                if k == 0:
                    A, B = [Ak], [Bk]
                else:
                    A.append(Ak)
                    B.append(Bk)
                # u = (v + B) / A, coefficient k (v: Taylor coefficients of yd'' at t0)
                num.append((vS[k] if k < len(vS) else ZERO) + Bk)
                uS.append(div_coeff(num, A, uS, k))
            out = run.coeff(k)
            for i in range(4):
                acc[i].append(out[i])
            lam.append(out[4])
            # state derivatives
            for i, dS in enumerate((xd_, zd_, t1d, t2d)):
                Y[i].append(dS[k] / (k + 1))
            for i in range(4):
                Y[4 + i].append(acc[i][k] / (k + 1))
        aux = {"lam": lam, "mu": muS, "xd": xd_[:p]}
        if self.active:
            ydot = [a_ - b_ for a_, b_ in zip(t1d[:p], t2d[:p])]
            aux["u"] = uS
            aux["ydot"] = ydot
            aux["ydot_u"] = [mul_coeff(ydot, uS, k) for k in range(p)]
        # friction power  mu lambda xd / cos^2 phi  (energy balance check)
        ml = [mul_coeff(muS, lam, k) for k in range(p)]
        aux["fric_power"] = [mul_coeff(ml, xd_, k) / mp.cos(self.phi) ** 2 for k in range(p)]
        return Y, aux

    @staticmethod
    def _shift(poly, t0):
        """Coefficients of poly(t0 + tau) in tau."""
        n = len(poly)
        out = []
        for k in range(n):
            out.append(mp.fsum(mp.binomial(j, k) * poly[j] * t0 ** (j - k)
                               for j in range(k, n)))
        return out

    # ---------------------------------------------------------------- integration
    def y0_init(self):
        """Eq. 33 (active, omega0) or (P2b) (passive)."""
        if self.active:
            a = self.alpha
            w0 = mpv(self.cfg["omega0"])
            return [ZERO, ZERO, -a / 2, ZERO, ZERO, ZERO, w0, w0]
        y = [ZERO] * 8
        y[6] = mp.mpf(1) / 2
        return y

    def integrate(self, p, tol, verbose=False):
        y = self.y0_init()
        self.y0 = list(y)
        t = ZERO
        quad = {"abs_ydot_u": ZERO, "ydot_u": ZERO, "fric_work": ZERO,
                "int_xd": ZERO}
        lam_min = mp.inf
        nsteps = 0
        phase = 0 if self.active else 1
        while True:
            Y, aux = self.expand(t, y, p, phase)
            # step size from the last two coefficients of every component
            h = mp.inf
            for cs in Y + [aux["fric_power"]] + ([aux["ydot_u"]] if self.active else []):
                sc = max(ONE, abs(cs[0]))
                for m in (len(cs) - 2, len(cs) - 1):
                    if cs[m] != 0:
                        h = min(h, (tol * sc / abs(cs[m])) ** (ONE / m))
            h *= mp.mpf("0.9")
            if self.active and phase == 0 and t + h >= self.T_set:
                h = self.T_set - t
                switch = True
            else:
                switch = False
            # heel strike inside [0, h]?
            f = [c_ for c_ in Y[2]]
            f[0] -= self.th_event
            tau_ev = self._first_up_crossing(f, h)
            if tau_ev is not None:
                h = tau_ev
            # quadratures over [0, h]
            if self.active and phase == 0:
                quad["abs_ydot_u"] += self._abs_integral(aux["ydot_u"], h)
            if self.active:
                quad["ydot_u"] += poly_integral(aux["ydot_u"], 0, h)
            quad["fric_work"] += poly_integral(aux["fric_power"], 0, h)
            quad["int_xd"] += poly_integral(aux["xd"], 0, h)
            for j in range(0, 33):
                lam_min = min(lam_min, poly_eval(aux["lam"], h * j / 32))
            y = [poly_eval(cs, h) for cs in Y]
            t = t + h
            nsteps += 1
            if verbose:
                print(f"  t={mp.nstr(t, 8)} h={mp.nstr(h, 3)} th1={mp.nstr(y[2], 8)}")
            if tau_ev is not None:
                break
            if switch:
                t = self.T_set
                phase = 1
            if t > 10:
                raise RuntimeError("no heel strike")
        y[2] = self.th_event  # the event condition holds to the working precision
        return t, y, quad, lam_min, nsteps

    def _first_up_crossing(self, f, h, n=64):
        prev = poly_eval(f, 0)
        a = ZERO
        for j in range(1, n + 1):
            b = h * j / n
            fb = poly_eval(f, b)
            if prev < 0 <= fb:
                return self._newton(f, a, b)
            prev, a = fb, b
        return None

    @staticmethod
    def _newton(f, a, b):
        df = poly_deriv(f)
        # bisection to a safe start, then Newton to full precision
        for _ in range(30):
            m = (a + b) / 2
            if poly_eval(f, m) < 0:
                a = m
            else:
                b = m
        x = (a + b) / 2
        for _ in range(50):
            dx = poly_eval(f, x) / poly_eval(df, x)
            x -= dx
            if abs(dx) <= mp.eps * 4 * max(abs(x), mp.mpf(10) ** -10):
                break
        return x

    def _abs_integral(self, cs, h, n=64):
        """Integral of |sum cs[k] tau^k| over [0, h] (sign changes located by Newton)."""
        pts = [ZERO]
        prev = poly_eval(cs, 0)
        for j in range(1, n + 1):
            b = h * j / n
            fb = poly_eval(cs, b)
            if prev * fb < 0:
                a = h * (j - 1) / n
                fcs = cs if prev < 0 else [-c_ for c_ in cs]
                pts.append(self._newton(fcs, a, b))
            prev = fb
        pts.append(h)
        return mp.fsum(abs(poly_integral(cs, pts[i], pts[i + 1])) for i in range(len(pts) - 1))

    # ---------------------------------------------------------------- impact and reset
    def step(self, p, tol, integrator=None):
        t0 = time.time()
        T, y, quad, lam_min, nsteps = (integrator or self.integrate)(p, tol)
        x_, z_, t1, t2, xd_, zd_, t1d, t2d = y
        imp = "impact2_level" if self.active else "impact_slope"
        out = self.kern[imp](t1, xd_, zd_, t1d, t2d)
        nI = 2 if self.active else 1
        lamI = out[:nI]
        qdp = out[nI:]
        xf, zf, xdf, zdf = self.kern["fore_foot"](x_, z_, t1, qdp[0], qdp[1], qdp[2])
        tphi = mp.tan(self.phi)
        checks = {}
        if self.active:
            checks["z_f(T) (should be 0)"] = zf
            checks["zd_f+ (should be 0)"] = zdf
            zf_store, zdf_store = ZERO, ZERO
        else:
            checks["z_f + x_f tan(phi) (should be 0)"] = zf + xf * tphi
            checks["zd_f+ + xd_f+ tan(phi) (should be 0)"] = zdf + xdf * tphi
            zf_store, zdf_store = zf, zdf
        q_minus = [x_, z_, t1, t2]
        qd_minus = [xd_, zd_, t1d, t2d]
        q_plus = [xf, zf_store, t1 - self.alpha, t2]
        qd_plus = [xdf, zdf_store, qdp[2], qdp[3]]
        l2 = 2 * self.l * mp.sin(self.alpha / 2)
        if self.active:
            dx = quad["int_xd"] + l2                       # Eq. 34
            checks["dx - (x+ - x(0))"] = dx - (xf - self.y0[0])
        else:
            dx = quad["int_xd"] / mp.cos(self.phi) + l2    # Eq. 47
            checks["dx - (x+ - x(0))/cos(phi)"] = dx - (xf - self.y0[0]) / mp.cos(self.phi)
        V = dx / T
        res = dict(T=T, q_minus=q_minus, qd_minus=qd_minus, q_plus=q_plus, qd_plus=qd_plus,
                   dx=dx, V=V, lambdaI=lamI)
        # energy balance over the stance phase: E(T) - E(0) = int u ydot + int friction power
        E = lambda yy: mp.fsum(self.kern["energy"](yy[1], yy[2], yy[4], yy[5], yy[6], yy[7]))
        work = quad["fric_work"] + (quad["ydot_u"] if self.active else 0)
        checks["energy balance E(T)-E(0)-work"] = E(y) - E(self.y0) - work
        if self.active:
            checks["y(T) - alpha/2 (tracking)"] = (t1 - t2) - self.alpha / 2
            p_ = quad["abs_ydot_u"] / T
            res["p"] = p_
            res["SR"] = p_ / (self.mt * self.g * V)
        else:
            res["p"] = None
            res["SR"] = None
        res["checks"] = checks
        res["lambda_min"] = lam_min
        res["nsteps"] = nsteps
        res["seconds"] = time.time() - t0
        return res


class GBS:
    """Second, independent integrator for the cross-check: Gragg-Bulirsch-Stoer extrapolation
    of the modified midpoint rule (step-size controlled, error estimate from the last two
    extrapolation columns), right-hand side from the sin/cos form of the kernels evaluated
    with lambdify (no Taylor arithmetic, no poly form), heel strike by the Illinois method on
    re-integration from the last accepted step.  Quadratures (int |ydot u|, int xd, friction
    work) are extra state components."""

    KMAX = 14

    def __init__(self, case):
        self.cs = case
        K = md.derive().kernels
        params = {m1: P_TABLE1[m1], m2: P_TABLE1[m2], l: P_TABLE1[l], I1: P_TABLE1[I1],
                  I2: P_TABLE1[I2], g: P_TABLE1[g], alpha: ALPHA, phi: case.cfg["phi"]}
        lf = lambda kn: sp.lambdify(K[kn]["inputs"], [e.subs(params) for _, e in
                                                       K[kn]["outputs"]], modules="mpmath",
                                    cse=True)
        if case.active:
            self.AB = lf("control_level")
            self.acc = lf("accel_level")
            self.lam = lf("lambda_level")
        else:
            self.acc = lf("accel_slope")
            self.lam = lf("lambda_slope")
        self.cphi = mp.cos(case.phi)

    def rhs(self, t, y, phase):
        cs = self.cs
        x_, z_, t1, t2, xd_, zd_, t1d, t2d = y[:8]
        muv = -cs.mu0 * mp.tanh(cs.c * xd_ / self.cphi)
        if cs.active:
            A, B = self.AB(t1, t1d, muv)
            v = poly_eval(cs.ydd_poly, t) if phase == 0 else ZERO
            uv = (v + B) / A
            q = self.acc(t1, t1d, uv, muv)
            lam = self.lam(t1, t1d, uv, muv)[0]
            yu = (t1d - t2d) * uv
            pabs = abs(yu) if phase == 0 else ZERO
        else:
            q = self.acc(t1, t1d, muv)
            lam = self.lam(t1, t1d, muv)[0]
            yu = ZERO
            pabs = ZERO
        fric = muv * lam * xd_ / self.cphi ** 2
        return [xd_, zd_, t1d, t2d, q[0], q[1], q[2], q[3], pabs, yu, fric, xd_]

    def one(self, t, y, H, phase, tol):
        """One extrapolated step; returns (y_new, accepted, k_used)."""
        T = []
        n = len(y)
        f0 = self.rhs(t, y, phase)
        for j in range(1, self.KMAX + 1):
            nj = 2 * j
            h = H / nj
            zm = list(y)
            zc = [a + h * b for a, b in zip(y, f0)]
            for m in range(1, nj):
                fc = self.rhs(t + m * h, zc, phase)
                zm, zc = zc, [a + 2 * h * b for a, b in zip(zm, fc)]
            fc = self.rhs(t + H, zc, phase)
            row = [[(a + b + h * c_) / 2 for a, b, c_ in zip(zm, zc, fc)]]
            for k in range(1, j):
                r = mp.mpf(nj) ** 2 / mp.mpf(2 * (j - k)) ** 2 - 1
                row.append([a + (a - b) / r for a, b in zip(row[k - 1], T[-1][k - 1])])
            T.append(row)
            if j >= 3:
                err = max(abs(a - b) / max(ONE, abs(a)) for a, b in zip(row[-1], row[-2]))
                if err < tol:
                    return row[-1], True, j
        return None, False, self.KMAX

    def advance(self, t, y, t_end, phase, tol, H):
        """Integrate from t to t_end exactly (adaptive); returns (y, H_next)."""
        while t < t_end:
            h = min(H, t_end - t)
            yn, ok, k = self.one(t, y, h, phase, tol)
            if not ok:
                H = h / 2
                continue
            t, y = t + h, yn
            H = h * (mp.mpf(3) / 2 if k < self.KMAX - 4 else 1)
        return y, H

    def integrate(self, p_unused, tol):
        cs = self.cs
        y = [*cs.y0_init(), ZERO, ZERO, ZERO, ZERO]
        cs.y0 = y[:8]
        t = ZERO
        H = mp.mpf("0.001")
        phase = 0 if cs.active else 1
        nsteps = 0
        while True:
            t_lim = cs.T_set if (cs.active and phase == 0) else t + 1
            h = min(H, t_lim - t)
            yn, ok, k = self.one(t, y, h, phase, tol)
            if not ok:
                H = h / 2
                continue
            nsteps += 1
            if yn[2] >= cs.th_event:
                # Illinois on g(tau) = th1(t + tau) - event, tau in (0, h]
                g = lambda tau: self.advance(t, y, t + tau, phase, tol, tau)[0][2] - cs.th_event
                a, b = ZERO, h
                ga, gb = y[2] - cs.th_event, yn[2] - cs.th_event
                side = 0
                for _ in range(200):
                    c_ = (a * gb - b * ga) / (gb - ga)
                    gc = g(c_)
                    if gc == 0 or abs(b - a) < mp.eps * 100:
                        break
                    if gc * gb > 0:
                        b, gb = c_, gc
                        if side == -1:
                            ga /= 2
                        side = -1
                    else:
                        a, ga = c_, gc
                        if side == 1:
                            gb /= 2
                        side = 1
                    if abs(gc) < tol * mp.mpf(10) ** -3:
                        break
                y = self.advance(t, y, t + c_, phase, tol, c_)[0]
                t = t + c_
                break
            t, y = t + h, yn
            H = h * (mp.mpf(3) / 2 if k < self.KMAX - 4 else 1)
            if cs.active and phase == 0 and t == cs.T_set:
                phase = 1
        quad = {"abs_ydot_u": y[8], "ydot_u": y[9], "fric_work": y[10], "int_xd": y[11]}
        yy = y[:8]
        yy[2] = cs.th_event
        return t, yy, quad, mp.nan, nsteps


def flat(res):
    vals = [res["T"], *res["q_minus"], *res["qd_minus"], *res["q_plus"], *res["qd_plus"],
            res["dx"], res["V"]]
    if res["p"] is not None:
        vals += [res["p"], res["SR"]]
    return vals


def s(v, n=OUT_DIGITS):
    if abs(v) < ZERO_BELOW:    # exact zero up to rounding (e.g. th2 at heel strike)
        return "0"
    return mp.nstr(v, n, strip_zeros=False, min_fixed=-4, max_fixed=6)


def flat_names(res):
    n = ["T"] + [f"q_minus[{i}]" for i in range(4)] + [f"qd_minus[{i}]" for i in range(4)]
    n += [f"q_plus[{i}]" for i in range(4)] + [f"qd_plus[{i}]" for i in range(4)] + ["dx", "V"]
    return n + (["p", "SR"] if res["p"] is not None else [])


def rel_diffs(r1, r2):
    """Relative differences (absolute below 1e-3) of all reported quantities."""
    with mp.workdps(60):
        return {k: abs(x - y) / max(abs(y), mp.mpf(10) ** -3)
                for k, x, y in zip(flat_names(r1), flat(r1), flat(r2))}


def run_case(name):
    results = []
    for dps, p, tol in SETTINGS:
        with mp.workdps(dps):
            case = Case(name)
            r = case.step(p, tol)
            results.append((dps, p, tol, r))
            print(f"{name}: Taylor dps={dps} order={p} tol={mp.nstr(tol, 2)}: {r['nsteps']} "
                  f"steps, {r['seconds']:.1f} s, T={mp.nstr(r['T'], 35)}", flush=True)
    dps_g, tol_g = GBS_SETTING
    with mp.workdps(dps_g):
        case = Case(name)
        rg = case.step(None, tol_g, integrator=GBS(case).integrate)
        print(f"{name}: GBS dps={dps_g} tol={mp.nstr(tol_g, 2)}: {rg['nsteps']} steps, "
              f"{rg['seconds']:.1f} s, T={mp.nstr(rg['T'], 30)}", flush=True)
    d_taylor = rel_diffs(results[0][3], results[1][3])
    d_gbs = rel_diffs(rg, results[1][3])
    worst = max(d_taylor.values())
    worst_gbs = max(v for k, v in d_gbs.items() if k not in ("p", "SR"))
    worst_gbs_p = max([v for k, v in d_gbs.items() if k in ("p", "SR")] + [mp.mpf(0)])
    with mp.workdps(60):
        if worst_gbs > mp.mpf(10) ** -20:
            raise AssertionError(f"{name}: Taylor and GBS differ by {worst_gbs}")
    digits = int(mp.floor(-mp.log10(worst))) - 1 if worst > 0 else OUT_DIGITS
    digits = min(digits, 30)
    r = results[1][3]   # the finer run is written (it is at least as accurate)
    cfg = CASES[name]
    with mp.workdps(50):
        params = {"m1": "2", "m2": "1", "l": "1", "I1": "0.5", "I2": "1", "g": "9.81",
                  "alpha": s(mpv(ALPHA), 40), "phi": s(mpv(cfg["phi"]), 40),
                  "mu0": s(mpv(cfg["mu0"])), "c": s(mpv(cfg["c"]))}
        if name == "active":
            params.update({"T_set": s(mpv(cfg["T_set"])), "K_P": "0", "K_D": "0",
                           "omega0": s(mpv(cfg["omega0"]))})
            q0 = ["0", "0", s(-mpv(ALPHA) / 2, 40), "0"]
            qd0 = ["0", "0", s(mpv(cfg["omega0"])), s(mpv(cfg["omega0"]))]
        else:
            q0 = ["0", "0", "0", "0"]
            qd0 = ["0", "0", "0.5", "0"]
        out = {
            "case": name,
            "params": params,
            "q0": q0,
            "qd0": qd0,
            "T": s(r["T"]),
            "q_minus": [s(v) for v in r["q_minus"]],
            "qd_minus": [s(v) for v in r["qd_minus"]],
            "q_plus": [s(v) for v in r["q_plus"]],
            "qd_plus": [s(v) for v in r["qd_plus"]],
            "dx": s(r["dx"]),
            "V": s(r["V"]),
            "p": None if r["p"] is None else s(r["p"]),
            "SR": None if r["SR"] is None else s(r["SR"]),
            "digits_claimed": digits,
            "method": (f"Taylor series method (automatic differentiation of the SymPy kernels), "
                       f"order {results[1][1]}, local tolerance {mp.nstr(results[1][2], 2)}, "
                       f"mp.dps={results[1][0]}; event by Newton on the Taylor polynomial; "
                       f"checked against order {results[0][1]}, tolerance "
                       f"{mp.nstr(results[0][2], 2)}, mp.dps={results[0][0]}: max relative "
                       f"difference {mp.nstr(worst, 3)}; independent check by Gragg-Bulirsch-"
                       f"Stoer extrapolation (tol {mp.nstr(tol_g, 2)}, mp.dps={dps_g}): max "
                       f"relative difference {mp.nstr(worst_gbs, 3)}"
                       + (f" (p and SR: {mp.nstr(worst_gbs_p, 3)}, |ydot u| has kinks)"
                          if name == "active" else "")
                       + "; relative differences are absolute below 1e-3"),
        }
        info = {"lambda_min": s(r["lambda_min"], 12),
                "lambdaI": [s(v, 20) for v in r["lambdaI"]],
                "checks": {k: mp.nstr(v, 3) for k, v in r["checks"].items()},
                "steps": [res[3]["nsteps"] for res in results] + [rg["nsteps"]],
                "seconds": [round(res[3]["seconds"], 1) for res in results]
                + [round(rg["seconds"], 1)],
                "taylor_coarse_vs_fine": {k: mp.nstr(v, 3) for k, v in d_taylor.items()},
                "gbs_vs_taylor_fine": {k: mp.nstr(v, 3) for k, v in d_gbs.items()}}
    return out, info


def write_step(name, outdir):
    """Compute one case, write tests/data/step_<name>.json; return (deterministic report,
    timing line)."""
    out, info = run_case(name)
    with open(os.path.join(outdir, f"step_{name}.json"), "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    secs = info.pop("seconds")
    return info, f"step_{name}: seconds (Taylor coarse, Taylor fine, GBS) = {secs}"


def main(outdir):
    t0 = time.time()
    md.derive()
    print(f"derivation {time.time() - t0:.1f} s", flush=True)
    for name in ("active", "passive"):
        info, timing = write_step(name, outdir)
        print(json.dumps(info, indent=1))
        print(timing, flush=True)
    print(f"steps total {time.time() - t0:.1f} s")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..",
                                                             "tests", "data"))
