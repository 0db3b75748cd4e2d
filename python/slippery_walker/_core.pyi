"""Type stubs of the extension module ``slippery_walker._core`` (the Rust core, PyO3).

The public, documented functions are those of ``slippery_walker``; these return plain dicts
of lists that the package turns into NumPy arrays. Every argument is keyword-only.
"""

from typing import Any, Dict, List, Optional

__version__: str
MAX_STEPS: int

def simulate(
    *,
    scene: str,
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
) -> Dict[str, Any]: ...
def sweep(
    *,
    scene: str,
    mu0_from: float,
    mu0_to: float,
    mu0_step: float,
    t_set: List[float],
    phi: List[float],
    restart: bool,
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
    scene: str,
    grid: Dict[str, List[float]],
    friction: Optional[str],
    impact: Optional[str],
    method: str,
    rtol: Optional[float],
    atol: Optional[float],
    duration: Optional[float],
    max_steps: int,
    until_periodic: Optional[float],
) -> Dict[str, Any]: ...
def fixed_point(
    *,
    scene: str,
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
) -> str: ...
