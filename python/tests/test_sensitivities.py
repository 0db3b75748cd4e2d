"""``fixed_point(..., sensitivities=[...])``: the gait's derivatives in run-time parameters,
as ``walker fixed-point --sensitivities``, and the errors for names that are not parameters."""

import pytest
import slippery_walker as sw


def test_the_sensitivities_to_mu0_and_t_set_come_with_their_error_estimates():
    fp = sw.fixed_point(scene="active-level", sensitivities=["mu0", "T_set"])
    assert fp.status == "converged"
    assert set(fp.sensitivities) == {"mu0", "T_set"}
    for name, s in fp.sensitivities.items():
        assert set(s["d_state"]) == set(fp.section), name
        for key in ("dT", "dV", "d_dx"):
            assert s[key]["error"] >= 0 and abs(s[key]["error"]) < 1e-2 * max(1, abs(s[key]["value"]))
        # V = dx / T: its derivative is that of the quotient. The sensitivities take T and dx
        # from their own map at rtol 1e-12, the search's at 1e-10: 1e-8 relative covers that.
        dv = (s["d_dx"]["value"] - fp.V * s["dT"]["value"]) / fp.T
        assert s["dV"]["value"] == pytest.approx(dv, rel=1e-8, abs=1e-10)
        assert len(s["d_multipliers"]) == len(fp.multipliers)
    # a longer ramp makes a slower, longer step (Fig. 8 of the paper: V falls with T_set)
    assert fp.sensitivities["T_set"]["dT"]["value"] > 0
    assert fp.sensitivities["T_set"]["dV"]["value"] < 0


def test_without_the_keyword_the_result_has_no_sensitivities():
    fp = sw.fixed_point(scene="active-level")
    assert fp.sensitivities is None and "sensitivities" not in fp.json


@pytest.mark.parametrize("bad", ["bogus", "omega0"])
def test_a_name_that_is_not_a_run_time_parameter_is_a_value_error_with_the_valid_names(bad):
    with pytest.raises(ValueError, match=r"invalid sensitivities: .*" + bad + r".*valid: .*T_set"):
        sw.fixed_point(scene="active-level", sensitivities=["mu0", bad])
