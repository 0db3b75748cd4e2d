"""Floors that change under the walker (``docs/floors.md``): ``simulate(floor=...)`` and
``survive(...)`` equal the command line's JSON for the same arguments (exactly: the same
library functions on the same inputs; see ``test_cli_equality.py``), and a floor given as a
dict gets a floor file's checks, its errors naming the key."""

import json

import pytest
import slippery_walker as sw
from conftest import ROOT, cli_json
from test_cli_equality import assert_steps_equal

MARKOV_FILE = ROOT / "python" / "tests" / "floors" / "markov.toml"

MARKOV = {
    "kind": "random",
    "seed": 9,
    "mu0": {"distribution": "markov", "dry": 0.3, "icy": 0.05, "dry_length": 20,
            "icy_length": 1.5},
}
"""The floor of ``floors/markov.toml`` as a dict."""


def test_simulate_on_a_steps_floor_equals_the_cli_with_mu0_steps():
    cli = cli_json("simulate_mu0_steps")
    w = sw.simulate(scene="active-level", t_set=0.3, friction="coulomb", max_steps=6,
                    floor={"kind": "steps", "mu0": [0.4, 0.4, 0.4, 0.05, 0.4]})
    assert (w.status, w.failure) == (cli["status"], cli["failure"])
    assert_steps_equal(w, cli["steps"])
    assert w.floor_mu0.tolist() == [s["floor"]["mu0"] for s in cli["steps"]]


def test_simulate_without_a_floor_has_no_floor_column():
    w = sw.simulate(max_steps=2)
    assert w.floor_mu0 is None


def test_survive_equals_the_cli_for_a_file_and_for_the_same_floor_as_a_dict():
    cli = cli_json("survive_markov")
    by_file = sw.survive(scene="passive-slope", floor=MARKOV_FILE, walks=16, max_steps=30)
    by_dict = sw.survive(scene="passive-slope", floor=MARKOV, walks=16, max_steps=30)
    assert by_file == cli
    assert by_dict == cli
    # The batch is not trivial: some walks fail on the ice, so the comparison covers the
    # curve, the estimates and the failures by kind, not only sixteen censored walks.
    assert 0 < cli["survival"]["failures"] <= 16


def test_survive_walk_zero_is_simulates_walk_on_the_same_floor():
    s = sw.survive(scene="passive-slope", floor=MARKOV, walks=3, max_steps=30)
    w = sw.simulate(scene="passive-slope", floor=MARKOV, max_steps=30)
    assert s["outcomes"][0]["steps"] == w.steps
    assert s["outcomes"][0]["failure"] == (None if w.ok else w.status)


def with_mu0(**fields):
    d = {**MARKOV, "mu0": {**MARKOV["mu0"], **fields}}
    return d


@pytest.mark.parametrize("floor, key, text", [
    # A floor that sets neither mu0 nor phi names mu0.
    ({"kind": "uniform"}, "floor['mu0']", "gives mu0, phi or both"),
    ({"kind": "wet", "mu0": 0.3}, "floor['kind']", "expected"),
    ({"kind": "uniform", "mu0": -0.3}, "floor['mu0']", "must be > 0"),
    ({"kind": "steps", "mu0": [0.4, 0.0]}, "floor['mu0'][1]", "must be > 0"),
    (with_mu0(icy_length=0.5), "floor['mu0']['icy_length']", "[1, 1e9]"),
    ({**MARKOV, "seed": -1}, "floor['seed']", "whole number"),
    ({**MARKOV, "phi": {"distribution": "uniform", "lo": 0.1, "hi": float("inf")}},
     "floor['phi']['hi']", "must be finite"),
    ({"kind": "steps", "phi": [0.2, float("nan")]}, "floor['phi'][1]", "must be finite"),
    ({"kind": "random", "seed": 1, "mu0": {"distribution": "uniform", "lo": 0.3, "hi": 0.2}},
     "floor['mu0']['hi']", "must be > mu0.lo"),
    ({"kind": "patches", "mu0": 0.6, "patch": [{"from": 2.0, "to": 1.0, "mu0": 0.05}]},
     "floor['patch'][0]['to']", "must be > patch[0].from"),
    ({"kind": "patches", "mu0": 0.6,
      "patch": [{"from": 1.0, "to": 2.0, "mu0": 0.05}, {"from": 1.5, "to": 3.0, "mu0": 0.2}]},
     "floor['patch'][1]['from']", "do not overlap"),
])
def test_a_bad_floor_dict_raises_value_error_naming_the_key(floor, key, text):
    with pytest.raises(ValueError) as e:
        sw.survive(scene="passive-slope", floor=floor, walks=2, max_steps=2)
    assert f"invalid {key}" in str(e.value)
    assert text in str(e.value)


