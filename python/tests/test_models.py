"""Model files through the module: any walker of ``models/*.toml`` runs with ``model=``, a
file that is not shipped is derived when the call starts (``walker-load``), and the results
carry the model's own state names and sizes."""

from pathlib import Path

import numpy as np
import pytest
import slippery_walker as sw
from conftest import MODELS

COMPASS = MODELS / "compass-gait.toml"


def test_the_compass_gait_on_coulomb_friction_with_a_coulomb_impact_walks_its_cycle():
    # mu0 = 5: the foot never slips, in the stance or at the impact, and the walk is the
    # frictionless-floor compass gait started on its 3 degree cycle ([start]).
    w = sw.simulate(model=COMPASS, friction="coulomb", impact="coulomb", set={"mu0": 5},
                    max_steps=5)
    assert w.status == "ok" and w.steps == 5
    # the stuck impact stops the new stance foot: xd+ = zd+ = 0 to rounding
    np.testing.assert_allclose(w.qd_plus[:, :2], 0.0, rtol=0, atol=1e-12)
    # the start is the cycle to six digits (models/compass-gait.toml), which the stable
    # cycle (multipliers of modulus 0.58 and 0.13) keeps: every period within 1e-6 of the first
    np.testing.assert_allclose(w.T, w.T[0], rtol=0, atol=1e-6)


def test_the_compass_gait_walks_with_its_own_state_names_and_sizes():
    # Coulomb friction, the frictionless impact: five steps (measured with the command line,
    # data/simulate_compass_gait.json).
    w = sw.simulate(model=COMPASS, friction="coulomb", impact="frictionless", max_steps=5,
                    trajectory=True, dt=0.01)
    assert (w.status, w.steps) == ("ok", 5)
    assert w.state_names == ("x", "z", "th_st", "th_sw", "xd", "zd", "th_std", "th_swd")
    assert w.input_names == ()
    assert w.q_plus.shape == w.qd_plus.shape == (5, 4)
    assert w.states.shape == (len(w.times), 8) and w.u.shape == (len(w.times), 0)
    # the model reports T, dx and V only (its [descriptors]); p and SR are NaN
    assert np.isnan(w.p).all() and np.isnan(w.SR).all()
    # after each impact both feet are on the 3 degree slope: th_st + th_sw = 2 phi
    phi = sw.describe(model=COMPASS).parameters["phi"].value
    np.testing.assert_allclose(w.q_plus[:, 2] + w.q_plus[:, 3], 2 * phi, rtol=0, atol=1e-9)


def test_a_changed_copy_of_a_model_file_is_derived_and_equals_set_on_the_shipped_one(tmp_path):
    text = COMPASS.read_text()
    old = 'name = "m"\nunit = "kg"\ndoc = "mass of each leg, a point at a from its foot"\n' \
          'range = "(0, inf)"\ndefault = 5.0\n'
    assert old in text
    copy = tmp_path / "compass-gait-heavy.toml"
    copy.write_text(text.replace(old, old.replace("default = 5.0", "default = 6.0")))
    kw = dict(friction="coulomb", impact="frictionless", max_steps=5)
    derived = sw.simulate(model=copy, **kw)
    shipped = sw.simulate(model=COMPASS, set={"m": 6.0}, **kw)
    default = sw.simulate(model=COMPASS, **kw)
    assert sw.describe(model=copy).parameters["m"].value == 6.0
    assert derived.status == shipped.status == "ok" and derived.steps == shipped.steps == 5
    # The derived kernels are the lowered graph evaluated by walker-load's interpreter, the
    # shipped ones compiled Rust of the same derivation: the two differ by rounding, which the
    # integrator carries along. Each walk is within its integrator's tolerance (rtol = 1e-10
    # per step of the error control) of the exact motion; over the few hundred integrator
    # steps of five walking steps that bounds their distance by about 1e-8 (measured:
    # 6e-13). atol covers the components that are zero up to rounding (z, zd).
    for key in ("T", "dx", "V", "q_plus", "qd_plus"):
        np.testing.assert_allclose(getattr(derived, key), getattr(shipped, key),
                                   rtol=1e-8, atol=1e-10, err_msg=key)
    # and the changed default is what it walked with: one kilogram more changes the gait
    assert np.abs(derived.T - default.T).max() > 1e-4


