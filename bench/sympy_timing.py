"""Time SymPy deriving the walker's kernels (run with sympy_ref's venv; bench/run_sympy_timing.sh).

Two SymPy derivations, each stage's wall time printed (flushed) as soon as it finishes, so that a
run stopped by `timeout` still reports how far it got:

1. `sympy_ref.model.derive()`: the independent reference derivation of every kernel, which does
   its algebra on polynomial stand-ins for sin/cos reduced modulo sin^2 + cos^2 = 1 (already a
   specialised, fast route);
2. the plain route: from M, h, J, J_mu and J_I (taken from step 1's model), solve the stance KKT
   system and the impact system symbolically (Matrix.LUsolve) and `sympy.simplify` the
   results: qdd and lambda of the level walker with friction, then the impact2_level map.
"""
import sys
import time

sys.path.insert(0, sys.argv[1] if len(sys.argv) > 1 else "sympy_ref")
t0 = time.perf_counter()
import sympy as sp  # noqa: E402
import model as md  # noqa: E402

print(f"sympy {sp.__version__}; import {time.perf_counter() - t0:.2f} s", flush=True)
t0 = time.perf_counter()
mdl = md.derive()
print(f"[1] sympy_ref derive() (all {len(mdl.kernels)} kernels, stand-in polynomials): "
      f"{time.perf_counter() - t0:.2f} s", flush=True)

M, h, S = mdl.M, mdl.h, mdl.S
J, Jmu = mdl.J_level, mdl.Jmu_level
t0 = time.perf_counter()
Jh = J + Jmu
K = sp.zeros(5, 5)
K[:4, :4] = M
K[:4, 4] = -Jh.T
K[4, :4] = J
rhs = sp.zeros(5, 1)
rhs[:4, 0] = S * md.u - h
sol = K.LUsolve(rhs)
print(f"[2a] KKT LUsolve (unsimplified): {time.perf_counter() - t0:.2f} s", flush=True)
t1 = time.perf_counter()
lam = sp.simplify(sol[4])
print(f"[2b] simplify(lambda): {time.perf_counter() - t1:.2f} s; ops {sp.count_ops(lam)}",
      flush=True)
for i in range(4):
    t1 = time.perf_counter()
    e = sp.simplify(sol[i])
    print(f"[2c] simplify(qdd{i}): {time.perf_counter() - t1:.2f} s; ops {sp.count_ops(e)}",
          flush=True)
t1 = time.perf_counter()
JI = mdl.JI["impact2_level"]
n = 4 + JI.rows
KI = sp.zeros(n, n)
KI[:4, :4] = M
KI[:4, 4:] = -JI.T
KI[4:, :4] = JI
bI = sp.zeros(n, 1)
bI[:4, 0] = M * sp.Matrix(md.QD)
solI = KI.LUsolve(bI)
for i in range(n):
    e = sp.simplify(solI[i])
    print(f"[2d] simplify(impact2_level out {i}): cumulative {time.perf_counter() - t1:.2f} s; "
          f"ops {sp.count_ops(e)}", flush=True)
print(f"[2] plain route total: {time.perf_counter() - t0:.2f} s", flush=True)
