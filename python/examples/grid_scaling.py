"""Wall time of a 10,000-walk grid on a local Dask cluster of 1 and of 2 worker processes.

The two cluster sizes alternate (1, 2, 1, 2, ...) so that both see the same load of a shared
machine; each prints its wall time, and the best of each is compared at the end.

    python python/examples/grid_scaling.py [--points 10000] [--duration 5] [--rounds 2]
"""

import argparse
import time

import numpy as np
import pandas as pd
from dask.distributed import Client, LocalCluster

from slippery_walker.dask import grid_sweep


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=10_000)
    ap.add_argument("--duration", type=float, default=5.0)
    ap.add_argument("--rounds", type=int, default=2)
    a = ap.parse_args()
    side = int(np.sqrt(a.points))
    mu0, t_set = np.meshgrid(np.linspace(0.05, 1.0, side), np.linspace(0.2, 0.4, a.points // side))
    grid = pd.DataFrame({"mu0": mu0.ravel(), "t_set": t_set.ravel()})
    best = {}
    tables = {}
    for r in range(a.rounds):
        for workers in (1, 2):
            with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                              dashboard_address=None) as cluster, Client(cluster) as client:
                client.wait_for_workers(workers)
                t0 = time.perf_counter()
                tables[workers] = grid_sweep(client, grid, duration=a.duration)
                dt = time.perf_counter() - t0
            best[workers] = min(best.get(workers, np.inf), dt)
            print(f"round {r}: {workers} worker(s): {len(grid)} walks in {dt:.1f} s", flush=True)
    pd.testing.assert_frame_equal(tables[1], tables[2], check_exact=True)
    print(f"best: 1 worker {best[1]:.1f} s, 2 workers {best[2]:.1f} s, "
          f"speed-up {best[1] / best[2]:.2f}; tables identical; "
          f"status counts: {tables[1]['status'].value_counts().to_dict()}")


if __name__ == "__main__":
    main()
