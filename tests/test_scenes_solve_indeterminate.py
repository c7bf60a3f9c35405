"""The general solve on a statically indeterminate scene (the general-scene benchmark's: a
10-joint snake on Coulomb ground, two objects and four pegs touching it, 33 rows on 19
coordinates), batched as `forward` runs it: its accelerations against the exact piece
enumerated in NumPy around Clarabel's solution (1e-9), its KKT conditions checked densely,
its dependent flag against the rank of the face's rows (NumPy's SVD) and its minimum-norm
forces against Clarabel's."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg.scenes.model import WARM_CHUNK
from snakecg.scenes.solve import DISC

from scene_rows_equal import rows_equal
from scenes_reference import (approximate_accelerations, dense_problem, enumerate_pieces,
                              indeterminate_scene, kkt_violations)

JOINTS = 10


def _scene(q):
    return indeterminate_scene(q, JOINTS)


@pytest.fixture(scope="module")
def batch():
    rng = np.random.default_rng(20261205)
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(JOINTS))]
    model = snakecg.load(_scene(q))
    tau = rng.normal(0, 0.1, (40, JOINTS))
    res = model.forward(np.repeat(q[None], len(tau), axis=0), tau)
    return model, q, tau, res


def _sample(model, q, tau):
    """The one-sample result and its dense problem (M, A, G, b in NumPy)."""
    one = model.forward(q, tau)
    return one, dense_problem(one, model, tau)


def test_accelerations_against_enumerated_pieces(batch):
    model, q, tau, res = batch
    assert np.all(res.status == 0)
    assert len(res._rows[0].kind) == 20 and res._rows[0].A.shape == (33, 19)
    worst = 0.0
    for s in range(0, len(tau), 4):
        one, p = _sample(model, q, tau[s])
        a = np.r_[res.qdd[s], np.ravel(res.a_obj[s])]
        assert np.allclose(a, np.r_[one.qdd, np.ravel(one.a_obj)], rtol=0, atol=1e-12 * max(
            1.0, np.abs(a).max()))  # the batch answers each sample as one alone
        ref, _ = enumerate_pieces(p, approximate_accelerations(p))
        assert ref is not None
        worst = max(worst, np.abs(a - ref).max() / max(1.0, np.abs(ref).max()))
        assert kkt_violations(p, res._raw["lam"][s][:len(p["b"])], a) == []
    assert worst <= 1e-9


def test_dependent_flag_against_the_rank_of_the_face(batch):
    """The flag is set exactly where the rows that do not accelerate (held, or on a set's
    limit without sliding) are dependent: their rank by NumPy's SVD below their number."""
    model, q, tau, res = batch
    flags = res._raw["info"]["dependent"]
    assert np.all(np.isin(flags, (0, 1, 2)))
    p = _sample(model, q, tau[0])[1]  # (the rows are the batch's: one configuration)
    seen = set()
    for s in range(len(tau)):
        a = np.r_[res.qdd[s], np.ravel(res.a_obj[s])]
        face = _face(p, a)
        sv = np.linalg.svd(p["A"][face], compute_uv=False)
        rank = int(np.sum(sv > 1e-9 * sv.max()))
        assert (flags[s] > 0) == (rank < len(face)), (s, rank, len(face), flags[s])
        seen.add(bool(flags[s] > 0))
    assert True in seen  # (the check met dependent faces)


def _face(p, a):
    """The rows that do not accelerate (held, or on a set's limit without sliding), by block."""
    w = p["A"] @ a
    return [st + i for kind, st, _ in p["blocks"] for i in range(2 if kind >= DISC else 1)
            if np.abs(w[st:st + (2 if kind >= DISC else 1)]).max() <= 1e-7 * max(
                1.0, np.abs(w).max())]


