"""The module's results equal the ``walker`` command line's JSON for the same arguments.

The comparison is exact (``==`` on floats): the module and the command line call the same
library functions with the same inputs, and Rust does not reorder floating-point arithmetic,
so the same release build of the library gives the same bits; the CLI prints the shortest
decimal that reads back to the same double (serde_json), so parsing it gives those bits back.
"""

import numpy as np
import slippery_walker as sw
from conftest import MODELS, cli_json


def assert_steps_equal(walk, steps):
    assert walk.steps == len(steps)
    for key in ("T", "dx", "V"):
        assert walk.__getattribute__(key).tolist() == [s[key] for s in steps], key
    for key in ("p", "SR"):
        want = [np.nan if s[key] is None else s[key] for s in steps]
        np.testing.assert_array_equal(getattr(walk, key), want, err_msg=key)
    assert walk.q_plus.tolist() == [s["q_plus"] for s in steps]
    assert walk.qd_plus.tolist() == [s["qd_plus"] for s in steps]
    assert walk.foot_impulse.tolist() == [s["foot_impulse"] for s in steps]


def test_simulate_equals_the_cli_fig5_walk():
    cli = cli_json("simulate_active")
    w = sw.simulate(scene="active-level", mu0=0.4, t_set=0.3, omega0=0.8, max_steps=5)
    assert (w.status, w.failure) == (cli["status"], cli["failure"])
    assert_steps_equal(w, cli["steps"])


def test_simulate_with_coulomb_friction_and_impact_equals_the_cli():
    cli = cli_json("simulate_coulomb")
    w = sw.simulate(mu0=0.3, friction="coulomb", impact="coulomb", max_steps=4)
    assert w.status == cli["status"]
    assert_steps_equal(w, cli["steps"])


def test_a_fall_is_a_result_equal_to_the_clis_failure():
    # Fig. 14 (phi = 0.10, mu0 = 0.19, omega0 = 0.5): the wheel falls backward in step 1.
    cli = cli_json("simulate_fig14_fall")
    w = sw.simulate(scene="passive-slope", mu0=0.19, phi=0.10, omega0=0.5, max_steps=5)
    assert w.status == "fell-backward" == cli["status"]
    assert not w.ok
    assert w.failure == cli["failure"]
    assert w.failure["step"] == 1
    assert_steps_equal(w, cli["steps"])
    assert np.isnan(w.p).all()  # the passive wheel has no input power


def sweep_rows_of_cli(cli):
    rows = []
    for chain in cli["chains"]:
        for p in chain["points"]:
            rows.append((chain["value"], p))
    return rows


def assert_sweep_equal(s, cli):
    rows = sweep_rows_of_cli(cli)
    assert len(s) == len(rows)
    assert {ch["param"] for ch in cli["chains"]} == {s.chain_param}
    for k, (value, p) in enumerate(rows):
        assert s["chain"][k] == value
        assert s[s.param][k] == p[s.param]
        assert s["steps"][k] == p["steps"]
        assert s["periodic"][k] == p["periodic"]
        assert s["failure"][k] == p["failure"]
        last = p["last"]
        for key in ("T", "dx", "V"):
            assert s[key][k] == last[key], (k, key)
        assert s["q_plus"][k].tolist() == last["q_plus"]


def test_sweep_with_chains_continuing_from_the_previous_mu0_equals_the_cli():
    cli = cli_json("sweep_active")
    s = sw.sweep(mu0_from=0.1, mu0_to=0.4, mu0_step=0.1, t_set=[0.3, 0.4], duration=5)
    assert_sweep_equal(s, cli)


def test_sweep_restarting_every_point_equals_the_cli():
    cli = cli_json("sweep_passive_restart")
    s = sw.sweep(scene="passive-slope", mu0_from=0.1, mu0_to=0.3, mu0_step=0.1, phi=0.1,
                 restart=True, duration=5)
    assert_sweep_equal(s, cli)


def test_sweep_of_another_parameter_equals_the_cli():
    cli = cli_json("sweep_m2")
    s = sw.sweep(param="m2", from_=0.8, to=1.2, step=0.2, t_set=0.3, duration=3)
    assert s.param == "m2"
    assert_sweep_equal(s, cli)


def assert_fixed_point_equal(fp, cli):
    assert fp.json == cli
    assert fp.status == cli["status"]
    assert fp.T == cli["T"] and fp.V == cli["V"]
    assert fp.state_plus.tolist() == cli["state_plus"]
    assert fp.multipliers.tolist() == [complex(m["re"], m["im"]) for m in cli["multipliers"]]
    # Each multiplier has its error bound, a number for the simple multipliers of these gaits.
    assert list(fp.multiplier_errors) == cli["multiplier_errors"]
    assert len(fp.multiplier_errors) == len(fp.multipliers)
    assert all(e is None or e >= 0 for e in fp.multiplier_errors)
    assert list(fp.section) == cli["section"]


def test_fixed_point_equals_the_cli():
    fp = sw.fixed_point(mu0=0.4)
    assert_fixed_point_equal(fp, cli_json("fixed_point_active"))
    # The compiled walker's exact Jacobian: its multipliers good to 1.8e-11 (docs/poincare.md).
    assert max(fp.multiplier_errors) < 1e-9


def test_fixed_point_of_a_model_file_equals_the_cli():
    fp = sw.fixed_point(model=MODELS / "compass-gait.toml", friction="coulomb",
                        impact="frictionless")
    assert_fixed_point_equal(fp, cli_json("fixed_point_compass_gait"))


def test_simulate_from_a_start_given_by_init_equals_the_cli():
    cli = cli_json("simulate_init")
    w = sw.simulate(init={"th1d": 0.7, "th2d": 0.9}, max_steps=3)
    assert (w.status, w.failure) == (cli["status"], cli["failure"])
    assert_steps_equal(w, cli["steps"])


def test_simulate_of_a_model_file_equals_the_cli():
    cli = cli_json("simulate_compass_gait")
    w = sw.simulate(model=MODELS / "compass-gait.toml", friction="coulomb",
                    impact="frictionless", max_steps=5)
    assert (w.status, w.failure) == (cli["status"], cli["failure"])
    assert_steps_equal(w, cli["steps"])


def test_a_grid_point_is_the_walk_of_simulate_with_its_parameters():
    grid = {"mu0": [0.2, 0.4], "t_set": [0.3, 0.35], "omega0": [0.8, 0.9]}
    rows = sw.walk_points(grid, duration=3.0)
    for k in range(2):
        w = sw.simulate(mu0=grid["mu0"][k], t_set=grid["t_set"][k], omega0=grid["omega0"][k],
                        duration=3.0, max_steps=1000)
        assert rows["steps"][k] == w.steps
        assert rows["T"][k] == w.T[-1] and rows["V"][k] == w.V[-1]
        assert rows["qd_plus"][k].tolist() == w.qd_plus[-1].tolist()
