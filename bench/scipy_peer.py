"""SciPy peer of one walker simulation (bench/run_peer.sh runs it).

The active walker of the paper (Table 1, mu0 = 0.4, c = 100, T_set = 0.3, omega0 = 0.8,
K_P = K_D = 0) walked for 100 s, written the generic way: every right-hand-side call assembles
M, h, J, J_mu and solves the stance KKT system [[M, -Jhat^T], [J, 0]] with numpy.linalg.solve
(for the right-hand sides [S; 0] and [h; 0]: A, B of Eqs. 30-31, u = (v + B)/A, qdd), the heel
strike th1 = alpha/2 is a terminal event of solve_ivp(method="DOP853"), T_set is a breakpoint
(the integration is restarted there), the impact (fore foot + torso lock, Eqs. 12-16) is one
linear solve of the impact KKT system, and the reset is the fore-foot change of coordinates.

The same walk is run with the walker CLI (`walker simulate ... --json`, DOP853) in the same
run: at SciPy's tolerance, and at the loosest tolerance (decades, rtol = 100 atol) whose error
is at most SciPy's, for the ratio at equal error. Errors are against a SciPy run at a tight
tolerance (--ref-rtol); wall times are medians of --reps runs.
"""
from __future__ import annotations

import argparse
import json
import math
import statistics
import subprocess
import sys
import time

import numpy as np
import scipy
from scipy.integrate import solve_ivp

M1, M2, L, I1, I2, G = 2.0, 1.0, 1.0, 0.5, 1.0, 9.81
ALPHA = math.pi / 6
MT = M1 + M2
S = np.array([0.0, 0.0, 1.0, -1.0])


def desired(t, t_set):
    if t >= t_set:
        return ALPHA / 2, 0.0, 0.0
    s = max(t, 0.0) / t_set
    s2 = s * s
    s3 = s2 * s
    y = ALPHA * s3 * (10 + s * (-15 + 6 * s)) - ALPHA / 2
    yd = ALPHA * 30 * s2 * (1 - 2 * s + s2) / t_set
    ydd = ALPHA * 60 * s * (1 - 3 * s + 2 * s2) / (t_set * t_set)
    return y, yd, ydd


def mass(th1):
    s, c = math.sin(th1), math.cos(th1)
    return np.array([[MT, 0, MT * L * c, 0],
                     [0, MT, -MT * L * s, 0],
                     [MT * L * c, -MT * L * s, MT * L * L + I1, 0],
                     [0, 0, 0, I2]])


def bias(th1, w):
    s, c = math.sin(th1), math.cos(th1)
    return np.array([-MT * L * w * w * s, MT * (G - L * w * w * c), -MT * G * L * s, 0.0])


class Walker:
    def __init__(self, mu0, c, t_set):
        self.mu0, self.c, self.t_set = mu0, c, t_set
        self.nrhs = 0

    def rhs(self, t, y):
        self.nrhs += 1
        th1, xd, th1d = y[2], y[4], y[6]
        mu = -self.mu0 * math.tanh(self.c * xd)
        k = np.zeros((5, 5))
        k[:4, :4] = mass(th1)
        k[:4, 4] = -np.array([mu, 1.0, 0.0, 0.0])   # -(J + J_mu)^T
        k[4, :4] = [0.0, 1.0, 0.0, 0.0]              # J
        b = np.zeros((5, 2))
        b[:4, 0] = S
        b[:4, 1] = bias(th1, th1d)
        x = np.linalg.solve(k, b)
        a = S @ x[:4, 0]
        bb = S @ x[:4, 1]
        yd = desired(t, self.t_set)
        v = yd[2]                                     # K_P = K_D = 0 (Eq. 32)
        u = (v + bb) / a                              # Eq. 31
        qdd = x[:4, 0] * u - x[:4, 1]
        return np.concatenate([y[4:8], qdd])

    def impact(self, yv):
        th1 = yv[2]
        qd = yv[4:8]
        m = mass(th1)
        jf = np.array([0.0, 1.0, L * (math.sin(-th1) - math.sin(-th1 + ALPHA)), 0.0])
        jl = np.array([0.0, 0.0, 1.0, -1.0])
        k = np.zeros((6, 6))
        k[:4, :4] = m
        k[:4, 4] = -jf
        k[:4, 5] = -jl
        k[4, :4] = jf
        k[5, :4] = jl
        b = np.zeros(6)
        b[:4] = m @ qd
        return np.linalg.solve(k, b)[:4]

    def step(self, s0, rtol, atol):
        heel = lambda t, y: y[2] - ALPHA / 2
        heel.terminal = True
        heel.direction = 1
        r1 = solve_ivp(self.rhs, (0.0, self.t_set), s0, method="DOP853", rtol=rtol, atol=atol,
                       events=heel)
        if r1.status == 1:
            raise RuntimeError("impact before T_set")
        r2 = solve_ivp(self.rhs, (self.t_set, 10.0), r1.y[:, -1], method="DOP853", rtol=rtol,
                       atol=atol, events=heel)
        if r2.status != 1:
            raise RuntimeError("no heel strike")
        te = r2.t_events[0][0]
        ye = r2.y_events[0][0]
        x, z, th1, th2 = ye[:4]
        xd, zd, th1d, th2d = self.impact(ye)
        sa, ca = math.sin(th1 - ALPHA), math.cos(th1 - ALPHA)
        s1, c1 = math.sin(th1), math.cos(th1)
        xf = x + L * s1 - L * sa
        xdf = xd + L * c1 * th1d - L * ca * th1d
        zdf = zd - L * s1 * th1d + L * sa * th1d
        return te, np.array([xf, 0.0, th1 - ALPHA, th2, xdf, zdf, th1d, th2d])

    def walk(self, omega0, duration, rtol, atol):
        s = np.array([0.0, 0.0, -ALPHA / 2, 0.0, 0.0, 0.0, omega0, omega0])
        t = 0.0
        periods = []
        while t < duration:
            te, s = self.step(s, rtol, atol)
            t += te
            periods.append(te)
        return periods, s


