"""Operation counts of common-subexpression-eliminated kernels (sympy_ref/opcount.json).

Kernels: accel_level with mu = -mu0 tanh(c xd) substituted (inputs th1, th1d, xd, u),
lambda_level (mu an input), impact2_level, impact3_level.

Two variants of the output expressions are counted:
  * "reduced":    the canonical form of model.py (rational functions of sin/cos of th1, alpha,
                  reduced modulo sin^2 + cos^2 = 1); these are the expressions kernels.py
                  evaluates;
  * "simplified": sympy.simplify applied to each output first (for accel_level before the
                  friction law is substituted).
Each variant goes through sympy.cse (default settings) and the operations of the resulting
straight-line program are counted by the walker below (a binary operation counts once:
an n-ary sum is n-1 additions, a product a*b/(c*d) is 2 multiplications and 1 division, a
leading factor -1 is a negation, x**2 and x**3 are integer powers (their exponent is listed),
x**(1/2) is a sqrt, sin/cos/tanh are transcendental calls).  sympy.count_ops(visual=True) of
the same program is given as well for reference.

Usage: python opcount.py [OUT.json]
"""
from __future__ import annotations

import json
import os
import sys
from collections import Counter

import sympy as sp

import model as md
from model import mu, xd

mu0, c = sp.symbols("mu0 c", positive=True)


def walk(e, cnt):
    """Count the operations of one expression tree (no sharing inside: cse did that)."""
    if e.is_Atom:
        return
    if e.is_Add:
        # a - b is one subtraction (counted with the additions), not an addition and a negation
        cnt["add"] += len(e.args) - 1
        neg = [a for a in e.args if a.could_extract_minus_sign()]
        if len(neg) == len(e.args):
            cnt["neg"] += 1
        for a in e.args:
            walk(-a if a in neg else a, cnt)
        return
    if e.is_Mul:
        num, den = [], []
        for a in e.args:
            if a.is_Pow and a.exp.is_Number and a.exp < 0:
                den.append(sp.Pow(a.base, -a.exp))
            elif a.is_Rational and not a.is_Integer:   # p/q: a multiplication by p and division by q
                if a.p != 1 and a.p != -1:
                    num.append(sp.Integer(abs(a.p)))
                if a.p < 0:
                    cnt["neg"] += 1
                den.append(sp.Integer(a.q))
            elif a == -1:
                cnt["neg"] += 1
            else:
                num.append(a)
        if len(num) > 1:
            cnt["mul"] += len(num) - 1
        if len(den) > 1:
            cnt["mul"] += len(den) - 1
        if den:
            cnt["div"] += 1
        for a in num + den:
            walk(a, cnt)
        return
    if e.is_Pow:
        ex = e.exp
        if ex == sp.Rational(1, 2):
            cnt["sqrt"] += 1
        elif ex == -1:
            cnt["div"] += 1
        elif ex.is_Integer and ex < 0:
            cnt["div"] += 1
            cnt[f"pow_int{-int(ex)}"] += 1
        elif ex.is_Integer:
            cnt[f"pow_int{int(ex)}"] += 1
        else:
            cnt["pow"] += 1
        walk(e.base, cnt)
        if not ex.is_Number:
            walk(ex, cnt)
        return
    if isinstance(e, sp.Function):
        cnt[type(e).__name__] += 1
        for a in e.args:
            walk(a, cnt)
        return
    raise TypeError(type(e))


def count(exprs):
    repl, red = sp.cse(exprs)
    cnt = Counter()
    for _, e in repl:
        walk(e, cnt)
    for e in red:
        walk(e, cnt)
    visual = sum((sp.count_ops(e, visual=True) for _, e in repl), sp.Integer(0)) + \
        sum((sp.count_ops(e, visual=True) for e in red), sp.Integer(0))
    ops = dict(sorted(cnt.items()))
    arith = sum(v for k, v in cnt.items() if k in ("add", "mul", "div", "neg"))
    powers = sum(v for k, v in cnt.items() if k.startswith("pow") or k == "sqrt")
    transc = sum(v for k, v in cnt.items()
                 if k not in ("add", "mul", "div", "neg", "sqrt") and not k.startswith("pow"))
    return {"cse_assignments": len(repl), "outputs": len(red), "ops": ops,
            "arithmetic": arith, "powers": powers, "transcendental": transc,
            "total": arith + powers + transc, "sympy_count_ops": str(visual)}


def kernel_exprs(mdl, name, simplify=False):
    """Output expressions of a kernel (optionally sympy.simplify'd; for accel_level the
    simplification is done before mu = -mu0 tanh(c xd) is substituted, which is equivalent
    and much faster)."""
    k = mdl.kernels[name]
    exprs = [e for _, e in k["outputs"]]
    if simplify:
        exprs = [sp.simplify(e) for e in exprs]
    inputs = [str(s) for s in k["inputs"]]
    if name == "accel_level":
        exprs = [e.subs(mu, -mu0 * sp.tanh(c * xd)) for e in exprs]
        inputs = ["th1", "th1d", "xd", "u"]
    params = sorted({str(s) for e in exprs for s in e.free_symbols} - set(inputs))
    return exprs, inputs, params


def run():
    mdl = md.derive()
    out = {"description": __doc__.strip().splitlines()[0],
           "counting": "see sympy_ref/opcount.py docstring", "kernels": {}}
    for name in ("accel_level", "lambda_level", "impact2_level", "impact3_level"):
        exprs, inputs, params = kernel_exprs(mdl, name)
        simp = kernel_exprs(mdl, name, simplify=True)[0]
        out["kernels"][name] = {
            "inputs": inputs,
            "params": [str(p) for p in md.PARAMS if str(p) in params] +
                      [p for p in ("mu0", "c") if p in params],
            "outputs": [n for n, _ in mdl.kernels[name]["outputs"]],
            "reduced": count(exprs),
            "simplified": count(simp),
        }
    return out


def main(path):
    out = run()
    with open(path, "w") as fh:
        json.dump(out, fh, indent=1)
        fh.write("\n")
    return out


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__),
                                                             "opcount.json"))
