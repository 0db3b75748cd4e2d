"""Limit-cycle walkers on slippery ground (Asano, Kikuchi, Shibata), with a Rust core.

Any planar walker of a model file (``models/*.toml``, ``docs/model-format.md``) runs through
one simulator; the paper's two walkers are the built-in scenes ``"active-level"`` and
``"passive-slope"``. The functions take keyword arguments with the meaning of the ``walker``
command line's flags and return NumPy arrays:

- :func:`simulate` -- one walk: per-step descriptors ``T``, ``dx``, ``V``, ``p``, ``SR``,
  ``q_plus``, ``qd_plus``; with ``trajectory=True`` also the motion at exact times.
- :func:`sweep` -- walks over a grid of one parameter (``mu0`` by default) for chains of
  ``t_set`` or ``phi``, procedures (P1a)-(P5a) and (P1b)-(P5b).
- :func:`walk_points` -- independent walks at the points of a parameter grid (one process);
  :func:`slippery_walker.dask.grid_sweep` runs the same on a Dask cluster.
- :func:`survive` -- many seeded walks on a floor whose ``mu0`` (or slope ``phi``) changes
  between steps, and how far the walker gets; :func:`survival` -- the statistics of their
  outcomes; :func:`slippery_walker.dask.survival_grid` runs batches of them on a Dask cluster;
  :func:`mfpt` -- the same time by the Markov-chain (mesh) approximation.
- :func:`fixed_point` -- the limit cycle and its Floquet multipliers.
- :func:`describe` -- a walker's parameters, state components, inputs and start.
- :func:`design` -- the run-time parameters that make the best periodic gait on a floor,
  with the friction it needs as a constraint (``walker design``).

Every function takes the walker as ``scene=`` (a built-in name or a scene file) or ``model=``
(a model file; one that is not shipped is derived when the call starts), its run-time
parameters by keyword (``mu0``, ``c``, ``t_set``, ``phi``) or by name (``set={name: value}``),
and, where a walk starts, ``omega0`` (the paper's start parameter) and ``init={name: value}``
(components of the start by name, e.g. ``{"th1d": 0.7}``).

Bad input raises :class:`ValueError` naming the argument and its valid range. A walker failure
(lift-off, falling, ...) is a result: ``status`` names it and ``failure`` holds its details.
Long runs release the GIL; sweeps and grids can be interrupted with Ctrl-C.
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from typing import Any, Dict, Iterable, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np

from . import _core

__version__: str = _core.__version__
"""The package's version (that of the Rust crate)."""

MAX_STEPS: int = _core.MAX_STEPS
"""The most steps one walk may take (``max_steps``), as the command line's ``--max-steps``."""

__all__ = [
    "FixedPoint",
    "ArgumentTypeError",
    "ModelInfo",
    "Parameter",
    "Sweep",
    "Walk",
    "__version__",
    "describe",
    "design",
    "fixed_point",
    "simulate",
    "survival",
    "survive",
    "mfpt",
    "sweep",
    "walk_points",
]

Path = Union[str, "os.PathLike[str]"]
"""A file's path: a string or a path-like object."""

Values = Optional[Mapping[str, float]]
"""Values by name (``set``, ``init``): a dict of numbers, or None for none."""


def _arr(values: Iterable[float], width: Optional[int] = None) -> np.ndarray:
    a = np.asarray(values, dtype=np.float64)
    return a if width is None else a.reshape(-1, width)


def _failure(text: Optional[str]) -> Optional[Dict[str, Any]]:
    return None if text is None else json.loads(text)


class ArgumentTypeError(TypeError, ValueError):
    """An argument of the wrong type (a string, a complex number or a bool where a number
    goes, a float where a count goes, ...): a :class:`TypeError`, and a :class:`ValueError` as
    every other bad argument, so that ``except ValueError`` catches every bad argument."""


ECHO = 80
"""The most characters of a rejected value that an error message repeats."""

MAX_NAME = 256
"""The longest name (a law, a method, a parameter, a key of ``set``/``init``, a column)."""

MAX_PATH = 4096
"""The longest file path or scene name (the usual ``PATH_MAX``)."""


def _short(v: Any) -> str:
    """``repr(v)``, cut to :data:`ECHO` characters: a megabyte argument is not echoed whole."""
    try:
        r = repr(v)
    except Exception:  # a hostile __repr__
        r = f"<{type(v).__name__}>"
    return r if len(r) <= ECHO else r[:ECHO - 3] + "..."


def _type_error(arg: str, v: Any, must_be: str) -> ArgumentTypeError:
    return ArgumentTypeError(
        f"invalid {arg}: {_short(v)} ({type(v).__name__}): must be {must_be}")


def _float(arg: str, v: Any) -> Optional[float]:
    """``v`` as a float, or None for None: a real number (not a bool, a string or a complex
    number: :class:`ArgumentTypeError`); one too large for a float64 (``10**400``) is a
    :class:`ValueError` naming ``arg``, as any other value out of range."""
    if v is None:
        return None
    if isinstance(v, (bool, np.bool_, str, bytes, complex, np.complexfloating)):
        raise _type_error(arg, v, "a real number")
    try:
        return float(v)
    except OverflowError:
        raise ValueError(f"invalid {arg}: {_short(v)}: must be finite (it is too large "
                         "for a float64)") from None
    except Exception:  # TypeError, ValueError, or whatever a hostile __float__ raises
        raise _type_error(arg, v, "a real number") from None


def _int(arg: str, v: Any, lo: int, hi: int) -> int:
    """``v`` as an int in ``[lo, hi]``: an integer (not a bool or a float)."""
    if isinstance(v, (bool, np.bool_)) or not isinstance(v, (int, np.integer)):
        raise _type_error(arg, v, "an integer")
    if not lo <= v <= hi:
        raise ValueError(f"invalid {arg}: {_short(v)}: must be in [{lo}, {hi}]")
    return int(v)


def _bool(arg: str, v: Any) -> bool:
    """``v`` as a bool: True or False only (``"False"`` is a string, not a no)."""
    if not isinstance(v, (bool, np.bool_)):
        raise _type_error(arg, v, "True or False")
    return bool(v)


