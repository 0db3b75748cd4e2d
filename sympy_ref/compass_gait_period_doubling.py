"""An independent reference for the compass gait's period doublings in the slope.

Goswami, Thuilot and Espiau, "A study of the passive gait of a compass-like biped robot:
symmetry and chaos", IJRR 17(12) 1998: m = 5, m_H = 10, a = b = 0.5, l = 1, g = 9.81 (the
parameters of models/compass-gait.toml). Their equations of motion and impact law are written
out here by hand (angles from the vertical in their convention, the negatives of the model
file's), integrated with SciPy's DOP853 at rtol = atol = 1e-12, the heel strike located on the
dense output, and the Poincare map's Jacobian taken by central differences of step 1e-6 on the
three free post-impact coordinates (theta_s, theta_s dot, theta_ns dot; theta_ns = -2 phi -
theta_s on the section). The period doubling is where a multiplier crosses -1, bracketed by
bisection in the slope.

Run: python3 sympy_ref/compass_gait_period_doubling.py
"""

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

m, mh, a, b, g = 5.0, 10.0, 0.5, 0.5, 9.81
l = a + b


def rhs(_t, y):
    tns, ts, dns, ds = y
    s, c = np.sin(ts - tns), np.cos(ts - tns)
    M = np.array([[m * b * b, -m * l * b * c], [-m * l * b * c, mh * l * l + m * (l * l + a * a)]])
    N = np.array([[0.0, m * l * b * s * ds], [-m * l * b * s * dns, 0.0]])
    G = np.array([m * b * g * np.sin(tns), -(mh * l + m * a + m * l) * g * np.sin(ts)])
    dd = np.linalg.solve(M, -N @ np.array([dns, ds]) - G)
    return [dns, ds, dd[0], dd[1]]


def impact(y):
    tns, ts, dns, ds = y
    c2 = np.cos(tns - ts)  # cos(2 alpha), 2 alpha the angle between the legs
    qm = np.array([[-m * a * b, -m * a * b + (mh * l * l + 2 * m * a * l) * c2], [0.0, -m * a * b]])
    qp = np.array(
        [
            [m * b * (b - l * c2), m * l * (l - b * c2) + m * a * a + mh * l * l],
            [m * b * b, -m * b * l * c2],
        ]
    )
    dp = np.linalg.solve(qp, qm @ np.array([dns, ds]))
    return np.array([ts, tns, dp[0], dp[1]])


def step(x, phi):
    """One step from the section coordinates x = (theta_s, theta_s dot, theta_ns dot)."""
    ts, ds, dns = x
    y0 = [-2 * phi - ts, ts, dns, ds]
    sol = solve_ivp(rhs, (0, 3.0), y0, method="DOP853", rtol=1e-12, atol=1e-12, dense_output=True)
    t = sol.t
    guard = sol.y[0] + sol.y[1] + 2 * phi
    apart = sol.y[0] - sol.y[1]
    for i in range(1, len(t)):
        if guard[i - 1] * guard[i] <= 0 and apart[i] > 0.05 and t[i] > 0.05:
            ti = brentq(lambda s: sol.sol(s)[0] + sol.sol(s)[1] + 2 * phi, t[i - 1], t[i], xtol=1e-15)
            yp = impact(sol.sol(ti))
            return np.array([yp[1], yp[3], yp[2]]), ti
    raise RuntimeError("no heel strike")


def fixed_point(phi, x):
    for _ in range(30):
        fx, _ = step(x, phi)
        J = jacobian(x, phi)
        dx = np.linalg.solve(J - np.eye(3), -(fx - x))
        x = x + dx
        if np.max(np.abs(dx)) < 1e-12:
            break
    return x


def jacobian(x, phi, h=1e-6):
    J = np.zeros((3, 3))
    for j in range(3):
        e = np.zeros(3)
        e[j] = h
        J[:, j] = (step(x + e, phi)[0] - step(x - e, phi)[0]) / (2 * h)
    return J


def min_real_multiplier(phi, x):
    x = fixed_point(phi, x)
    ev = np.linalg.eigvals(jacobian(x, phi))
    return min(e.real for e in ev if abs(e.imag) < 1e-9) if any(abs(e.imag) < 1e-9 for e in ev) else 0.0, x, ev


if __name__ == "__main__":
    x = np.array([0.218669, -1.092384, -0.377374])
    phi = np.radians(3.0)
    x = fixed_point(phi, x)
    print("phi = 3 deg: theta_s, theta_s dot, theta_ns dot =", x, "(model file: -th_st, -th_std, -th_swd)")
    # Walk up the slope to bracket the first crossing of -1.
    prev = None
    for deg in np.arange(3.0, 5.6, 0.1):
        lam, x, ev = min_real_multiplier(np.radians(deg), x)
        print(f"{deg:.2f} deg: multipliers {np.round(ev, 6)}")
        if lam < -1 and prev is not None:
            lo, hi, xs = prev[0], deg, prev[1]
            for _ in range(30):
                mid = 0.5 * (lo + hi)
                lm, xm, _ = min_real_multiplier(np.radians(mid), xs)
                if lm < -1:
                    hi = mid
                else:
                    lo, xs = mid, xm
            print(f"first period doubling: phi = {0.5 * (lo + hi):.8f} deg = {np.radians(0.5 * (lo + hi)):.10f} rad")
            break
        prev = (deg, x)
