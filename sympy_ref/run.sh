#!/usr/bin/env bash
# Regenerate every reference file: tests/data/*.json and sympy_ref/{closed_forms.txt,opcount.json}.
# Creates sympy_ref/.venv (gitignored) with the pinned sympy/mpmath on first use.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(dirname "$here")"
venv="$here/.venv"
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet --disable-pip-version-check -r "$here/requirements.txt"
fi
py="$venv/bin/python"
data="$root/tests/data"
mkdir -p "$data"
cd "$here"
start=$(date +%s)
# the kernel tables and the two step references are independent: run them in parallel
"$py" kernels.py "$data" > "$here/.kernels.log" 2>&1 &
pk=$!
"$py" steps.py "$data" > "$here/.steps.log" 2>&1 &
ps=$!
"$py" closed_forms.py > "$here/closed_forms.txt"
"$py" opcount.py "$here/opcount.json"
fail=0
wait $pk || fail=1
wait $ps || fail=1
cat "$here/.kernels.log" "$here/.steps.log"
rm -f "$here/.kernels.log" "$here/.steps.log"
[ $fail = 0 ] || { echo "FAILED"; exit 1; }
echo "done in $(( $(date +%s) - start )) s"