def _str(arg: str, v: Any, limit: int = MAX_NAME) -> Optional[str]:
    """``v`` as a name of at most ``limit`` characters, or None for None."""
    if v is None:
        return None
    if not isinstance(v, str):
        raise _type_error(arg, v, "a string")
    if len(v) > limit:
        raise ValueError(f"invalid {arg}: {_short(v)}: {len(v)} characters; at most {limit}")
    if any(ord(ch) < 0x20 or ord(ch) == 0x7F for ch in v):
        raise ValueError(f"invalid {arg}: {_short(v)}: must not contain control characters")
    return v


def _path(arg: str, p: Optional[Path]) -> Optional[str]:
    if p is None:
        return None
    try:
        path = os.fspath(p)
    except TypeError:
        raise _type_error(arg, p, "a name or a file path") from None
    if isinstance(path, bytes):
        raise _type_error(arg, p, "a name or a file path (str)")
    return _str(arg, path, MAX_PATH)


def _pairs(arg: str, values: Values) -> List[Tuple[str, float]]:
    """``values`` as ``(name, value)`` pairs in the caller's order, each value a number."""
    if values is None:
        return []
    if not isinstance(values, Mapping):
        raise _type_error(arg, values, "a dict of names to numbers")
    out = []
    for k, v in values.items():
        if not isinstance(k, str):
            raise _type_error(arg, k, "a dict whose keys are names (str)")
        _str(arg, k)
        out.append((k, _float(f"{arg}['{k}']", v)))
    return out


def _walker(scene: Optional[Path], model: Optional[Path], set: Values) -> Dict[str, Any]:
    """The walker's keyword arguments of the core functions."""
    return dict(scene=_path("scene", scene), model=_path("model", model),
                set=_pairs("set", set))


def _options(method: Any, rtol: Any, atol: Any, friction: Any, impact: Any) -> Dict[str, Any]:
    """The integrator's and the laws' keyword arguments of the core functions, checked for
    their types."""
    return dict(method=_str("method", method), rtol=_float("rtol", rtol),
                atol=_float("atol", atol), friction=_str("friction", friction),
                impact=_str("impact", impact))


