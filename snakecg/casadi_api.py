"""The generated CasADi functions as public API: for one's own ``casadi.Opti``, acados, ...

Every model function that snakecg evaluates (``mass_matrix``, ``constrained_dynamics``,
``interaction_maps``, ...) is a named :class:`casadi.Function`, serialized with the model.
:meth:`~snakecg.RobotModel.casadi_function` returns it; its inputs are those listed in the
model's manifest, in order. :func:`function_inputs` gives, for a loaded robot or scene, the
value of every input that does not change with the configuration and the torque (the
parameter vector ``K``, the scene's contact link, side, object mass, ...), plus the at-rest
defaults of the state inputs, so that ``f(q=q, tau=tau, **model.function_inputs(name))``
reproduces what the runtime computes. ``casadi_function(name, bind=True)`` embeds those values
and places the object from ``q`` symbolically: a function of ``q`` and ``tau`` only, whose
derivatives CasADi computes.

The inputs, their meaning and the layout of ``K`` are documented in docs/how-to/casadi.md.
"""

from __future__ import annotations

import numpy as np

from .errors import InputError

__all__ = ["casadi_function", "function_inputs", "parameter_names", "STATE_INPUTS",
           "SCENE_INPUTS", "ACTIVE_SET_INPUTS"]

#: Inputs that take the state at rest by default (zeros): snake velocities, object twist and
#: external wrench on the object.
STATE_INPUTS = ("v", "v_obj", "f_obj")
#: Inputs fixed by the scene (object, contact, wheels); a plain robot model has none of them.
SCENE_INPUTS = ("contact_link", "side", "object_mass", "object_inertia", "wheel_offset",
                "contact_offset", "object_distance")
#: Inputs that select the active set: ``free`` (1 = the row's force is solved for, 0 = fixed to
#: ``lam_fixed``), ``free_lost`` (the same with the contact lost), ``lam_fixed`` and the
#: Tikhonov term ``regularization`` (0 unless the held rows are dependent).
ACTIVE_SET_INPUTS = ("free", "free_lost", "lam_fixed", "regularization")
#: Inputs that follow the configuration: the object's pose and the contact point in its frame
#: (the scene's placement, function ``place_object``).
PLACEMENT_INPUTS = ("q_obj", "rho")

_CASADI: dict[str, object] = {}


def _backend(model):
    """CasADi's evaluation of the model's generated functions (shared per model folder)."""
    be = model.backend
    if getattr(be, "kind", None) == "casadi" and hasattr(be, "casadi_function"):
        return be
    key = str(model.folder)
    if key not in _CASADI:
        from .native import CasadiBackend

        _CASADI[key] = CasadiBackend(model.folder, model.manifest)
    return _CASADI[key]


def _signature(model, name) -> dict:
    names = [f["name"] for f in model.manifest["functions"]]
    if not isinstance(name, str) or name not in names:
        raise InputError(f"name must be the name of a generated function, one of "
                         f"{', '.join(names)}; got {name!r}")
    return next(f for f in model.manifest["functions"] if f["name"] == name)


def casadi_function(model, name: str, *, bind: bool = False, **inputs):
    """The generated :class:`casadi.Function` ``name`` of ``model``'s joint count.

    ``bind=False`` (default): the function as generated, every input in the manifest's order
    (``f.name_in()``). ``bind=True``: a function of the remaining inputs only (``q``,
    ``tau``, ... in the generated order) with :func:`function_inputs` embedded as constants
    and, for a scene, ``q_obj`` and ``rho`` computed from ``q`` by ``place_object`` (so they
    follow the configuration, derivatives included). Keyword ``inputs`` override the embedded
    values; an input given as ``None`` stays an input of the bound function.
    """
    sig = _signature(model, name)
    f = _backend(model).casadi_function(name)
    if not bind:
        if inputs:
            raise InputError("input values are only taken with bind=True; got "
                             + ", ".join(sorted(inputs)))
        return f
    import casadi as ca

    in_names = [i["name"] for i in sig["inputs"]]
    unknown = sorted(set(inputs) - set(in_names))
    if unknown:
        raise InputError(f"{name} has no input {unknown[0]!r}; its inputs are "
                         f"{', '.join(in_names)}")
    fixed = function_inputs(model, name)
    place = hasattr(model, "scene") and "q" in in_names and all(
        k in in_names for k in PLACEMENT_INPUTS)
    for k, val in inputs.items():
        if val is None:
            fixed.pop(k, None)
        else:
            fixed[k] = _column(name, k, val, _rows(sig, k))
    syms, args = [], {}
    for item in sig["inputs"]:
        k = item["name"]
        if k in fixed:
            args[k] = ca.DM(fixed[k].reshape(item["rows"], item["cols"], order="F"))
        elif place and k in PLACEMENT_INPUTS and k not in inputs:
            continue  # from place_object below
        else:
            s = ca.MX.sym(k, item["rows"], item["cols"])
            syms.append(s)
            args[k] = s
    if place:
        missing = [k for k in PLACEMENT_INPUTS if k not in args]
        if missing:
            placed = casadi_function(model, "place_object", bind=True)(q=args["q"])
            for k in missing:
                args[k] = placed[k]
    outs = f.call(args)
    out_names = [o["name"] for o in sig["outputs"]]
    return ca.Function(f"{name}_bound", syms, [outs[k] for k in out_names],
                       [s.name() for s in syms], out_names)


