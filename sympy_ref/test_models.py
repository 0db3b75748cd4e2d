"""Tests of the generic model reference (models.py, check_models.py); run with
`sympy_ref/.venv/bin/python -m pytest sympy_ref/test_models.py` or as a script.

The paper's two model files must reproduce the hand-written derivation (model.py) to the working
precision; the compass gait's M must be Goswami et al.'s; the outputs chosen for the actuated
models must leave A invertible at their start postures; every shipped model file must load and
have its reference data with every output name.
"""
from __future__ import annotations

import json
import os
import sys

import mpmath as mp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import check_models as cm  # noqa: E402
import models as ms  # noqa: E402


def test_paper_models_agree_with_the_hand_written_derivation():
    import model as md
    mdl = md.derive()
    for name in cm.PAPER:
        fresh, js, count = cm.check_paper(name, mdl)
        assert count > 0
        assert fresh < mp.mpf(10) ** -40, (name, fresh)
        assert js < mp.mpf(10) ** -31, (name, js)


def test_compass_gait_mass_matrix_is_goswamis():
    assert cm.check_goswami()


def test_actuated_models_have_invertible_A_at_the_start_posture():
    for name in cm.START:
        det, zf, _ = cm.check_start_A(name)
        assert abs(det) > 1e-6, (name, det)
        assert abs(zf) < 1e-12, (name, zf)     # both feet on the floor


def test_every_model_has_reference_data():
    for path in ms.model_files():
        m = ms.load(path)
        with open(os.path.join(ms.OUTDIR, f"{m.name}.json")) as fh:
            data = json.load(fh)
        assert data["coordinates"] == [s.name for s in m.q]
        assert len(data["samples"]) == ms.N_STRIKE + ms.N_GENERIC
        for row in data["samples"]:
            assert set(row["out"]) == set(data["names"])


if __name__ == "__main__":
    for name, fn in list(globals().items()):
        if name.startswith("test_"):
            fn()
            print("ok", name)
