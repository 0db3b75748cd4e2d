"""SymPy's derivation time and kernel size for every shipped model (sympy_ref/model_timings.csv).

For BENCHMARKS.md: the pipeline's derivation time and operation counts of each model are set next
to SymPy's for the same model.  For each models/*.toml this measures, in one fresh process per
model (so no SymPy cache is shared between models):

* `derive_s`: wall time of models.derive (parse excluded): energies -> M, h by Euler-Lagrange, S,
  J, J_mu, the stick and impact rows, the outputs' Jacobian, and, where `closed` is `yes`, the
  closed forms of lambda, qdd, Y, A, B, u, the closed-loop qdd and lambda, and both impact maps
  (models.closed_forms: adj(M)/det(M) reduced modulo sin^2 + cos^2 = 1, no cancellation);
* `cse_s`: wall time of `sympy.cse` over those kernels (models.kernel_exprs);
* `ops`: `sympy.count_ops` of the straight-line program after cse (its replacements plus the
  reduced expressions);
* `outputs`: the number of kernel expressions.

Where `closed` is `no` (five-link, n = 7) the closed forms are not derived: the symbolic adjugate
of a 7x7 M is not bounded in time; M, h and the structured ingredients (J, J_mu, S, J_s, J_I,
H, Hdot qd) are derived and counted instead, and models.py evaluates the structured quantities
numerically (mpmath linear algebra).  Timings depend on the machine and its load: the CSV records
the load average at the start of each measurement.

Usage: python model_timings.py [OUT.csv]   (default sympy_ref/model_timings.csv)
"""
from __future__ import annotations

import csv
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

FIELDS = ["model", "n", "inputs", "closed", "derive_s", "cse_s", "ops", "outputs", "loadavg_1min"]


def measure(path):
    import sympy as sp
    import models as ms
    m = ms.load(path)
    closed = len(m.q) <= ms.CLOSED_MAX_N
    load = os.getloadavg()[0]
    t0 = time.perf_counter()
    d = ms.derive(m, closed=closed)
    t1 = time.perf_counter()
    ex = ms.kernel_exprs(d)
    repl, red = sp.cse(ex)
    t2 = time.perf_counter()
    ops = sum(sp.count_ops(e) for _, e in repl) + sum(sp.count_ops(e) for e in red)
    return {"model": m.name, "n": len(m.q), "inputs": len(m.inputs),
            "closed": "yes" if closed else "no", "derive_s": f"{t1 - t0:.3f}",
            "cse_s": f"{t2 - t1:.3f}", "ops": ops, "outputs": len(ex),
            "loadavg_1min": f"{load:.2f}"}


def main(out):
    import models as ms
    rows = []
    for path in ms.model_files():
        r = subprocess.run([sys.executable, __file__, "--one", path], capture_output=True,
                           text=True, check=True)
        row = dict(zip(FIELDS, r.stdout.strip().splitlines()[-1].split(",")))
        print(row, flush=True)
        rows.append(row)
    with open(out, "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=FIELDS, lineterminator="\n")
        w.writeheader()
        w.writerows(rows)


if __name__ == "__main__":
    if len(sys.argv) > 2 and sys.argv[1] == "--one":
        row = measure(sys.argv[2])
        print(",".join(str(row[k]) for k in FIELDS))
    else:
        main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "model_timings.csv"))
