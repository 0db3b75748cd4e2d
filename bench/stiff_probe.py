"""Would an implicit method beat DOP853 where the foot creeps? (BENCHMARKS.md section 2)

One stance phase of the active walker (Table 1, c = 100, T_set = 0.3) on its steady gait at
mu0 (default 1.0, where the foot creeps through nearly the whole stance), integrated by SciPy's
DOP853, Radau (Radau IIA of order 5, the L-stable method), BDF and LSODA at a few tolerances.
Step counts and evaluations are the methods' own, so they say what an implicit method would
save in steps, independently of SciPy's per-step overhead. The heel-strike time is compared
with DOP853 at 1e-13. The last block shows the step sizes before and after T_set.

Run: bench/.venv/bin/python bench/stiff_probe.py [mu0]   (bench/run_peer.sh creates the venv)
"""
from __future__ import annotations

import sys

import numpy as np
from scipy.integrate import solve_ivp

import scipy_peer as sp

HEEL = lambda t, y: y[2] - sp.ALPHA / 2  # noqa: E731 (solve_ivp reads attributes off it)
HEEL.terminal = True
HEEL.direction = 1


def stance(w, s, method, tol):
    """Integrate one stance from s; returns (t, h, xd) along the steps, counters, heel time."""
    r1 = solve_ivp(w.rhs, (0.0, w.t_set), s, method=method, rtol=tol, atol=tol, events=HEEL)
    r2 = solve_ivp(w.rhs, (w.t_set, 10.0), r1.y[:, -1], method=method, rtol=tol, atol=tol,
                   events=HEEL)
    t = np.concatenate([r1.t, r2.t[1:]])
    xd = np.concatenate([r1.y[4], r2.y[4, 1:]])
    counts = (len(t) - 2, r1.nfev + r2.nfev, r1.njev + r2.njev, r1.nlu + r2.nlu)
    return t, xd, counts, r2.t_events[0][0]


def main():
    mu0 = float(sys.argv[1]) if len(sys.argv) > 1 else 1.0
    w = sp.Walker(mu0, 100.0, 0.3)
    s = np.array([0.0, 0.0, -sp.ALPHA / 2, 0.0, 0.0, 0.0, 0.8, 0.8])
    for _ in range(30):  # onto the steady gait
        _, s = w.step(s, 1e-10, 1e-10)
    *_, t_ref = stance(w, s, "DOP853", 1e-13)
    print(f"mu0 = {mu0}: one stance, T = {t_ref:.12f} s (DOP853 at 1e-13)")
    print("method  tol    steps  nfev  njev  nlu  |T - T_ref|")
    for method in ["DOP853", "Radau", "BDF", "LSODA"]:
        for tol in [1e-7, 1e-9, 1e-10]:
            _, _, (steps, nfev, njev, nlu), te = stance(w, s, method, tol)
            print(f"{method:7} {tol:.0e} {steps:6d} {nfev:5d} {njev:5d} {nlu:4d}  {abs(te - t_ref):.1e}")
    print("step sizes h (ms) and c xd at every 12th step, tol 1e-9:")
    for method in ["DOP853", "Radau"]:
        t, xd, *_ = stance(w, s, method, 1e-9)
        h = np.diff(t)
        row = " ".join(f"{t[i]:.3f}:{1e3 * h[i]:.2f}:{100 * xd[i]:+.2f}" for i in range(0, len(h), 12))
        print(f"{method}: {row}")


if __name__ == "__main__":
    main()
