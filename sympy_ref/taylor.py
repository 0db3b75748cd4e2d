"""Taylor-mode automatic differentiation of SymPy expressions with mpmath coefficients.

`Program(exprs, inputs, consts)` compiles rational expressions (Add, Mul, integer Pow) of the
`inputs` into a straight-line program.  `Program.run(series)` returns a `Run` object whose
`coeff(k)` computes the k-th Taylor coefficient of every node, given that the k-th coefficients
of the input series are known (the usual recurrences: convolution for products, the division
recurrence for quotients).  Transcendental functions (sin/cos pair, tanh) are provided as
separate recurrences that the caller drives.
"""
from __future__ import annotations

import mpmath as mp
import sympy as sp

ZERO = mp.mpf(0)   # exact at any precision
ONE = mp.mpf(1)


class Program:
    def __init__(self, exprs, inputs, consts=None):
        consts = consts or {}
        self.inputs = list(inputs)
        self.ops = []          # (kind, a, b, value)
        self._memo = {}
        self._in_idx = {}
        for i, s in enumerate(self.inputs):
            self._in_idx[s] = self._add(("in", i, None, None))
        self._consts = {s: mp.mpf(v) for s, v in consts.items()}
        repl, red = sp.cse(list(exprs), optimizations="basic")
        self._cse = {}
        for s, e in repl:
            self._cse[s] = self._compile(e)
        self.outputs = [self._compile(e) for e in red]

    # --------------------------------------------------------------- compiler
    def _add(self, op):
        self.ops.append(op)
        return len(self.ops) - 1

    def _const(self, v):
        key = ("c", v)
        if key not in self._memo:
            self._memo[key] = self._add(("const", None, None, v))
        return self._memo[key]

    def _is_const(self, n):
        return self.ops[n][0] == "const"

    def _val(self, n):
        return self.ops[n][3]

    def _bin(self, kind, a, b):
        if self._is_const(a) and self._is_const(b):
            va, vb = self._val(a), self._val(b)
            return self._const({"add": va + vb, "mul": va * vb, "div": va / vb}[kind])
        if kind == "mul" and self._is_const(a):
            return self._scale(self._val(a), b)
        if kind == "mul" and self._is_const(b):
            return self._scale(self._val(b), a)
        if kind == "div" and self._is_const(b):
            return self._scale(1 / self._val(b), a)
        key = (kind, a, b)
        if key not in self._memo:
            self._memo[key] = self._add((kind, a, b, None))
        return self._memo[key]

    def _scale(self, c, a):
        if c == 1:
            return a
        key = ("scale", c, a)
        if key not in self._memo:
            self._memo[key] = self._add(("scale", a, None, c))
        return self._memo[key]

    def _compile(self, e):
        if e in self._in_idx:
            return self._in_idx[e]
        if e in self._cse:
            return self._cse[e]
        if e in self._consts:
            return self._const(self._consts[e])
        if e.is_Number:
            return self._const(mp.mpf(e.p) / e.q if e.is_Rational else mp.mpf(str(e)))
        if e.is_Add:
            nodes = [self._compile(a) for a in e.args]
            acc = nodes[0]
            for n in nodes[1:]:
                acc = self._bin("add", acc, n)
            return acc
        if e.is_Mul:
            num, den = [], []
            for a in e.args:
                if a.is_Pow and a.exp.is_Integer and a.exp < 0:
                    den.append(self._compile(sp.Pow(a.base, -a.exp)))
                else:
                    num.append(self._compile(a))
            acc = num[0] if num else self._const(mp.mpf(1))
            for n in num[1:]:
                acc = self._bin("mul", acc, n)
            if den:
                d = den[0]
                for n in den[1:]:
                    d = self._bin("mul", d, n)
                acc = self._bin("div", acc, d)
            return acc
        if e.is_Pow and e.exp.is_Integer:
            n = int(e.exp)
            if n < 0:
                return self._bin("div", self._const(mp.mpf(1)), self._compile(e.base ** -n))
            b = self._compile(e.base)
            acc = None
            sq = b
            while n:
                if n & 1:
                    acc = sq if acc is None else self._bin("mul", acc, sq)
                n >>= 1
                if n:
                    sq = self._bin("mul", sq, sq)
            return acc
        raise TypeError(f"cannot compile {e!r} ({type(e)})")

    def run(self, series):
        return Run(self, series)


class Run:
    """Per-step evaluation state: coefficient lists for every node."""

    def __init__(self, prog, series):
        self.p = prog
        self.series = series         # list of coefficient lists, one per input
        self.c = [[] for _ in prog.ops]

    def coeff(self, k):
        ops = self.p.ops
        c = self.c
        fdot = mp.fdot
        for n, (kind, a, b, v) in enumerate(ops):
            cn = c[n]
            if kind == "in":
                cn.append(self.series[a][k])
            elif kind == "const":
                cn.append(v if k == 0 else ZERO)
            elif kind == "add":
                cn.append(c[a][k] + c[b][k])
            elif kind == "scale":
                cn.append(v * c[a][k])
            elif kind == "mul":
                ca, cb = c[a], c[b]
                if k == 0:
                    cn.append(ca[0] * cb[0])
                else:
                    cn.append(fdot(ca[:k + 1], cb[k::-1]))
            elif kind == "div":
                ca, cb = c[a], c[b]
                if k == 0:
                    cn.append(ca[0] / cb[0])
                else:
                    s = fdot(cb[1:k + 1], cn[k - 1::-1])
                    cn.append((ca[k] - s) / cb[0])
        return [c[o][k] for o in self.p.outputs]


# ------------------------------------------------------------------ elementary recurrences
def sincos_coeff(th, s, c, k):
    """Append coefficient k of sin(th), cos(th) to s, c (th has coefficients 0..k)."""
    if k == 0:
        s.append(mp.sin(th[0]))
        c.append(mp.cos(th[0]))
        return
    js = [j * th[j] for j in range(1, k + 1)]
    s.append(mp.fdot(js, c[k - 1::-1]) / k)
    c.append(-mp.fdot(js, s[k - 1::-1]) / k)


def tanh_coeff(w, T, D, k):
    """Append coefficient k of T = tanh(w) and D = 1 - T^2."""
    if k == 0:
        T.append(mp.tanh(w[0]))
        D.append(1 - T[0] ** 2)
        return
    js = [j * w[j] for j in range(1, k + 1)]
    T.append(mp.fdot(js, D[k - 1::-1]) / k)
    D.append(-mp.fdot(T[:k + 1], T[k::-1]))


def mul_coeff(a, b, k):
    return mp.fdot(a[:k + 1], b[k::-1])


def div_coeff(a, b, q, k):
    """Coefficient k of q = a / b (q has coefficients 0..k-1)."""
    if k == 0:
        return a[0] / b[0]
    return (a[k] - mp.fdot(b[1:k + 1], q[k - 1::-1])) / b[0]


def poly_eval(cs, tau):
    """Horner evaluation of sum cs[k] tau^k."""
    r = ZERO
    for ck in reversed(cs):
        r = r * tau + ck
    return r


def poly_deriv(cs):
    return [k * cs[k] for k in range(1, len(cs))]


def poly_integral(cs, a, b):
    """Integral of sum cs[k] tau^k over [a, b]."""
    F = lambda t: poly_eval([ZERO] + [ck / (k + 1) for k, ck in enumerate(cs)], t)
    return F(b) - F(a)
