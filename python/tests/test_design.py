"""``design(...)``: the gait design of ``walker design``; its result equals the command line's
JSON for the same request (the same library function on the same inputs: equal to the bit, as
``test_cli_equality.py`` argues), and a bad request is a ``ValueError`` naming the argument."""

import json
import subprocess

import pytest
import slippery_walker as sw

import conftest

# The paper's walker with its foot held on mu0 = 0.5, the ramp's duration designed: nine gait
# evaluations, a few hundredths of a second.
PAPER = dict(scene="active-level", set={"mu0": 0.5}, friction="coulomb", impact="coulomb")
CLI_PAPER = ["--scene", "active-level", "--set", "mu0=0.5", "--friction", "coulomb",
             "--impact", "coulomb"]


def cli_design(*args):
    """``walker design ARGS --json`` of the command line the Rust tests build, parsed."""
    run = subprocess.run([conftest.walker_binary(), "design", *args, "--json"],
                         cwd=conftest.ROOT, capture_output=True, text=True, check=True)
    return json.loads(run.stdout)


def test_a_design_equals_the_command_lines_json_for_the_same_request():
    d = sw.design(**PAPER, vary={"T_set": (0.2, 0.4, 0.3)})
    assert d == cli_design(*CLI_PAPER, "--vary", "T_set=0.2:0.4:0.3")
    assert d["status"] == "optimal"
    assert [c["name"] for c in d["constraints"]] == [
        "multipliers", "impact-friction", "normal-force", "stance-friction",
        "strike-after-ramp"]


def test_input_bounds_restarts_and_margins_reach_the_library_as_the_flags_do():
    d = sw.design(**PAPER, vary={"T_set": (0.2, 0.4)}, max_input=[30.0], ramp_margin=0.02,
                  friction_margin=0.02, restarts=2, seed=3, max_evaluations=20)
    cli = cli_design(*CLI_PAPER, "--vary", "T_set=0.2:0.4", "--max-input", "30",
                     "--ramp-margin", "0.02", "--friction-margin", "0.02", "--restarts", "2",
                     "--seed", "3", "--max-evaluations", "20")
    assert d == cli
    bound = next(c for c in d["constraints"] if c["name"] == "input-0")
    assert bound["limit"] == 30.0 and bound["value"] == d["gait"]["max_input"][0]
    assert len(d["restarts"]) == 3


def test_an_infeasible_design_is_a_result_naming_the_constraint():
    d = sw.design(scene="active-level", set={"mu0": 0.3}, friction="coulomb", impact="coulomb",
                  vary={"T_set": (0.2, 0.4, 0.3)})
    assert (d["status"], d["violated"]) == ("infeasible", "stance-friction")


@pytest.mark.parametrize("kwargs, message", [
    (dict(vary={"T_sat": (0.2, 0.4)}), r"invalid vary: `T_sat` is not a run-time parameter"),
    (dict(vary={"T_set": (0.4, 0.2)}), r"invalid vary: bounds of `T_set` are \[0.4, 0.2\]"),
    (dict(vary={"T_set": (0.2, 0.4, 0.5)}), r"invalid vary: start of `T_set` is 0.5"),
    (dict(vary={"T_set": (0.2,)}), r"invalid vary\['T_set'\]: .*\(lo, hi\) or \(lo, hi, start\)"),
    (dict(vary={}), r"invalid vary: "),
    (dict(vary={"T_set": (0.2, 0.4)}, objective="walk"), r"invalid objective: `walk`"),
    (dict(vary={"T_set": (0.2, 0.4)}, objective="speed"),
     r"invalid max_power: objective `speed` on model `paper-active` needs an effort bound"),
    (dict(vary={"T_set": (0.2, 0.4)}, objective="speed", max_power=5.0, min_speed=0.5),
     r"invalid min_speed: min-speed bounds what objective `speed` optimises"),
    (dict(vary={"T_set": (0.2, 0.4)}, objective="power", max_power=5.0),
     r"invalid max_power: max-power bounds what objective `power` optimises"),
    (dict(vary={"T_set": (0.2, 0.4)}, min_speed=-1.0),
     r"invalid min_speed: min-speed is -1: must be finite and > 0"),
    (dict(vary={"T_set": (0.2, 0.4)}, max_speed=0.0),
     r"invalid max_speed: max-speed is 0: must be finite and > 0"),
    (dict(vary={"T_set": (0.2, 0.4)}, min_speed=0.9, max_speed=0.8),
     r"invalid max_speed: max-speed is 0.8, below min-speed 0.9: must be at least min-speed"),
    (dict(vary={"T_set": (0.2, 0.4)}, objective="speed", max_power=5.0, max_speed=0.9),
     r"invalid max_speed: max-speed bounds what objective `speed` optimises"),
    (dict(vary={"T_set": (0.2, 0.4)}, max_power=float("nan")),
     r"invalid max_power: max-power is NaN: must be finite and > 0"),
    (dict(vary={"T_set": (0.2, 0.4)}, clearance=0.0),
     r"invalid clearance: clearance is 0: must be finite and > 0"),
    (dict(vary={"T_set": (0.2, 0.4)}, clearance=0.01),
     r"invalid clearance: clearance needs a swing foot; model `paper-active` has none"),
    (dict(vary={"T_set": (0.2, 0.4)}, multiplier_margin=1.0),
     r"invalid multiplier_margin: .*must be in \[0, 1\)"),
    (dict(vary={"T_set": (0.2, 0.4)}, ramp_margin=-0.1),
     r"invalid ramp_margin: ramp margin is -0.1: must be finite and >= 0"),
    (dict(vary={"T_set": (0.2, 0.4)}, max_input=0.0),
     r"invalid max_input: input bound is 0: must be finite and > 0"),
    (dict(vary={"T_set": (0.2, 0.4)}, max_input=[1.0, 2.0]),
     r"invalid max_input: 2 input bounds for a walker with 1 input\(s\)"),
    (dict(vary={"T_set": (0.2, 0.4)}, max_evaluations=0), r"invalid max_evaluations: 0"),
    (dict(vary={"T_set": (0.2, 0.4)}, restarts=101), r"invalid restarts: 101"),
    (dict(vary={"T_set": (0.2, 0.4)}, tol=2.0), r"invalid tol: 2"),
])
def test_a_bad_request_is_a_value_error_naming_the_argument(kwargs, message):
    with pytest.raises(ValueError, match=message):
        sw.design(scene="active-level", **kwargs)