@dataclass(frozen=True)
class Walk:
    """One walk: its outcome and one row per completed step.

    ``status`` is ``"ok"`` or the failure's name (``"lift-off"``, ``"fell-backward"``, a fall
    named in the model file, ...); ``failure`` is the command line's JSON object of the failure
    as a dict (``kind``, ``step``, ``t``, ``state``, ...) or None. Per-step arrays (one row per
    step): ``T`` (s), ``dx`` (m), ``V`` (m/s), ``p`` (W) and ``SR`` (NaN for a walker without
    inputs, such as the passive wheel, or a model that does not report them), ``q_plus`` and
    ``qd_plus`` after each impact (shape ``(steps, n)`` for a model with ``n`` coordinates: 4
    for the paper's walkers, ``[x, z, th1, th2]`` and ``[xd, zd, th1d, th2d]``), and
    ``foot_impulse``, the striking foot's impulse ``[Lambda_t, Lambda_n]`` (N s) at the heel
    strike that ends each step (shape ``(steps, 2)``; ``Lambda_t = 0`` for the frictionless
    impact). ``state_names`` names the ``2 n`` state components (the coordinates, then their velocities),
    ``input_names`` the inputs. ``floor_mu0`` (a walk on ``floor=`` only, else None): each
    step's friction coefficient ``mu0`` (at its start, on a floor of patches by position);
    on a floor of patches also ``floor_mu0_strike``, the ``mu0`` of the patch each strike
    landed on, and ``floor_crossings``, how many patch boundaries each stance foot slid across
    (``docs/floors.md``).

    With ``trajectory=True``: ``times`` (s since the start of the walk, exactly ``k * dt``),
    ``states`` (shape ``(frames, 2 n)``, in the order of ``state_names``, in the stance leg's
    coordinates), ``u`` (the inputs, shape ``(frames, m)`` in the order of ``input_names``),
    ``frame_steps`` (the step of each frame), ``end_time`` (the last impact or the failure)
    and ``truncated`` (``max_frames`` was reached).
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
    foot_impulse: np.ndarray
    floor_mu0: Optional[np.ndarray] = None
    floor_mu0_strike: Optional[np.ndarray] = None
    floor_crossings: Optional[np.ndarray] = None
    times: Optional[np.ndarray] = None
    states: Optional[np.ndarray] = None
    frame_steps: Optional[np.ndarray] = None
    end_time: Optional[float] = None
    truncated: bool = False
    state_names: Tuple[str, ...] = ()
    input_names: Tuple[str, ...] = ()
    u: Optional[np.ndarray] = None

    @property
    def ok(self) -> bool:
        """True if the walk reached its limits without a failure."""
        return self.failure is None

    @property
    def steps(self) -> int:
        """The number of completed steps."""
        return len(self.T)


def _walk(d: Mapping[str, Any]) -> Walk:
    names = tuple(d["state_names"])
    inputs = tuple(d["input_names"])
    n = len(names) // 2
    extra: Dict[str, Any] = {}
    if "times" in d:
        frames = len(d["times"])
        extra = dict(
            times=_arr(d["times"]),
            states=_arr(d["states"]).reshape(frames, 2 * n),
            u=_arr(d["u"]).reshape(frames, len(inputs)),
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
        q_plus=_arr(d["q_plus"], n),
        qd_plus=_arr(d["qd_plus"], n),
        foot_impulse=_arr(d["foot_impulse"], 2),
        floor_mu0=_arr(d["floor_mu0"]) if "floor_mu0" in d else None,
        floor_mu0_strike=_arr(d["floor_mu0_strike"]) if "floor_mu0_strike" in d else None,
        floor_crossings=(
            np.asarray(d["floor_crossings"], dtype=np.int64) if "floor_crossings" in d else None
        ),
        state_names=names,
        input_names=inputs,
        **extra,
    )


def simulate(
    *,
    scene: Optional[Path] = None,
    model: Optional[Path] = None,
    set: Values = None,
    init: Values = None,
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
    floor: Optional[Floor] = None,
) -> Walk:
    """Simulate one walk, as ``walker simulate --json``.

    Args:
        scene: ``"active-level"`` (the default), ``"passive-slope"`` or the path of a scene
            ``.toml`` (a model scene, or the paper's scene format).
        model: instead of ``scene``, the path of a model file (``docs/model-format.md``) with
            its defaults; the shipped models run compiled kernels, any other file is derived
            when the call starts.
        set: any run-time parameter of the model by name, ``{"K_P": 10.0}``, applied after the
            keywords below; each checked against the range its model file gives.
        init: start from these values of coordinates or velocities instead of the model's
            start, ``{"th1d": 0.7}`` (names in :attr:`Walk.state_names`).
        mu0: friction coefficient ``mu0`` (the model's friction parameter; default: the
            scene's).
        t_set: ramp duration ``T_set`` (s; the active walker).
        omega0: initial angular velocity (rad/s; the paper's start parameter: an error for a
            model without one, which takes ``init``).
        phi: slope angle (rad; the model's slope; an error on a level floor).
        c: sharpness of the friction law ``mu = -mu0 tanh(c xd)`` (s/m).
        friction: ``"none"``, ``"tanh"`` (Eqs. 26, 37) or ``"coulomb"`` (Eq. 25); default: the
            scene's.
        impact: ``"frictionless"`` (the paper's) or ``"coulomb"``; default: the scene's.
        method: ``"dop853"`` or ``"rodas4"`` (stiff friction, large ``mu0 c``).
        rtol, atol: integrator tolerances, ``rtol`` in [2.2e-15, 1), ``atol`` in [2.2e-308, 1)
            (default 1e-10 and 1e-12; 1e-8 and 1e-10 with rodas4).
        duration: stop after the step that passes this time (s, in (0, 1e9]; default: no limit).
        max_steps: stop after this many steps (at most :data:`MAX_STEPS`).
        trajectory: also sample the motion at ``0, dt, 2 dt, ...`` from the dense output.
        dt: the interval of the trajectory's frames (s, > 0).
        max_frames: the most frames (in [1, 1000000]).
        floor: walk on a floor whose ``mu0`` changes between steps (``docs/floors.md``), as
            ``walker simulate --floor FILE``: the path of a floor file or a dict of its
            structure, ``{"kind": "steps", "mu0": [0.4, 0.05, 0.4]}``; a random floor walks its
            walk 0. Not with ``mu0`` (or the friction coefficient in ``set``), nor with
            ``trajectory``. Each step's ``mu0`` is :attr:`Walk.floor_mu0`.

    Returns:
        The :class:`Walk`; a failure is its ``status``, not an exception.

    Raises:
        ValueError: an argument out of its range (the message names it and the range; a key
            of ``set`` or ``init`` as ``set['name']``).
    """
    trajectory = _bool("trajectory", trajectory)
    dt = _float("dt", dt)
    if trajectory and not (dt is not None and dt > 0 and np.isfinite(dt)):
        raise ValueError(f"invalid dt: {_short(dt)}: must be finite and > 0")
    d = _core.simulate(
        **_walker(scene, model, set), init=_pairs("init", init), mu0=_float("mu0", mu0),
        t_set=_float("t_set", t_set), omega0=_float("omega0", omega0), phi=_float("phi", phi),
        c=_float("c", c), **_options(method, rtol, atol, friction, impact),
        duration=_float("duration", duration),
        max_steps=_int("max_steps", max_steps, 0, MAX_STEPS),
        trajectory_dt=dt if trajectory else None,
        max_frames=_int("max_frames", max_frames, 1, 1_000_000),
        floor=_floor(floor),
    )
    return _walk(d)


Floor = Union[str, "os.PathLike[str]", Mapping[str, Any]]
"""A floor (``docs/floors.md``): a floor file's path, or a dict of the file's structure."""


def _floor(floor: Any) -> Any:
    """``floor`` as the core takes it: a path as a string, a mapping as a dict (the core
    checks it with the floor file's parser), None for None."""
    if floor is None:
        return None
    if isinstance(floor, Mapping):
        return dict(floor)
    if isinstance(floor, (str, os.PathLike)):
        return _path("floor", floor)
    raise _type_error("floor", floor, "a floor file's path or a dict")


def _survive_options(
    *, floor: Any, scene: Any = None, model: Any = None, set: Any = None, init: Any = None,
    t_set: Any = None, omega0: Any = None, phi: Any = None, c: Any = None, friction: Any = None,
    impact: Any = None, method: Any = "dop853", rtol: Any = None, atol: Any = None,
) -> Dict[str, Any]:
    """The core's arguments of :func:`survive` but the counts, checked for their types."""
    return dict(
        **_walker(scene, model, set), init=_pairs("init", init), floor=_floor(floor),
        t_set=_float("t_set", t_set), omega0=_float("omega0", omega0), phi=_float("phi", phi),
        c=_float("c", c), **_options(method, rtol, atol, friction, impact))


MAX_WALK_INDEX: int = 2**63 - 1
"""The largest index a walk may have (``first_walk + walks - 1``): the largest seed."""


def survive(
    *,
    floor: Floor,
    walks: int = 100,
    max_steps: int = 1000,
    first_walk: int = 0,
    scene: Optional[Path] = None,
    model: Optional[Path] = None,
    set: Values = None,
    init: Values = None,
    t_set: Optional[float] = None,
    omega0: Optional[float] = None,
    phi: Optional[float] = None,
    c: Optional[float] = None,
    friction: Optional[str] = None,
    impact: Optional[str] = None,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
) -> Dict[str, Any]:
    """How far the walker gets on a floor, as ``walker survive --json`` (``docs/floors.md``):
    ``walks`` walks from the start, walk ``i`` on the floor's stream ``i``, each until it fails
    or completes ``max_steps`` steps, on all local cores with the GIL released (Ctrl-C raises
    :class:`KeyboardInterrupt`). The result depends only on the arguments, not on the number of
    cores or processes.

    Args:
        floor: the path of a floor file or a dict of its structure, e.g. ``{"kind": "random",
            "seed": 3, "mu0": {"distribution": "markov", "dry": 0.3, "icy": 0.05,
            "dry_length": 30, "icy_length": 1.5}}``, or with a slope per step ``"phi": {...}``
            beside or instead of ``"mu0"``; a dict gets a file's checks, and an error names its
            key (``floor['mu0']['hi']``).
        walks: the number of walks, in [1, 100000].
        max_steps: each walk's step limit, in [1, :data:`MAX_STEPS`]; ``walks * max_steps`` at
            most 1e8.
        first_walk: the first walk's index: the walks are ``first_walk`` to ``first_walk +
            walks - 1``, each on its own stream of the floor, so that the walks ``a..b`` of a
            batch are the batch with ``first_walk=a, walks=b-a`` (as ``walker survive
            --first-walk``); the last index at most :data:`MAX_WALK_INDEX`. Ranges of one
            batch, their outcomes put in walk order, give the batch's statistics by
            :func:`survival` (:func:`slippery_walker.dask.survival_grid` does this on Dask).
        scene, model, set, init, t_set, omega0, phi, c, friction, impact, method, rtol, atol:
            as :func:`simulate` (``mu0``, and ``phi`` for a floor that sets the slope, are the
            floor's; ``set`` may not give them).

    Returns:
        The command line's JSON as a dict: ``max_steps``, ``outcomes`` (a list of ``{"walk",
        "steps", "failure"}``, ``failure`` the failure's name or None at the limit) and
        ``survival`` (``walks``, ``failures``, ``censored``, ``curve``: a list of ``{"step",
        "alive", "at_risk", "failed"}`` points, ``mfpt``: ``restricted_mean``,
        ``sample_mean``, ``exponential``, ``attempts``, and ``failures_by_kind``).

    Raises:
        ValueError: an argument out of its range, or a floor the walker cannot take (named).
        TypeError: a floor (or a value in it) of a type no floor file has.
    """
    text = _core.survive(
        **_survive_options(floor=floor, scene=scene, model=model, set=set, init=init,
                           t_set=t_set, omega0=omega0, phi=phi, c=c, friction=friction,
                           impact=impact, method=method, rtol=rtol, atol=atol),
        walks=_int("walks", walks, 1, 100_000),
        max_steps=_int("max_steps", max_steps, 1, MAX_STEPS),
        first_walk=_int("first_walk", first_walk, 0, MAX_WALK_INDEX),
    )
    return json.loads(text)


def mfpt(
    *,
    floor: Floor,
    mesh: int = 17,
    samples: int = 16,
    box_scale: Optional[float] = None,
    half_widths: Optional[Sequence[float]] = None,
    walks: Optional[int] = None,
    max_steps: int = 1000,
    scene: Optional[Path] = None,
    model: Optional[Path] = None,
    set: Values = None,
    init: Values = None,
    t_set: Optional[float] = None,
    omega0: Optional[float] = None,
    phi: Optional[float] = None,
    c: Optional[float] = None,
    friction: Optional[str] = None,
    impact: Optional[str] = None,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
) -> Dict[str, Any]:
    """The mean first-passage time by the Markov-chain (mesh) approximation, as ``walker mfpt
    --json`` (``docs/floors.md``): the Poincare section meshed around the gait's fixed point,
    one step per mesh point and floor sample, the chain's second eigenvalue. Runs with the GIL
    released (Ctrl-C is raised when the mesh ends).

    Args:
        floor: as :func:`survive`: a random (or uniform) floor of friction, of slopes, or
            both (the chain carries the slope of the step before; the walks start on its
            central slope); a ``steps`` floor is refused (named).
        mesh: points per coordinate of the section, in [2, 129] (odd puts one on the fixed
            point).
        samples: floor samples of an independent distribution, in [1, 256].
        box_scale: the box as this factor times the spread of pilot walks, in (0, 100]
            (default 1.5); not with ``half_widths``.
        half_widths: the box's half-widths, one per coordinate of the section, each > 0.
        walks: also walk this many times from the fixed point (each of at most ``max_steps``
            steps) and report their statistics as ``monte_carlo``.
        max_steps: the step limit of those walks.
        scene, model, set, init, t_set, omega0, phi, c, friction, impact, method, rtol, atol:
            as :func:`survive`.

    Returns:
        The command line's JSON as a dict (``lambda2``, ``mfpt``: ``eigen`` and
        ``from_fixed_point``, None for an infinite time, ``fall_share``, ``centre``, ...), and
        with ``walks`` ``monte_carlo``: ``walks``, ``failures``, ``censored``, ``mfpt``,
        ``failures_by_kind``.

    Raises:
        ValueError: an argument out of its range, a floor the mesh cannot take, a mesh too
            large, or no gait to mesh around (named).
        TypeError: a floor (or a value in it) of a type no floor file has.
    """
    widths = None
    if half_widths is not None:
        if isinstance(half_widths, (str, bytes)) or not isinstance(half_widths, Sequence):
            raise _type_error("half_widths", half_widths, "a list of numbers")
        widths = [_float(f"half_widths[{i}]", w) for i, w in enumerate(half_widths)]
    text = _core.mfpt(
        **_survive_options(floor=floor, scene=scene, model=model, set=set, init=init,
                           t_set=t_set, omega0=omega0, phi=phi, c=c, friction=friction,
                           impact=impact, method=method, rtol=rtol, atol=atol),
        mesh=_int("mesh", mesh, 2, 129),
        samples=_int("samples", samples, 1, 256),
        box_scale=_float("box_scale", box_scale),
        half_widths=widths,
        walks=None if walks is None else _int("walks", walks, 1, 100_000),
        max_steps=_int("max_steps", max_steps, 1, MAX_STEPS),
    )
    return json.loads(text)


def survival(outcomes: Sequence[Mapping[str, Any]]) -> Dict[str, Any]:
    """The survival statistics of walks' outcomes: :func:`survive`'s ``survival`` of a batch
    with these outcomes, computed by the same library function (``walker::floor::survival``),
    so that the outcomes of a batch's ranges of walks (``first_walk``), put back in walk order,
    give exactly the whole batch's statistics.

    Args:
        outcomes: a list of :func:`survive`'s outcomes, dicts ``{"walk": index, "steps":
            completed steps, "failure": a failure's name or None}``, at least one.

    Returns:
        A dict as ``survive(...)["survival"]``: ``walks``, ``failures``, ``censored``,
        ``curve``, ``mfpt``, ``failures_by_kind``.

    Raises:
        ValueError: no outcome, or a value out of its range (named ``outcomes[i]['steps']``).
        ArgumentTypeError: an outcome that is not such a dict, or a value of the wrong type.
    """
    if isinstance(outcomes, (str, bytes, Mapping)) or not isinstance(outcomes, Sequence):
        raise _type_error("outcomes", outcomes, "a list of survive's outcomes (dicts)")
    walks: List[int] = []
    steps: List[int] = []
    failures: List[Optional[str]] = []
    for i, o in enumerate(outcomes):
        name = f"outcomes[{i}]"
        if not isinstance(o, Mapping):
            raise _type_error(name, o, "a dict with keys walk, steps, failure")
        missing = [k for k in ("walk", "steps", "failure") if k not in o]
        if missing:
            raise ValueError(f"invalid {name}: missing key {missing[0]!r}: an outcome has "
                             "walk, steps and failure")
        walks.append(_int(f"{name}['walk']", o["walk"], 0, MAX_WALK_INDEX))
        steps.append(_int(f"{name}['steps']", o["steps"], 0, MAX_STEPS))
        failures.append(_str(f"{name}['failure']", o["failure"]))
    return json.loads(_core.survival(walks=walks, steps=steps, failures=failures))


@dataclass(frozen=True)
class Sweep:
    """Walks over a grid, one row per walk (a column each, all of the same length).

    For :func:`sweep`: ``chain`` (the chain's value of ``chain_param``, ``T_set`` or the
    slope; NaN for a sweep without chains) and the swept values under the swept parameter's
    name (``param``, ``"mu0"`` by default); for :func:`walk_points`: the grid's columns. Then
    ``steps`` (completed steps), ``status`` (``"ok"``, ``"periodic"`` or the failure's name),
    ``periodic``, ``failure`` (dicts or None) and the last step's ``T``, ``dx``, ``V``, ``p``,
    ``SR`` (NaN where there is no such value: no completed step, or ``p`` and ``SR`` of a walker
    without inputs), ``q_plus`` and ``qd_plus`` (shape ``(rows, n)``, named by
    ``state_names``).
    """

    columns: Dict[str, Any] = field(default_factory=dict)
    state_names: Tuple[str, ...] = ("x", "z", "th1", "th2", "xd", "zd", "th1d", "th2d")
    param: Optional[str] = None
    chain_param: Optional[str] = None

    def __getitem__(self, name: str) -> Any:
        return self.columns[name]

    def __len__(self) -> int:
        return len(self.columns["status"])

    def to_pandas(self) -> Any:
        """The rows as a pandas DataFrame (``q_plus``/``qd_plus`` split into a column per
        state component, ``<name>_plus``: ``x_plus``, ..., ``th2d_plus`` for the paper's
        walkers; ``failure`` left out: ``status`` names it)."""
        import pandas as pd

        return pd.DataFrame(_flat_columns(self.columns, self.state_names))


def _flat_columns(cols: Mapping[str, Any], names: Sequence[str]) -> Dict[str, Any]:
    n = len(names) // 2
    out: Dict[str, Any] = {}
    for k, v in cols.items():
        if k == "q_plus":
            out.update({f"{s}_plus": v[:, i] for i, s in enumerate(names[:n])})
        elif k == "qd_plus":
            out.update({f"{s}_plus": v[:, i] for i, s in enumerate(names[n:])})
        elif k == "failure":
            continue
        else:
            out[k] = v
    return out


def _rows(d: Mapping[str, Any], first: Mapping[str, Any]) -> Sweep:
    """The :class:`Sweep` of the core's rows ``d``, after the columns ``first``."""
    names = tuple(d["state_names"])
    n = len(names) // 2
    cols: Dict[str, Any] = dict(first)
    cols["steps"] = np.asarray(d["steps"], dtype=np.int64)
    cols["status"] = np.asarray(d["status"], dtype=object)
    cols["periodic"] = np.asarray(d["periodic"], dtype=bool)
    cols["failure"] = [_failure(f) for f in d["failure"]]
    for k in ("T", "dx", "V", "p", "SR"):
        cols[k] = _arr(d[k])
    cols["q_plus"] = _arr(d["q_plus"], n)
    cols["qd_plus"] = _arr(d["qd_plus"], n)
    return Sweep(cols, state_names=names, param=d.get("param"),
                 chain_param=d.get("chain_param"))


def _alias(name: str, value: Optional[float], paper: str, paper_value: Optional[float]
           ) -> Tuple[str, float]:
    """One end or the step of a sweep's range, given as ``name`` or as its paper's name."""
    if value is not None and paper_value is not None:
        raise ValueError(f"invalid {paper}: give either {name} or {paper}, not both")
    if value is None and paper_value is None:
        raise TypeError(f"sweep() missing required keyword argument: '{name}' (or '{paper}')")
    return (name, value) if value is not None else (paper, paper_value)  # type: ignore


def sweep(
    *,
    scene: Optional[Path] = None,
    model: Optional[Path] = None,
    param: Optional[str] = None,
    from_: Optional[float] = None,
    to: Optional[float] = None,
    step: Optional[float] = None,
    mu0_from: Optional[float] = None,
    mu0_to: Optional[float] = None,
    mu0_step: Optional[float] = None,
    t_set: Union[float, Sequence[float], None] = None,
    phi: Union[float, Sequence[float], None] = None,
    restart: bool = False,
    set: Values = None,
    init: Values = None,
    omega0: Optional[float] = None,
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
    """Sweep the run-time parameter ``param`` from ``from_`` to ``to`` by ``step``, as
    ``walker sweep --json``.

    ``param`` is any run-time parameter of the model (default: its friction coefficient,
    ``mu0``); ``mu0_from``, ``mu0_to`` and ``mu0_step`` are the paper's names of ``from_``,
    ``to`` and ``step`` (either name, not both). Each chain (a ``t_set`` value or a ``phi``
    value; default: one chain at the scene's ``T_set``, else its slope) walks every value for
    ``duration`` seconds (at most ``max_steps`` steps), starting from the previous value's last
    post-impact state (from the start after a failure, or always with ``restart=True``). The
    start is the model's (``omega0``, ``init`` as in :func:`simulate`). Chains run in parallel.
    ``until_periodic`` (in (0, 1)) stops a walk once its gait is periodic to that tolerance.
    At most 64 chains and 100000 points. Other arguments as in :func:`simulate`.

    Returns:
        A :class:`Sweep`, one row per (chain, value), chains one after another; the values
        are the column named by the parameter (``s["mu0"]``).

    Raises:
        ValueError: an argument out of its range (the message names it and the range; a value
            of the range outside the parameter's range is named by the end it lies at).
        KeyboardInterrupt: Ctrl-C (seen between chunks of a few values).
    """
    names = (
        _alias("from_", from_, "mu0_from", mu0_from),
        _alias("to", to, "mu0_to", mu0_to),
        _alias("step", step, "mu0_step", mu0_step),
    )
    names = tuple((n, _float(n, v)) for n, v in names)
    duration = _float("duration", duration)
    if duration is None:
        raise _type_error("duration", duration, "a real number")
    d = _core.sweep(
        **_walker(scene, model, set), init=_pairs("init", init), param=_str("param", param),
        from_=names[0][1], to=names[1][1], step=names[2][1],
        range_names=tuple(n for n, _ in names),
        t_set=_list("t_set", t_set), phi=_list("phi", phi), restart=_bool("restart", restart),
        omega0=_float("omega0", omega0), c=_float("c", c),
        **_options(method, rtol, atol, friction, impact),
        duration=duration, max_steps=_int("max_steps", max_steps, 0, MAX_STEPS),
        until_periodic=_float("until_periodic", until_periodic),
    )
    return _rows(d, {"chain": _arr(d["chain"]), d["param"]: _arr(d["value"])})


MAX_CHAINS = 64
"""The most chains of a sweep (``t_set`` or ``phi`` values)."""


def _list(arg: str, x: Union[float, Sequence[float], None]) -> list:
    """A number or a sequence of numbers as a list of floats (at most :data:`MAX_CHAINS`)."""
    if x is None:
        return []
    if isinstance(x, (str, bytes, Mapping)):
        raise _type_error(arg, x, "a number or a sequence of numbers")
    items = list(x) if isinstance(x, (Sequence, np.ndarray)) else [x]
    if len(items) > MAX_CHAINS:
        raise ValueError(f"invalid {arg}: {len(items)} values: at most {MAX_CHAINS} chains")
    if any(v is None for v in items):
        raise _type_error(arg, x, "a number or a sequence of numbers (not None)")
    return [_float(arg, v) for v in items]


GRID_COLUMNS = ("mu0", "c", "t_set", "phi", "omega0")
"""The keyword columns of a grid (besides any parameter of the model by its name)."""


def walk_points(
    grid: Any,
    *,
    scene: Optional[Path] = None,
    model: Optional[Path] = None,
    set: Values = None,
    init: Values = None,
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
        grid: a dict of equal-length arrays or a pandas DataFrame whose columns are keywords
            of :func:`simulate` (``mu0``, ``c``, ``t_set``, ``phi``, ``omega0``) or the names
            of any parameters of the model (``K_P``, ``m1``, ...); missing ones: the scene's
            values, or those of ``set``.
        set: values for every point, applied before the point's own.
        init: the start of every point, as in :func:`simulate`.
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
    d = _core.walk_points(**_grid_options(cols, scene=scene, model=model, set=set, init=init,
                                          friction=friction, impact=impact, method=method,
                                          rtol=rtol, atol=atol, duration=duration,
                                          max_steps=max_steps, until_periodic=until_periodic))
    return _rows(d, dict(cols))


def _grid_options(cols: Mapping[str, np.ndarray], *, scene: Any, model: Any, set: Any,
                  init: Any, friction: Any, impact: Any, method: Any, rtol: Any, atol: Any,
                  duration: Any, max_steps: Any, until_periodic: Any,
                  check_only: bool = False) -> Dict[str, Any]:
    """The core's arguments of a grid: its columns as bytes of float64 (8 bytes a value, not
    a Python float each), the others checked for their types."""
    return dict(
        **_walker(scene, model, set), init=_pairs("init", init),
        grid=[(k, np.ascontiguousarray(v, dtype=np.float64).tobytes()) for k, v in cols.items()],
        **_options(method, rtol, atol, friction, impact), duration=_float("duration", duration),
        max_steps=_int("max_steps", max_steps, 0, MAX_STEPS),
        until_periodic=_float("until_periodic", until_periodic), check_only=check_only)


def _grid_columns(grid: Any) -> Dict[str, np.ndarray]:
    """The grid's columns as one-dimensional float64 arrays (the caller's own where they are
    such already: a large grid is not copied into Python floats)."""
    if hasattr(grid, "to_dict") and hasattr(grid, "columns"):
        if len(set(map(str, grid.columns))) != len(grid.columns):
            raise ValueError("invalid grid: two columns have the same name")
        items = [(str(k), grid[k].to_numpy()) for k in grid.columns]
    elif isinstance(grid, Mapping):
        items = [(k, v) for k, v in grid.items()]
    else:
        raise _type_error("grid", grid, "a dict of arrays or a pandas DataFrame")
    out: Dict[str, np.ndarray] = {}
    for k, v in items:
        if not isinstance(k, str):
            raise _type_error("grid", k, "a dict whose keys are column names (str)")
        k = _str("grid", k)
        if isinstance(v, (str, bytes)):
            raise _type_error(k, v, "a column of numbers")
        try:
            a = np.asarray(v)
            if a.dtype.kind in "cbUSOVMm" and a.dtype != object:
                raise _type_error(k, v, "a column of real numbers")
            if a.dtype == object:
                a = np.array([_float(k, x) for x in a.ravel()], dtype=np.float64).reshape(a.shape)
            a = a.astype(np.float64, copy=False)
        except Exception as e:  # including what a hostile element's __float__ raises
            if isinstance(e, ValueError) and str(e).startswith("invalid "):
                raise
            raise _type_error(k, v, "a column of real numbers") from None
        if a.ndim != 1:
            raise ValueError(f"invalid {k}: the grid column must be one-dimensional")
        out[k] = a
    return out


@dataclass(frozen=True)
class FixedPoint:
    """The result of a fixed-point search, as ``walker fixed-point --json``.

    ``status`` is ``"converged"``, ``"family"`` (a family of cycles, multiplier 1 structural),
    ``"not-converged"``, ``"invalid-gait"`` or ``"failed"`` (with ``reason``). Where a cycle
    was found: ``state_plus`` (the post-impact state, ``2 n`` values named by
    ``state_names``), ``T``, ``V``, ``dx``, ``multipliers`` (complex, of the map reduced to the
    Poincare section's free coordinates, named by ``section``: ``("xd", "th1d")`` for the
    paper's walkers), ``multiplier_errors`` (each multiplier's error bound, in the same order;
    None for a multiplier that is not simple; ``docs/poincare.md``), ``residual``,
    ``iterations``, ``failure`` (the name of a failure of the walk on the cycle, or None).
    ``json`` is the command line's whole JSON object.
    ``sensitivities`` (where asked for) maps each parameter to ``walker fixed-point
    --sensitivities``'s object: ``d_state`` (by section coordinate), ``dT``, ``dV``, ``d_dx``
    (each ``{"value", "error"}``), ``d_multipliers`` (``{"re", "im", "error"}`` or None),
    ``map_d_state``, ``map_dT``, ``value``, ``step``; if they could not be computed,
    ``json["sensitivities_error"]`` says why.
    """

    status: str
    json: Dict[str, Any]
    reason: Optional[str] = None
    state_plus: Optional[np.ndarray] = None
    T: Optional[float] = None
    V: Optional[float] = None
    dx: Optional[float] = None
    multipliers: Optional[np.ndarray] = None
    multiplier_errors: Tuple[Optional[float], ...] = ()
    residual: Optional[float] = None
    iterations: Optional[int] = None
    failure: Optional[Dict[str, Any]] = None
    section: Tuple[str, ...] = ()
    state_names: Tuple[str, ...] = ()
    sensitivities: Optional[Dict[str, Any]] = None


def fixed_point(
    *,
    scene: Optional[Path] = None,
    model: Optional[Path] = None,
    set: Values = None,
    init: Values = None,
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
    sensitivities: Optional[Sequence[str]] = None,
) -> FixedPoint:
    """Find the limit cycle (fixed point of the Poincare map) and its Floquet multipliers.

    The search starts with a warm-up walk from the model's start: ``omega0`` (> 0; the
    paper's walkers) and ``init`` change it as in :func:`simulate`; the other arguments as in
    :func:`simulate`. A search that fails is a result (``status == "failed"``).
    ``sensitivities`` (run-time parameter names, ``["mu0", "T_set"]``) adds the gait's
    derivatives in them with error estimates (:class:`FixedPoint`; ``docs/poincare.md``).

    Raises:
        ValueError: an argument out of its range (the message names it and the range), or a
            name in ``sensitivities`` that is not a run-time parameter (with the valid names).
    """
    if sensitivities is None:
        wanted: List[str] = []
    elif isinstance(sensitivities, (str, bytes)) or not isinstance(sensitivities, Sequence):
        raise _type_error("sensitivities", sensitivities, "a list of parameter names (str)")
    else:
        wanted = []
        for name in sensitivities:
            if not isinstance(name, str):
                raise _type_error("sensitivities", name, "a list of parameter names (str)")
            wanted.append(name)
    text, names = _core.fixed_point(
        **_walker(scene, model, set), init=_pairs("init", init), mu0=_float("mu0", mu0),
        t_set=_float("t_set", t_set), omega0=_float("omega0", omega0), phi=_float("phi", phi),
        c=_float("c", c), **_options(method, rtol, atol, friction, impact),
        sensitivities=wanted,
    )
    j = json.loads(text)
    names = tuple(names)
    if j.get("status") == "failed" and "state_plus" not in j:
        return FixedPoint(status="failed", json=j, state_names=names, reason=j.get("reason"))
    mult = np.array([complex(m["re"], m["im"]) for m in j.get("multipliers", [])])
    return FixedPoint(
        status=j["status"],
        json=j,
        state_names=names,
        state_plus=_arr(j["state_plus"]),
        T=j["T"],
        V=j["V"],
        dx=j["dx"],
        multipliers=mult,
        multiplier_errors=tuple(j.get("multiplier_errors", ())),
        section=tuple(j["section"]),
        residual=j["residual"],
        iterations=j["iterations"],
        failure=j.get("failure"),
        sensitivities=j.get("sensitivities"),
    )


@dataclass(frozen=True)
class Parameter:
    """A parameter of a model: its value, ``unit``, valid ``range`` (as its model file writes
    it, ``"(0, inf)"``), ``doc``, and whether it belongs to the ``start`` (the paper's
    ``omega0``) rather than the dynamics."""

    value: float
    unit: str
    range: str
    doc: str
    start: bool


@dataclass(frozen=True)
class ModelInfo:
    """A walker as :func:`describe` reports it: its ``model`` (name) and ``title``, the
    ``scene``'s name, its ``friction`` and ``impact`` laws, its ``parameters`` by name (in the
    model file's order, with the values of the scene and ``set``), ``state_names`` (what
    ``init`` takes), ``input_names`` and ``start`` (the state a walk starts from)."""

    model: str
    scene: str
    title: Optional[str]
    friction: str
    impact: str
    parameters: Dict[str, Parameter]
    state_names: Tuple[str, ...]
    input_names: Tuple[str, ...]
    start: np.ndarray


def describe(
    *,
    scene: Optional[Path] = None,
    model: Optional[Path] = None,
    set: Values = None,
    friction: Optional[str] = None,
    impact: Optional[str] = None,
) -> ModelInfo:
    """What a scene or a model file offers: its parameters (the names ``set``, a sweep's
    ``param`` and a grid's columns take), its state components (the names ``init`` takes),
    its inputs and its start. Arguments as in :func:`simulate`.

    Raises:
        ValueError: a bad argument (the message names it).
    """
    d = _core.describe(**_walker(scene, model, set), friction=_str("friction", friction),
                       impact=_str("impact", impact))
    return ModelInfo(
        model=d["model"],
        scene=d["scene"],
        title=d["title"],
        friction=d["friction"],
        impact=d["impact"],
        parameters={name: Parameter(value, unit, rng, doc, start)
                    for name, value, unit, rng, doc, start in d["parameters"]},
        state_names=tuple(d["state_names"]),
        input_names=tuple(d["input_names"]),
        start=_arr(d["start"]),
    )


OBJECTIVES = ("specific_resistance", "power", "friction", "speed")
"""The objectives of :func:`design` (``walker design --objective``)."""


def _vary(vary: Any) -> List[Tuple[str, float, float, Optional[float]]]:
    """``{name: (lo, hi)}`` or ``{name: (lo, hi, start)}`` as ``(name, lo, hi, start)``."""
    if not isinstance(vary, Mapping) or not vary:
        raise _type_error("vary", vary, "a non-empty dict of names to (lo, hi) or (lo, hi, start)")
    out = []
    for k, v in vary.items():
        if not isinstance(k, str):
            raise _type_error("vary", k, "a dict whose keys are parameter names (str)")
        _str("vary", k)
        arg = f"vary['{k}']"
        if isinstance(v, (str, bytes, Mapping)) or not isinstance(v, (Sequence, np.ndarray)) \
                or len(v) not in (2, 3):
            raise _type_error(arg, v, "(lo, hi) or (lo, hi, start), numbers")
        lo, hi = _float(arg, v[0]), _float(arg, v[1])
        start = _float(arg, v[2]) if len(v) == 3 else None
        out.append((k, lo, hi, start))
    return out


def design(
    *,
    vary: Mapping[str, Sequence[float]],
    scene: Optional[Path] = None,
    model: Optional[Path] = None,
    set: Values = None,
    friction: Optional[str] = None,
    impact: Optional[str] = None,
    method: str = "dop853",
    rtol: Optional[float] = None,
    atol: Optional[float] = None,
    objective: str = "specific_resistance",
    multiplier_margin: float = 0.05,
    friction_margin: float = 0.01,
    normal_margin: float = 0.0,
    ramp_margin: float = 0.01,
    max_input: Union[float, Sequence[float], None] = None,
    clearance: Optional[float] = None,
    min_speed: Optional[float] = None,
    max_speed: Optional[float] = None,
    max_power: Optional[float] = None,
    max_evaluations: int = 100,
    tol: float = 1e-10,
    restarts: int = 0,
    seed: int = 0,
) -> Dict[str, Any]:
    """Design a gait: the run-time parameters ``vary`` (``{name: (lo, hi)}`` or ``{name:
    (lo, hi, start)}``; the start defaults to the model's value) within their bounds that
    minimise ``objective`` (one of :data:`OBJECTIVES`) of the periodic gait, subject to its
    multipliers ``<= 1 - multiplier_margin``, the friction it needs ``<= mu0 -
    friction_margin`` (stance and strike), the normal force ``>= normal_margin``, the strike
    ``ramp_margin`` (s) after the desired trajectories' ramps end, and with ``max_input`` (one
    bound for every input or one per input) ``max |u_i| <= U_i`` along the stance; with
    ``clearance`` (m) the swing foot's height above the floor ``>= clearance * 4 s (1 - s)``
    at every stance sample (``s = t / T``); with ``min_speed`` (m/s) the mean speed ``V >=
    min_speed``, with ``max_speed`` ``V <= max_speed`` (both equal: a gait at that speed); with
    ``max_power`` (W) the mean input power ``p <= max_power`` (the effort
    bound the ``speed`` objective, which maximises ``V``, needs on an actuated walker). As
    ``walker design`` (``docs/design.md``); the other arguments as in :func:`simulate`.

    Returns the command line's JSON (``walker design --json``) as a dict: ``status``
    (``optimal``, ``feasible`` or ``infeasible`` with ``violated`` naming the constraint),
    ``value``, ``parameters``, ``gait``, ``constraints`` (each with its ``slack``),
    ``kkt_residual``, ``evaluations`` (and ``restarts`` with ``restarts > 0``); or ``{"status":
    "failed", "reason"}`` where the start has no periodic gait.

    Raises:
        ValueError: a bad argument (the message names it and its valid range).
    """
    text = _core.design(
        **_walker(scene, model, set), **_options(method, rtol, atol, friction, impact),
        vary=_vary(vary), objective=_str("objective", objective),
        multiplier_margin=_float("multiplier_margin", multiplier_margin),
        friction_margin=_float("friction_margin", friction_margin),
        normal_margin=_float("normal_margin", normal_margin),
        ramp_margin=_float("ramp_margin", ramp_margin),
        max_input=_list("max_input", max_input),
        clearance=_float("clearance", clearance),
        min_speed=_float("min_speed", min_speed),
        max_speed=_float("max_speed", max_speed),
        max_power=_float("max_power", max_power),
        max_evaluations=_int("max_evaluations", max_evaluations, 1, 10_000),
        tol=_float("tol", tol), restarts=_int("restarts", restarts, 0, 100),
        seed=_int("seed", seed, 0, 2**64 - 1),
    )
    result: Dict[str, Any] = json.loads(text)
    return result
