"""Independent references for the integrators' cross-check (walker/tests/it/ode_crosscheck.rs):
two nonlinear problems without closed-form solutions, solved here by solvers no one in this
project wrote.

- Lotka-Volterra, x' = a x - b x y, y' = -c y + d x y with (a, b, c, d) = (1.5, 1, 3, 1) from
  (1, 1), at t = 0.5, 1, ..., 10: mpmath's `odefun` (a Taylor series method whose degree and
  step follow the working precision) at 40 significant digits, so the values are exact far
  below the double precision they are written in. SciPy's DOP853 at rtol = atol = 1e-13 is
  run beside it as a check of this script (their distance is written too).
- Robertson's stiff chemical kinetics (Robertson 1966; Hairer and Wanner, Solving Ordinary
  Differential Equations II, Section IV.1) from (1, 0, 0) at t = 40: SciPy's Radau IIA (order 5)
  at rtol = 1e-12 with atol = 1e-20 per component, the reference; SciPy's BDF at the same
  tolerances beside it, whose relative distance (written too) bounds the reference's error.

Writes tests/data/ode_crosscheck.json (deterministic: no timing in it). Run with the
environment of run.sh: sympy_ref/.venv/bin/python sympy_ref/ode_crosscheck.py (about ten
seconds).
"""

import json
import os

import mpmath
import numpy as np
from scipy.integrate import solve_ivp

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(os.path.dirname(HERE), "tests", "data", "ode_crosscheck.json")

LV = (1.5, 1.0, 3.0, 1.0)
LV_Y0 = (1.0, 1.0)
LV_T = [0.5 * k for k in range(1, 21)]


def lotka_volterra():
    a, b, c, d = LV
    mpmath.mp.dps = 40
    f = mpmath.odefun(
        lambda t, y: [a * y[0] - b * y[0] * y[1], -c * y[1] + d * y[0] * y[1]],
        0,
        [mpmath.mpf(LV_Y0[0]), mpmath.mpf(LV_Y0[1])],
    )
    exact = [[float(v) for v in f(mpmath.mpf(t))] for t in LV_T]
    sol = solve_ivp(
        lambda t, y: [a * y[0] - b * y[0] * y[1], -c * y[1] + d * y[0] * y[1]],
        (0.0, LV_T[-1]), LV_Y0, method="DOP853", t_eval=LV_T, rtol=1e-13, atol=1e-13)
    dop = np.asarray(sol.y).T
    check = float(np.max(np.abs(dop - np.asarray(exact)) / np.abs(np.asarray(exact))))
    assert check < 1e-9, check
    return {
        "params_abcd": list(LV),
        "y0": list(LV_Y0),
        "t": LV_T,
        "y": exact,
        "method": "mpmath.odefun (Taylor series), 40 significant digits",
        "scipy_dop853_rtol1e-13_max_rel_distance": float(f"{check:.3g}"),
    }


def robertson_rhs(t, y):
    d0 = -0.04 * y[0] + 1e4 * y[1] * y[2]
    d2 = 3e7 * y[1] * y[1]
    return [d0, -d0 - d2, d2]


def robertson_jac(t, y):
    return [[-0.04, 1e4 * y[2], 1e4 * y[1]],
            [0.04, -1e4 * y[2] - 6e7 * y[1], -1e4 * y[1]],
            [0.0, 6e7 * y[1], 0.0]]


def robertson():
    t_end = 40.0
    runs = {}
    for method in ("Radau", "BDF"):
        sol = solve_ivp(robertson_rhs, (0.0, t_end), [1.0, 0.0, 0.0], method=method,
                        jac=robertson_jac, rtol=1e-12, atol=1e-20, t_eval=[t_end])
        assert sol.success, sol.message
        runs[method] = sol.y[:, -1]
    rel = float(np.max(np.abs(runs["Radau"] - runs["BDF"]) / np.abs(runs["Radau"])))
    assert rel < 1e-8, rel
    return {
        "y0": [1.0, 0.0, 0.0],
        "t_end": t_end,
        "y": [float(v) for v in runs["Radau"]],
        "method": "scipy.integrate.solve_ivp Radau, rtol 1e-12, atol 1e-20, exact Jacobian",
        "scipy_bdf_max_rel_distance": float(f"{rel:.3g}"),
    }


def main():
    out = {
        "source": "sympy_ref/ode_crosscheck.py",
        "lotka_volterra": lotka_volterra(),
        "robertson": robertson(),
    }
    with open(OUT, "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    print(f"wrote {OUT}: Lotka-Volterra DOP853 distance "
          f"{out['lotka_volterra']['scipy_dop853_rtol1e-13_max_rel_distance']}, "
          f"Robertson Radau/BDF distance {out['robertson']['scipy_bdf_max_rel_distance']}")


if __name__ == "__main__":
    main()
