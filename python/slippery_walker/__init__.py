"""Limit-cycle walkers on slippery ground (Asano, Kikuchi, Shibata), with a Rust core.

The functions take keyword arguments with the meaning of the ``walker`` command line's flags
and return NumPy arrays:

- :func:`simulate` -- one walk: per-step descriptors ``T``, ``dx``, ``V``, ``p``, ``SR``,
  ``q_plus``, ``qd_plus``; with ``trajectory=True`` also the motion at exact times.
- :func:`sweep` -- walks over a grid of ``mu0`` for chains of ``t_set`` (active walker) or
  ``phi`` (passive wheel), procedures (P1a)-(P5a) and (P1b)-(P5b).
- :func:`walk_points` -- independent walks at the points of a parameter grid (one process);
  :func:`slippery_walker.dask.grid_sweep` runs the same on a Dask cluster.
- :func:`fixed_point` -- the limit cycle and its Floquet multipliers.

Bad input raises :class:`ValueError` naming the argument and its valid range. A walker failure
(lift-off, falling, ...) is a result: ``status`` names it and ``failure`` holds its details.
Long runs release the GIL; sweeps and grids can be interrupted with Ctrl-C.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from typing import Any, Dict, Iterable, Mapping, Optional, Sequence, Union

import numpy as np

from . import _core

__version__: str = _core.__version__
"""The package's version (that of the Rust crate)."""

MAX_STEPS: int = _core.MAX_STEPS
"""The most steps one walk may take (``max_steps``), as the command line's ``--max-steps``."""

__all__ = [
    "FixedPoint",
    "Sweep",
    "Walk",
    "__version__",
    "fixed_point",
    "simulate",
    "sweep",
    "walk_points",
]


def _arr(values: Iterable[float], width: int = 0) -> np.ndarray:
    a = np.asarray(values, dtype=np.float64)
    return a.reshape(-1, width) if width else a


def _failure(text: Optional[str]) -> Optional[Dict[str, Any]]:
    return None if text is None else json.loads(text)


@dataclass(frozen=True)
class Walk:
    """One walk: its outcome and one row per completed step.

    ``status`` is ``"ok"`` or the failure's name (``"lift-off"``, ``"fell-backward"``, ...);
    ``failure`` is the command line's JSON object of the failure as a dict (``kind``,
    ``step``, ``t``, ``state``, ...) or None. Per-step arrays (one row per step): ``T`` (s),
    ``dx`` (m), ``V`` (m/s), ``p`` (W) and ``SR`` (NaN for the passive wheel, which has no
    input), ``q_plus`` ``[x, z, th1, th2]`` and ``qd_plus`` ``[xd, zd, th1d, th2d]`` after each
    impact (shape ``(steps, 4)``).

    With ``trajectory=True``: ``times`` (s since the start of the walk, exactly ``k * dt``),
    ``states`` (shape ``(frames, 8)``, ``[x, z, th1, th2, xd, zd, th1d, th2d]`` in the stance
    leg's coordinates), ``frame_steps`` (the step of each frame), ``end_time`` (the last
    impact or the failure) and ``truncated`` (``max_frames`` was reached).
    """

    status: str
    failure: Optional[Dict[str, Any]]
    T: np.ndarray
    dx: np.ndarray
    V: np.ndarray
    p: np.ndarray
    SR: np.ndarray
    q_plus: np.ndarray
    qd_plus: np.ndarray
    times: Optional[np.ndarray] = None
    states: Optional[np.ndarray] = None
    frame_steps: Optional[np.ndarray] = None
    end_time: Optional[float] = None
    truncated: bool = False

    @property
    def ok(self) -> bool:
        """True if the walk reached its limits without a failure."""
        return self.failure is None

    @property
    def steps(self) -> int:
        """The number of completed steps."""
        return len(self.T)


