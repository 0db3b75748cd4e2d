"""Bad input raises ValueError naming the argument and its valid range (the range its model
file gives for a parameter, the command line's for a flag; a key of ``set`` or ``init`` as
``set['name']``); nothing else is raised."""

import pytest
import slippery_walker as sw
from conftest import MODELS

COMPASS = str(MODELS / "compass-gait.toml")


@pytest.mark.parametrize(
    "kwargs, named, range_text",
    [
        (dict(mu0=-1.0), "mu0", "[0, inf)"),
        (dict(t_set=0.0), "t_set", "(0, inf)"),
        (dict(c=float("nan")), "c", "(0, inf)"),
        (dict(rtol=2.0), "rtol", "in [2.220446049250313e-15, 1)"),
        (dict(rtol=1e-300), "rtol", "in [2.220446049250313e-15, 1)"),
        (dict(atol=0.0), "atol", "in [2.2250738585072014e-308, 1)"),
        (dict(duration=-1.0), "duration", "(0, 1e9]"),
        (dict(max_steps=sw.MAX_STEPS + 1), "max_steps", "[0, 1000000]"),
        (dict(max_steps=-1), "max_steps", "[0, 1000000]"),
        (dict(friction="dry"), "friction", '"none", "tanh" or "coulomb"'),
        (dict(impact="elastic"), "impact", '"frictionless" or "coulomb"'),
        (dict(method="rk4"), "method", '"dop853" or "rodas4"'),
        (dict(phi=0.1), "phi", "model `paper-active` has no slope"),
        (dict(scene="passive-slope", t_set=0.3), "t_set", "has no parameter T_set"),
        (dict(scene="moon"), "scene", "active-level, passive-slope"),
        (dict(scene="active-level", model=COMPASS), "model", "either scene= or model="),
        (dict(model="no-such-model.toml"), "model", "no-such-model.toml: cannot be read"),
        (dict(model=MODELS), "model", "is not a regular file"),
        (dict(model=COMPASS, omega0=0.8), "omega0", "has no start parameter omega0"),
        (dict(trajectory=True, dt=0.0), "dt", "> 0"),
        (dict(trajectory=True, max_frames=0), "max_frames", "[1, 1000000]"),
        (dict(trajectory=True, max_frames=-3), "max_frames", "[1, 1000000]"),
        (dict(omega0=float("inf")), "omega0", "finite"),
    ],
)
def test_simulate_names_the_bad_argument_and_its_range(kwargs, named, range_text):
    with pytest.raises(ValueError) as e:
        sw.simulate(**kwargs)
    msg = str(e.value)
    assert msg.startswith(f"invalid {named}:"), msg
    assert range_text in msg, msg


def test_the_slope_range_comes_from_the_model_file():
    # models/paper-passive.toml: phi, range = "[0, pi/2)"
    with pytest.raises(ValueError, match=r"^invalid phi: 2: must be in \[0, pi/2\)$"):
        sw.simulate(scene="passive-slope", phi=2.0)


@pytest.mark.parametrize("call", [
    lambda **kw: sw.simulate(**kw),
    lambda **kw: sw.fixed_point(**kw),
    lambda **kw: sw.sweep(mu0_from=0.1, mu0_to=0.2, mu0_step=0.1, **kw),
    lambda **kw: sw.walk_points({"mu0": [0.3]}, **kw),
    lambda **kw: sw.describe(**kw),
], ids=["simulate", "fixed_point", "sweep", "walk_points", "describe"])
def test_every_function_names_the_key_of_set_with_the_model_files_range(call):
    # models/paper-active.toml: K_P, range = "[0, inf)"
    with pytest.raises(ValueError, match=r"^invalid set\['K_P'\]: -1: must be in \[0, inf\)$"):
        call(set={"K_P": -1.0})
    with pytest.raises(ValueError,
                       match=r"^invalid set\['gravity'\]: .* its parameters: m1, m2, l, "):
        call(set={"gravity": 9.81})
    # A wrong type: sw.ArgumentTypeError, a TypeError that is also a ValueError.
    with pytest.raises(TypeError, match=r"^invalid set\['T_set'\]: 'fast' \(str\): must be a real "
                                        r"number$"):
        call(set={"T_set": "fast"})


