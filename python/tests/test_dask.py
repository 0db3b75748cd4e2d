"""``slippery_walker.dask.grid_sweep`` on a local cluster of two worker processes gives the
same table as walking the same points in one process."""

import numpy as np
import pandas as pd
import pytest
import slippery_walker as sw
from conftest import MODELS
from dask.distributed import Client, LocalCluster
from slippery_walker.dask import grid_sweep


@pytest.fixture(scope="module")
def client():
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as c:
        yield c


def grid():
    mu0, t_set = np.meshgrid(np.linspace(0.05, 0.6, 6), [0.25, 0.3, 0.35])
    return pd.DataFrame({"mu0": mu0.ravel(), "t_set": t_set.ravel()})


def test_grid_sweep_on_two_processes_equals_one_process(client):
    g = grid()
    dist = grid_sweep(client, g, duration=5.0, chunk_size=4)
    local = sw.walk_points(g, duration=5.0).to_pandas()
    pd.testing.assert_frame_equal(dist, local, check_exact=True)
    assert list(dist["mu0"]) == list(g["mu0"])
    assert len(dist) == 18


def test_grid_sweep_takes_a_dict_and_keeps_failures_as_rows(client):
    # Fig. 14's fall (phi = 0.10, mu0 = 0.19, omega0 = 0.5) among walking points.
    g = {"mu0": [0.19, 0.5], "phi": [0.10, 0.10], "omega0": [0.5, 0.5]}
    dist = grid_sweep(client, g, scene="passive-slope", duration=5.0)
    assert dist["status"].tolist()[0] == "fell-backward"
    assert dist["status"].tolist()[1] != "fell-backward"
    local = sw.walk_points(g, scene="passive-slope", duration=5.0).to_pandas()
    pd.testing.assert_frame_equal(dist, local, check_exact=True)


def test_grid_sweep_checks_every_point_before_sending_work(client):
    with pytest.raises(ValueError, match=r"^invalid t_set: -1: .*\(grid row 2\)"):
        grid_sweep(client, {"t_set": [0.3, 0.3, -1.0]})


def test_grid_sweep_of_a_model_file_that_is_not_shipped_equals_one_process(client, tmp_path):
    # A copy of the compass gait whose hip mass is written `1*(m_H)`: the same walker, but not
    # the compiled model's canonical content, so every worker derives it (walker-load).
    copy = tmp_path / "compass-gait-copy.toml"
    text = (MODELS / "compass-gait.toml").read_text()
    assert 'mass = "m_H"' in text
    copy.write_text(text.replace('mass = "m_H"', 'mass = "1*(m_H)"'))
    g = {"phi": [0.04, 0.045, 0.05, 0.055], "mu0": [0.5, 0.6, 0.7, 0.8]}
    kw = dict(model=copy, friction="coulomb", impact="frictionless", duration=2.0)
    dist = grid_sweep(client, g, chunk_size=2, **kw)
    local = sw.walk_points(g, **kw).to_pandas()
    pd.testing.assert_frame_equal(dist, local, check_exact=True)
    assert "th_swd_plus" in dist.columns
    assert (dist["status"] == "ok").any()
