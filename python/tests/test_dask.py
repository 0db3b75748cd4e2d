"""``slippery_walker.dask.grid_sweep`` and ``survival_grid`` on a local cluster of two worker
processes give the same table, and the same batches of walks on floors, as one process."""

import json

import numpy as np
import pandas as pd
import pytest
import slippery_walker as sw
from conftest import MODELS
from dask.distributed import Client, LocalCluster
from slippery_walker.dask import _survive_chunk, grid_sweep, survival_grid


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


MARKOV = {"kind": "random", "seed": 9,
          "mu0": {"distribution": "markov", "dry": 0.3, "icy": 0.05, "dry_length": 20,
                  "icy_length": 1.5}}
UNIFORM = {"kind": "random", "seed": 4, "mu0": {"distribution": "uniform", "lo": 0.08, "hi": 0.4}}
SETTINGS = [{"scene": "passive-slope"}, {"scene": "passive-slope", "phi": 0.15},
            {"t_set": 0.3, "friction": "coulomb"}]


def local_batches(grid, floors, seeds, **kw):
    """The batches of ``survival_grid`` run by ``survive`` in this process, in its order."""
    return [sw.survive(**entry, floor={**f, "seed": s}, **kw)
            for entry in grid for f in floors for s in seeds]


def test_survival_grid_on_two_processes_equals_survive_in_one_process(client):
    kw = dict(walks=12, max_steps=30)
    cells = survival_grid(client, SETTINGS, floor=[MARKOV, UNIFORM], seeds=[9, 10],
                          chunk_size=5, **kw)
    local = local_batches(SETTINGS, [MARKOV, UNIFORM], [9, 10], **kw)
    assert [c["result"] for c in cells] == local
    # Bit for bit: the same JSON text, key order and digits included.
    assert [json.dumps(c["result"]) for c in cells] == [json.dumps(r) for r in local]
    assert [(c["grid"], c["floor"], c["seed"], c["error"]) for c in cells] == [
        (g, f, s, None) for g in range(3) for f in range(2) for s in (9, 10)]
    assert cells[4]["settings"] == SETTINGS[1]
    # Not trivial: walks fail (on the passive wheel's slope) and walks reach the limit.
    failures = sum(r["survival"]["failures"] for r in local)
    censored = sum(r["survival"]["censored"] for r in local)
    assert failures > 0 and censored > 0, (failures, censored)


def test_survival_grid_gives_the_same_batches_for_any_chunk_size(client):
    kw = dict(floor=MARKOV, walks=10, max_steps=30, scene="passive-slope")
    default = survival_grid(client, [{}, {"phi": 0.15}], **kw)
    for chunk_size in (1, 3, 10, 1000):
        assert survival_grid(client, [{}, {"phi": 0.15}], chunk_size=chunk_size, **kw) == default
    assert [c["result"] for c in default] == [
        sw.survive(**kw), sw.survive(**kw, phi=0.15)]


def test_survival_grid_without_seeds_walks_each_floor_on_its_own_seed(client, tmp_path):
    path = tmp_path / "markov.toml"
    path.write_text('kind = "random"\nseed = 9\n[mu0]\ndistribution = "markov"\ndry = 0.3\n'
                    'icy = 0.05\ndry_length = 20\nicy_length = 1.5\n')
    cells = survival_grid(client, floor=[path, UNIFORM], walks=6, max_steps=20,
                          scene="passive-slope")
    assert [c["seed"] for c in cells] == [None, None]
    assert cells[0]["result"] == sw.survive(floor=MARKOV, walks=6, max_steps=20,
                                            scene="passive-slope")
    assert cells[1]["result"] == sw.survive(floor=UNIFORM, walks=6, max_steps=20,
                                            scene="passive-slope")


@pytest.mark.parametrize("kwargs, message", [
    (dict(walks=0), r"^invalid walks: 0: must be in \[1, 100000\]"),
    (dict(max_steps=0), r"^invalid max_steps: 0"),
    (dict(walks=100_000, max_steps=1001), r"^invalid walks: .*steps in all"),
    (dict(chunk_size=0), r"^invalid chunk_size: 0: must be an integer >= 1"),
    (dict(seeds=[1, -1]), r"^invalid seeds\[1\]: -1: must be in \[0, 9223372036854775807\]"),
    (dict(grid=[{}, {"scene": "active-level", "t_set": -1.0}]), r"^invalid t_set: -1.*\(grid\[1\], floor\[0\]\)$"),
    (dict(grid=[{"tset": 0.3}]), r"^invalid grid\[0\]: 'tset': not a keyword"),
    (dict(floor=[MARKOV, {**UNIFORM, "mu0": {**UNIFORM["mu0"], "hi": 0.01}}]),
     r"^invalid floor\['mu0'\]\['hi'\]: 0\.01: must be > mu0\.lo.*\(grid\[0\], floor\[1\]\)$"),
    (dict(floor=[{"kind": "uniform", "mu0": 0.3}], seeds=[1]),
     r"^invalid floor\[0\]: .*seeds are given, so every floor must be a random floor"),
    (dict(floor=[]), r"^invalid floor: \[\] \(list\): must be a floor"),
    (dict(set={"mu0": 0.3}), r"^invalid set\['mu0'\]: cannot be given with floor"),
])
def test_survival_grid_refuses_bad_arguments_naming_them_before_sending_work(client, kwargs,
                                                                              message):
    args = {**dict(floor=MARKOV, walks=4, max_steps=10, scene="passive-slope"), **kwargs}
    with pytest.raises(ValueError, match=message):
        survival_grid(client, args.pop("grid", None), **args)


def test_a_task_that_raises_returns_its_error_instead_of_losing_the_others():
    # The chunk a worker runs: an exception becomes the batch's error, not the gather's.
    options = sw._survive_options(floor=MARKOV, scene="passive-slope", t_set=-1.0)
    got = _survive_chunk(options, 0, 2, 5)
    assert set(got) == {"error"} and got["error"].startswith("ValueError: invalid t_set")
    good = _survive_chunk(sw._survive_options(floor=MARKOV, scene="passive-slope"), 3, 2, 30)
    assert good == sw.survive(floor=MARKOV, scene="passive-slope", walks=5, max_steps=30)[
        "outcomes"][3:5]


def test_survival_grid_takes_a_dataframe_of_settings_as_a_list_of_dicts(client):
    kw = dict(floor=MARKOV, walks=4, max_steps=20, scene="passive-slope")
    by_frame = survival_grid(client, pd.DataFrame({"phi": [0.15, 0.2]}), **kw)
    by_list = survival_grid(client, [{"phi": 0.15}, {"phi": 0.2}], **kw)
    assert [c["result"] for c in by_frame] == [c["result"] for c in by_list]
    assert [c["settings"] for c in by_frame] == [{"phi": 0.15}, {"phi": 0.2}]
