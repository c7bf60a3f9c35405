"""The paper's linear maps at rest of a scene model for a given active set (eqs. 17, 22-25,
28, 29, 31), and the metrics' quadratic forms: the generated ``interaction_maps`` and
``metric_forms`` at the scene's placement of the object, with the held rows' dependent samples
re-solved with the solver's Tikhonov term. Free functions of the model; the
:class:`~snakecg.SceneModel` methods of the same names call them."""

from __future__ import annotations

import numpy as np

from .errors import InputError
from .kernels import at_origin
from .solver import ABSENT, HELD, LOST, PIVOT_TOL, REGULARIZATION, SLIDE_NEG, SLIDE_POS
from .solver import _free_and_fixed

__all__ = ["at_rest", "maps", "state_forms", "state_maps"]


def place_object(model, q):
    """:meth:`SceneModel.place_object`: the object's pose, the contact point in its frame and
    in the world, for one configuration or a batch."""
    qa, batched = model._q(q)
    n = qa.shape[0]
    model._check_memory("place_object", n, ["place_object"])
    q_obj, rho, P = place(model, qa, n)
    if batched:
        return q_obj, rho, P
    return q_obj[0], rho[0], P[0]


def place(model, qa, n: int):
    """:func:`place_object` of a checked batch ``qa`` of ``n`` rows (generated
    ``place_object`` at the scene's contact)."""
    o = model._named("place_object", n, q=model._arg(qa, n), K=model.parameters,
                     contact_link=model._contact_link,
                     contact_offset=[model.scene.contact_offset],
                     object_distance=[model.scene.object_distance], side=model._side)
    return o["q_obj"][:, :, 0], o["rho"][:, :, 0], o["contact_point"][:, :, 0]


def maps(model, q, *, contact: bool = True, wheel_state=None) -> dict[str, np.ndarray]:
    """The paper's linear maps at rest for a given active set (default: everything held).

    Keys (each ``(..., rows, cols)``): ``qdd_from_tau`` (eq. 22), ``qdd_from_f_obj``
    (eq. 23), ``a_obj_from_tau`` (eq. 24), ``a_obj_from_f_obj`` (eq. 25),
    ``lam_from_tau``/``lam_from_f_obj`` (eq. 17), ``xi_tau`` (eq. 28), ``omega_tau``
    (eq. 29), ``lambda_form_tau`` (``lam^T G_c lam`` as a form in ``tau``),
    ``input_metric`` (``B^T M_s^-1 B``, eq. 31 corrected), ``projector_constrained``
    (eq. 14), ``projector_orthogonal`` (eq. 19), ``delassus`` (``G_c``), plus the
    ``*_offset`` vectors produced by sliding wheels' fixed forces and ``w_*`` maps of the
    rows' accelerations. ``pivot_ratio`` and ``singular``: the held rows were dependent;
    such samples are re-evaluated with a tiny Tikhonov term (least-norm forces, as in
    ``forward``).
    """
    if not isinstance(contact, (bool, np.bool_)):
        raise InputError(f"contact must be True or False, got {contact!r:.60}")
    if wheel_state is not None and not isinstance(wheel_state, str) and not (
            isinstance(wheel_state, (list, tuple, np.ndarray))
            and all(isinstance(w, (str, np.str_)) for w in wheel_state)):
        raise InputError(f"wheel_state must be None, a state name or a list of "
                         f"{model.n_links} of them, got {wheel_state!r:.60}")
    qa, batched = model._q(q)
    n = qa.shape[0]
    model._check_memory("maps", n, ["place_object", "interaction_maps"])
    state = np.where(model.present, HELD, ABSENT).astype(np.int8)
    if not contact:
        state[0] = LOST
    if wheel_state is not None:
        ws = [wheel_state] if isinstance(wheel_state, str) else list(wheel_state)
        if len(ws) != model.n_links:
            raise InputError(f"wheel_state must list {model.n_links} link states (one per"
                             f" link: 'stick', 'slide+', 'slide-', or 'none' without a"
                             f" wheel), got {wheel_state!r}")
        codes = {"stick": HELD, "slide+": SLIDE_POS, "slide-": SLIDE_NEG}
        for i, s in enumerate(ws):
            if model.present[i + 1] and s not in codes:
                raise InputError(f"wheel_state[{i}] must be 'stick', 'slide+' or 'slide-'"
                                 f" (link {i + 1} has a wheel), got {s!r}")
            if not model.present[i + 1]:
                if s not in ("none", *codes):
                    raise InputError(f"wheel_state[{i}] must be a wheel state ('none' for"
                                     f" link {i + 1}, which has no wheel), got {s!r}")
                continue
            state[i + 1] = codes[s]
    out = _maps(model, qa, n, state)
    return out if batched else {k: v[0] for k, v in out.items()}

def state_maps(model, qa, state) -> dict[str, np.ndarray]:
    """:func:`maps` of a checked batch ``qa`` for the row states ``state`` (``(n_c,)``
    solver codes, :mod:`snakecg.solver`), every sample batched."""
    return _maps(model, qa, qa.shape[0], np.asarray(state, dtype=np.int8))

