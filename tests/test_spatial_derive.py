"""The spatial derivation: its structured form against its closed form, the derived
parameters, the kinematic map, the checked-in folders' freshness and the code's growth."""

from __future__ import annotations

import json
from importlib import metadata
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from snakecg_derive.spatial.build import build_spatial_function
from snakecg_derive.spatial.catalog import CHECKED_IN_SPATIAL_JOINTS, SPATIAL_FUNCTIONS
from snakecg_derive.spatial.closed import closed_form_jacobians, closed_form_mass_matrix
from snakecg_derive.spatial.model import derive_spatial_model
from snakecg_derive.spatial.render import render_spatial_model, write_spatial_model

GENERATED = Path(__file__).parents[1] / "generated" / "spatial"


def _numbers(rng, s):
    """Raw parameters (unit axes) and a state as a substitution for the closed form, and the
    same as the generated functions' inputs."""
    nl, na = s.n_links, s.n_joints
    axes = rng.normal(size=(na, 3))
    axes /= np.linalg.norm(axes, axis=1)[:, None]
    raw = {"link_mass": rng.uniform(0.5, 2, nl), "link_com": rng.normal(0, 0.1, 3 * nl),
           "link_inertia": np.tile([0.02, 0.03, 0.04, 0.001, -0.002, 0.003], nl),
           "joint_xyz": rng.normal(0, 0.2, 3 * na), "joint_rpy": rng.uniform(-3, 3, 3 * na),
           "joint_axis": axes.ravel(), "gravity": np.array([0.0, 0.0, -9.81])}
    quat = rng.normal(size=4)
    q = np.r_[rng.normal(size=3), quat / np.linalg.norm(quat), rng.uniform(-3, 3, na)]
    subs = {}
    for name, syms, _ in s.raw_inputs:
        subs.update(zip(syms, raw[name]))
    subs.update(zip(s.q, q))
    return raw, q, subs


@pytest.mark.parametrize("n_links", (2, pytest.param(3, marks=pytest.mark.slow)))
def test_structured_mass_matrix_equals_the_closed_form(rng, n_links):
    """The recursion in axis frames (composite bodies about the base origin) and the closed
    form (poses differentiated, eq. M = sum J^T diag(m, I) J) agree to 1e-13."""
    d = derive_spatial_model(n_links)
    s = d.symbols
    raw, q, subs = _numbers(rng, s)
    fns = {f.name: build_spatial_function(f, "t_") for f in d.spec.functions}
    K = fns["derived_parameters"](*[raw[n] for n, _, _ in s.raw_inputs])
    M = np.array(fns["mass_matrix"](q, K))
    Mc = np.array(closed_form_mass_matrix(s).xreplace(subs).evalf(), dtype=float)
    assert np.abs(M - Mc).max() <= 1e-13 * np.abs(Mc).max()
    J = np.array(fns["link_jacobians"](q, K)).reshape(n_links, 6, s.nv)
    for i, (Jc, Jw) in enumerate(closed_form_jacobians(s)):
        assert np.allclose(np.array(Jw.xreplace(subs).evalf(), dtype=float), J[i, 3:],
                           rtol=0, atol=1e-13)


def test_axis_frames_take_z_to_the_axis(rng):
    """Every derived axis frame is a rotation with P e_z = a, on both branches (a_z >= 0 and
    a_z < 0) and at the poles."""
    d = derive_spatial_model(5)
    s = d.symbols
    f = build_spatial_function(d.spec.function("derived_parameters"), "t_")
    axes = np.array([[0, 0, 1.0], [0, 0, -1.0], [0.3, -0.5, 0.2], [0.3, 0.5, -0.9]])
    raw, _, _ = _numbers(rng, s)
    raw["joint_axis"] = axes.ravel()
    K = np.array(f(*[raw[n] for n, _, _ in s.raw_inputs])).ravel()
    start = len(s.raw_parameters)
    for j, a in enumerate(axes):
        P = K[start + 9 * j: start + 9 * j + 9].reshape(3, 3, order="F")
        assert np.allclose(P.T @ P, np.eye(3), atol=1e-15) and np.isclose(np.linalg.det(P), 1)
        assert np.allclose(P[:, 2], a / np.linalg.norm(a), atol=1e-15)


def test_kinematic_map_is_the_quaternion_rate(rng):
    """qdot = G v: the base position moves with R v_lin, the quaternion with 1/2 q (x) w
    (checked against a finite difference of Pinocchio's integrate)."""
    pin = pytest.importorskip("pinocchio", reason="Pinocchio is a test extra")
    d = derive_spatial_model(3)
    G = build_spatial_function(d.spec.function("kinematic_map"), "t_")
    model = pin.Model()
    j = model.addJoint(0, pin.JointModelFreeFlyer(), pin.SE3.Identity(), "b")
    for _ in range(2):
        j = model.addJoint(j, pin.JointModelRZ(), pin.SE3.Identity(), f"j{_}")
    q = pin.randomConfiguration(model, -np.ones(model.nq), np.ones(model.nq))
    v = rng.normal(size=model.nv)
    eps = 1e-7
    fd = (pin.integrate(model, q, v * eps) - pin.integrate(model, q, -v * eps)) / (2 * eps)
    assert np.allclose(np.array(G(q)) @ v, fd, atol=1e-8)


def test_catalog_lists_what_is_derived():
    names = tuple(f.name for f in derive_spatial_model(2).spec.functions)
    assert names == SPATIAL_FUNCTIONS


def test_generated_code_grows_like_n_squared():
    """Operations of the mass matrix and the link Jacobians at 4, 8, 16 links: the exponent
    of the last doubling stays below 2.2 (the structured form is O(n^2))."""
    from snakecg_derive.build import operation_count

    ops = {}
    for n in (4, 8, 16):
        d = derive_spatial_model(n)
        ops[n] = sum(operation_count(build_spatial_function(d.spec.function(name), "t_"))
                     for name in ("mass_matrix", "link_jacobians"))
    assert np.log2(ops[16] / ops[8]) < 2.2


def _pinned_toolchain():
    recorded = json.loads((GENERATED / "na1" / "manifest.json").read_text())["tools"]
    installed = {k: metadata.version(k) for k in recorded}
    if installed != recorded:
        pytest.fail(f"generated/spatial was produced with {recorded}, but {installed} is "
                    "installed: pip install '.[test]' (it pins them)", pytrace=False)


def test_checked_in_spatial_models_are_fresh(tmp_path):
    """Regenerating every checked-in spatial model gives the same bytes, no file missing or
    extra (regenerate with: python -m snakecg_derive.spatial --checked-in)."""
    _pinned_toolchain()
    for n in CHECKED_IN_SPATIAL_JOINTS:
        write_spatial_model(render_spatial_model(n + 1), tmp_path)

    def files(root):
        return {p.relative_to(root).as_posix(): p.read_bytes() for p in sorted(root.rglob("*"))
                if p.is_file() and "__pycache__" not in p.parts}

    fresh, committed = files(tmp_path), files(GENERATED)
    assert sorted(fresh) == sorted(committed)
    stale = [n for n in committed if fresh[n] != committed[n]]
    assert not stale, f"stale {stale}; regenerate: python -m snakecg_derive.spatial --checked-in"


def test_spec_has_no_free_symbols_and_is_deterministic():
    a, b = derive_spatial_model(3).spec, derive_spatial_model(3).spec
    assert a.digest() == b.digest()
    for f in a.functions:
        f.check_closed()
    assert all(isinstance(e, sp.Basic) for _, e in a.function("mass_matrix").assignments)
