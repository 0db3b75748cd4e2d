"""The overhead of a call through Python over the Rust core, measured side by side in one run.

Alternates rounds of (a) the same walk in Rust, in-process (`walker/examples/walk_timing.rs`,
median of its repeats) and (b) `slippery_walker.simulate(...)` (median of as many calls), and
prints the medians and their ratio per round. The walk: the active walker of Fig. 5
(mu0 = 0.4, T_set = 0.3, omega0 = 0.8), 20 s.

    cargo build --release -p walker --example walk_timing
    python/.venv/bin/python python/examples/overhead.py [--rounds 5] [--repeats 50]
"""

import argparse
import os
import statistics
import subprocess
import time

import slippery_walker as sw

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
TARGET = os.environ.get("CARGO_TARGET_DIR", os.path.join(ROOT, "target"))


def rust_median(duration: float, repeats: int) -> float:
    exe = os.path.join(TARGET, "release", "examples", "walk_timing")
    out = subprocess.run([exe, str(duration), str(repeats)], check=True, capture_output=True)
    return float(out.stdout)


def python_median(duration: float, repeats: int) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        sw.simulate(scene="active-level", mu0=0.4, t_set=0.3, omega0=0.8, duration=duration)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--repeats", type=int, default=50)
    ap.add_argument("--duration", type=float, default=20.0)
    a = ap.parse_args()
    ratios = []
    for r in range(a.rounds):
        rust = rust_median(a.duration, a.repeats)
        py = python_median(a.duration, a.repeats)
        ratios.append(py / rust)
        print(f"round {r}: rust {rust * 1e3:.3f} ms, python {py * 1e3:.3f} ms, ratio {py / rust:.3f}")
    print(f"median ratio {statistics.median(ratios):.3f}")


if __name__ == "__main__":
    main()
