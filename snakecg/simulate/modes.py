"""Modes: which constraint rows hold (the active set, in the solver's row codes), and the
events that take one mode to the next."""

from __future__ import annotations

import numpy as np

from ..solver import ABSENT, HELD, LOST, SLIDE_NEG, SLIDE_POS
from .records import SimEvent

__all__ = ["Mode", "STATE_NAMES", "transitions"]

STATE_NAMES = {ABSENT: "none", HELD: "stick", LOST: "lost", SLIDE_POS: "slide+",
               SLIDE_NEG: "slide-"}
_SLIDE = (SLIDE_POS, SLIDE_NEG)


class Mode:
    """An active set: row states (solver codes) and whether the contact point left the link,
    with what the right-hand side needs of it precomputed (``free``: held rows as 0/1,
    ``lam_fixed``: the forces of sliding wheels, ``+-`` their ``bounds``)."""

    __slots__ = ("state", "off_link", "free", "lam_fixed", "free_idx", "slide_idx",
                 "contact_held", "wheel_names", "ff", "specs", "description")

    _cache: dict = {}  # (state, bounds, off_link) -> Mode, for Mode.of

    @classmethod
    def of(cls, state: np.ndarray, bounds: np.ndarray, off_link: bool) -> Mode:
        """The mode ``Mode(state, bounds, off_link)``, built once per distinct mode and
        shared (its arrays are read-only); a bounded cache."""
        state = np.asarray(state, dtype=np.int8)
        key = (state.tobytes(), bounds.tobytes(), bool(off_link))
        mode = cls._cache.get(key)
        if mode is None:
            if len(cls._cache) >= 4096:
                cls._cache.clear()
            mode = cls._cache[key] = cls(state, bounds, off_link)
        return mode

    def __init__(self, state: np.ndarray, bounds: np.ndarray, off_link: bool):
        self.state = np.asarray(state, dtype=np.int8).copy()
        self.off_link = bool(off_link)
        self.free = (self.state == HELD).astype(float)
        lf = np.zeros(len(state))
        lf[self.state == SLIDE_POS] = bounds[self.state == SLIDE_POS]
        lf[self.state == SLIDE_NEG] = -bounds[self.state == SLIDE_NEG]
        self.lam_fixed = lf
        self.free_idx = np.flatnonzero(self.state == HELD)
        self.ff = np.ix_(self.free_idx, self.free_idx)
        self.slide_idx = np.flatnonzero((self.state == SLIDE_POS) | (self.state == SLIDE_NEG))
        self.contact_held = bool(self.state[0] == HELD)
        self.wheel_names = tuple("none" if s in (ABSENT, LOST) else STATE_NAMES[int(s)]
                                 for s in self.state[1:])
        for a in (self.state, self.free, self.lam_fixed, self.free_idx, self.slide_idx):
            a.flags.writeable = False
        self.specs = None  # its terminal events (snakecg.simulate.events.Events.specs)
        c = "held" if self.contact_held else ("off link" if self.off_link else "separated")
        self.description = f"contact {c}; wheels " + " ".join(self.wheel_names)

    def describe(self) -> str:
        return self.description


def transitions(t, old: Mode, new: Mode, *, impact: bool) -> list[SimEvent]:
    """The events that take ``old`` to ``new``, row by row (a contact that closes with an
    ``impact`` is recorded by the impact itself)."""
    before, after = old.describe(), new.describe()
    out = []
    if old.state[0] == HELD and new.state[0] != HELD:
        kind = "off_link" if new.off_link and not old.off_link else "separation"
        out.append(SimEvent(float(t), kind, 0, before, after, {}))
    elif old.state[0] != HELD and new.state[0] == HELD and not impact:
        out.append(SimEvent(float(t), "touch", 0, before, after, {}))
    for r in range(1, len(old.state)):
        a, b = old.state[r], new.state[r]
        kind = None
        if a == HELD and b in _SLIDE:
            kind = "breakaway"
        elif a in _SLIDE and b == HELD:
            kind = "stick"
        elif a in _SLIDE and b in _SLIDE and a != b:
            kind = "reverse"
        if kind:
            out.append(SimEvent(float(t), kind, r, before, after, {}))
    return out
