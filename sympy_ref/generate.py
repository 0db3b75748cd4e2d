"""Regenerate every reference file in one process tree.

The symbolic derivation (model.derive) runs once in the parent; the independent jobs (one per
kernel table, one per step case, the closed forms and the operation counts) then run in
forked worker processes, one per CPU.  Every output is deterministic (fixed seeds, no timing
in any file); timings go to stdout only.

Usage: python generate.py [--jobs N] [--only NAME ...]
  (writes ../tests/data/*.json, closed_forms.txt, opcount.json, report.json)

--only regenerates just the named outputs: kernel names (tests/data/<kernel>.json), `step:active`
/ `step:passive`, `impact_friction` (tests/data/impact_friction.json), `closed_forms`, `opcount`,
`models` (tests/data/models/<name>.json for every models/*.toml, models.py; `--only models` alone
skips the paper model's derivation); report.json then keeps every other entry as it was.
For the impact with friction:
`bash sympy_ref/run.sh --only impact_coulomb_level impact_coulomb_slope impact_friction`.
"""
from __future__ import annotations

import argparse
import json
import multiprocessing
import os
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DATA = os.path.join(os.path.dirname(HERE), "tests", "data")
sys.path.insert(0, HERE)

import model as md  # noqa: E402


def task(spec):
    kind, arg = spec
    t0 = time.time()
    if kind == "kernel":
        import kernels
        res = kernels.write_kernel(arg, DATA)
        line = f"kernel {arg}"
    elif kind == "step":
        import steps
        res, line = steps.write_step(arg, DATA)
    elif kind == "closed_forms":
        import closed_forms
        with open(os.path.join(HERE, "closed_forms.txt"), "w") as fh:
            fh.write(closed_forms.text())
        res, line = None, "closed_forms.txt"
    elif kind == "impact_friction":
        import impact_friction
        res = impact_friction.main(os.path.join(DATA, "impact_friction.json"))
        line = "impact_friction"
    elif kind == "models":
        import models
        res = models.main()
        line = "models"
    elif kind == "opcount":
        import opcount
        opcount.main(os.path.join(HERE, "opcount.json"))
        res, line = None, "opcount.json"
    else:
        raise KeyError(kind)
    return spec, res, f"{line}: {time.time() - t0:.1f} s"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    ap.add_argument("--only", nargs="+", metavar="NAME",
                    help="regenerate only these outputs (see the module docstring)")
    args = ap.parse_args()
    t0 = time.time()
    if args.only == ["models"]:     # the model files need nothing of the paper's derivation
        import models
        res = models.main()
        with open(os.path.join(HERE, "report.json")) as fh:
            report = json.load(fh)
        report["models"] = res
        with open(os.path.join(HERE, "report.json"), "w") as fh:
            json.dump(report, fh, indent=1)
            fh.write("\n")
        print(f"total: {time.time() - t0:.1f} s")
        return
    mdl = md.derive()
    print(f"derivation: {time.time() - t0:.1f} s", flush=True)
    os.makedirs(DATA, exist_ok=True)
    # longest first, for load balance
    specs = ([("step", "passive"), ("step", "active"), ("impact_friction", None),
              ("opcount", None), ("closed_forms", None), ("models", None)]
             + [("kernel", k) for k in mdl.kernels])
    if args.only:
        def name(spec):
            kind, arg = spec
            return arg if kind == "kernel" else (f"step:{arg}" if kind == "step" else kind)
        unknown = set(args.only) - {name(s) for s in specs}
        if unknown:
            ap.error(f"--only: unknown {sorted(unknown)}; valid: {[name(s) for s in specs]}")
        specs = [s for s in specs if name(s) in args.only]
    results = {}
    ctx = multiprocessing.get_context("fork")
    with ctx.Pool(args.jobs) as pool:
        for spec, res, line in pool.imap_unordered(task, specs, chunksize=1):
            results[spec] = res
            print(line, flush=True)
    old = {}
    if args.only:
        with open(os.path.join(HERE, "report.json")) as fh:
            old = json.load(fh)
    pick = lambda spec, section, key: (results[spec] if spec in results
                                       else old.get(section, {}).get(key))
    report = {
        "kernels": {k: pick(("kernel", k), "kernels", k) for k in mdl.kernels},
        "steps": {c: pick(("step", c), "steps", c) for c in ("active", "passive")},
        "impact_friction": (results[("impact_friction", None)]
                            if ("impact_friction", None) in results
                            else old.get("impact_friction")),
        "models": (results[("models", None)] if ("models", None) in results
                   else old.get("models")),
    }
    with open(os.path.join(HERE, "report.json"), "w") as fh:
        json.dump(report, fh, indent=1)
        fh.write("\n")
    print(f"total: {time.time() - t0:.1f} s")


if __name__ == "__main__":
    main()