def _min_norm_on_face(p, lam, face):
    """Clarabel's minimum-norm forces of the face's rows among all in their sets that give
    the same generalized force (A_F^T lam_F = A_F^T lam*_F; the moving rows' forces are
    fixed by their motion), the rest kept."""
    import cvxpy as cp

    AF = p["A"][face]
    _, sv, Vt = np.linalg.svd(AF.T)
    N = Vt[int(np.sum(sv > 1e-9 * sv.max())):].T
    t = cp.Variable(N.shape[1])
    lf = lam[face] + N @ t
    pos = {row: j for j, row in enumerate(face)}
    cons = []
    for kind, st, par in p["blocks"]:
        if st not in pos:
            continue
        if kind == DISC:
            cons.append(cp.norm(lf[pos[st]:pos[st] + 2]) <= par[0])
        else:  # this scene's other blocks: contacts
            cons.append(lf[pos[st]] >= 0)
    prob = cp.Problem(cp.Minimize(cp.sum_squares(lf)), cons)
    prob.solve(solver="CLARABEL", tol_gap_abs=1e-10, tol_gap_rel=1e-10, tol_feas=1e-10)
    out = lam.copy()
    out[face] = lam[face] + N @ t.value
    return out, prob.status


def test_minimum_norm_forces_against_clarabel(batch):
    """Where the flag says the forces are minimum-norm (1), no forces of the face within their
    sets with the same generalized force are shorter (Clarabel, to 1e-7)."""
    model, q, tau, res = batch
    flagged = np.flatnonzero(res._raw["info"]["dependent"] == 1)
    assert len(flagged) >= 2
    p = _sample(model, q, tau[0])[1]
    for s in flagged[:4]:
        a = np.r_[res.qdd[s], np.ravel(res.a_obj[s])]
        lam = res._raw["lam"][s][:len(p["b"])]
        ref, status = _min_norm_on_face(p, lam, _face(p, a))
        assert status == "optimal"
        assert np.linalg.norm(lam) <= np.linalg.norm(ref) * (1 + 1e-7) + 1e-9


@pytest.fixture(scope="module")
def grid():
    """A torque map of the scene (two joints' torques on a 36 x 32 grid, the others fixed),
    batched as `forward` runs it: neighbours with nearly the same pieces, so that the solves
    start from the last sample's."""
    rng = np.random.default_rng(7)
    q = np.r_[0.0, 0.0, 0.0, 0.25 * np.sin(np.arange(JOINTS))]
    model = snakecg.load(_scene(q))
    a, b = np.meshgrid(np.linspace(-0.3, 0.3, 36), np.linspace(-0.3, 0.3, 32), indexing="ij")
    tau = np.repeat(rng.normal(0, 0.1, (1, JOINTS)), a.size, axis=0)
    tau[:, 2], tau[:, 6] = a.ravel(), b.ravel()
    return model, q, tau, model.forward(np.repeat(q[None], len(tau), axis=0), tau)


