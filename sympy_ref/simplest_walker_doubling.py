"""Independent reference for the simplest walking model's first period doubling in its slope.

Garcia, Chatterjee, Ruina and Coleman (1998) report the period-one gait stable for
0 < gamma < 0.015 rad, then period doubling on the way to chaos. This script locates the
doubling with sympy_ref/simplest_walker.py's own derivation (its Lagrangian, impact and
variational equations, nothing read from the Rust code): the fixed point is followed in the
slope phi from the file's 0.009 by Newton's method, and the slope where the real multiplier
crosses -1 is found by Brent's method on (smallest real multiplier + 1), each evaluation a
converged fixed point (residual below 1e-13) and its multipliers.

Writes sympy_ref/simplest_walker_doubling.json (about five minutes on a busy two-core
machine). Run: sympy_ref/.venv/bin/python sympy_ref/simplest_walker_doubling.py
"""

import json
import os

import numpy as np
from scipy.optimize import brentq

import simplest_walker as sw

# The bracket: Garcia et al.'s 0.015, +-0.0005 (their last digit).
BRACKET = (0.0145, 0.0155)
XTOL = 1e-12


def fixed_point(d, phi, r):
    """The fixed point at slope phi by Newton's method from r, and its multipliers."""
    sw.PARAMS["phi"] = phi
    fn = sw.numeric(d)
    for _ in range(30):
        p, _, j, _ = sw.reduced(fn, r)
        res = p - r
        if np.linalg.norm(res) < 1e-13:
            break
        r = r + np.linalg.solve(np.eye(3) - j, res)
    else:
        raise RuntimeError(f"no fixed point at phi = {phi}")
    p, period, j, _ = sw.reduced(fn, r)
    return r, period, np.linalg.eigvals(j)


def main():
    d = sw.derive()
    theta, thetad = 0.2003109, -0.1998325
    phi0 = 0.009
    r = np.array([phi0 - theta, -thetad, -thetad * np.cos(2 * theta)])
    # March to the bracket (the fixed point moves with the slope; Newton needs a near guess).
    for phi in (0.009, 0.011, 0.013, BRACKET[0]):
        r, _, _ = fixed_point(d, phi, r)
    guess = {"r": r}
    evaluations = []

    def smallest_real_plus_one(phi):
        r, period, eig = fixed_point(d, phi, guess["r"])
        guess["r"] = r
        real = [float(e.real) for e in eig if abs(e.imag) < 1e-12]
        evaluations.append({"phi": phi, "multipliers": [[float(e.real), float(e.imag)] for e in eig]})
        return min(real) + 1.0

    pd = brentq(smallest_real_plus_one, *BRACKET, xtol=XTOL)
    r, period, eig = fixed_point(d, pd, guess["r"])
    out = {
        "model": "models/simplest-walker.toml",
        "params": {k: v for k, v in sw.PARAMS.items() if k != "phi"},
        "integration": {"method": "DOP853", "rtol": sw.RTOL, "atol": sw.ATOL},
        "bracket": list(BRACKET),
        "xtol": XTOL,
        "period_doubling_phi": pd,
        "fixed_point_at_doubling": list(map(float, r)),
        "period_at_doubling": float(period),
        "multipliers_at_doubling": [[float(e.real), float(e.imag)] for e in eig],
        "evaluations": evaluations,
    }
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "simplest_walker_doubling.json"), "w") as fh:
        json.dump(out, fh, indent=2)
        fh.write("\n")
    print(json.dumps({k: out[k] for k in ("period_doubling_phi", "multipliers_at_doubling")}))


if __name__ == "__main__":
    main()
