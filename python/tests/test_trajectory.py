"""``trajectory=True``: frames at exactly ``k * dt`` up to the walk's end, with the walk itself
unchanged (the same steps as without frames)."""

import numpy as np
import slippery_walker as sw


def test_frames_are_at_exact_multiples_of_dt_up_to_the_end():
    kw = dict(mu0=0.4, t_set=0.3, omega0=0.8, max_steps=2)
    w = sw.simulate(trajectory=True, dt=0.01, **kw)
    plain = sw.simulate(**kw)
    np.testing.assert_array_equal(w.T, plain.T)
    n = len(w.times)
    assert w.states.shape == (n, 8)
    assert w.frame_steps.shape == (n,)
    # exact: the library puts frame k at time k * dt (sim/trajectory.rs)
    assert w.times.tolist() == [k * 0.01 for k in range(n)]
    assert w.end_time == w.T.sum()
    assert n == int(np.floor(w.end_time / 0.01)) + 1
    assert not w.truncated
    assert set(w.frame_steps.tolist()) == {0, 1}
    short = sw.simulate(trajectory=True, dt=0.01, max_frames=5, **kw)
    assert (len(short.times), short.truncated) == (5, True)


def test_a_failed_walk_has_frames_up_to_its_failure():
    w = sw.simulate(scene="passive-slope", mu0=0.19, phi=0.10, omega0=0.5, max_steps=5,
                    trajectory=True, dt=0.01)
    assert w.status == "fell-backward"
    assert w.end_time == w.T.sum() + w.failure["t"]
    assert w.times[-1] <= w.end_time < w.times[-1] + 0.01
    assert np.isfinite(w.states).all()
