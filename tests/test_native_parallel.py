"""Large batches are split across threads (snakecg.native): results must not depend on it."""

from __future__ import annotations

import numpy as np

import snakecg
from snakecg.native import _PARALLEL_MIN


def test_threaded_batches_equal_one_thread(monkeypatch, rng):
    model = snakecg.load(snakecg.Scene(snakecg.Robot(joints=3), scenario="wheels"))
    if model.backend.kind != "compiled":
        import pytest

        pytest.skip("no C compiler: the CasADi backend does not split batches")
    n = 2 * _PARALLEL_MIN + 7  # uneven chunks
    q = rng.uniform(-2, 2, (n, 6))
    tau = rng.normal(scale=0.1, size=(n, 3))
    results = {}
    for threads in ("1", "3"):
        monkeypatch.setenv("SNAKECG_THREADS", threads)
        res = model.forward(q, tau)
        M = model.mass_matrix(q)
        results[threads] = (res, M)
    (r1, M1), (r3, M3) = results["1"], results["3"]
    np.testing.assert_array_equal(M1, M3)
    for field in ("qdd", "a_obj", "lam", "sr", "norm_lambda"):
        np.testing.assert_array_equal(getattr(r1, field), getattr(r3, field))
    np.testing.assert_array_equal(r1.wheel_state, r3.wheel_state)
