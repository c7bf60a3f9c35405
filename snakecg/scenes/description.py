"""A general scene: the robot with capsule links, one ground model per link, movable objects
and fixed obstacles. Immutable and validated at the boundary: every problem is collected and
raised at once as one :class:`~snakecg.errors.InputError` naming the key and the form.

The paper's :class:`~snakecg.Scene` is one special case (:meth:`GeneralScene.from_scene`): the
object touched at the middle of a face, with its COM on the contact normal at
``object_distance``, is at rest the same body as a disc of that radius touching the link (the
normal passes through the COM in both), with the paper's mass and inertia.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, fields

from .._inputs import MAX_PARAMETER, beyond_parameter_limit
from ..errors import InputError
from ..robot import DEFAULT_GRAVITY, Robot, Scene

__all__ = ["GROUND_MODELS", "Ground", "SceneObject", "Obstacle", "GeneralScene", "pair_mu"]

GROUND_MODELS = ("frictionless", "wheels", "ideal_wheels", "coulomb", "anisotropic")
OBJECT_SHAPES = ("box", "disc")
OBSTACLE_SHAPES = ("peg", "wall", "box")


def _num(v) -> bool:
    return isinstance(v, numbers.Real) and not isinstance(v, bool) and math.isfinite(v)


def _vec(v, n) -> bool:
    return (isinstance(v, (list, tuple)) and len(v) == n and all(_num(x) for x in v))


def _too_large(where: str, item) -> list[str]:
    """Every finite number of ``item``'s fields (a dataclass) beyond MAX_PARAMETER."""
    out = []
    for f in fields(item):
        v = getattr(item, f.name)
        vals = v.values() if isinstance(v, dict) else v if isinstance(v, (list, tuple)) else (v,)
        if any(_num(x) and abs(x) > MAX_PARAMETER for x in vals):
            out.append(beyond_parameter_limit(f"{where}.{f.name}", f"{v!r:.60}"))
    return out


def _mu_contact_problems(v, where: str) -> list[str]:
    if v is None or (_num(v) and v >= 0):
        return []
    return [f"{where}.mu_contact must be a finite number >= 0 (Coulomb's coefficient at its "
            f"contacts), got {v!r:.60}"]


def pair_mu(scene_mu: float, mu_a: float | None, mu_b: float | None) -> float:
    """The Coulomb coefficient of a contact between two bodies: the larger of their own
    ``mu_contact`` where either has one (as MuJoCo takes the larger of two geoms'), else the
    scene's ``mu_contact`` (a link has none of its own)."""
    given = [m for m in (mu_a, mu_b) if m is not None]
    return float(max(given)) if given else float(scene_mu)


@dataclass(frozen=True)
class Ground:
    """The ground under one link: ``model`` one of :data:`GROUND_MODELS`. ``wheels``: lateral
    force bounded by ``mu m_i g`` at ``wheel_offset`` from the COM; ``coulomb``: a disc of
    radius ``mu m_i g`` at the COM; ``anisotropic``: a split ellipse at the COM with
    ``mu_forward`` (along the link, resisting forward sliding), ``mu_backward`` and
    ``mu_lateral`` (across)."""

    model: str = "frictionless"
    mu: float = 0.1
    mu_forward: float = 0.1
    mu_backward: float = 0.1
    mu_lateral: float = 0.1
    wheel_offset: float = 0.0

    def problems(self, where: str) -> list[str]:
        out = []
        if self.model not in GROUND_MODELS:
            out.append(f"{where}.model must be one of {', '.join(GROUND_MODELS)}, got "
                       f"{self.model!r:.60}")
        for k in ("mu", "mu_forward", "mu_backward", "mu_lateral"):
            v = getattr(self, k)
            if not _num(v) or v < 0:
                out.append(f"{where}.{k} must be a finite number >= 0, got {v!r:.60}")
        if not _num(self.wheel_offset):
            out.append(f"{where}.wheel_offset must be a finite number (m), got "
                       f"{self.wheel_offset!r:.60}")
        return out


