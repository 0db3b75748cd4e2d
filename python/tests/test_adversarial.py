"""A few hundred adversarial calls (``fuzz_calls.py``, seeded), in a child process so that a
crash or a hang is seen: every call returns a result or raises ValueError/TypeError whose
message names the argument that was made bad, echoes at most a short piece of it, holds no
control character, and comes within a time bound; the child neither crashes nor hangs.
The failing inputs found by the generator are kept below as regression tests."""

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import slippery_walker as sw

HERE = Path(__file__).resolve().parent

SEED = 35
CALLS = 300

# A call walks at most 3 steps or derives nothing (shipped models only), so it takes
# milliseconds; 5 s per call allows for a loaded 2-core machine while a hang (a FIFO read, a
# read of /dev/zero) or work without bound is far beyond it. The whole child: 300 calls at the
# bound would be 25 min, so 120 s is the budget for the suite's "under a minute" plus load.
PER_CALL_SECONDS = 5.0
CHILD_SECONDS = 120.0

# The child's peak resident set: the interpreter, NumPy and the module take of the order of
# 100 MB; every call walks at most 3 steps or is refused before any work, and a grid streams,
# so nothing grows with the calls. 1 GiB is far above that and far below what a file read
# without bound (/dev/zero) or a grid built whole (a million points took 2 GB) would take.
MAX_RSS_KB = 1 << 20

# An error message repeats at most ~80 characters of a value; with the argument's name, its
# valid range and a list of a model's names it stays well under this.
MAX_MESSAGE = 1500


RANGE = ("from_", "to", "step", "mu0_from", "mu0_to", "mu0_step")


def named(arg: str, message: str) -> bool:
    """Whether `message` names `arg` (a key of set/init as set['k'], a grid by a column)."""
    if arg == "grid":
        return message.startswith("invalid ")
    if arg in RANGE:
        # The three values of a sweep's range decide its number of points together: a huge
        # `to` may be reported as the `step` that would give too many points.
        return any(message.startswith(f"invalid {a}:") for a in RANGE)
    return message.startswith(f"invalid {arg}:") or message.startswith(f"invalid {arg}[")


@pytest.fixture(scope="module")
def child(tmp_path_factory):
    """The child's records, one per call, and its peak resident set (kilobytes)."""
    scratch = tmp_path_factory.mktemp("fuzz")
    env = dict(os.environ)
    run = subprocess.run(
        [sys.executable, str(HERE / "fuzz_calls.py"), str(SEED), str(CALLS), str(scratch)],
        capture_output=True, text=True, timeout=CHILD_SECONDS, env=env, cwd=HERE,
    )
    lines = [json.loads(line) for line in run.stdout.splitlines() if line.startswith("{")]
    peaks = [r["peak_rss_kb"] for r in lines if "peak_rss_kb" in r]
    lines = [r for r in lines if "peak_rss_kb" not in r]
    started = [r for r in lines if r.get("start")]
    done = [r for r in lines if not r.get("start")]
    assert run.returncode == 0, (f"the child ended with {run.returncode} during "
                                 f"{started[-1] if started else None}: {run.stderr[-2000:]}")
    assert len(done) == CALLS
    assert len(peaks) == 1, "the child reports its peak resident set once, at its end"
    return done, peaks[0]


@pytest.fixture(scope="module")
def records(child):
    return child[0]


def test_the_calls_stay_within_a_memory_bound(child):
    peak = child[1]
    assert peak <= MAX_RSS_KB, f"the child held {peak // 1024} MiB at its peak"


def test_every_adversarial_call_returns_or_raises_a_named_error(records):
    bad = [r for r in records
           if r["outcome"] not in ("ok", "ValueError", "TypeError")
           or (r["outcome"] != "ok" and not named(r["arg"], r["message"]))]
    assert not bad, bad[:5]


def test_no_adversarial_call_takes_long(records):
    slow = [r for r in records if r["seconds"] > PER_CALL_SECONDS]
    assert not slow, slow[:5]


def test_no_message_echoes_a_long_value_or_a_control_character(records):
    long = [r for r in records if r["message_len"] > MAX_MESSAGE]
    assert not long, [(r["fn"], r["arg"], r["label"], r["message_len"]) for r in long[:5]]
    # A newline is allowed: a TOML error shows the line and a caret under the column.
    control = [r for r in records if any(ord(ch) < 0x20 and ch != "\n" for ch in r["message"])]
    assert not control, control[:5]


def test_the_generator_reaches_every_kind_of_argument(records):
    args = {r["arg"] for r in records}
    for arg in ("model", "scene", "set", "init", "grid", "max_steps", "friction", "duration"):
        assert arg in args, sorted(args)
    assert sum(r["outcome"] != "ok" for r in records) > CALLS // 2


# Regression tests: inputs issue 35 and the generator found, each with what it now gets.

def test_a_number_too_large_for_a_float_is_a_value_error_naming_it():
    with pytest.raises(ValueError, match=r"^invalid mu0: 1000000.*: must be finite"):
        sw.simulate(mu0=10**400)
    with pytest.raises(ValueError, match=r"^invalid set\['K_P'\]: "):
        sw.simulate(set={"K_P": -10**400})