def state_forms(model, qa, state) -> dict[str, np.ndarray]:
    """The metrics' quadratic forms in ``tau`` at rest (generated ``metric_forms``) of a
    checked batch ``qa`` for the row states ``state``; dependent held rows regularised."""
    return _metric_forms(model, qa, qa.shape[0], np.asarray(state, dtype=np.int8))

def at_rest(model, fname: str, qa, *free_args):
    """Evaluate a generated at-rest function (``interaction_maps``, ``metric_forms``,
    ``metric_extremes``) on a checked batch ``qa`` at the scene's placement: ``free_args``
    are its inputs after ``wheel_offset`` up to ``regularization`` (0). Returns the inputs
    and the outputs by name."""
    return _at_rest(model, fname, qa, qa.shape[0], *free_args)

def _maps(model, qa, n, state):
    free, lam_fixed = _free_and_fixed(state[None, :], model.bounds)
    args, raw = _at_rest(model, "interaction_maps", qa, n, free[0], lam_fixed[0])
    res = {}
    for name_, o in raw.items():
        if name_ == "pivot_ratio":  # the only scalar (a 1x1 map is still a matrix)
            res[name_] = o[:, 0, 0].copy()
        elif o.shape[2] == 1 and name_.endswith("offset"):
            res[name_] = np.ascontiguousarray(o[:, :, 0])
        else:
            res[name_] = np.ascontiguousarray(o)
    # dependent held rows: re-solve those samples with the solver's Tikhonov term
    finite = np.all(np.isfinite(res["lam_from_tau"].reshape(n, -1)), axis=1)
    singular = ~(res["pivot_ratio"] > PIVOT_TOL) | ~finite
    if np.any(singular):
        sub = np.flatnonzero(singular)
        scale = np.abs(np.diagonal(res["delassus"][sub], axis1=1, axis2=2)).max(axis=1)
        reg = (REGULARIZATION * np.maximum(scale, 1e-300)).reshape(-1, 1)
        sub_args = {k: a[sub] if a.ndim == 2 else a for k, a in args.items()}
        again = model._named("interaction_maps", len(sub), **{**sub_args,
                                                              "regularization": reg})
        for name_, o in again.items():
            if name_ != "pivot_ratio":
                res[name_][sub] = o.reshape(res[name_][sub].shape)
    res["singular"] = singular
    return res

def _at_rest(model, fname: str, qa, n: int, *free_args):
    """Evaluate a generated at-rest function (``interaction_maps``, ``metric_forms``,
    ``metric_extremes``) at the scene's placement of the object.

    ``free_args`` are the inputs that follow ``wheel_offset`` up to ``regularization``
    (the held-row masks, fixed forces, in signature order); ``regularization`` is 0.
    Returns the inputs ``{name: array}`` and ``{output name: (n, rows, cols) array}``.
    """
    qa = at_origin(qa)[0]  # (the object placed from the base at the origin)
    q_obj, rho, _ = place(model, qa, n)
    names = model.backend.signatures[fname].in_names
    tail = names[names.index("wheel_offset") + 1: names.index("regularization")]
    if len(tail) != len(free_args):
        raise InputError(f"{fname} takes {', '.join(tail)} after wheel_offset")
    args = {"q": model._arg(qa, n), "K": model.parameters,
            "contact_link": model._contact_link, "side": model._side,
            "object_mass": model._object_mass, "object_inertia": model._object_inertia,
            "q_obj": model._arg(q_obj, n), "rho": model._arg(rho, n),
            "wheel_offset": model._wheel_offset, **dict(zip(tail, free_args)),
            "regularization": np.zeros(1)}
    args = {k: np.ascontiguousarray(a, dtype=float) for k, a in args.items()}
    outs = model._named(fname, n, **args)
    return args, outs.as_dict()

def _metric_forms(model, qa, n, state):
    """Quadratic forms of the metrics at rest (generated ``metric_forms``), batched.

    Samples whose held rows are dependent fall back to :func:`_maps` (regularised).
    """
    free, _ = _free_and_fixed(state[None, :], model.bounds)
    _, raw = _at_rest(model, "metric_forms", qa, n, free[0])
    res = {}
    for name_, o in raw.items():
        if name_ == "pivot_ratio":  # the only scalar (a 1x1 form is still a matrix)
            res[name_] = o[:, 0, 0].copy()
        elif name_ == "contact_from_tau":
            res[name_] = np.ascontiguousarray(o[:, 0, :])
        else:
            res[name_] = np.ascontiguousarray(o)
    finite = np.all(np.isfinite(res["omega_tau"].reshape(n, -1)), axis=1)
    singular = ~(res["pivot_ratio"] > PIVOT_TOL) | ~finite
    if np.any(singular):
        sub = np.flatnonzero(singular)
        again = _maps(model, np.ascontiguousarray(qa[sub] if qa.shape[0] > 1 else qa),
                           len(sub), state)
        for k in ("omega_tau", "xi_tau", "lambda_form_tau", "input_metric"):
            res[k][sub] = again[k]
        res["contact_from_tau"][sub] = again["lam_from_tau"][:, 0, :]
    res["singular"] = singular
    return res
