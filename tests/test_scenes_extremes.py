"""Extremes of the metrics of a general scene over the input ellipsoid (snakecg.scenes.
extremes): the exact pieces against SciPy's generalized eigenvalues on forms built by a dense
saddle-point model, and every method against a brute-force search with the compiled forward
solve over dense torques on the ellipsoid's boundary (no sample beats an extreme, a bound
holds every sample, and the returned torque reaches the value)."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

import snakecg
from snakecg import Robot, Scene
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene, Ground, SceneObject
from snakecg.scenes.toml_reading import read_scene

from scenes_reference import POLYHEDRAL, dense_problem, small_scenes

METRICS = ("norm_a_obj", "norm_qdd", "norm_lambda", "sr")


def boundary(rng, model, q, count):
    """``count`` random torques with tau^T B^T M_s^-1 B tau = 1 (eq. 31), and N."""
    M = model.mass_matrix(np.asarray(q, float))
    N = np.linalg.inv(M)[3:, 3:]
    t = rng.normal(size=(count, model.n_joints))
    t /= np.sqrt(np.einsum("ki,ij,kj->k", t, N, t))[:, None]
    return t, N


def sampled(model, q, taus):
    res = model.forward(np.repeat(np.asarray(q, float)[None], len(taus), axis=0), taus)
    assert np.all(res.status == 0)
    # where nothing moves (|a|_M^2 below 1e-12 of the free motion's 1) sr is a ratio of
    # rounding errors: 0 by the paper's convention
    still = res.norm_a_obj + res.norm_qdd < 1e-12
    return {"norm_a_obj": res.norm_a_obj, "norm_qdd": res.norm_qdd,
            "norm_lambda": res.norm_lambda, "sr": np.where(still, 0.0, res.sr)}, res


def held_form(p, held, ns):
    """Columns of (qdd, a_obj, lam) per unit torque with the rows ``held`` (bool per row)
    held and the others free of force: the saddle-point system solved densely."""
    A, M = p["A"], p["M"]
    n = M.shape[0]
    H = np.flatnonzero(held)
    K = np.zeros((n + H.size, n + H.size))
    K[:n, :n], K[:n, n:], K[n:, :n] = M, -A[H].T, A[H]
    na = ns - 3
    rhs = np.zeros((n + H.size, na))
    rhs[3:ns] = np.eye(na)
    x = np.linalg.solve(K, rhs)
    lam = np.zeros((A.shape[0], na))
    lam[H] = x[n:]
    return x[:n], lam


@pytest.mark.parametrize("joints", [2, 3])
def test_exact_pieces_against_scipy_generalized_eigenvalues(joints, rng):
    """The paper's ideal-wheel scene as a general one: one contact, every wheel row held. The
    forms are even, so each half (contact held, contact open) has the extremes of its whole
    form: SciPy's eigh(X, N) per half, the max of the two."""
    for _ in range(5):
        scene = Scene(Robot(joints=joints), scenario="ideal_wheels")
        model = snakecg.load(GeneralScene.from_scene(scene))
        q = np.r_[0.0, 0.0, 0.0, rng.uniform(-1.5, 1.5, joints)]
        res = model.forward(q, np.zeros(joints))
        p = dense_problem(res, model, np.zeros(joints))
        ns = model.n_coordinates
        rows = res._rows[0]
        contact = np.array([lab[0] == "contact" for lab in rows.labels])
        N = np.linalg.inv(model.mass_matrix(q))[3:, 3:]
        ex = model.extremes(q)
        assert ex.certified and ex.method.startswith("exact")
        tops = {m: [] for m in METRICS}
        for keep in (True, False):
            a, lam = held_form(p, np.where(contact, keep, True), ns)
            Ms = p["M"][:ns, :ns]
            forms = {"norm_qdd": a[:ns].T @ Ms @ a[:ns],
                     "norm_a_obj": a[ns:].T @ p["M"][ns:, ns:] @ a[ns:],
                     "norm_lambda": lam.T @ p["G"] @ lam}
            for m, X in forms.items():
                tops[m].append(scipy.linalg.eigh(X, N, eigvals_only=True)[-1])
            if keep:
                D = forms["norm_a_obj"] + forms["norm_qdd"]
                tops["sr"].append(scipy.linalg.eigh(forms["norm_a_obj"], D,
                                                    eigvals_only=True)[-1])
        for m in METRICS:
            assert ex.max[m] == pytest.approx(max(tops[m]), rel=1e-9, abs=1e-13), m
            assert ex.bound_max[m] == ex.max[m] and ex.gap[m] == 0.0


