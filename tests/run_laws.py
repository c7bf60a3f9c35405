"""The physical laws a general scene's run must keep, asserted alike by the tests that run one.

References apart from the code under test: the overlap from ``capsule_reference`` (NumPy
capsule distances), and the laws themselves: the kinetic energy never above its start plus the
torques' work less the friction's dissipation and the impacts' loss (plus the contacts' work),
the dissipation never decreasing, the contacts' impulses never negative, and every step's KKT
certificate at 1e-9 at most.
"""

from __future__ import annotations

import numpy as np

from capsule_reference import deepest_overlap


def assert_run_laws(scene, run) -> None:
    """No overlap beyond the run's tolerance, its certificate, energy and impulses."""
    assert deepest_overlap(scene, np.asarray(run.q)) <= run.tolerance
    assert max(run.certificate.values()) <= 1e-9
    ke = np.asarray(run.kinetic_energy)
    budget = (np.asarray(run.work_tau) - np.asarray(run.friction_dissipation)
              - np.asarray(run.impact_loss) + np.asarray(run.contact_work))
    assert np.all(ke - ke[0] <= budget + 1e-9 * max(1.0, np.abs(run.work_tau).max()))
    assert np.all(np.diff(run.friction_dissipation) >= -1e-15)
    assert np.all(np.asarray(run.contact_impulse) >= 0)