def test_input_bounds_on_a_walker_without_inputs_name_max_input():
    with pytest.raises(ValueError, match=r"invalid max_input: input bounds need an actuated"):
        sw.design(model=str(conftest.MODELS / "compass-gait.toml"), friction="coulomb",
                  vary={"mu0": (0.5, 0.9)}, objective="friction", max_input=1.0)


# The paper's walker held on mu0 = 1, its ramp designed from 0.4 s: at most a few dozen gait
# evaluations of the compiled model, under a second.
FAST = dict(scene="active-level", set={"mu0": 1.0}, friction="coulomb", impact="coulomb",
            vary={"T_set": (0.2, 0.4, 0.4)})
CLI_FAST = ["--scene", "active-level", "--set", "mu0=1.0", "--friction", "coulomb",
            "--impact", "coulomb", "--vary", "T_set=0.2:0.4:0.4"]


def test_a_least_speed_and_the_speed_objective_equal_the_command_lines_json():
    d = sw.design(**FAST, min_speed=0.85)
    assert d == cli_design(*CLI_FAST, "--min-speed", "0.85")
    row = d["constraints"][-1]
    assert (row["name"], row["limit"], row["value"]) == (
        "min-speed", 0.85, d["gait"]["fixed_point"]["V"])
    d = sw.design(**FAST, objective="speed", max_power=12.0)
    assert d == cli_design(*CLI_FAST, "--objective", "speed", "--max-power", "12")
    assert d["objective"] == "speed" and d["value"] == d["gait"]["fixed_point"]["V"]
    assert d["constraints"][-1]["name"] == "max-power"


def test_a_speed_band_equals_the_command_lines_json():
    # min_speed = max_speed: a gait at one speed, faster than the cheapest (0.781 m/s).
    d = sw.design(**FAST, min_speed=0.82, max_speed=0.82)
    assert d == cli_design(*CLI_FAST, "--min-speed", "0.82", "--max-speed", "0.82")
    rows = {c["name"]: c for c in d["constraints"]}
    assert (rows["min-speed"]["sense"], rows["max-speed"]["sense"]) == (">=", "<=")
    assert rows["max-speed"]["limit"] == 0.82
    assert abs(d["gait"]["fixed_point"]["V"] - 0.82) <= 1e-8


def test_a_clearance_equals_the_command_lines_json_and_names_the_row():
    # The three-link biped's straight legs leave no clearance (docs/design.md): infeasible.
    model = str(conftest.MODELS / "three-link.toml")
    d = sw.design(model=model, friction="coulomb", impact="coulomb", objective="friction",
                  vary={"beta": (0.3, 0.45)}, max_evaluations=3, clearance=0.01)
    assert d == cli_design("--model", model, "--friction", "coulomb", "--impact", "coulomb",
                           "--objective", "friction", "--vary", "beta=0.3:0.45",
                           "--max-evaluations", "3", "--clearance", "0.01")
    assert (d["status"], d["violated"]) == ("infeasible", "clearance")
    # At most 0 in continuous time; the 400 samples can miss the instant the swing leg is
    # vertical by half a sample, worth at most about 1.4e-6 m there (cli/tests/it/
    # design_bounds_cli.rs).
    assert d["constraints"][-1]["value"] == d["gait"]["clearance"] <= 1e-5
