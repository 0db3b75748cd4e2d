"""Adversarial calls of the module, made by a seeded generator (run by ``test_adversarial.py`` in
a child process, so that a crash or a hang is seen as such and not taken for a result).

Each case is a valid, quick call with one argument replaced by a hostile value: a wrong type,
a huge, non-finite or complex number, a huge string, an adversarial file (a FIFO, ``/dev/zero``,
a file above the size limit, a directory, a missing file, binary garbage), a conflicting alias,
or a big grid. The child prints one JSON line per call: the case, what it raised (or ``ok``),
the message and the seconds it took; the parent checks every line.

Usage: ``python fuzz_calls.py SEED COUNT DIR`` (``DIR``: a scratch directory for the files).
"""

from __future__ import annotations

import json
import math
import os
import random
import sys
import time
from typing import Any, Callable, Dict, List, Tuple

import numpy as np
import slippery_walker as sw

MODELS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "models")
COMPASS = os.path.join(MODELS, "compass-gait.toml")


class Hostile:
    """An object whose conversions and repr fail or lie."""

    def __float__(self) -> float:
        raise RuntimeError("no float here")

    def __repr__(self) -> str:
        return "Hostile()"


def files(scratch: str) -> Dict[str, str]:
    """The adversarial files, made in `scratch`."""
    out = {}
    fifo = os.path.join(scratch, "fifo.toml")
    if not os.path.exists(fifo):
        os.mkfifo(fifo)
    out["fifo"] = fifo
    zero = os.path.join(scratch, "zero.toml")
    if not os.path.lexists(zero):
        os.symlink("/dev/zero", zero)
    out["dev-zero-link"] = zero
    out["dev-zero"] = "/dev/zero"
    huge = os.path.join(scratch, "huge.toml")
    with open(huge, "w") as f:
        f.write("# padding\n" * 300_000)  # 3 MB, above the 1 MiB limit
    out["huge"] = huge
    out["directory"] = scratch
    out["missing"] = os.path.join(scratch, "missing.toml")
    garbage = os.path.join(scratch, "garbage.toml")
    with open(garbage, "wb") as f:
        f.write(bytes(random.Random(7).randrange(256) for _ in range(4096)))
    out["garbage"] = garbage
    empty = os.path.join(scratch, "empty.toml")
    open(empty, "w").close()
    out["empty"] = empty
    return out


NUMBERS: List[Tuple[str, Any]] = [
    ("nan", math.nan), ("inf", math.inf), ("-inf", -math.inf), ("1e308", 1e308),
    ("-1e308", -1e308), ("10**400", 10**400), ("-10**400", -10**400), ("0", 0.0),
    ("-1", -1.0), ("1e-320", 1e-320), ("complex", 1 + 2j), ("np.complex", np.complex128(0.3)),
    ("str", "0.3"), ("str-False", "False"), ("bytes", b"0.3"), ("bool", True),
    ("list", [0.3]), ("dict", {"a": 1}), ("object", object()), ("hostile", Hostile()),
    ("np.float32", np.float32(0.3)), ("np.nan32", np.float32("nan")),
    ("megabyte-str", "x" * 1_000_000), ("control-str", "a\x1b[31m\x00b"),
]
COUNTS: List[Tuple[str, Any]] = [
    ("float", 3.0), ("10**400", 10**400), ("-10**30", -10**30), ("str", "3"), ("bool", True),
    ("complex", 3j), ("nan", math.nan), ("np.int64", np.int64(3)), ("none", None),
]
NAMES: List[Tuple[str, Any]] = [
    ("unknown", "dry"), ("megabyte", "x" * 1_000_000), ("control", "co\x1bulomb\x00"),
    ("int", 3), ("bytes", b"tanh"), ("empty", ""), ("list", ["tanh"]),
]
BOOLS: List[Tuple[str, Any]] = [
    ("str-False", "False"), ("int", 0), ("float", 1.0), ("none", None), ("list", [True]),
]


