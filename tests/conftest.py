"""Shared fixtures of the test suite.

* A private model cache for the whole session: unless ``SNAKECG_CACHE_DIR`` is already set,
  it points at a fresh folder under pytest's temporary root *before any test runs*, so models
  generated or compiled by the tests (and by the subprocesses they start, which inherit the
  environment) never touch the user's cache. Test modules must not load models at import time.
* ``rng``: a ``numpy.random.Generator`` seeded from the test's node id, so every test has its
  own fixed stream (reordering or selecting tests does not change the numbers a test sees).
* ``random_robot``: a factory of robots with random per-link parameters over wide ranges.
* Every simulation any test runs is checked (autouse ``_simulations_never_overlap``): no
  sample before the first violation that the contact check reports overlaps beyond the
  tolerance, measured by the independent geometry of ``overlap_reference.py``.
"""

from __future__ import annotations

import os
import zlib

import numpy as np
import pytest

import snakecg


@pytest.fixture(scope="session", autouse=True)
def snakecg_cache_dir(tmp_path_factory):
    """The session's ``SNAKECG_CACHE_DIR`` (the caller's one if set, else a fresh folder)."""
    given = os.environ.get("SNAKECG_CACHE_DIR")
    if given:
        yield given
        return
    path = str(tmp_path_factory.mktemp("snakecg-cache"))
    os.environ["SNAKECG_CACHE_DIR"] = path
    try:
        yield path
    finally:
        os.environ.pop("SNAKECG_CACHE_DIR", None)


@pytest.fixture(autouse=True)
def _simulations_never_overlap(monkeypatch):
    """Every trajectory a simulation returns in this test is checked against the independent
    geometry (:func:`overlap_reference.check_trajectory`)."""
    from overlap_reference import check_trajectory

    from snakecg.simulate import simulator

    run = simulator.Simulator.run

    def checked(self):
        traj = run(self)
        check_trajectory(self.model.scene, self.settings.geometry_check, traj)
        return traj

    monkeypatch.setattr(simulator.Simulator, "run", checked)


@pytest.fixture
def rng(request) -> np.random.Generator:
    """A generator seeded from the test's node id (stable across runs and selections)."""
    return np.random.default_rng(zlib.crc32(request.node.nodeid.encode()))


def log_uniform(rng: np.random.Generator, lo: float, hi: float, size) -> np.ndarray:
    return np.exp(rng.uniform(np.log(lo), np.log(hi), size))


def random_link_parameters(rng: np.random.Generator, n_links: int) -> dict[str, tuple]:
    """Per-link parameters over wide ranges (four decades of mass and inertia, two of length),
    COM anywhere between 5 % and 95 % of the link."""
    length = log_uniform(rng, 0.02, 2.0, n_links)
    return {
        "mass": tuple(log_uniform(rng, 0.01, 100.0, n_links)),
        "length": tuple(length),
        "inertia": tuple(log_uniform(rng, 1e-5, 1.0, n_links)),
        "com": tuple(length * rng.uniform(0.05, 0.95, n_links)),
    }


@pytest.fixture
def random_robot(rng):
    """``random_robot(joints)``: a :class:`snakecg.Robot` with random per-link parameters."""

    def make(joints: int) -> snakecg.Robot:
        return snakecg.Robot(joints=joints, **random_link_parameters(rng, joints + 1))

    return make