def test_init_replaces_components_of_the_start_as_omega0_does():
    # models/paper-active.toml: [start] th1 = -alpha/2, th1d = th2d = omega0
    by_init = sw.simulate(init={"th1d": 0.8, "th2d": 0.8}, max_steps=3)
    by_omega0 = sw.simulate(omega0=0.8, max_steps=3)
    assert by_init.T.tolist() == by_omega0.T.tolist()
    assert by_init.qd_plus.tolist() == by_omega0.qd_plus.tolist()
    other = sw.simulate(init={"th1d": 0.8, "th2d": 0.9}, max_steps=3)
    assert other.T.tolist() != by_omega0.T.tolist()


def test_a_restarted_sweep_of_any_parameter_is_simulate_at_each_value():
    s = sw.sweep(param="m2", from_=0.8, to=1.2, step=0.2, restart=True, duration=3.0)
    assert (s.param, s.chain_param) == ("m2", "T_set")
    # the values are from + k step, as walker::sweep::mu0_grid makes them
    assert s["m2"].tolist() == [0.8 + 0.2 * k for k in range(3)]
    for k, m2 in enumerate(s["m2"]):
        w = sw.simulate(set={"m2": m2}, duration=3.0, max_steps=1000)
        assert s["steps"][k] == w.steps
        assert s["T"][k] == w.T[-1] and s["q_plus"][k].tolist() == w.q_plus[-1].tolist()


def test_the_paper_names_of_a_sweeps_range_are_its_new_names():
    a = sw.sweep(mu0_from=0.2, mu0_to=0.4, mu0_step=0.1, duration=3.0)
    b = sw.sweep(from_=0.2, to=0.4, step=0.1, param="mu0", duration=3.0)
    a_df, b_df = a.to_pandas(), b.to_pandas()
    assert list(a_df.columns[:2]) == ["chain", "mu0"]
    assert a_df.equals(b_df)


def test_a_grid_column_may_name_any_parameter_of_the_model():
    grid = {"K_D": [0.0, 2.0], "T_set": [0.3, 0.35], "omega0": [0.8, 0.9]}
    rows = sw.walk_points(grid, duration=3.0)
    for k in range(2):
        w = sw.simulate(set={"K_D": grid["K_D"][k], "T_set": grid["T_set"][k]},
                        omega0=grid["omega0"][k], duration=3.0, max_steps=1000)
        assert rows["steps"][k] == w.steps
        assert rows["T"][k] == w.T[-1] and rows["qd_plus"][k].tolist() == w.qd_plus[-1].tolist()


def test_a_model_files_grid_has_its_state_names_in_the_table():
    df = sw.walk_points({"phi": [0.04, 0.05]}, model=COMPASS, impact="frictionless",
                        duration=2.0).to_pandas()
    assert [c for c in df.columns if c.endswith("_plus")] == [
        "x_plus", "z_plus", "th_st_plus", "th_sw_plus",
        "xd_plus", "zd_plus", "th_std_plus", "th_swd_plus"]


def test_the_fixed_point_names_its_section_coordinates():
    # models/paper-active.toml: [section] free = ["xd", "th1d"];
    # models/compass-gait.toml: free = ["th_st", "xd", "th_std", "th_swd"]
    fp = sw.fixed_point(mu0=0.4)
    assert fp.section == ("xd", "th1d") and len(fp.multipliers) == 2
    cg = sw.fixed_point(model=COMPASS, friction="coulomb", impact="frictionless")
    assert cg.status == "converged"
    assert cg.section == ("th_st", "xd", "th_std", "th_swd") and len(cg.multipliers) == 4
    assert cg.state_names[2:4] == ("th_st", "th_sw") and cg.state_plus.shape == (8,)
    # Goswami et al.'s period-one gait on 3 degrees is stable: every multiplier inside
    assert np.abs(cg.multipliers).max() < 1


def test_describe_reads_the_model_files_parameters_and_start():
    info = sw.describe(model=COMPASS, set={"phi": 0.04})
    assert info.model == "compass-gait" and info.impact == "coulomb"
    assert list(info.parameters) == ["m", "m_H", "a", "b", "g", "phi", "mu0", "c"]
    assert info.parameters["m_H"].range == "(0, inf)" and info.parameters["phi"].value == 0.04
    # [start] th_sw = "2*phi + 0.218669"
    assert info.start[info.state_names.index("th_sw")] == 2 * 0.04 + 0.218669
    active = sw.describe()
    assert active.scene == "active-level" and active.input_names == ("u",)
    assert active.parameters["omega0"].start and not active.parameters["T_set"].start


def test_no_friction_runs_the_model_with_mu0_zero():
    a = sw.simulate(friction="none", max_steps=3)
    b = sw.simulate(mu0=0.0, max_steps=3)
    assert a.T.tolist() == b.T.tolist()
