#!/usr/bin/env bash
# Creates bench/.venv with the pinned NumPy/SciPy, builds the walker CLI in release and runs the
# SciPy peer next to it: bench/run_peer.sh [extra args of scipy_peer.py]
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(dirname "$here")"
if [ ! -x "$here/.venv/bin/python" ]; then
    python3 -m venv "$here/.venv"
    "$here/.venv/bin/pip" install -q -r "$here/requirements.txt"
fi
(cd "$root" && cargo build --release -p walker-cli --bin walker)
"$here/.venv/bin/python" "$here/scipy_peer.py" --walker "$root/target/release/walker" "$@"