def _walk(d: Mapping[str, Any]) -> Walk:
    extra: Dict[str, Any] = {}
    if "times" in d:
        extra = dict(
            times=_arr(d["times"]),
            states=_arr(d["states"], 8),
            frame_steps=np.asarray(d["frame_steps"], dtype=np.int64),
            end_time=d["end_time"],
            truncated=d["truncated"],
        )
    return Walk(
        status=d["status"],
        failure=_failure(d["failure"]),
        T=_arr(d["T"]),
        dx=_arr(d["dx"]),
        V=_arr(d["V"]),
        p=_arr(d["p"]),
        SR=_arr(d["SR"]),
        q_plus=_arr(d["q_plus"], 4),
        qd_plus=_arr(d["qd_plus"], 4),
        **extra,
    )


def simulate(
    *,
    scene: str = "active-level",
    mu0: Optional[float] = None,
    t_set: Optional[float] = None,
    omega0: Optional[float] = None,
    phi: Optional[float] = None,
    c: Optional[float] = None,
    friction: Optional[str] = None,
    impact: Optional[str] = None,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    duration: Optional[float] = None,
    max_steps: int = 100,
    trajectory: bool = False,
    dt: float = 0.01,
    max_frames: int = 100_000,
) -> Walk:
    """Simulate one walk, as ``walker simulate --json``.

    Args:
        scene: ``"active-level"``, ``"passive-slope"`` or the path of a scene ``.toml``.
        mu0: friction coefficient ``mu0`` (>= 0; default: the scene's).
        t_set: ramp duration ``T_set`` (s, > 0; active walker).
        omega0: initial angular velocity (rad/s; default: the scene's).
        phi: slope angle (rad, in [0, pi/2); passive wheel; 0 for the active walker).
        c: sharpness of the friction law ``mu = -mu0 tanh(c xd)`` (s/m, > 0).
        friction: ``"tanh"`` (Eqs. 26, 37) or ``"coulomb"`` (Eq. 25); default: the scene's.
        impact: ``"frictionless"`` (the paper's) or ``"coulomb"``; default: the scene's.
        method: ``"dop853"`` or ``"rodas4"`` (stiff friction, large ``mu0 c``).
        rtol, atol: integrator tolerances, in (0, 1) (default 1e-10 and 1e-12; 1e-8 and 1e-10
            with rodas4).
        duration: stop after the step that passes this time (s, > 0; default: no limit).
        max_steps: stop after this many steps (at most :data:`MAX_STEPS`).
        trajectory: also sample the motion at ``0, dt, 2 dt, ...`` from the dense output.
        dt: the interval of the trajectory's frames (s, > 0).
        max_frames: the most frames (in [1, 1000000]).

    Returns:
        The :class:`Walk`; a failure is its ``status``, not an exception.

    Raises:
        ValueError: an argument out of its range (the message names it and the range).
    """
    d = _core.simulate(
        scene=scene, mu0=mu0, t_set=t_set, omega0=omega0, phi=phi, c=c,
        friction=friction, impact=impact, method=method, rtol=rtol, atol=atol,
        duration=duration, max_steps=max_steps,
        trajectory_dt=dt if trajectory else None, max_frames=max_frames,
    )
    return _walk(d)


@dataclass(frozen=True)
class Sweep:
    """Walks over a grid, one row per walk (a column each, all of the same length).

    ``chain`` (``T_set`` or ``phi``; only for :func:`sweep`), ``mu0``, ``steps`` (completed
    steps), ``status`` (``"ok"``, ``"periodic"`` or the failure's name), ``periodic``,
    ``failure`` (dicts or None) and the last step's ``T``, ``dx``, ``V``, ``p``, ``SR``
    (NaN where there is no such value: no completed step, or the passive wheel's ``p`` and
    ``SR``), ``q_plus`` and ``qd_plus`` (shape ``(rows, 4)``).
    """

    columns: Dict[str, Any] = field(default_factory=dict)

    def __getitem__(self, name: str) -> Any:
        return self.columns[name]

    def __len__(self) -> int:
        return len(self.columns["status"])

    def to_pandas(self) -> Any:
        """The rows as a pandas DataFrame (``q_plus``/``qd_plus`` split into ``x_plus``,
        ``z_plus``, ``th1_plus``, ``th2_plus``, ``xd_plus``, ... columns; ``failure`` as the
        failure's kind name or None)."""
        import pandas as pd

        return pd.DataFrame(_flat_columns(self.columns))


_Q = ("x", "z", "th1", "th2")


