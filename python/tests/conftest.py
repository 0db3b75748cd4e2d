"""Shared helpers of the Python tests: the command line's JSON outputs, made when a test asks.

``cli_json(name)`` runs the ``walker`` command named ``name`` in ``CLI_COMMANDS`` from the
repository root (the binary ``cargo test --workspace`` builds, found once per session) and
returns its JSON: the module and the command line are compared on the same build of the
library, never against outputs kept from an older one.
"""

import functools
import json
import subprocess
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

MODELS = ROOT / "models"
"""The shipped model files (``models/*.toml`` of the repository)."""

CLI_COMMANDS = {
    "simulate_active": "simulate --scene active-level --mu0 0.4 --t-set 0.3 --omega0 0.8 "
                       "--max-steps 5",
    "simulate_fig14_fall": "simulate --scene passive-slope --mu0 0.19 --phi 0.10 --omega0 0.5 "
                           "--max-steps 5",
    "simulate_coulomb": "simulate --scene active-level --mu0 0.3 --impact coulomb "
                        "--friction coulomb --max-steps 4",
    "sweep_active": "sweep --scene active-level --mu0-from 0.1 --mu0-to 0.4 --mu0-step 0.1 "
                    "--t-set 0.3 --t-set 0.4 --duration 5",
    "sweep_passive_restart": "sweep --scene passive-slope --mu0-from 0.1 --mu0-to 0.3 "
                             "--mu0-step 0.1 --phi 0.1 --restart --duration 5",
    "fixed_point_active": "fixed-point --scene active-level --mu0 0.4",
    "simulate_init": "simulate --scene active-level --init th1d=0.7 --init th2d=0.9 "
                     "--max-steps 3",
    "simulate_compass_gait": "simulate --model models/compass-gait.toml --friction coulomb "
                             "--impact frictionless --max-steps 5",
    "sweep_m2": "sweep --scene active-level --param m2 --from 0.8 --to 1.2 --step 0.2 "
                "--t-set 0.3 --duration 3",
    "fixed_point_compass_gait": "fixed-point --model models/compass-gait.toml "
                                "--friction coulomb --impact frictionless",
    "simulate_mu0_steps": "simulate --scene active-level --t-set 0.3 --friction coulomb "
                          "--mu0-steps 0.4,0.4,0.4,0.05,0.4 --max-steps 6",
    "survive_markov": "survive --scene passive-slope --floor python/tests/floors/markov.toml "
                      "--walks 16 --max-steps 30",
    "mfpt_wheel": "mfpt --model models/rimless-wheel.toml --friction coulomb --impact coulomb "
                  "--floor python/tests/floors/wheel-ice.toml --mesh 5 --samples 4 --walks 20 "
                  "--max-steps 200",
    "mfpt_wheel_slopes": "mfpt --model models/rimless-wheel.toml --friction coulomb "
                         "--impact coulomb --floor python/tests/floors/wheel-slopes.toml "
                         "--set mu0=0.8 --mesh 5 --samples 4 --walks 20 --max-steps 200",
}
"""The ``walker`` commands the module's results are compared with, by name."""


@functools.cache
def walker_binary() -> Path:
    """The command line as ``cargo test --workspace`` builds it (for the CLI's own tests), found
    through cargo's build messages: after ``cargo test`` this builds nothing (what ``.ci/run``
    does), and on its own it builds what the Rust tests would."""
    run = subprocess.run(["cargo", "test", "--workspace", "--no-run", "--quiet",
                          "--message-format=json"], cwd=ROOT, check=True, capture_output=True,
                         text=True)
    for line in run.stdout.splitlines():
        msg = json.loads(line)
        target = msg.get("target", {})
        # the program itself, not its unit tests' harness (also a `bin` artifact)
        if (msg.get("reason") == "compiler-artifact" and target.get("name") == "walker"
                and "bin" in target.get("kind", []) and msg.get("executable")
                and not msg.get("profile", {}).get("test")):
            return Path(msg["executable"])
    raise RuntimeError("cargo built no `walker` binary")


@functools.cache
def _cli_text(name: str) -> str:
    run = subprocess.run([walker_binary(), *CLI_COMMANDS[name].split(), "--json"], cwd=ROOT,
                         capture_output=True, text=True, check=True)
    return run.stdout


def cli_json(name: str):
    """The JSON output of the ``walker`` command ``CLI_COMMANDS[name]``."""
    return json.loads(_cli_text(name))