def test_warm_batch_against_references_and_cold_samples(grid, monkeypatch):
    """The map's batch (warm starts) against the one-sample calls (cold): the same status,
    accelerations and metrics to 1e-10, the same dependent flag, the forces to 1e-9 where the
    flag says minimum-norm (1); against the exact pieces enumerated in NumPy (1e-9), the KKT
    conditions checked densely and Clarabel's minimum-norm forces; and the same bytes on two
    threads (the batch split on its cold samples)."""
    model, q, tau, res = grid
    info = res._raw["info"]
    assert np.all(res.status == 0)
    warm = np.arange(len(tau)) % WARM_CHUNK != 0
    # the starts were taken (no sweeps: a cold solve of these 33 rows on 19 coordinates
    # begins with sweeps) in most samples: the comparisons below are of warm solves
    assert np.mean(info["sweeps"][warm] == 0) > 0.6
    p = _sample(model, q, tau[0])[1]
    basic = differ = 0
    for s in range(len(tau)):
        one = model.forward(q, tau[s])
        assert one.status == 0 and one._raw["info"]["dependent"][0] == info["dependent"][s]
        a1, a = np.r_[one.qdd, np.ravel(one.a_obj)], np.r_[res.qdd[s], np.ravel(res.a_obj[s])]
        scale = max(1.0, np.abs(a1).max())
        assert np.abs(a - a1).max() <= 1e-10 * scale
        f = np.zeros(len(a1))
        f[3:3 + JOINTS] = tau[s]
        a_free = np.linalg.solve(p["M"], f)
        form = a_free @ p["M"] @ a_free  # the metrics' scale: the free motion's |a|^2_M
        for name in ("norm_qdd", "norm_a_obj", "norm_lambda"):
            assert abs(getattr(res, name)[s] - getattr(one, name)) <= 1e-10 * max(
                abs(getattr(one, name)), form, 1e-300), name
        assert abs(res.sr[s] - one.sr) <= 1e-10
        lam1, lam = one._raw["lam"][0][:len(p["b"])], res._raw["lam"][s][:len(p["b"])]
        near = np.abs(lam - lam1).max() <= 1e-9 * max(1.0, np.abs(lam1).max())
        if info["dependent"][s] == 2:  # another basic solution of the face: checked below
            basic += 1
            differ += not near
        else:
            assert near, s
        for key in ("primal", "dual", "complementarity"):
            assert info[key][s] <= 1e-9, key
        if s % 64 == 17 or not near:  # the references: the pieces on a sample of the map,
            ps = dense_problem(one, model, tau[s])  # the KKT conditions where forces differ
            assert kkt_violations(ps, lam, a) == []
        if s % 64 == 17:
            ref, _ = enumerate_pieces(ps, approximate_accelerations(ps))
            assert ref is not None
            assert np.abs(a - ref).max() <= 1e-9 * max(1.0, np.abs(ref).max())
    print(f"flag 2 (basic forces kept): {basic} of {len(tau)}, forces differing {differ}")
    flagged = np.flatnonzero(info["dependent"] == 1)
    assert len(flagged) >= 2
    for s in flagged[:: max(1, len(flagged) // 4)][:4]:
        a = np.r_[res.qdd[s], np.ravel(res.a_obj[s])]
        lam = res._raw["lam"][s][:len(p["b"])]
        ref, status = _min_norm_on_face(p, lam, _face(p, a))
        assert status == "optimal"
        assert np.linalg.norm(lam) <= np.linalg.norm(ref) * (1 + 1e-7) + 1e-9
    monkeypatch.setenv("SNAKECG_THREADS", "2")
    two = model.forward(np.repeat(q[None], len(tau), axis=0), tau)
    assert rows_equal(two._out, res._out)


def test_room_of_the_first_pass_changes_no_answer(grid, monkeypatch):
    """Where some samples find more contacts than the first pass has room for, the batch is
    solved again whole, so each sample starts from the same neighbour as with room for all:
    every number equals the run with room (forces of dependent faces included); and the
    details' forces (solved again in one call) are the records' own. The batch alternates
    the map's configuration (7 contacts) with one that leaves a peg (6 contacts)."""
    import snakecg.scenes.model as scene_model

    model, q, tau, _ = grid
    apart = q.copy()
    apart[3 + 5] -= 0.05
    Q = np.array([q if (s // 3) % 2 == 0 else apart for s in range(300)])
    T = tau[:300]
    roomy = model.forward(Q, T)
    assert sorted({len(c) for c in roomy.contacts}) == [6, 7]
    assert np.any(roomy._raw["info"]["dependent"] == 1)  # dependent faces are met
    monkeypatch.setattr(scene_model, "CONTACTS_FIRST", 6)  # the 7-contact samples out of room
    tight = model.forward(Q, T)
    for name in ("qdd", "a_obj", "norm_lambda", "norm_a_obj", "norm_qdd", "sr", "status"):
        np.testing.assert_array_equal(getattr(tight, name), getattr(roomy, name), name)
    assert tight.contacts == roomy.contacts and tight.ground == roomy.ground
    lam = tight._raw["lam"]
    for s in range(300):
        forces = [c["force"] for c in tight.contacts[s]]
        np.testing.assert_array_equal(lam[s][:len(forces)], forces)