@pytest.mark.parametrize("floor, key", [
    ({"kind": "uniform", "mu0": None}, "floor['mu0']"),
    ({"kind": "steps", "mu0": [0.4, object()]}, "floor['mu0'][1]"),
    ({1: "uniform"}, "floor"),
    (3.0, "floor"),
])
def test_a_floor_value_of_no_floor_files_type_raises_type_error_naming_the_key(floor, key):
    with pytest.raises(TypeError) as e:
        sw.simulate(floor=floor, max_steps=1)
    assert f"invalid {key}" in str(e.value)


def test_a_floor_with_mu0_or_mu0_in_set_is_refused():
    with pytest.raises(ValueError, match="mu0"):
        sw.simulate(floor={"kind": "uniform", "mu0": 0.3}, mu0=0.3, max_steps=1)
    with pytest.raises(ValueError, match="floor"):
        sw.survive(floor={"kind": "uniform", "mu0": 0.3}, set={"mu0": 0.3}, walks=1,
                   max_steps=1)


def test_survive_counts_out_of_range_name_their_keyword():
    with pytest.raises(ValueError, match="invalid walks"):
        sw.survive(floor=MARKOV, walks=0, max_steps=1)
    with pytest.raises(ValueError, match="invalid walks"):
        sw.survive(floor=MARKOV, walks=100_000, max_steps=1001)


def test_survive_from_first_walk_has_the_batchs_walks_of_those_indices():
    whole = sw.survive(scene="passive-slope", floor=MARKOV, walks=16, max_steps=30)
    part = sw.survive(scene="passive-slope", floor=MARKOV, walks=5, max_steps=30, first_walk=7)
    assert part["outcomes"] == whole["outcomes"][7:12]
    assert [o["walk"] for o in part["outcomes"]] == list(range(7, 12))


def test_survival_of_a_batchs_outcomes_gathered_from_ranges_is_the_batchs_survival():
    whole = sw.survive(scene="passive-slope", floor=MARKOV, walks=16, max_steps=30)
    outcomes = []
    for a, b in [(0, 1), (1, 9), (9, 16)]:
        outcomes += sw.survive(scene="passive-slope", floor=MARKOV, walks=b - a, max_steps=30,
                               first_walk=a)["outcomes"]
    assert outcomes == whole["outcomes"]
    # The same library function on the same outcomes: the same digits, not merely close ones.
    assert json.dumps(sw.survival(outcomes)) == json.dumps(whole["survival"])
    assert 0 < whole["survival"]["failures"] < 16


@pytest.mark.parametrize("first_walk, error, text", [
    (-1, ValueError, "invalid first_walk: -1: must be in [0, 9223372036854775807]"),
    (2**63 - 2, ValueError, "invalid first_walk: 9223372036854775806: must be a whole number "
                            "in [0, 9223372036854775805]"),
    (1.0, TypeError, "invalid first_walk: 1.0 (float): must be an integer"),
])
def test_survive_refuses_a_first_walk_out_of_range_naming_it(first_walk, error, text):
    with pytest.raises(error) as e:
        sw.survive(floor=MARKOV, scene="passive-slope", walks=3, max_steps=1,
                   first_walk=first_walk)
    assert str(e.value) == text


@pytest.mark.parametrize("outcomes, error, text", [
    ([], ValueError, "invalid outcomes: empty: must hold at least one walk's outcome"),
    ("walks", TypeError, "invalid outcomes: 'walks' (str): must be a list of survive's outcomes"),
    ([{"walk": 0, "steps": 3}], ValueError, "invalid outcomes[0]: missing key 'failure'"),
    ([{"walk": 0, "steps": 3, "failure": None}, {"walk": 1, "steps": -1, "failure": None}],
     ValueError, "invalid outcomes[1]['steps']: -1: must be in [0, 1000000]"),
    ([{"walk": 0, "steps": 3, "failure": 7}], TypeError, "invalid outcomes[0]['failure']: 7"),
    ([3], TypeError, "invalid outcomes[0]: 3 (int): must be a dict"),
])
def test_survival_refuses_bad_outcomes_naming_them(outcomes, error, text):
    with pytest.raises(error) as e:
        sw.survival(outcomes)
    assert str(e.value).startswith(text)


WHEEL = ROOT / "models" / "rimless-wheel.toml"

SLOPES = {"kind": "random", "seed": 4,
          "phi": {"distribution": "uniform", "lo": 0.15, "hi": 0.25}}
