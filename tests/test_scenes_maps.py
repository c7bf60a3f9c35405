"""The linear maps of a general scene for a fixed block state (snakecg.scenes.maps), against a
dense NumPy KKT model written apart (the saddle-point system of the held rows solved by
least squares) and finite differences of the compiled forward solve within a piece."""

from __future__ import annotations

import numpy as np
import pytest

import snakecg
from snakecg import Robot
from snakecg.errors import InputError
from snakecg.scenes import GeneralScene
from snakecg.scenes.solve import BOX, DISC, SLIDE, SPLIT

from scenes_reference import ALL_MODELS, POLYHEDRAL, dense_problem, peg_obstacles, random_scene


def solved(rng, models, tries=60):
    """A random solved one-sample problem with 1-6 contacts and independent rows."""
    for _ in range(tries):
        robot, ground, objects, pegs, q, tau = random_scene(rng, models)
        try:
            m0 = snakecg.load(GeneralScene(robot, ground=ground, objects=objects))
            model = snakecg.load(GeneralScene(robot, ground=ground, objects=objects,
                                              obstacles=peg_obstacles(m0, pegs, q)))
            res = model.forward(q, tau)
        except InputError:
            continue
        if 1 <= len(res.contacts) <= 6 and res.status == 0 and res.dependent == 0:
            return model, res, q, tau
    raise AssertionError("no random scene found")


def state_of(res):
    """The forward result's block states as maps' state entries (a sliding 2-D set at the
    parametric angle of its force)."""
    rows = res._rows[0]
    lam, codes = res._raw["lam"][0], res._raw["state"][0]
    out = []
    for kind, st, par, code, label in zip(rows.kind, rows.start, rows.par, codes,
                                          rows.labels):
        par = np.ravel(par)
        if label[0] == "contact":
            out.append("held" if code == 0 else "open")
        elif kind == BOX:
            out.append("stick" if code == 0 else "none" if code == 1
                       else ("slide+" if lam[st] > 0 else "slide-"))
        elif kind in (DISC, SPLIT):
            if code == SLIDE:
                l0, l1 = lam[st:st + 2]
                if kind == DISC:
                    c, s = l0 / par[0], l1 / par[0]
                else:
                    c, s = l0 / (par[0] if l0 < 0 else par[1]), l1 / par[2]
                out.append(("slide", float(np.arctan2(s, c))))
            else:
                out.append("stick" if code == 0 else "none")
        else:
            out.append("held")
    return out


def dense_affine(p, state_codes, lam_fixed, tau, f_obj):
    """a and lam from the saddle-point system [[M, -A_H^T], [A_H, 0]] [a; lam_H] =
    [B tau + f_obj + A_F^T lam_F; 0] (NumPy least squares)."""
    A, M = p["A"], p["M"]
    held = np.array([i for i, c in enumerate(state_codes) if c], dtype=int)
    free = np.array([i for i, c in enumerate(state_codes) if not c], dtype=int)
    n, h = M.shape[0], held.size
    f = np.zeros(n)
    ns = n - f_obj.size
    f[3:ns] = tau
    f[ns:] = f_obj
    f += A[free].T @ lam_fixed
    K = np.zeros((n + h, n + h))
    K[:n, :n] = M
    K[:n, n:] = -A[held].T
    K[n:, :n] = A[held]
    x = np.linalg.lstsq(K, np.r_[f, np.zeros(h)], rcond=None)[0]
    lam = np.zeros(A.shape[0])
    lam[held] = x[n:]
    lam[free] = lam_fixed
    return x[:n], lam


