"""The paper's scene simulated with contacts from geometry: ``model.simulate(...,
contacts="geometry")`` on a :class:`snakecg.Scene`.

The paper's model has one contact, a point fixed in the object sliding along the contact
link's face. Lying flush on the plate's face, the link can then turn about that point, and
one half of it goes into the plate at once (the contact check stops such a run with
``penetration``). Here the same scene is the general one of
:meth:`~snakecg.scenes.GeneralScene.from_scene` with the object as the paper's square plate
(side ``2 object_distance``, the scene's mass and inertia, a face along the contact link), and
it runs the general scene's time stepping (:mod:`snakecg.scenes.stepping`): every contact
found from the geometry at every step, so a flush face holds at both ends of the overlap, a
corner of the plate takes over when the link turns, and other links touching the plate are
contacts too.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError
from .description import GeneralScene
from .stepping import _simulate, simulate_scene

#: simulate_scene's defaults of dt and output_every
_DEFAULTS = simulate_scene.__kwdefaults__
#: :func:`_checked`'s check on the run's record (not done in the engine's loop)
RECORD = object()

__all__ = ["plate_scene", "simulate_with_geometry"]


def plate_scene(scene) -> GeneralScene:
    """The paper's ``scene`` as a general scene with its square plate."""
    return GeneralScene.from_scene(scene, object_shape="box")


def simulate_with_geometry(model, q0, tau, duration, v0=None, *, q_obj0=None, v_obj0=None,
                           f_obj=None, dt=None, tolerance=None, output_every=None,
                           progress=False):
    """Simulate the paper's scene of ``model`` (a loaded :class:`snakecg.Scene`) with the
    contacts from geometry: the general scene of :func:`plate_scene`, stepped by
    :func:`snakecg.scenes.stepping.simulate_scene` with ``dt`` (default 1e-3 s),
    ``tolerance`` (m; default 1e-5 of the scene's size) and ``output_every``, with the
    paper's contact check at every sample (in the engine's loop; :func:`_checked`).
    ``q_obj0``, ``v_obj0``, ``f_obj``: the plate's pose, twist and a constant wrench on it,
    3 numbers each. Returns a :class:`~snakecg.scenes.run_record.SceneRun`."""
    general = _plate_model(model)

    def one_object(name, value):
        if value is None:
            return None
        arr = np.asarray(value, dtype=float) if not isinstance(value, (str, bytes)) else None
        if arr is None or arr.size != 3:
            raise InputError(f"{name} must be 3 numbers (the plate's x, y, angle or their "
                             f"rates / the wrench F_x, F_y, torque), got {value!r:.60}")
        return arr.reshape(1, 3)

    run, first = _simulate(
        general, q0, duration, v0, tau, _DEFAULTS["dt"] if dt is None else dt,
        one_object("q_obj0", q_obj0), one_object("v_obj0", v_obj0), one_object("f_obj", f_obj),
        tolerance, _DEFAULTS["output_every"] if output_every is None else output_every,
        progress, lambda tol: _run_check(model, tol)[1].address)
    return _checked(model, run, first)


def _plate_model(model):
    """The loaded general scene of :func:`plate_scene`, made once per model (kept in its
    data's derived constants)."""
    derived = model.data().derived
    got = derived.get("scenes.plate_model")
    if got is None:
        from . import load_scene

        got = derived["scenes.plate_model"] = load_scene(plate_scene(model.scene))
    return got


def _run_check(model, tolerance):
    """The paper's contact check of a run with ``tolerance`` (m): its
    :class:`snakecg.geometry.ContactCheck` (every link a segment against the plate, the links
    against each other) and the model's check of a run over it
    (:class:`snakecg.simulate.contact_check.RunCheck`: compiled where the model is), made once
    per tolerance (kept in the model's data's derived constants)."""
    derived = model.data().derived
    key = ("scenes.plate_check", float(tolerance))
    got = derived.get(key)
    if got is None:
        from ..geometry import ContactCheck
        from ..simulate.contact_check import RunCheck
        from ..simulate.dynamics import N_WORK

        check = ContactCheck.of_scene(model.scene, tolerance=tolerance, radius=0.0)
        ns = model.n_coordinates
        got = derived[key] = (check, RunCheck(model, "report", ns, 2 * (ns + 3) + N_WORK,
                                              shape=check))  # the state y = (q, q_obj, ...)
    return got


def _checked(model, run, first=RECORD):
    """``run`` after the paper's contact check (:class:`snakecg.geometry.ContactCheck`, every
    link against the plate and the links against each other) at every sample, with the run's
    tolerance: a completed run that overlaps beyond it at a sample says so (status
    ``penetration`` or ``self_contact``, ``violation`` at the first such sample), the
    trajectory kept whole. ``first``: the check done in the engine's loop (the first sample
    beyond the tolerance, ``(index, overlap, pair)``, or ``None``), or :data:`RECORD`: done
    here on the run's record."""
    if run.status != "completed":
        return run
    check, rc = _run_check(model, run.tolerance)
    if first is RECORD:
        first = rc.first_beyond(run.states(), run.tolerance)
        first = None if first[0] is None else first
    if first is not None:
        k, depth, pair = first
        i, j = check.pairs[pair]
        names = [f"link {i + 1}", "object 1" if j is None else f"link {j + 1}"]
        message = (f"{names[0]} and {names[1]} overlap by {depth:.3g} m at the sample "
                   f"t = {run.t[k]:.6g} s (tolerance {run.tolerance:.3g} m; the paper's "
                   "contact check, every sample); the trajectory goes on as stepped")
        run.status = check.kind(pair)
        run.message = message
        run.violation = {"t": float(run.t[k]), "bodies": names, "message": message}
    return run
