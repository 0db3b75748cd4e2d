"""Bad input raises ValueError naming the argument and its valid range (the range its model
file gives for a parameter, the command line's for a flag); nothing else is raised."""

import pytest
import slippery_walker as sw


@pytest.mark.parametrize(
    "kwargs, named, range_text",
    [
        (dict(mu0=-1.0), "mu0", "[0, inf)"),
        (dict(t_set=0.0), "t_set", "(0, inf)"),
        (dict(c=float("nan")), "c", "(0, inf)"),
        (dict(rtol=2.0), "rtol", "in (0, 1)"),
        (dict(atol=0.0), "atol", "in (0, 1)"),
        (dict(duration=-1.0), "duration", "> 0"),
        (dict(max_steps=sw.MAX_STEPS + 1), "max_steps", "[0, 1000000]"),
        (dict(max_steps=-1), "max_steps", "[0, 1000000]"),
        (dict(friction="dry"), "friction", '"none", "tanh" or "coulomb"'),
        (dict(impact="elastic"), "impact", '"frictionless" or "coulomb"'),
        (dict(method="rk4"), "method", '"dop853" or "rodas4"'),
        (dict(phi=0.1), "phi", "model `paper-active` has no slope"),
        (dict(scene="moon"), "scene", "active-level, passive-slope"),
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


@pytest.mark.parametrize(
    "kwargs, named",
    [
        (dict(mu0_from=-0.1, mu0_to=0.2, mu0_step=0.1), "mu0_from"),
        (dict(mu0_from=0.3, mu0_to=0.2, mu0_step=0.1), "mu0_to"),
        (dict(mu0_from=0.1, mu0_to=0.2, mu0_step=0.0), "mu0_step"),
        (dict(mu0_from=0.0, mu0_to=1.0, mu0_step=1e-6), "mu0_step"),
        (dict(mu0_from=0.1, mu0_to=0.2, mu0_step=0.1, t_set=[0.3, -1.0]), "t_set"),
        (dict(mu0_from=0.1, mu0_to=0.2, mu0_step=0.1, until_periodic=1.5), "until_periodic"),
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
    with pytest.raises(ValueError, match=r"^invalid grid: the columns must have the same"):
        sw.walk_points({"mu0": [0.1, 0.2], "c": [10.0]})