def test_maps_against_a_dense_kkt_model(rng):
    checked = 0
    for _ in range(40):
        model, res, q, tau = solved(rng, ALL_MODELS)
        st = state_of(res)
        mp = model.maps(q, state=st)
        no = model.scene.n_objects
        p = dense_problem(res, model, tau)
        rows = res._rows[0]
        lam0 = res._raw["lam"][0][:p["A"].shape[0]]
        held_rows, fixed = [], []
        for (kind, s, _), code in zip(p["blocks"], mp["state"]):
            size = 2 if kind in (DISC, SPLIT) else 1
            held_rows += [code == 0] * size
            if code != 0:
                fixed += list(lam0[s:s + size])
        for trial in range(3):
            t = rng.normal(size=model.n_joints) * (1 + trial)
            fo = rng.normal(size=3 * no)
            a_ref, lam_ref = dense_affine(p, held_rows, np.array(fixed), t, fo)
            qdd = mp["qdd_from_tau"] @ t + mp["qdd_from_f_obj"] @ fo + mp["qdd_offset"]
            ao = (mp["a_obj_from_tau"] @ t + mp["a_obj_from_f_obj"] @ fo
                  + mp["a_obj_offset"])
            lam = mp["lam_from_tau"] @ t + mp["lam_from_f_obj"] @ fo + mp["lam_offset"]
            w = mp["w_from_tau"] @ t + mp["w_from_f_obj"] @ fo + mp["w_offset"]
            scale = max(1.0, np.abs(a_ref).max())
            assert np.abs(qdd - a_ref[:model.n_coordinates]).max() <= 1e-9 * scale
            assert np.abs(ao.ravel() - a_ref[model.n_coordinates:]).max(initial=0) <= 1e-9 * scale
            assert np.abs(lam - lam_ref).max() <= 1e-9 * max(1.0, np.abs(lam_ref).max())
            assert np.allclose(w, rows.A @ a_ref, atol=1e-9 * scale)
        # at the forward solve's own torque and state, the maps give its answer
        qdd = mp["qdd_from_tau"] @ tau + mp["qdd_offset"]
        assert np.abs(qdd - res.qdd).max() <= 1e-8 * max(1.0, np.abs(res.qdd).max())
        # the forms are the metrics of the homogeneous part (eqs. 26-29)
        t = rng.normal(size=model.n_joints)
        Q, Ao = mp["qdd_from_tau"] @ t, mp["a_obj_from_tau"] @ t
        assert np.isclose(t @ mp["xi_tau"] @ t, Q @ p["M"][:len(Q), :len(Q)] @ Q,
                          rtol=1e-10, atol=1e-14)
        I_o = [np.diag([o.mass, o.mass, o.plate_inertia]) for o in model.scene.objects]
        assert np.isclose(t @ mp["omega_tau"] @ t,
                          sum(Ao[j] @ I_o[j] @ Ao[j] for j in range(no)), rtol=1e-10,
                          atol=1e-14)
        Lt = mp["lam_from_tau"] @ t
        assert np.isclose(t @ mp["lambda_form_tau"] @ t, Lt @ p["G"] @ Lt, rtol=1e-9,
                          atol=1e-14)
        checked += 1
    assert checked == 40


def test_maps_against_finite_differences_of_forward(rng):
    """Within a piece the compiled forward solve is affine in tau: its differences equal the
    maps' columns."""
    compared = 0
    for _ in range(40):
        model, res, q, tau = solved(rng, POLYHEDRAL + ("coulomb",))
        st = state_of(res)
        if any(isinstance(s, tuple) for s in st):
            continue  # a sliding disc turns with tau: not affine
        mp = model.maps(q, state=st)
        h = 1e-5 * max(1.0, np.abs(tau).max())
        for j in range(model.n_joints):
            t2 = tau.copy()
            t2[j] += h
            r2 = model.forward(q, t2)
            if state_of(r2) != st:
                continue
            d = (r2.qdd - res.qdd) / h
            assert np.allclose(d, mp["qdd_from_tau"][:, j], rtol=1e-5,
                               atol=1e-5 * max(1.0, np.abs(mp["qdd_from_tau"]).max()))
            da = (r2.a_obj - res.a_obj) / h
            assert np.allclose(da, mp["a_obj_from_tau"][:, :, j], rtol=1e-5,
                               atol=1e-5 * max(1.0, np.abs(mp["a_obj_from_tau"]).max(initial=0)))
            compared += 1
    assert compared >= 40


def test_maps_states_are_checked_before_any_work():
    scene = GeneralScene(Robot(joints=1))
    model = snakecg.load(scene)
    assert model.maps([0.0] * 4)["blocks"] == []
    with pytest.raises(InputError, match=r"q must be 4 finite numbers"):
        model.maps([0.0] * 3)
    with pytest.raises(InputError, match=r"state must list 0 block states"):
        model.maps([0.0] * 4, state=["held"])
    from snakecg.scenes.toml_reading import read_scene

    model = snakecg.load(read_scene("examples/scenes/wall_push.toml"))
    with pytest.raises(InputError, match=r"state\[0\] \(contact link 1 - obstacle 1 \(wall\)"
                                         r"\) must be one of held, open"):
        model.maps([0.0] * 6, state=["stick"] + ["held"] * 2 + ["stick"] * 5)
    mp = model.maps([0.0] * 6, state=["open"] * 3 + [("slide", 0.5)] * 5)
    assert np.allclose(mp["lam_offset"][3:5], 0.3 * 1.0 * 9.81 * np.array([np.cos(0.5),
                                                                           np.sin(0.5)]))