def _flat_columns(cols: Mapping[str, Any]) -> Dict[str, Any]:
    out: Dict[str, Any] = {}
    for k, v in cols.items():
        if k == "q_plus":
            out.update({f"{n}_plus": v[:, i] for i, n in enumerate(_Q)})
        elif k == "qd_plus":
            out.update({f"{n}d_plus": v[:, i] for i, n in enumerate(_Q)})
        elif k == "failure":
            continue
        else:
            out[k] = v
    return out


def _rows(d: Mapping[str, Any]) -> Dict[str, Any]:
    cols: Dict[str, Any] = {}
    for k in ("chain", "mu0"):
        if k in d:
            cols[k] = _arr(d[k])
    cols["steps"] = np.asarray(d["steps"], dtype=np.int64)
    cols["status"] = np.asarray(d["status"], dtype=object)
    cols["periodic"] = np.asarray(d["periodic"], dtype=bool)
    cols["failure"] = [_failure(f) for f in d["failure"]]
    for k in ("T", "dx", "V", "p", "SR"):
        cols[k] = _arr(d[k])
    cols["q_plus"] = _arr(d["q_plus"], 4)
    cols["qd_plus"] = _arr(d["qd_plus"], 4)
    return cols


def sweep(
    *,
    scene: str = "active-level",
    mu0_from: float,
    mu0_to: float,
    mu0_step: float,
    t_set: Union[float, Sequence[float], None] = None,
    phi: Union[float, Sequence[float], None] = None,
    restart: bool = False,
    c: Optional[float] = None,
    friction: Optional[str] = None,
    impact: Optional[str] = None,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    duration: float = 100.0,
    max_steps: int = 1000,
    until_periodic: Optional[float] = None,
) -> Sweep:
    """Sweep ``mu0`` from ``mu0_from`` to ``mu0_to`` by ``mu0_step``, as ``walker sweep --json``.

    Each chain (a ``t_set`` value for the active walker, a ``phi`` value for the passive wheel;
    default: the scene's) walks every ``mu0`` for ``duration`` seconds (at most ``max_steps``
    steps), starting from the previous ``mu0``'s last post-impact state (from the initial
    condition after a failure, or always with ``restart=True``). Chains run in parallel.
    ``until_periodic`` (in (0, 1)) stops a walk once its gait is periodic to that tolerance.
    At most 64 chains and 100000 points. Other arguments as in :func:`simulate`.

    Returns:
        A :class:`Sweep`, one row per (chain, mu0), chains one after another.

    Raises:
        ValueError: an argument out of its range (the message names it and the range).
        KeyboardInterrupt: Ctrl-C (seen between chunks of a few ``mu0`` values).
    """
    d = _core.sweep(
        scene=scene, mu0_from=mu0_from, mu0_to=mu0_to, mu0_step=mu0_step,
        t_set=_list(t_set), phi=_list(phi), restart=restart, c=c, friction=friction,
        impact=impact, method=method, rtol=rtol, atol=atol, duration=duration,
        max_steps=max_steps, until_periodic=until_periodic,
    )
    return Sweep(_rows(d))


def _list(x: Union[float, Sequence[float], None]) -> list:
    if x is None:
        return []
    return [float(v) for v in np.atleast_1d(np.asarray(x, dtype=np.float64))]


GRID_COLUMNS = ("mu0", "c", "t_set", "phi", "omega0")
"""The parameters a grid point may set (the columns of a grid)."""


