"""Shared helpers of the Python tests: the command line's JSON outputs kept in ``data/``.

Each file in ``data/`` is the output of the ``walker`` command named in ``CLI_COMMANDS``, run
from the repository root after ``cargo build --release -p walker-cli``; re-make them with
``python/tests/make-cli-data.sh`` when the library's results change on purpose.
"""

import json
from pathlib import Path

DATA = Path(__file__).parent / "data"

MODELS = Path(__file__).resolve().parents[2] / "models"
"""The shipped model files (``models/*.toml`` of the repository)."""


def cli_json(name: str):
    """The command line's JSON output kept as ``data/<name>.json``."""
    return json.loads((DATA / f"{name}.json").read_text())