@dataclass(frozen=True)
class SceneObject:
    """A movable rigid plate: ``shape`` box (``size = (a, b)``, a along its x axis) or disc
    (``radius``); ``mass``; ``inertia`` about its COM (default: the uniform plate's); placed by
    ``pose = (x, y, theta)`` or ``touching = {link, offset, side}`` (then it touches that link,
    at ``offset`` m from its rear end, on its left or right, a box with a face along the link);
    ``mu``: Coulomb friction with the ground at its COM (None: none); ``mu_contact``: its
    Coulomb friction at contacts with other bodies (None: the scene's ``mu_contact``; a pair's
    coefficient is :func:`pair_mu`'s)."""

    shape: str = "box"
    size: tuple | None = None
    radius: float | None = None
    mass: float = 1.0
    inertia: float | None = None
    pose: tuple | None = None
    touching: dict | None = None
    mu: float | None = None
    name: str | None = None
    mu_contact: float | None = None

    @property
    def plate_inertia(self) -> float:
        if self.inertia is not None:
            return float(self.inertia)
        if self.shape == "disc":
            return 0.5 * self.mass * self.radius ** 2
        a, b = self.size
        return self.mass * (a * a + b * b) / 12.0

    @property
    def half_depth(self) -> float:
        """From the touched face to the COM, along the normal."""
        return self.radius if self.shape == "disc" else self.size[1] / 2

    def problems(self, where: str, n_links: int | None, lengths=None) -> list[str]:
        out = []
        if self.shape not in OBJECT_SHAPES:
            out.append(f"{where}.shape must be 'box' or 'disc', got {self.shape!r:.60}")
        if self.shape == "box" and not (_vec(self.size, 2) and min(self.size) > 0):
            out.append(f"{where}.size must be [a, b] with a, b > 0 (m), got {self.size!r:.60}")
        if self.shape == "disc" and not (_num(self.radius) and self.radius > 0):
            out.append(f"{where}.radius must be a number > 0 (m), got {self.radius!r:.60}")
        if not (_num(self.mass) and self.mass > 0):
            out.append(f"{where}.mass must be a number > 0 (kg), got {self.mass!r:.60}")
        if self.inertia is not None and not (_num(self.inertia) and self.inertia > 0):
            out.append(f"{where}.inertia must be a number > 0 (kg m^2), got "
                       f"{self.inertia!r:.60}")
        if self.mu is not None and not (_num(self.mu) and self.mu >= 0):
            out.append(f"{where}.mu must be a number >= 0, got {self.mu!r:.60}")
        out += _mu_contact_problems(self.mu_contact, where)
        if (self.pose is None) == (self.touching is None):
            out.append(f"{where} needs exactly one of pose = [x, y, theta] or touching = "
                       f"{{link, offset, side}}")
        elif self.pose is not None and not _vec(self.pose, 3):
            out.append(f"{where}.pose must be [x, y, theta] (m, m, rad), got {self.pose!r:.60}")
        elif self.touching is not None:
            t = self.touching
            if not isinstance(t, dict) or set(t) - {"link", "offset", "side"} or "link" not in t:
                out.append(f"{where}.touching must be {{link = K, offset = S, side = 'left' "
                           f"| 'right'}}, got {t!r:.80}")
            else:
                k = t["link"]
                if (isinstance(k, bool) or not isinstance(k, numbers.Integral) or k < 1
                        or (n_links is not None and k > n_links)):
                    out.append(f"{where}.touching.link must be a link number 1..{n_links}, "
                               f"got {k!r:.60}")
                if "offset" in t and not _num(t["offset"]):
                    out.append(f"{where}.touching.offset must be a number (m from the link's "
                               f"rear end), got {t['offset']!r:.60}")
                elif ("offset" in t and lengths is not None and not isinstance(k, bool)
                      and isinstance(k, numbers.Integral) and 1 <= k <= len(lengths)
                      and not 0 <= t["offset"] <= lengths[k - 1]):
                    out.append(f"{where}.touching.offset must be within link {k}, 0 to "
                               f"{lengths[k - 1]:g} m from its rear end, got "
                               f"{t['offset']!r:.60}")
                if t.get("side", "left") not in ("left", "right"):
                    out.append(f"{where}.touching.side must be 'left' or 'right', got "
                               f"{t.get('side')!r:.60}")
        return out