def _check_against_samples(model, q, ex, rng, count=5000, tol=1e-9):
    taus, N = boundary(rng, model, q, count)
    vals, _ = sampled(model, q, taus)
    for m in METRICS:
        assert vals[m].max() <= ex.bound_max[m] + tol, m
        assert vals[m].min() >= ex.bound_min[m] - tol, m
        assert ex.max[m] <= ex.bound_max[m] and ex.min[m] >= ex.bound_min[m]
        # the returned torques lie on the boundary and reach the values
        for attr in ("max", "min"):
            t = getattr(ex, "tau_" + attr)[m]
            assert t @ N @ t == pytest.approx(1.0, rel=1e-9)
            got, _ = sampled(model, q, t[None])
            assert got[m][0] == pytest.approx(getattr(ex, attr)[m], rel=1e-8, abs=1e-8), m
    return vals


def test_exact_pieces_against_brute_force_forward(rng):
    """Random polyhedral scenes (contacts, bounded and ideal wheels): no dense sample of the
    ellipsoid beats the exact extremes, and the best one comes close."""
    done = 0
    for model, q, res in small_scenes(rng, 12, POLYHEDRAL):
        if done == 8:
            break
        ex = model.extremes(q)
        if not ex.method.startswith("exact"):
            continue
        assert ex.certified, ex.reason
        vals = _check_against_samples(model, q, ex, rng)
        for m in ("norm_qdd", "norm_lambda"):  # dense samples come near the extremes
            assert vals[m].max() >= ex.max[m] - 0.05
        done += 1
    assert done == 8


def test_pegs_example_exact():
    model = snakecg.load(read_scene("examples/scenes/pegs.toml"))
    q = np.array([0, 0, 0, 0.6, -0.6, 0.6])
    ex = model.extremes(q)
    assert ex.certified and ex.method.startswith("exact")
    _check_against_samples(model, q, ex, np.random.default_rng(1))


@pytest.mark.parametrize("path,q", [("wall_push", [0, 0, 0, 0.05, 0, 0]),
                                    ("two_objects", [0, 0, 0, 0.05, -0.05, 0.05])])
def test_certified_bounds_hold_every_sample(path, q, rng):
    """Coulomb ground: the bounds hold every dense sample; the values are attained. (Nearly
    straight: bent further, friction holds every torque of the unit ellipsoid still, answered
    exactly in tests/test_scenes_friction_hold.py.)"""
    model = snakecg.load(read_scene(f"examples/scenes/{path}.toml"))
    q = np.array(q, float)
    ex = model.extremes(q, budget=20000, gap=1e-3)
    assert ex.method.startswith("certified bounds")
    assert ex.samples <= 20000
    taus, N = boundary(rng, model, q, 5000)
    vals, res = sampled(model, q, taus)
    D = res.norm_a_obj + res.norm_qdd
    for m in METRICS:
        v = vals[m] if m != "sr" else vals[m][D >= 1e-3]  # sr: where the system moves
        assert v.max(initial=0) <= ex.bound_max[m] + 1e-9, m
        if m != "sr":
            assert v.min() >= ex.bound_min[m] - 1e-9, m
        t = ex.tau_max[m]
        got, _ = sampled(model, q, t[None])
        assert got[m][0] == pytest.approx(ex.max[m], rel=1e-8, abs=1e-12)
        assert vals[m].max() <= ex.max[m] + ex.gap[m] + 1e-9
    for j in range(model.scene.n_objects):  # each object, and their sum
        assert ex.max[f"norm_a_obj[{j + 1}]"] <= ex.max["norm_a_obj"] + 1e-12
        each = res.norm_a_obj_each[:, j]
        assert each.max() <= ex.bound_max[f"norm_a_obj[{j + 1}]"] + 1e-9


