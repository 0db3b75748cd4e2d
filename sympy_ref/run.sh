#!/usr/bin/env bash
# Regenerate every reference file: tests/data/*.json and
# sympy_ref/{closed_forms.txt, opcount.json, report.json}.
# Creates sympy_ref/.venv (gitignored) with the pinned sympy/mpmath on first use.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
venv="$here/.venv"
if [ ! -x "$venv/bin/python" ]; then
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet --disable-pip-version-check -r "$here/requirements.txt"
fi
start=$(date +%s)
"$venv/bin/python" "$here/generate.py" "$@"
echo "run.sh: $(( $(date +%s) - start )) s (excluding venv creation)"
