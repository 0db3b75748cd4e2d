"""Type stubs of the extension module ``slippery_walker._core`` (the Rust core, PyO3).

The public, documented functions are those of ``slippery_walker``; these return plain dicts
of lists that the package turns into NumPy arrays. Every argument is keyword-only. ``set`` and
``init`` are ``(name, value)`` pairs in the caller's order; ``scene`` and ``model`` are paths
or names (at most one of them; neither: the scene ``active-level``).
"""

from typing import Any, Dict, List, Optional, Tuple

__version__: str
MAX_STEPS: int

def simulate(
    *,
    scene: Optional[str],
    model: Optional[str],
    set: List[Tuple[str, float]],
    init: List[Tuple[str, float]],
    mu0: Optional[float],
    t_set: Optional[float],
    omega0: Optional[float],
    phi: Optional[float],
    c: Optional[float],
    friction: Optional[str],
    impact: Optional[str],
    method: str,
    rtol: Optional[float],
    atol: Optional[float],
    duration: Optional[float],
    max_steps: int,
    trajectory_dt: Optional[float],
    max_frames: int,
    floor: Optional[Any] = ...,
) -> Dict[str, Any]: ...
def sweep(
    *,
    scene: Optional[str],
    model: Optional[str],
    set: List[Tuple[str, float]],
    init: List[Tuple[str, float]],
    param: Optional[str],
    from_: float,
    to: float,
    step: float,
    range_names: Tuple[str, str, str],
    t_set: List[float],
    phi: List[float],
    restart: bool,
    omega0: Optional[float],
    c: Optional[float],
    friction: Optional[str],
    impact: Optional[str],
    method: str,
    rtol: Optional[float],
    atol: Optional[float],
    duration: float,
    max_steps: int,
    until_periodic: Optional[float],
) -> Dict[str, Any]: ...
def walk_points(
    *,
    scene: Optional[str],
    model: Optional[str],
    set: List[Tuple[str, float]],
    init: List[Tuple[str, float]],
    grid: List[Tuple[str, bytes]],
    friction: Optional[str],
    impact: Optional[str],
    method: str,
    rtol: Optional[float],
    atol: Optional[float],
    duration: Optional[float],
    max_steps: int,
    until_periodic: Optional[float],
    check_only: bool = ...,
) -> Dict[str, Any]: ...
def fixed_point(
    *,
    scene: Optional[str],
    model: Optional[str],
    set: List[Tuple[str, float]],
    init: List[Tuple[str, float]],
    mu0: Optional[float],
    t_set: Optional[float],
    omega0: Optional[float],
    phi: Optional[float],
    c: Optional[float],
    friction: Optional[str],
    impact: Optional[str],
    method: str,
    rtol: Optional[float],
    atol: Optional[float],
    sensitivities: List[str],
) -> Tuple[str, List[str]]: ...
def describe(
    *,
    scene: Optional[str],
    model: Optional[str],
    set: List[Tuple[str, float]],
    friction: Optional[str],
    impact: Optional[str],
) -> Dict[str, Any]: ...
def survive(
    *,
    scene: Optional[str],
    model: Optional[str],
    set: List[Tuple[str, float]],
    init: List[Tuple[str, float]],
    floor: Any,
    t_set: Optional[float],
    omega0: Optional[float],
    phi: Optional[float],
    c: Optional[float],
    friction: Optional[str],
    impact: Optional[str],
    method: str,
    rtol: Optional[float],
    atol: Optional[float],
    walks: int,
    max_steps: int,
    first_walk: int = ...,
    threads: Optional[int] = ...,
    check_only: bool = ...,
) -> str: ...
def survival(
    *,
    walks: List[int],
    steps: List[int],
    failures: List[Optional[str]],
) -> str: ...