@pytest.mark.parametrize("call", [
    lambda **kw: sw.simulate(**kw),
    lambda **kw: sw.fixed_point(**kw),
    lambda **kw: sw.sweep(mu0_from=0.1, mu0_to=0.2, mu0_step=0.1, **kw),
    lambda **kw: sw.walk_points({"mu0": [0.3]}, **kw),
], ids=["simulate", "fixed_point", "sweep", "walk_points"])
def test_every_walk_names_the_key_of_init_and_lists_the_state_components(call):
    with pytest.raises(ValueError, match=r"^invalid init\['th9'\]: \"th9\": must be a coordinate "
                                         r"or velocity of model `paper-active`: x, z, "
                                         r"th1, th2, xd, zd, th1d, th2d$"):
        call(init={"th9": 0.0})
    with pytest.raises(ValueError, match=r"^invalid init\['th1d'\]: inf: must be finite$"):
        call(init={"th1d": float("inf")})


def test_a_model_files_own_names_are_the_keys_of_set_and_init():
    with pytest.raises(ValueError, match=r"^invalid init\['th1'\]: .*compass-gait.*th_st, "):
        sw.simulate(model=COMPASS, init={"th1": 0.1})
    with pytest.raises(ValueError, match=r"^invalid set\['m_H'\]: 0: must be in \(0, inf\)$"):
        sw.simulate(model=COMPASS, set={"m_H": 0.0})


@pytest.mark.parametrize(
    "kwargs, named",
    [
        (dict(mu0_from=-0.1, mu0_to=0.2, mu0_step=0.1), "mu0_from"),
        (dict(mu0_from=0.3, mu0_to=0.2, mu0_step=0.1), "mu0_to"),
        (dict(mu0_from=0.1, mu0_to=0.2, mu0_step=0.0), "mu0_step"),
        (dict(mu0_from=0.0, mu0_to=1.0, mu0_step=1e-6), "mu0_step"),
        (dict(mu0_from=0.1, mu0_to=0.2, mu0_step=0.1, t_set=[0.3, -1.0]), "t_set"),
        (dict(mu0_from=0.1, mu0_to=0.2, mu0_step=0.1, until_periodic=1.5), "until_periodic"),
        (dict(from_=-0.1, to=0.2, step=0.1), "from_"),
        (dict(from_=0.1, to=0.2, step=-1.0), "step"),
        (dict(from_=0.1, mu0_from=0.1, to=0.2, step=0.1), "mu0_from"),
        (dict(param="gravity", from_=1.0, to=2.0, step=1.0), "param"),
        (dict(from_=0.1, to=0.2, step=0.1, t_set=0.3, phi=0.1), "phi"),
        (dict(scene="passive-slope", from_=0.1, to=0.2, step=0.1, t_set=0.3), "t_set"),
    ],
)
def test_sweep_names_the_bad_argument(kwargs, named):
    with pytest.raises(ValueError, match=f"^invalid {named}:"):
        sw.sweep(**kwargs)


def test_a_bad_grid_value_names_its_column_and_row():
    with pytest.raises(ValueError, match=r"^invalid mu0: -1: must be .*\(grid row 1\)"):
        sw.walk_points({"mu0": [0.1, -1.0]})
    # g is a parameter of the model (gravity), so a column may set it now
    with pytest.raises(ValueError, match=r"^invalid grid: unknown column \"gravity\""):
        sw.walk_points({"gravity": [9.8]})
    with pytest.raises(ValueError, match=r"^invalid K_P: -1: must be in \[0, inf\) \(grid row 0\)"):
        sw.walk_points({"K_P": [-1.0]})
    with pytest.raises(ValueError, match=r"^invalid grid: the columns must have the same"):
        sw.walk_points({"mu0": [0.1, 0.2], "c": [10.0]})


def test_a_sweep_without_its_range_is_a_type_error_naming_both_names():
    with pytest.raises(TypeError, match=r"'from_' \(or 'mu0_from'\)"):
        sw.sweep(to=1.0, step=0.1)