def run_scipy(rtol, atol, reps, args):
    times = []
    out = None
    for _ in range(reps):
        w = Walker(args.mu0, args.c, args.t_set)
        t0 = time.perf_counter()
        periods, s = w.walk(args.omega0, args.duration, rtol, atol)
        times.append(time.perf_counter() - t0)
        out = (periods, s, w.nrhs)
    return times, out


def run_walker(binary, reps, args, rtol, atol):
    cmd = [binary, "simulate", "--scene", "active-level", "--mu0", str(args.mu0), "--c",
           str(args.c), "--t-set", str(args.t_set), "--omega0", str(args.omega0), "--duration",
           str(args.duration), "--max-steps", "100000", "--rtol", repr(rtol), "--atol",
           repr(atol), "--json"]
    times = []
    doc = None
    for _ in range(reps):
        t0 = time.perf_counter()
        res = subprocess.run(cmd, check=True, capture_output=True, text=True)
        times.append(time.perf_counter() - t0)
        doc = json.loads(res.stdout)
    steps = doc["steps"]
    last = steps[-1]
    s = np.array(last["q_plus"] + last["qd_plus"])
    return times, ([st["T"] for st in steps], s)


def rel_norm(a, b):
    return float(np.max(np.abs(a - b)) / np.max(np.abs(b)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--walker", required=True)
    ap.add_argument("--mu0", type=float, default=0.4)
    ap.add_argument("--c", type=float, default=100.0)
    ap.add_argument("--t-set", type=float, default=0.3)
    ap.add_argument("--omega0", type=float, default=0.8)
    ap.add_argument("--duration", type=float, default=100.0)
    ap.add_argument("--rtol", type=float, default=1e-10)
    ap.add_argument("--atol", type=float, default=1e-12)
    ap.add_argument("--ref-rtol", type=float, default=1e-12)
    ap.add_argument("--ref-atol", type=float, default=1e-14)
    ap.add_argument("--reps", type=int, default=3)
    ap.add_argument("--walker-reps", type=int, default=11)
    args = ap.parse_args()
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}, scipy {scipy.__version__}")

    t_ref, (p_ref, s_ref, n_ref) = run_scipy(args.ref_rtol, args.ref_atol, 1, args)
    print(f"scipy reference rtol={args.ref_rtol:g} atol={args.ref_atol:g}: {len(p_ref)} steps, "
          f"{n_ref} rhs, {t_ref[0]:.2f} s")
    t_sp, (p_sp, s_sp, n_sp) = run_scipy(args.rtol, args.atol, args.reps, args)
    e_sp = rel_norm(s_sp, s_ref)
    t_w, (p_w, s_w) = run_walker(args.walker, args.walker_reps, args, args.rtol, args.atol)
    # Equal error: the loosest walker tolerance (rtol = 100 atol, decades) whose final-state
    # error is at most SciPy's.
    equal = None
    for k in range(4, 11):
        rtol = 10.0 ** -k
        t, (p, s) = run_walker(args.walker, args.walker_reps, args, rtol, rtol / 100.0)
        if len(p) == len(p_ref) and rel_norm(s, s_ref) <= e_sp:
            equal = (rtol, t, p, s)
            break
    ms, mw = statistics.median(t_sp), statistics.median(t_w)
    rows = [
        (f"scipy DOP853 + numpy.linalg.solve, rtol {args.rtol:g}", t_sp, len(p_sp), e_sp,
         abs(sum(p_sp) - sum(p_ref)) / sum(p_ref), n_sp),
        (f"walker CLI (DOP853, generated kernels; incl. process start), rtol {args.rtol:g}", t_w,
         len(p_w), rel_norm(s_w, s_ref), abs(sum(p_w) - sum(p_ref)) / sum(p_ref), None),
    ]
    if equal is not None:
        rtol, t, p, s = equal
        rows.append((f"walker CLI at equal error, rtol {rtol:g}", t, len(p), rel_norm(s, s_ref),
                     abs(sum(p) - sum(p_ref)) / sum(p_ref), None))
    print(f"scipy at rtol={args.rtol:g} atol={args.atol:g}; walk of {args.duration:g} s")
    print("| run | wall median (s) | min | max | steps | final state rel. err | total time rel. err | rhs evals |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for name, t, n, es, et, nr in rows:
        print(f"| {name} | {statistics.median(t):.4f} | {min(t):.4f} | {max(t):.4f} | {n} | "
              f"{es:.2e} | {et:.2e} | {nr if nr is not None else '-'} |")
    print(f"wall-time ratio scipy / walker at the same tolerance: {ms / mw:.0f}x")
    if equal is not None:
        print(f"wall-time ratio scipy / walker at equal (or smaller) error: "
              f"{ms / statistics.median(equal[1]):.0f}x")


if __name__ == "__main__":
    main()