def _rows(sig: dict, k: str) -> int:
    item = next(i for i in sig["inputs"] if i["name"] == k)
    return item["rows"] * item["cols"]


def _column(fname: str, k: str, val, size: int) -> np.ndarray:
    try:
        arr = np.asarray(val, dtype=float).ravel(order="F")
    except (TypeError, ValueError):
        raise InputError(f"{fname} input {k} must be {size} numbers, got {val!r}") from None
    if arr.shape != (size,):
        raise InputError(f"{fname} input {k} must be {size} numbers, got shape "
                         f"{np.shape(val)}")
    return arr


def function_inputs(model, name: str, q=None) -> dict[str, np.ndarray]:
    """Values of the inputs of ``name`` that the robot or scene fixes, by input name.

    * ``K``: the robot's parameter vector (``model.parameters``, layout in docs/how-to/casadi.md);
    * scene inputs (a :class:`~snakecg.SceneModel` only): ``contact_link`` (one-hot over the
      links), ``side`` (+1 left, -1 right), ``object_mass``, ``object_inertia``,
      ``wheel_offset`` (one per link), ``contact_offset``, ``object_distance``, and
      ``placed`` = 0 (``contact_system`` takes the object's pose as given; 1 places it from
      ``q`` itself);
    * active set, as in the runtime's first pass: ``free`` = 1 on every row the scene has
      (contact and each wheel), 0 elsewhere; ``free_lost`` the same with the contact row 0;
      ``lam_fixed`` = 0; ``regularization`` = 0;
    * state at rest: ``v``, ``v_obj``, ``f_obj`` = 0.

    With ``q`` (one configuration), also ``q_obj`` and ``rho``: the scene's placement of the
    object at ``q``. Left out: ``q``, ``tau`` and the inputs of the link-local row functions.
    Every value is a 1-D float array of the input's size (column-major for a matrix input).
    """
    sig = _signature(model, name)
    n_c = model.n_constraints
    scene = getattr(model, "scene", None)
    values: dict[str, np.ndarray] = {
        "K": np.array(model.parameters, dtype=float),
        "v": np.zeros(model.n_coordinates), "v_obj": np.zeros(3), "f_obj": np.zeros(3),
        "lam_fixed": np.zeros(n_c), "regularization": np.zeros(1),
    }
    if scene is not None:
        present = np.asarray(model.present, dtype=float)
        lost = present.copy()
        lost[0] = 0.0
        values.update({
            "contact_link": np.asarray(model.scene_inputs["contact_link"], dtype=float).copy(),
            "side": np.array([scene.side_sign]),
            "object_mass": np.array([scene.object_mass]),
            "object_inertia": np.array([scene.object_inertia]),
            "wheel_offset": np.asarray(scene.wheel_offset, dtype=float).copy(),
            "contact_offset": np.array([scene.contact_offset]),
            "object_distance": np.array([scene.object_distance]),
            "free": present, "free_lost": lost, "placed": np.zeros(1),
        })
    in_names = [i["name"] for i in sig["inputs"]]
    need_scene = [k for k in in_names if k in SCENE_INPUTS + ("free", "free_lost")]
    if scene is None and need_scene:
        raise InputError(f"{name} takes scene inputs ({', '.join(need_scene)}): load a "
                         "snakecg.Scene, e.g. snakecg.load(snakecg.Scene(robot))")
    out = {k: values[k] for k in in_names if k in values}
    if q is not None and scene is not None and any(k in in_names for k in PLACEMENT_INPUTS):
        q_obj, rho, _ = model.place_object(q)
        if np.ndim(q_obj) != 1:
            raise InputError("q must be one configuration (n_s,) here, got a batch")
        placed = {"q_obj": np.asarray(q_obj, float), "rho": np.asarray(rho, float)}
        out.update({k: placed[k] for k in PLACEMENT_INPUTS if k in in_names})
    # the link-local row functions take one link's value under the same name: left out
    return {k: v for k, v in out.items() if v.shape == (_rows(sig, k),)}


def parameter_names(n_joints: int) -> list[str]:
    """Names of the entries of ``K`` for ``n_joints`` joints, in order (docs/how-to/casadi.md):
    ``m1..m_nl, l1..l_nl, I1..I_nl, c1..c_nl`` (the raw link parameters), then the derived
    constants ``mtot``, ``beta1..beta_nl``, ``gamma{j}_{k}`` (``j <= k``, row by row) and
    ``Jrot1..Jrot_nl``."""
    nl = n_joints + 1
    raw = [f"{s}{i}" for s in ("m", "l", "I", "c") for i in range(1, nl + 1)]
    beta = [f"beta{j}" for j in range(1, nl + 1)]
    gamma = [f"gamma{j}_{k}" for j in range(1, nl + 1) for k in range(j, nl + 1)]
    jrot = [f"Jrot{j}" for j in range(1, nl + 1)]
    return raw + ["mtot"] + beta + gamma + jrot