def walk_points(
    grid: Any,
    *,
    scene: str = "active-level",
    friction: Optional[str] = None,
    impact: Optional[str] = None,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    duration: Optional[float] = 20.0,
    max_steps: int = 1000,
    until_periodic: Optional[float] = None,
) -> Sweep:
    """Walk every point of ``grid`` in this process, each as :func:`simulate` with the point's
    parameters, and return one row per point with its outcome and last step.

    Args:
        grid: a dict of equal-length arrays or a pandas DataFrame whose columns are among
            ``mu0``, ``c``, ``t_set``, ``phi``, ``omega0`` (missing ones: the scene's values).
        duration: walk each point for this long (s, > 0; None: no limit).
        Other arguments as in :func:`simulate` and :func:`sweep`.

    Every point is checked before any is walked. Points run one after another on one core
    (use :func:`slippery_walker.dask.grid_sweep` for many cores or machines).

    Raises:
        ValueError: an unknown column, columns of different lengths, or a value out of its
            range (the message names the column, the range and the row).
        KeyboardInterrupt: Ctrl-C (seen every 16 points).
    """
    cols = _grid_columns(grid)
    d = _core.walk_points(
        scene=scene, grid=cols, friction=friction, impact=impact, method=method, rtol=rtol,
        atol=atol, duration=duration, max_steps=max_steps, until_periodic=until_periodic,
    )
    rows = _rows(d)
    return Sweep({**{k: np.asarray(v, dtype=np.float64) for k, v in cols.items()}, **rows})


def _grid_columns(grid: Any) -> Dict[str, list]:
    if hasattr(grid, "to_dict") and hasattr(grid, "columns"):
        items = [(str(k), grid[k].to_numpy()) for k in grid.columns]
    elif isinstance(grid, Mapping):
        items = [(str(k), v) for k, v in grid.items()]
    else:
        raise ValueError("invalid grid: must be a dict of arrays or a pandas DataFrame")
    out: Dict[str, list] = {}
    for k, v in items:
        try:
            a = np.asarray(v, dtype=np.float64)
        except (TypeError, ValueError):
            raise ValueError(f"invalid {k}: the grid column must hold numbers") from None
        if a.ndim != 1:
            raise ValueError(f"invalid {k}: the grid column must be one-dimensional")
        out[k] = a.tolist()
    return out


@dataclass(frozen=True)
class FixedPoint:
    """The result of a fixed-point search, as ``walker fixed-point --json``.

    ``status`` is ``"converged"``, ``"family"`` (a family of cycles, multiplier 1 structural),
    ``"not-converged"``, ``"invalid-gait"`` or ``"failed"`` (with ``reason``). Where a cycle
    was found: ``state_plus`` (the post-impact state, 8 values), ``T``, ``V``, ``dx``,
    ``multipliers`` (complex, of the reduced map in ``xd+``, ``th1d+``), ``residual``,
    ``iterations``, ``failure`` (a failure of the walk on the cycle, or None). ``json`` is the
    command line's whole JSON object.
    """

    status: str
    json: Dict[str, Any]
    reason: Optional[str] = None
    state_plus: Optional[np.ndarray] = None
    T: Optional[float] = None
    V: Optional[float] = None
    dx: Optional[float] = None
    multipliers: Optional[np.ndarray] = None
    residual: Optional[float] = None
    iterations: Optional[int] = None
    failure: Optional[Dict[str, Any]] = None


def fixed_point(
    *,
    scene: str = "active-level",
    mu0: Optional[float] = None,
    t_set: Optional[float] = None,
    omega0: Optional[float] = None,
    phi: Optional[float] = None,
    c: Optional[float] = None,
    friction: Optional[str] = None,
    impact: Optional[str] = None,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
) -> FixedPoint:
    """Find the limit cycle (fixed point of the Poincare map) and its Floquet multipliers.

    ``omega0`` (> 0) is the initial angular velocity of the warm-up walk; the other arguments
    as in :func:`simulate`. A search that fails is a result (``status == "failed"``).

    Raises:
        ValueError: an argument out of its range (the message names it and the range).
    """
    j = json.loads(
        _core.fixed_point(
            scene=scene, mu0=mu0, t_set=t_set, omega0=omega0, phi=phi, c=c,
            friction=friction, impact=impact, method=method, rtol=rtol, atol=atol,
        )
    )
    if j.get("status") == "failed" and "state_plus" not in j:
        return FixedPoint(status="failed", json=j, reason=j.get("reason"))
    mult = np.array([complex(m["re"], m["im"]) for m in j.get("multipliers", [])])
    return FixedPoint(
        status=j["status"],
        json=j,
        state_plus=_arr(j["state_plus"]),
        T=j["T"],
        V=j["V"],
        dx=j["dx"],
        multipliers=mult,
        residual=j["residual"],
        iterations=j["iterations"],
        failure=j.get("failure"),
    )
