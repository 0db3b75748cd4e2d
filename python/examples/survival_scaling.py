"""Throughput of walks on a random floor: `walker survive` on 1 and on 2 threads, and
`slippery_walker.dask.survival_grid` on a local Dask cluster of 1 and of 2 worker processes.

The work is a grid of batches (the active walker at three `T_set`, Coulomb friction, on a
floor with ice patches, two seeds): each batch runs once per round in each of the four ways,
the four alternating within a round so that all see the same load of a shared machine. Each
prints its wall time and its throughput in walk steps per second per core (step attempts: a
failed walk's last, unfinished step counts too), each round its speed-ups from 1 to 2 cores
(the same round's times, so the same load), and the best of each is compared at the end; and
every way's batches must be identical (the command line's JSON and the Dask results, parsed,
as dicts).

    python python/examples/survival_scaling.py [--walks 100] [--max-steps 200] [--rounds 2]
        [--walker target/release/walker]
"""

import argparse
import json
import os
import subprocess
import tempfile
import time
from pathlib import Path

from dask.distributed import Client, LocalCluster

from slippery_walker.dask import survival_grid

ROOT = Path(__file__).resolve().parents[2]

ICE = {"distribution": "markov", "dry": 0.4, "icy": 0.02, "dry_length": 30, "icy_length": 2}
"""Patches of ice (mu0 = 0.02) two steps long on average, on a dry road (0.4)."""

T_SET = [0.25, 0.3, 0.35]
SEEDS = [1, 2]


def floor_file(directory: str, seed: int) -> str:
    path = os.path.join(directory, f"ice-{seed}.toml")
    with open(path, "w") as f:
        f.write(f'kind = "random"\nseed = {seed}\n[mu0]\n')
        f.write("".join(f"{k} = {json.dumps(v)}\n" for k, v in ICE.items()))
    return path


def cli_batches(walker: str, directory: str, walks: int, max_steps: int, threads: int):
    """The grid's batches by `walker survive --json`, one after another, on `threads` threads."""
    env = {**os.environ, "RAYON_NUM_THREADS": str(threads)}
    out = []
    for t in T_SET:
        for seed in SEEDS:
            cmd = [walker, "survive", "--scene", "active-level", "--friction", "coulomb",
                   "--t-set", str(t), "--floor", floor_file(directory, seed), "--walks",
                   str(walks), "--max-steps", str(max_steps), "--json"]
            run = subprocess.run(cmd, env=env, capture_output=True, text=True, check=True)
            out.append(json.loads(run.stdout))
    return out


def dask_batches(workers: int, walks: int, max_steps: int):
    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        client.wait_for_workers(workers)
        t0 = time.perf_counter()
        cells = survival_grid(client, [{"t_set": t} for t in T_SET],
                              floor={"kind": "random", "seed": 0, "mu0": ICE}, seeds=SEEDS,
                              walks=walks, max_steps=max_steps, scene="active-level",
                              friction="coulomb")
        dt = time.perf_counter() - t0
    assert all(c["error"] is None for c in cells)
    return [c["result"] for c in cells], dt


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--walks", type=int, default=100)
    ap.add_argument("--max-steps", type=int, default=200)
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--walker", default=str(ROOT / "target" / "release" / "walker"))
    a = ap.parse_args()
    best = {}
    times = []
    results = {}
    with tempfile.TemporaryDirectory() as directory:
        for r in range(a.rounds):
            times.append({})
            for way, cores in (("walker survive, 1 thread", 1), ("survival_grid, 1 worker", 1),
                               ("walker survive, 2 threads", 2), ("survival_grid, 2 workers", 2)):
                if way.startswith("walker"):
                    t0 = time.perf_counter()
                    batches = cli_batches(a.walker, directory, a.walks, a.max_steps, cores)
                    dt = time.perf_counter() - t0
                else:
                    batches, dt = dask_batches(cores, a.walks, a.max_steps)
                results[way] = batches
                times[r][way] = dt
                steps = sum(b["survival"]["mfpt"]["attempts"] for b in batches)
                rate = steps / dt / cores
                best[way] = max(best.get(way, 0.0), rate)
                print(f"round {r}: {way}: {steps} steps in {dt:.1f} s, "
                      f"{rate:.0f} steps/s per core", flush=True)
            t = times[r]
            print(f"round {r}: speed-up from 1 to 2 cores: walker survive "
                  f"{t['walker survive, 1 thread'] / t['walker survive, 2 threads']:.2f}, "
                  f"survival_grid {t['survival_grid, 1 worker'] / t['survival_grid, 2 workers']:.2f}",
                  flush=True)
    reference = results["walker survive, 1 thread"]
    assert all(b == reference for b in results.values()), "the batches differ"
    failures = sum(b["survival"]["failures"] for b in reference)
    print(f"all {len(results)} ways gave identical batches ({len(reference)} batches, "
          f"{failures} of {len(reference) * a.walks} walks failed)")
    for way, rate in best.items():
        print(f"best: {way}: {rate:.0f} steps/s per core")
    one, two = best["survival_grid, 1 worker"], best["survival_grid, 2 workers"]
    print(f"best against best: survival_grid from 1 to 2 workers: speed-up {2 * two / one:.2f}; "
          f"walker survive from 1 to 2 threads: "
          f"{2 * best['walker survive, 2 threads'] / best['walker survive, 1 thread']:.2f}; "
          f"survival_grid / walker survive per core: 1 core "
          f"{one / best['walker survive, 1 thread']:.2f}, 2 cores "
          f"{two / best['walker survive, 2 threads']:.2f}")


if __name__ == "__main__":
    main()