"""Slopes uniform around the rimless wheel's own 0.2 rad (``docs/floors.md``)."""


def test_survive_on_random_slopes_walks_the_wheel_and_reports_each_walk():
    kw = dict(model=WHEEL, friction="coulomb", impact="coulomb", set={"mu0": 0.8},
              floor=SLOPES, walks=4, max_steps=20)
    r = sw.survive(**kw)
    assert [o["walk"] for o in r["outcomes"]] == [0, 1, 2, 3]
    assert all(0 < o["steps"] <= 20 for o in r["outcomes"])
    # Walk 0 of survive is simulate's walk on the same floor, its steps on their slopes.
    w = sw.simulate(model=WHEEL, friction="coulomb", impact="coulomb", set={"mu0": 0.8},
                    floor=SLOPES, max_steps=20)
    assert r["outcomes"][0]["steps"] == w.steps


def test_a_floor_that_sets_phi_refuses_phi_and_a_level_walker():
    with pytest.raises(ValueError, match="phi"):
        sw.survive(model=WHEEL, friction="coulomb", impact="coulomb", floor=SLOPES, phi=0.2,
                   walks=1, max_steps=1)
    with pytest.raises(ValueError, match="no slope angle"):
        sw.survive(scene="active-level", floor=SLOPES, walks=1, max_steps=1)


WHEEL_ICE = {"kind": "random", "seed": 5,
             "mu0": {"distribution": "uniform", "lo": 0.05, "hi": 0.5}}
"""The rimless wheel's slippery floor of ``docs/floors.md`` ("The mesh on a passive walker")."""


def test_mfpt_equals_the_cli_and_checks_its_arguments_by_name():
    kw = dict(model=WHEEL, friction="coulomb", impact="coulomb", floor=WHEEL_ICE, mesh=5,
              samples=4)
    r = sw.mfpt(**kw, walks=20, max_steps=200)
    cli = cli_json("mfpt_wheel")
    assert r == cli
    assert r["monte_carlo"]["walks"] == 20
    with pytest.raises(ValueError, match="invalid mesh"):
        sw.mfpt(**{**kw, "mesh": 1})
    with pytest.raises(ValueError, match="invalid half_widths: cannot be given with box_scale"):
        sw.mfpt(**kw, box_scale=1.0, half_widths=[0.1, 0.1])
    # A floor that sets the slope is meshed too (the chain carries the slope of the step
    # before), and the module's answer is the command line's, walks included.
    slopes = sw.mfpt(**{**kw, "floor": SLOPES}, set={"mu0": 0.8}, walks=20, max_steps=200)
    assert slopes == cli_json("mfpt_wheel_slopes")


ICE_PATCH = {"kind": "patches", "mu0": 0.6, "patch": [{"from": 2.0, "to": 2.6, "mu0": 0.05}]}
"""A dry floor with a patch of ice by position (``docs/floors.md``, "Patches by position")."""


def test_a_patches_floor_as_a_dict_is_the_same_floor_as_its_file(tmp_path):
    path = tmp_path / "ice-patch.toml"
    path.write_text('kind = "patches"\nmu0 = 0.6\n[[patch]]\nfrom = 2.0\nto = 2.6\nmu0 = 0.05\n')
    by_dict = sw.simulate(scene="active-level", t_set=0.3, max_steps=8, floor=ICE_PATCH)
    by_file = sw.simulate(scene="active-level", t_set=0.3, max_steps=8, floor=str(path))
    assert by_dict.ok and by_file.ok
    assert by_dict.steps == by_file.steps == 8
    assert by_dict.floor_mu0.tolist() == by_file.floor_mu0.tolist()
    # Step 4 stands on the ice: the foot the strike of step 3 put there.
    assert by_dict.floor_mu0.tolist()[4] == 0.05
    assert (by_dict.q_plus == by_file.q_plus).all()
    # The strike of step 3 lands on the ice; step 4's foot slides back onto the dry floor once
    # (docs/floors.md's example); the walk on the command line reports the same.
    assert by_dict.floor_mu0_strike.tolist()[3] == 0.05
    assert by_dict.floor_crossings.tolist()[4] == 1
    # Each step starts on the patch its strike put the new foot on.
    assert by_dict.floor_mu0_strike.tolist()[:-1] == by_dict.floor_mu0.tolist()[1:]


def test_a_floor_by_step_has_no_patch_columns():
    w = sw.simulate(scene="active-level", t_set=0.3, max_steps=3,
                    floor={"kind": "steps", "mu0": [0.4, 0.4, 0.5]})
    assert w.floor_mu0 is not None
    assert w.floor_mu0_strike is None and w.floor_crossings is None
