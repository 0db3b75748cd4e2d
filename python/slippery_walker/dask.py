"""Parameter studies on Dask: :func:`grid_sweep` splits a grid of parameter points into chunks
that the workers walk with the Rust core, and gathers one pandas DataFrame;
:func:`survival_grid` splits batches of walks on floors (:func:`slippery_walker.survive`, a
grid of settings times floors times seeds) into ranges of walks, and gathers each batch.

Each point is walked exactly as :func:`slippery_walker.walk_points` walks it in one process, so
the table equals ``walk_points(grid, ...).to_pandas()`` bit for bit, in the grid's order; each
batch equals :func:`slippery_walker.survive` of the same arguments in one process.
Works with any ``dask.distributed`` client: a ``LocalCluster``, a ``dask_jobqueue`` cluster
(Slurm, PBS, ...) or a scheduler address. Needs ``pandas`` and ``dask[distributed]``.
"""

from __future__ import annotations

import json
import os
from typing import Any, Dict, List, Mapping, Optional, Sequence

import numpy as np

import slippery_walker as _sw

__all__ = ["grid_sweep", "survival_grid"]


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


_SETTINGS = ("scene", "model", "set", "init", "t_set", "omega0", "phi", "c", "friction",
             "impact", "method", "rtol", "atol")
"""The keywords of :func:`slippery_walker.survive` that a grid entry may set."""


def _survive_chunk(options: Dict[str, Any], first_walk: int, walks: int,
                   max_steps: int) -> Any:
    """Walk the walks ``first_walk .. first_walk + walks`` of one batch on a worker, on one
    thread (the workers provide the parallelism), and return their outcomes in walk order;
    an exception is returned as its text, so that it costs its batch, not the others."""
    try:
        text = _sw._core.survive(**options, walks=walks, max_steps=max_steps,
                                 first_walk=first_walk, threads=1)
        return json.loads(text)["outcomes"]
    except Exception as e:  # one batch's failure is reported with it, never raised here
        return {"error": f"{type(e).__name__}: {e}"}


def _floors(floor: Any) -> List[Any]:
    """The floors of ``floor=``: one floor (a path or a dict) or a list of them."""
    if isinstance(floor, (str, os.PathLike, Mapping)):
        return [floor]
    if isinstance(floor, Sequence) and not isinstance(floor, bytes) and len(floor) > 0:
        return list(floor)
    raise _sw._type_error("floor", floor, "a floor (a file's path or a dict) or a non-empty "
                          "list of floors")


def _seeded(floor: Any, j: int, seed: Optional[int]) -> Any:
    """Floor ``j`` with ``seed`` as its seed (None: its own), as the core takes it."""
    if seed is None:
        if isinstance(floor, Mapping):
            return dict(floor)
        # A file's absolute path: a worker may run in another directory.
        return os.path.abspath(_sw._path(f"floor[{j}]", floor) or "")
    if not (isinstance(floor, Mapping) and floor.get("kind") == "random"):
        raise ValueError(f"invalid floor[{j}]: {_sw._short(floor)}: seeds are given, so every "
                         "floor must be a random floor given as a dict ({'kind': 'random', ...}); "
                         "a file's path keeps its own seed (leave seeds out)")
    return {**floor, "seed": seed}


def _settings(grid: Any) -> List[Dict[str, Any]]:
    """The grid's entries as dicts of :func:`slippery_walker.survive`'s keywords."""
    if grid is None:
        return [{}]
    if hasattr(grid, "to_dict") and hasattr(grid, "columns"):
        grid = grid.to_dict("records")
    if isinstance(grid, (str, bytes, Mapping)) or not isinstance(grid, Sequence):
        raise _sw._type_error("grid", grid, "a list of dicts of survive's keywords (or a "
                              "pandas DataFrame of them)")
    out = []
    for i, entry in enumerate(grid):
        if not isinstance(entry, Mapping):
            raise _sw._type_error(f"grid[{i}]", entry, "a dict of survive's keywords")
        for k in entry:
            if k not in _SETTINGS:
                raise ValueError(f"invalid grid[{i}]: {_sw._short(k)}: not a keyword a grid "
                                 f"entry may set; they are: {', '.join(_SETTINGS)}")
        out.append(dict(entry))
    return out