@dataclass(frozen=True)
class Obstacle:
    """A fixed body: ``peg`` (``center``, ``radius``), ``wall`` (``point``, ``normal`` into
    the free side) or ``box`` (``center``, ``size``, ``angle``); ``mu_contact``: its Coulomb
    friction at contacts (None: the scene's; a pair's coefficient is :func:`pair_mu`'s)."""

    shape: str = "peg"
    center: tuple | None = None
    radius: float | None = None
    point: tuple | None = None
    normal: tuple | None = None
    size: tuple | None = None
    angle: float = 0.0
    name: str | None = None
    mu_contact: float | None = None

    def problems(self, where: str) -> list[str]:
        out = _mu_contact_problems(self.mu_contact, where)
        if self.shape not in OBSTACLE_SHAPES:
            return out + [f"{where}.shape must be one of {', '.join(OBSTACLE_SHAPES)}, got "
                          f"{self.shape!r:.60}"]
        if self.shape in ("peg", "box") and not _vec(self.center, 2):
            out.append(f"{where}.center must be [x, y] (m), got {self.center!r:.60}")
        if self.shape == "peg" and not (_num(self.radius) and self.radius > 0):
            out.append(f"{where}.radius must be a number > 0 (m), got {self.radius!r:.60}")
        if self.shape == "box":
            if not (_vec(self.size, 2) and min(self.size) > 0):
                out.append(f"{where}.size must be [a, b] with a, b > 0 (m), got "
                           f"{self.size!r:.60}")
            if not _num(self.angle):
                out.append(f"{where}.angle must be a number (rad), got {self.angle!r:.60}")
        if self.shape == "wall":
            if not _vec(self.point, 2):
                out.append(f"{where}.point must be [x, y] (m), got {self.point!r:.60}")
            if not (_vec(self.normal, 2) and math.hypot(*self.normal) > 0):
                out.append(f"{where}.normal must be a nonzero [nx, ny], got "
                           f"{self.normal!r:.60}")
        return out