@pytest.mark.parametrize("value", [1 + 2j, np.complex128(0.3)])
def test_a_complex_value_is_a_type_error_naming_the_argument(value):
    with pytest.raises(TypeError, match=r"^invalid mu0: .*must be a real number"):
        sw.simulate(mu0=value)
    with pytest.raises(TypeError, match=r"^invalid mu0: .*real numbers"):
        sw.walk_points({"mu0": [0.3, value]})


def test_a_string_for_a_bool_is_a_type_error_naming_trajectory():
    with pytest.raises(TypeError, match=r"^invalid trajectory: 'False' \(str\): must be True or"):
        sw.simulate(trajectory="False")
    with pytest.raises(TypeError, match=r"^invalid restart: "):
        sw.sweep(from_=0.3, to=0.4, step=0.1, restart="no")


def test_errors_about_dt_name_dt():
    with pytest.raises(ValueError, match=r"^invalid dt: "):
        sw.simulate(trajectory=True, dt="fast")
    with pytest.raises(ValueError, match=r"^invalid dt: "):
        sw.simulate(trajectory=True, dt=-1.0)


def test_a_megabyte_argument_is_not_echoed_whole():
    for call in (lambda: sw.simulate(friction="x" * 1_000_000),
                 lambda: sw.simulate(set={"x" * 1_000_000: 1.0}),
                 lambda: sw.simulate(mu0="x" * 1_000_000),
                 lambda: sw.simulate(scene="x" * 1_000_000)):
        with pytest.raises(ValueError) as e:
            call()
        assert len(str(e.value)) < 300, len(str(e.value))


def test_a_count_must_be_an_integer():
    with pytest.raises(TypeError, match=r"^invalid max_steps: 3.0 \(float\): must be an integer"):
        sw.simulate(max_steps=3.0)
    with pytest.raises(ValueError, match=r"^invalid max_steps: 1000.*: must be in \[0, 1000000\]"):
        sw.simulate(max_steps=10**400)


def test_the_swept_parameter_cannot_also_be_the_chains():
    # issue 35: returned two identical chains.
    with pytest.raises(ValueError, match=r"^invalid t_set: T_set is the swept parameter"):
        sw.sweep(param="T_set", from_=0.3, to=0.4, step=0.1, t_set=[0.3, 0.5], duration=2.0)


def test_sweeping_the_default_chains_parameter_walks_one_chain_without_a_chain_value():
    s = sw.sweep(param="T_set", from_=0.3, to=0.4, step=0.1, duration=2.0)
    assert s.chain_param is None
    assert list(s["T_set"]) == [0.3, 0.4]
    assert all(math.isnan(c) for c in s["chain"])


def test_two_grid_columns_setting_one_parameter_are_refused():
    # issue 35: walked one and reported the other.
    with pytest.raises(ValueError, match=r'^invalid grid: columns "t_set" and "T_set" both set '
                                         r'T_set'):
        sw.walk_points({"t_set": [0.3], "T_set": [0.5]})


def test_a_parameter_by_keyword_and_in_set_is_refused():
    with pytest.raises(ValueError, match=r"^invalid set\['T_set'\]: T_set is given twice, also as t_set=; give it once$"):
        sw.simulate(t_set=0.3, set={"T_set": 0.4})
    with pytest.raises(ValueError, match=r"^invalid set\['mu0'\]: mu0 is given twice, also as mu0=; give it once$"):
        sw.fixed_point(mu0=0.3, set={"mu0": 0.4})


def test_a_control_character_in_a_name_is_escaped():
    with pytest.raises(ValueError) as e:
        sw.simulate(set={"gravity\x1b[31m": 9.8})
    msg = str(e.value)
    assert "\x1b" not in msg and ("\\x1b" in msg or "\\u{1b}" in msg), msg


def test_a_start_off_the_floor_is_refused_naming_init_and_the_component():
    # issue 35: init={'z': 1000.0} walked "ok" a kilometre above the floor.
    with pytest.raises(ValueError, match=r"^invalid init\['z'\]: the stance foot .* must be on "
                                         r"the floor \(z = 0\)"):
        sw.simulate(init={"z": 1000.0})
    with pytest.raises(ValueError, match=r"^invalid init\['zd'\]: .* must be along the floor"):
        sw.simulate(init={"zd": 1.0})
    # On the slope the floor is z = -x tan(phi): x alone moves the foot off it.
    with pytest.raises(ValueError, match=r"^invalid init\['x'\]: .*-x tan\(phi\)"):
        sw.simulate(scene="passive-slope", init={"x": 0.1})
    for call in (lambda **kw: sw.sweep(from_=0.3, to=0.4, step=0.1, duration=2.0, **kw),
                 lambda **kw: sw.walk_points({"mu0": [0.3]}, duration=2.0, **kw)):
        with pytest.raises(ValueError, match=r"^invalid init\['z'\]: "):
            call(init={"z": 1000.0})


def test_a_start_on_the_floor_given_by_init_walks():
    w = sw.simulate(init={"z": 0.0, "x": 0.5}, max_steps=2)
    assert w.steps == 2 and w.ok
    w = sw.simulate(scene="passive-slope", init={"x": 0.0, "z": 0.0}, max_steps=2)
    assert w.steps > 0
