"""Parameter studies on Dask: :func:`grid_sweep` splits a grid of parameter points into chunks
that the workers walk with the Rust core, and gathers one pandas DataFrame.

Each point is walked exactly as :func:`slippery_walker.walk_points` walks it in one process, so
the table equals ``walk_points(grid, ...).to_pandas()`` bit for bit, in the grid's order.
Works with any ``dask.distributed`` client: a ``LocalCluster``, a ``dask_jobqueue`` cluster
(Slurm, PBS, ...) or a scheduler address. Needs ``pandas`` and ``dask[distributed]``.
"""

from __future__ import annotations

import os
from typing import Any, Dict, Mapping, Optional

import numpy as np

import slippery_walker as _sw

__all__ = ["grid_sweep"]


def _walk_chunk(cols: Dict[str, Any], options: Dict[str, Any]) -> Any:
    """Walk one chunk of the grid on a worker and return its rows as a DataFrame."""
    return _sw.walk_points(cols, **options).to_pandas()


def _absolute(arg: str, p: Optional[_sw.Path]) -> Optional[str]:
    """A file's absolute path (a worker may run in another directory); a built-in scene's
    name as it is."""
    path = _sw._path(arg, p)
    if path is None or not path.endswith(".toml"):
        return path
    return os.path.abspath(path)


def grid_sweep(
    client: Any,
    grid: Any,
    *,
    chunk_size: Optional[int] = None,
    scene: Optional[_sw.Path] = None,
    model: Optional[_sw.Path] = None,
    set: Optional[Mapping[str, float]] = None,
    init: Optional[Mapping[str, float]] = None,
    friction: Optional[str] = None,
    impact: Optional[str] = None,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    duration: Optional[float] = 20.0,
    max_steps: int = 1000,
    until_periodic: Optional[float] = None,
) -> Any:
    """Walk every point of ``grid`` on the workers of ``client`` and return one table.

    Args:
        client: a ``dask.distributed.Client``.
        grid: a dict of equal-length arrays or a pandas DataFrame whose columns are keywords
            (``mu0``, ``c``, ``t_set``, ``phi``, ``omega0``) or parameters of the model by name
            (missing ones: the scene's values, or those of ``set``).
        scene, model: the walker, as in :func:`slippery_walker.simulate`. A file (a scene
            ``.toml`` or a model) is sent to the workers as its absolute path: they must see
            the same file system (a shared one on a cluster).
        chunk_size: points per task (>= 1; default: the points split into four tasks per
            worker thread, at least 16 points each).
        Other arguments as in :func:`slippery_walker.walk_points`.

    Returns:
        A pandas DataFrame, one row per point in the grid's order: the grid's columns,
        ``steps``, ``status`` (``"ok"``, ``"periodic"`` or the failure's name), ``periodic``
        and the last step's ``T``, ``dx``, ``V``, ``p``, ``SR`` and post-impact state.

    Raises:
        ValueError: a bad argument or grid value (every point is checked here, before any work
            is sent).
    """
    import pandas as pd

    cols = _sw._grid_columns(grid)
    kwargs = dict(scene=_absolute("scene", scene), model=_absolute("model", model), set=set, init=init,
                  friction=friction, impact=impact, method=method, rtol=rtol,
                  atol=atol, duration=duration, max_steps=max_steps,
                  until_periodic=until_periodic)
    # Check every argument (max_steps included) and every point here, before any work is sent,
    # without walking and without keeping a model per point: a bad value is a ValueError here.
    _sw._core.walk_points(**_sw._grid_options(cols, **kwargs, check_only=True))
    n = len(next(iter(cols.values()), []))
    if chunk_size is None:
        threads = max(1, sum(client.nthreads().values()))
        chunk_size = max(16, -(-n // (4 * threads)))
    if isinstance(chunk_size, (bool, np.bool_)) or not (
            isinstance(chunk_size, (int, np.integer)) and chunk_size >= 1):
        raise ValueError(f"invalid chunk_size: {_sw._short(chunk_size)}: must be an integer >= 1")
    if n == 0:
        return _walk_chunk(cols, kwargs)
    # The chunks are views of the columns (no copy on the client), made one at a time as the
    # tasks are submitted.
    futures = [client.submit(_walk_chunk, {k: v[i:i + chunk_size] for k, v in cols.items()},
                             kwargs, pure=False)
               for i in range(0, n, int(chunk_size))]
    parts = client.gather(futures)
    return pd.concat(parts, ignore_index=True)