@dataclass(frozen=True)
class GeneralScene:
    """Robot (links: capsules of ``radius``), ``ground`` (one :class:`Ground` for every link
    or a tuple of one per link), ``objects``, ``obstacles``, ``gravity``; ``tolerance``: a
    contact holds within ``tolerance * size`` (``size`` the scene's extent); ``mu_contact``:
    Coulomb's coefficient at the contacts between bodies (0, the default: frictionless, the
    paper's assumption 2; an object's or obstacle's own ``mu_contact`` overrides it at its
    contacts, :func:`pair_mu`)."""

    robot: Robot
    radius: float = 0.0
    ground: Ground | tuple = Ground()
    objects: tuple = ()
    obstacles: tuple = ()
    gravity: float = DEFAULT_GRAVITY
    tolerance: float = 1e-8
    mu_contact: float = 0.0

    def __post_init__(self):
        problems = []
        if not isinstance(self.robot, Robot):
            raise InputError(f"robot must be a snakecg.Robot, got {type(self.robot).__name__}")
        nl = self.robot.n_links
        if not (_num(self.radius) and self.radius >= 0):
            problems.append(f"robot.radius must be a number >= 0 (m), got {self.radius!r:.60}")
        g = self.ground
        if isinstance(g, Ground):
            g = (g,) * nl
        elif not (isinstance(g, (list, tuple)) and all(isinstance(x, Ground) for x in g)
                  and len(g) == nl):
            problems.append(f"ground must be one Ground or a list of {nl} (one per link), got "
                            f"{g!r:.80}")
            g = ()
        for i, x in enumerate(g):
            problems += x.problems("ground" if isinstance(self.ground, Ground)
                                   else f"ground[{i + 1}]")
        for i, o in enumerate(self.objects):
            if not isinstance(o, SceneObject):
                problems.append(f"object[{i + 1}] must be a SceneObject, got {o!r:.60}")
            else:
                problems += o.problems(f"object[{i + 1}]", nl, self.robot.length)
        for i, o in enumerate(self.obstacles):
            if not isinstance(o, Obstacle):
                problems.append(f"obstacle[{i + 1}] must be an Obstacle, got {o!r:.60}")
            else:
                problems += o.problems(f"obstacle[{i + 1}]")
        if not (_num(self.gravity) and self.gravity >= 0):
            problems.append(f"gravity must be a number >= 0 (m/s^2), got {self.gravity!r:.60}")
        if not (_num(self.mu_contact) and self.mu_contact >= 0):
            problems.append(f"mu_contact must be a finite number >= 0 (Coulomb's coefficient at "
                            f"the contacts), got {self.mu_contact!r:.60}")
        if not (_num(self.tolerance) and 0 < self.tolerance < 1e-2):
            problems.append(f"tolerance must be a number in (0, 0.01) (relative to the scene's "
                            f"size), got {self.tolerance!r:.60}")
        problems += [p for i, x in enumerate(g) for p in _too_large(
            "ground" if isinstance(self.ground, Ground) else f"ground[{i + 1}]", x)]
        problems += [p for i, o in enumerate(self.objects) if isinstance(o, SceneObject)
                     for p in _too_large(f"object[{i + 1}]", o)]
        problems += [p for i, o in enumerate(self.obstacles) if isinstance(o, Obstacle)
                     for p in _too_large(f"obstacle[{i + 1}]", o)]
        for name in ("radius", "gravity"):
            v = getattr(self, name)
            if _num(v) and abs(v) > MAX_PARAMETER:
                problems.append(beyond_parameter_limit(name, f"{v!r:.60}"))
        if problems:
            raise InputError("invalid scene: " + "; ".join(dict.fromkeys(problems)))  # (one
            # ground for every link: its problems once)
        object.__setattr__(self, "ground", tuple(g))
        object.__setattr__(self, "objects", tuple(self.objects))
        object.__setattr__(self, "obstacles", tuple(self.obstacles))

    @property
    def n_objects(self) -> int:
        return len(self.objects)

    @property
    def has_contact_friction(self) -> bool:
        """Some pair of bodies may touch with a Coulomb coefficient above 0."""
        return self.mu_contact > 0 or any(
            (o.mu_contact or 0) > 0 for o in (*self.objects, *self.obstacles))

    def body_name(self, kind: str, i: int) -> str:
        """``link 2``, ``object 1`` (or its name), ``obstacle 3`` (1-based)."""
        if kind == "link":
            return f"link {i + 1}"
        items = self.objects if kind == "object" else self.obstacles
        name = items[i].name
        return f"{kind} {i + 1}" + (f" ({name})" if name else "")

    @classmethod
    def from_scene(cls, scene: Scene, object_shape: str = "disc") -> GeneralScene:
        """The paper's scene as a general one: ground per link (a wheel, bounded or ideal, on
        every wheel link, frictionless elsewhere), one object (mass ``kappa m``, the scene's
        inertia) touching ``contact_link`` at ``contact_offset`` on ``side``, segment links.
        ``object_shape``: ``"disc"`` (default) of radius ``object_distance``, the same body
        at rest; ``"box"``: the square plate of side ``2 object_distance`` with a face along
        the link (the body the paper's simulation checks its geometry against), for motion
        over time, where the plate's faces and corners matter."""
        if not isinstance(scene, Scene):
            raise InputError(f"scene must be a snakecg.Scene, got {type(scene).__name__}")
        if object_shape not in OBJECT_SHAPES:
            raise InputError(f"object_shape must be 'disc' or 'box', got {object_shape!r:.60}")
        nl = scene.robot.n_links
        woff = scene.wheel_offset
        woff = woff if isinstance(woff, tuple) else (woff,) * nl
        model = {"frictionless": "frictionless", "wheels": "wheels",
                 "ideal_wheels": "ideal_wheels"}[scene.scenario]
        ground = tuple(
            Ground(model=model if (scene.has_wheels and i + 1 in scene.wheel_links)
                   else "frictionless", mu=scene.mu, wheel_offset=float(woff[i]))
            for i in range(nl))
        d = scene.object_distance
        size = {"radius": d} if object_shape == "disc" else {"size": (2 * d, 2 * d)}
        obj = SceneObject(shape=object_shape, **size, mass=scene.object_mass,
                          inertia=scene.object_inertia,
                          touching={"link": scene.contact_link, "offset": scene.contact_offset,
                                    "side": scene.side})
        return cls(scene.robot, radius=0.0, ground=ground, objects=(obj,),
                   gravity=scene.gravity)