def cases(rng: random.Random, scratch: str, count: int) -> List[Tuple[str, str, str, Callable[[], Any]]]:
    """`count` cases: (function, argument, value's label, call)."""
    fs = files(scratch)
    quick = dict(max_steps=3)
    base: Dict[str, Tuple[Callable[..., Any], Dict[str, Any]]] = {
        "simulate": (sw.simulate, dict(quick)),
        "sweep": (sw.sweep, dict(from_=0.3, to=0.4, step=0.1, duration=2.0, max_steps=3)),
        "walk_points": (lambda **kw: sw.walk_points(kw.pop("grid", {"mu0": [0.3, 0.4]}), **kw),
                        dict(duration=2.0, max_steps=3)),
        "fixed_point": (sw.fixed_point, {}),
        "describe": (sw.describe, {}),
    }
    numeric = {
        "simulate": ["mu0", "t_set", "omega0", "c", "rtol", "atol", "duration", "dt"],
        "sweep": ["from_", "to", "step", "mu0_from", "c", "duration", "until_periodic",
                  "t_set", "omega0"],
        "walk_points": ["duration", "rtol", "until_periodic"],
        "fixed_point": ["mu0", "t_set", "omega0", "c", "rtol"],
        "describe": [],
    }
    counted = {"simulate": ["max_steps", "max_frames"], "sweep": ["max_steps"],
               "walk_points": ["max_steps"]}
    named = {"simulate": ["friction", "impact", "method"], "sweep": ["friction", "param"],
             "walk_points": ["impact", "method"], "fixed_point": ["method"],
             "describe": ["friction", "impact"]}
    booleans = {"simulate": ["trajectory"], "sweep": ["restart"]}

    def make(fn: str, arg: str, value: Any, extra: Dict[str, Any] = None):
        f, kw = base[fn]
        kw = {**kw, **(extra or {})}
        if arg == "mu0_from":
            kw.pop("from_")
        kw[arg] = value
        return lambda: f(**kw)

    out = []
    kinds = ["number", "count", "name", "bool", "file", "set", "init", "grid", "alias"]
    while len(out) < count:
        fn = rng.choice(sorted(base))
        kind = rng.choice(kinds)
        if kind == "number" and numeric[fn]:
            arg = rng.choice(numeric[fn])
            label, v = rng.choice(NUMBERS)
            extra = {"trajectory": True} if arg == "dt" else None
            out.append((fn, arg, label, make(fn, arg, v, extra)))
        elif kind == "count" and fn in counted:
            arg = rng.choice(counted[fn])
            label, v = rng.choice(COUNTS)
            extra = {"trajectory": True} if arg == "max_frames" else None
            out.append((fn, arg, label, make(fn, arg, v, extra)))
        elif kind == "name":
            arg = rng.choice(named[fn])
            label, v = rng.choice(NAMES)
            out.append((fn, arg, label, make(fn, arg, v)))
        elif kind == "bool" and fn in booleans:
            arg = rng.choice(booleans[fn])
            label, v = rng.choice(BOOLS)
            out.append((fn, arg, label, make(fn, arg, v)))
        elif kind == "file":
            arg = rng.choice(["model", "scene"])
            label = rng.choice(sorted(fs))
            out.append((fn, arg, label, make(fn, arg, fs[label])))
        elif kind in ("set", "init") and not (kind == "init" and fn == "describe"):
            label, v = rng.choice(NUMBERS + [("unknown-key", "unknown-key"),
                                             ("long-key", "long-key"), ("not-a-dict", None)])
            if label == "unknown-key":
                value: Any = {"gravity\x1b": 9.8}
            elif label == "long-key":
                value = {"k" * 100_000: 1.0}
            elif label == "not-a-dict":
                value = [("T_set", 0.3)]
            else:
                value = {"T_set" if kind == "set" else "th1d": v}
            out.append((fn, kind, label, make(fn, kind, value)))
        elif kind == "grid" and fn == "walk_points":
            label, v = rng.choice(NUMBERS)
            choices = {
                "value": {"mu0": [0.3, v]},
                "ragged": {"mu0": [0.3, 0.4], "c": [10.0]},
                "2d": {"mu0": [[0.3, 0.4]]},
                "unknown": {"gravity\x1b" * 1000: [0.3]},
                "not-a-dict": [0.3, 0.4],
                "big-invalid": {"mu0": np.full(200_000, -1.0)},
            }
            which = rng.choice(sorted(choices))
            out.append((fn, "grid", f"{which}:{label}", make(fn, "grid", choices[which])))
        elif kind == "alias":
            if fn == "sweep":
                which = rng.choice(["param-chain", "range-twice"])
                extra = ({"param": "T_set", "t_set": [0.3, 0.5]} if which == "param-chain"
                         else {"mu0_to": 0.4})
                arg = "t_set" if which == "param-chain" else "mu0_to"
                out.append((fn, arg, which, make(fn, arg, extra[arg], extra)))
            elif fn == "walk_points":
                out.append((fn, "grid", "t_set-and-T_set",
                            make(fn, "grid", {"t_set": [0.3], "T_set": [0.5]})))
            elif fn in ("simulate", "fixed_point"):
                out.append((fn, "set", "keyword-and-set",
                            make(fn, "set", {"T_set": 0.4}, {"t_set": 0.3})))
    return out


def main() -> None:
    seed, count, scratch = int(sys.argv[1]), int(sys.argv[2]), sys.argv[3]
    rng = random.Random(seed)
    for i, (fn, arg, label, call) in enumerate(cases(rng, scratch, count)):
        print(json.dumps({"i": i, "fn": fn, "arg": arg, "label": label, "start": True}),
              flush=True)
        start = time.monotonic()
        try:
            call()
            outcome, message = "ok", ""
        except (ValueError, TypeError) as e:
            outcome = "ValueError" if isinstance(e, ValueError) else "TypeError"
            message = str(e)
        except BaseException as e:  # anything else is a finding, reported to the parent
            outcome, message = type(e).__name__, str(e)[:2000]
        took = time.monotonic() - start
        print(json.dumps({"i": i, "fn": fn, "arg": arg, "label": label, "outcome": outcome,
                          "message": message[:2000], "message_len": len(message),
                          "seconds": took}), flush=True)


if __name__ == "__main__":
    main()
    # The child's peak resident set (Linux: kilobytes), for the parent's memory bound.
    import resource
    print(json.dumps({"peak_rss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss}),
          flush=True)