def test_sr_bounds_say_they_leave_out_where_the_system_barely_moves(rng):
    """Anisotropic ground, a light disc and a heavy box on the tail: near the torques that
    barely move anything, sr (0/0 in the limit) exceeds the bound that holds everywhere
    else. The certificate says where its sr bounds hold, and they hold there (dense samples
    of the boundary)."""
    robot = Robot(joints=2, mass=(1.8372758359983001, 0.513359276666714, 0.5797477328445665),
                  length=(0.13274658414229454, 0.19268215119066423, 0.14142131731719346),
                  inertia=(0.0018765130410494638, 0.002495706365974305,
                           0.0036370277964803167))
    ground = tuple(Ground(model="anisotropic", mu_forward=f, mu_backward=b, mu_lateral=lat)
                   for f, b, lat in ((0.4110700288873764, 0.4329430802786753,
                                      0.22796310355280885),
                                     (0.17051030498649764, 0.10709227117904699,
                                      0.33541953700718824),
                                     (0.14728415654235577, 0.3729916738211128,
                                      0.7791781642877037)))
    objects = (SceneObject(shape="disc", radius=0.04777671561903046, mass=2.44052332517951,
                           touching={"link": 1, "offset": 0.02363037184251137,
                                     "side": "left"}),
               SceneObject(shape="box", size=(0.04805463751773643, 0.062310340275320134),
                           mass=46.87759884632557,
                           touching={"link": 1, "offset": 0.11163556007443937,
                                     "side": "left"}))
    model = snakecg.load(GeneralScene(robot, ground=ground, objects=objects))
    q = np.array([-0.048348068488258775, 2.4093218644493075, -2.5770613172376926,
                  -0.4050342269434065, 0.08232609349181863])
    ex = model.extremes(q, budget=3000, gap=1e-3)
    assert ex.method.startswith("certified bounds") and ex.certified
    assert "sr's bounds hold where |a|_M^2 >= 0.001" in ex.method
    taus, _ = boundary(rng, model, q, 6000)
    vals, res = sampled(model, q, taus)
    D = res.norm_a_obj + res.norm_qdd
    moves = D >= 1e-3
    assert vals["sr"][moves].max() <= ex.bound_max["sr"] + 1e-9
    assert vals["sr"][moves].min() >= ex.bound_min["sr"] - 1e-9
    assert vals["sr"][~moves].max() > ex.bound_max["sr"]  # what is left out, and why


def test_batches_and_bad_input():
    model = snakecg.load(read_scene("examples/scenes/pegs.toml"))
    q = np.array([[0, 0, 0, 0.6, -0.6, 0.6], [0, 0, 0, 0.6, -0.6, 0.6]], float)
    ex = model.extremes(q)
    assert ex.max["norm_qdd"].shape == (2,) and ex.certified.tolist() == [True, True]
    assert ex.tau_max["sr"].shape == (2, 3)
    with pytest.raises(InputError, match=r"q has shape \(5,\), expected \(6,\)"):
        model.extremes(np.zeros(5))
    with pytest.raises(InputError, match=r"gap must be a number in \(0, 1\)"):
        model.extremes(q[0], gap=2.0)
    with pytest.raises(InputError, match=r"budget must be an integer"):
        model.extremes(q[0], budget=10)
    coul = snakecg.load(read_scene("examples/scenes/wall_push.toml"))
    with pytest.raises(InputError, match=r"exact=True needs every block to be a 1-D set"):
        coul.extremes(np.zeros(6), exact=True)
