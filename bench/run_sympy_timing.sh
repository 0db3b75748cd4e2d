#!/usr/bin/env bash
# Times SymPy deriving the kernels (bench/sympy_timing.py), capped at ${CAP:-240} s, in
# sympy_ref/.venv (created from sympy_ref/requirements.txt if missing).
set -uo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
if [ ! -x "$root/sympy_ref/.venv/bin/python" ]; then
    python3 -m venv "$root/sympy_ref/.venv"
    "$root/sympy_ref/.venv/bin/pip" install -q -r "$root/sympy_ref/requirements.txt"
fi
timeout "${CAP:-240}" "$root/sympy_ref/.venv/bin/python" "$root/bench/sympy_timing.py" "$root/sympy_ref"
rc=$?
if [ $rc -eq 124 ]; then echo "stopped by the cap of ${CAP:-240} s"; fi