def survival_grid(
    client: Any,
    grid: Any = None,
    *,
    floor: Any,
    seeds: Optional[Sequence[int]] = None,
    walks: int = 100,
    max_steps: int = 1000,
    chunk_size: Optional[int] = None,
    scene: Optional[_sw.Path] = None,
    model: Optional[_sw.Path] = None,
    set: Optional[Mapping[str, float]] = None,
    init: Optional[Mapping[str, float]] = None,
    t_set: Optional[float] = None,
    omega0: Optional[float] = None,
    phi: Optional[float] = None,
    c: Optional[float] = None,
    friction: Optional[str] = None,
    impact: Optional[str] = None,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
) -> List[Dict[str, Any]]:
    """Run :func:`slippery_walker.survive` for every (grid entry, floor, seed) on the workers of
    ``client``, each batch split into ranges of walks, and return one result per batch.

    Walk ``i`` of a batch runs on the floor's stream ``i`` wherever it runs, so a range of walks
    ``[a, b)`` (a task: ``survive(first_walk=a, walks=b - a)`` on one thread) has exactly the
    outcomes of walks ``a..b`` of the whole batch; the outcomes are put back in walk order and
    their statistics computed by :func:`slippery_walker.survival`, the library's function. A
    batch's ``result`` is therefore equal (the same dict, bit for bit) to ``survive(**kwargs,
    **entry, floor=floor, walks=walks, max_steps=max_steps)`` in one process (``kwargs``: the
    keyword arguments below, ``floor`` with the batch's seed), on any number of workers and
    for any ``chunk_size``.

    Args:
        client: a ``dask.distributed.Client``.
        grid: the settings: a list of dicts (or a pandas DataFrame whose rows are such dicts)
            of :func:`slippery_walker.survive`'s walker and run-time keywords (``scene``,
            ``model``, ``set``, ``init``, ``t_set``, ``omega0``, ``phi``, ``c``, ``friction``,
            ``impact``, ``method``, ``rtol``, ``atol``), e.g. ``[{"t_set": 0.25}, {"t_set":
            0.3, "set": {"K_P": 40.0}}]``; an entry's keys replace the keyword arguments of
            the same name. None: one entry, the keyword arguments alone.
        floor: a floor (a floor file's path or a dict, as :func:`slippery_walker.survive`
            takes it) or a list of floors.
        seeds: None (each floor's own seed) or a list of seeds, each a whole number in
            ``[0, 2^63 - 1]``: every floor is walked with each (it replaces the floor's
            ``seed``; every floor must then be a random floor given as a dict).
        walks, max_steps: each batch's walks and their step limit, as
            :func:`slippery_walker.survive` takes them.
        chunk_size: walks per task (an integer >= 1; default: all walks split into four tasks
            per worker thread, at least 16 walks a task and at most one batch).
        scene, model, set, init, t_set, omega0, phi, c, friction, impact, method, rtol, atol:
            as :func:`slippery_walker.survive`, for every entry. A file (a scene ``.toml``, a
            model, a floor) is sent to the workers as its absolute path: they must see the
            same file system (a shared one on a cluster).

    Returns:
        A list with one dict per batch, in the order grid entry, then floor, then seed:
        ``grid`` (the entry's index), ``settings`` (the entry), ``floor`` (the floor's index),
        ``seed`` (the seed, or None for the floor's own), ``result`` (the batch's
        :func:`slippery_walker.survive` dict: ``max_steps``, ``outcomes``, ``survival``) and
        ``error`` (None, or why a task of the batch raised; then ``result`` is None). A walker
        failure is an outcome, and one batch's error does not cost the others their results.

    Raises:
        ValueError: a bad argument, grid entry, floor or seed, named (every batch's arguments
            are checked here, with the floor against the walker, before any work is sent).
        TypeError: an argument of the wrong type (:class:`slippery_walker.ArgumentTypeError`
            for the keywords of :func:`slippery_walker.survive`).
    """
    settings = dict(scene=scene, model=model, set=set, init=init, t_set=t_set, omega0=omega0,
                    phi=phi, c=c, friction=friction, impact=impact, method=method, rtol=rtol,
                    atol=atol)
    entries = _settings(grid)
    floors = _floors(floor)
    if seeds is None:
        seed_list: List[Optional[int]] = [None]
    else:
        if isinstance(seeds, (str, bytes, Mapping)) or not isinstance(seeds, Sequence) \
                or len(seeds) == 0:
            raise _sw._type_error("seeds", seeds, "None or a non-empty list of whole numbers")
        seed_list = [_sw._int(f"seeds[{i}]", s, 0, _sw.MAX_WALK_INDEX)
                     for i, s in enumerate(seeds)]
    walks = _sw._int("walks", walks, 1, 100_000)
    max_steps = _sw._int("max_steps", max_steps, 1, _sw.MAX_STEPS)
    if chunk_size is not None and (isinstance(chunk_size, (bool, np.bool_)) or not (
            isinstance(chunk_size, (int, np.integer)) and chunk_size >= 1)):
        raise ValueError(f"invalid chunk_size: {_sw._short(chunk_size)}: must be an integer >= 1")
    # Every batch's core arguments, checked here (the floor against the walker too) without
    # walking: a bad value is an error here, named with its batch, before any work is sent.
    batches = []
    for g, entry in enumerate(entries):
        kw = {**settings, **entry}
        for arg in ("scene", "model"):
            kw[arg] = _absolute(arg, kw.get(arg))
        for f, fl in enumerate(floors):
            for seed in seed_list:
                where = f"grid[{g}], floor[{f}]" + ("" if seed is None else f", seed {seed}")
                try:
                    options = _sw._survive_options(floor=_seeded(fl, f, seed), **kw)
                    _sw._core.survive(**options, walks=walks, max_steps=max_steps,
                                      check_only=True)
                except (TypeError, ValueError) as e:
                    raise type(e)(f"{e} ({where})") from None
                batches.append(({"grid": g, "settings": entry, "floor": f, "seed": seed},
                                options))
    if chunk_size is None:
        threads = max(1, sum(client.nthreads().values()))
        chunk_size = min(walks, max(16, -(-len(batches) * walks // (4 * threads))))
    chunk = int(chunk_size)
    futures = [[client.submit(_survive_chunk, options, a, min(chunk, walks - a), max_steps,
                              pure=False)
                for a in range(0, walks, chunk)]
               for _, options in batches]
    parts = client.gather(futures)
    out = []
    for (cell, _), chunks in zip(batches, parts):
        errors = [c["error"] for c in chunks if isinstance(c, dict)]
        if errors:
            out.append({**cell, "result": None, "error": errors[0]})
            continue
        outcomes = [o for c in chunks for o in c]
        result = {"max_steps": max_steps, "outcomes": outcomes,
                  "survival": _sw.survival(outcomes)}
        out.append({**cell, "result": result, "error": None})
    return out
