#!/usr/bin/env bash
# The Python tests: make a virtual environment (python/.venv, git-ignored), install the pinned
# test requirements and this package (built by maturin from the Rust crate), and run pytest.
# Usage: bash python/run-tests.sh [pytest arguments]
#        bash python/run-tests.sh --install-only   (the environment, requirements and package only)
#        bash python/run-tests.sh --env-only       (the environment and requirements only)
# The package builds in the release profile (pyproject.toml); MATURIN_PEP517_ARGS="--profile dev"
# builds it with the dev profile's settings instead, which after `cargo test` reuses the test
# build's artifacts and compiles the module's own crate only (what .ci/run does).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
cd "$here"
python="${PYTHON:-python3}"
if [ ! -x .venv/bin/python ]; then
    "$python" -m venv .venv
fi
.venv/bin/python -m pip install --quiet --upgrade pip
.venv/bin/python -m pip install --quiet -r requirements-test.txt
if [ "${1:-}" = "--env-only" ]; then
    exit 0
fi
# The pinned maturin of the requirements builds the package (no isolated build environment to
# fetch a second copy into; maturin's build hook runs the `maturin` on the PATH).
PATH="$here/.venv/bin:$PATH" .venv/bin/python -m pip install --quiet --force-reinstall --no-deps \
    --no-build-isolation .
if [ "${1:-}" = "--install-only" ]; then
    exit 0
fi
# From tests/, so that the installed package is imported, not the source folder.
cd tests
exec ../.venv/bin/python -m pytest -q -p no:cacheprovider "$@"
