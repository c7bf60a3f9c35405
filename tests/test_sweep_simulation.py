"""A sweep of a simulation metric (``snakecg.sweep(..., simulate=...)``, ``snakecg sweep
--simulate SECONDS --tau TAU``): every configuration also starts a push, simulated on the
Dask workers, and the store holds how each run ended and what it moved.

References: each configuration simulated here directly, outside Dask and the store, by
:func:`snakecg.simulate.simulate` (the stored values must be its values, bit for bit, after
the chunking, the workers and the Zarr round trip); the geometric feasibility of the start
(:func:`snakecg.geometry.feasibility`, a separate test of the shape): a start whose links
cross or enter the object can never complete a push; xarray reading the store's CF flags.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

import distributed

import snakecg
from snakecg.cli import main
from snakecg.simulate import simulate
from snakecg.sweeps.simulation import SIM_ARRAYS, STATUS_CODES

DEG = np.pi / 180
TAU = [0.035, 0.0, -0.014]
DURATION = 2e-4  # the paper scene's point contact lets the link turn into the object within ms
# the documented push (30, -35, 25 deg) and its neighbours, and shapes folded onto
# themselves (links that cross: no push can start there)
GRID = [np.array([30, 135]) * DEG, np.array([-35, 135]) * DEG, np.array([25, 0]) * DEG]


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=1, threads_per_worker=2, processes=False,
                                  dashboard_address=None) as cluster:
        with distributed.Client(cluster) as c:
            yield c


@pytest.fixture(scope="module")
def swept(tmp_path_factory, client):
    scene = snakecg.Scene(snakecg.Robot(joints=3))
    store = tmp_path_factory.mktemp("simsweep") / "push.zarr"
    res = snakecg.sweep(scene, grid=GRID, store=store, client=client, chunk=3, progress=False,
                        simulate={"duration": DURATION, "tau": TAU})
    return scene, store, res


def _configurations():
    g = np.meshgrid(*GRID, indexing="ij")
    qa = np.stack([x.ravel() for x in g], axis=1)
    return np.hstack([np.zeros((len(qa), 3)), qa])


def test_stored_runs_are_the_simulator_s_own(swept):
    """Every stored value equals the push simulated here directly from the same start."""
    import xarray as xr

    scene, store, res = swept
    assert res.configurations == 8 and res.chunks == 3
    ds = xr.open_zarr(store)
    model = snakecg.load(scene)
    q = _configurations()
    np.testing.assert_array_equal(ds["q"].values, np.round(np.rad2deg(q[:, 3:]), 9))
    refused = 0
    for i, qi in enumerate(q):
        try:
            traj = simulate(model, qi, TAU, DURATION)
        except snakecg.InputError:
            refused += 1
            assert ds["sim_status"].values[i] == STATUS_CODES["refused"]
            for name in SIM_ARRAYS[1:]:
                assert np.isnan(ds[name].values[i]), name
            continue
        s = traj.summary
        want = {"sim_status": STATUS_CODES[s["status"].split()[0]],
                "sim_t_end": traj.t[-1],
                "sim_object_dx": s["object_displacement"]["x"],
                "sim_object_dy": s["object_displacement"]["y"],
                "sim_object_dpsi": s["object_displacement"]["psi"],
                "sim_com_dx": s["snake_com_displacement"]["x"],
                "sim_com_dy": s["snake_com_displacement"]["y"],
                "sim_sr_mean": np.nan if s["sr_mean"] is None else s["sr_mean"]}
        for name in SIM_ARRAYS:
            np.testing.assert_array_equal(ds[name].values[i], want[name], err_msg=name)
    assert 0 < refused < len(q)
    # CF flags: xarray users read the codes' meanings from the store itself
    flags = ds["sim_status"].attrs
    assert dict(zip(flags["flag_meanings"].split(), flags["flag_values"])) == STATUS_CODES
    assert ds["sim_t_end"].attrs["units"] == "s"


def test_an_impossible_start_never_completes_a_push(swept):
    """Shapes whose links cross or enter the object (geometry.feasibility, evaluated here)
    end at once; the documented push from (30, -35, 25) deg completes its duration."""
    import xarray as xr

    from snakecg.geometry import feasibility

    scene, store, _ = swept
    ds = xr.open_zarr(store)
    q = _configurations()
    feasible = feasibility(snakecg.load(scene), q).feasible
    status = ds["sim_status"].values
    assert np.any(~feasible) and np.any(feasible)
    assert np.all(status[~feasible] != STATUS_CODES["completed"])
    assert not np.any(ds["sim_t_end"].values[~feasible] > 1e-9)
    first = 0  # (30, -35, 25) deg
    assert status[first] == STATUS_CODES["completed"]
    assert ds["sim_t_end"].values[first] == pytest.approx(DURATION, rel=1e-12)


def test_summary_counts_every_run_and_names_the_farthest_push(swept, capsys):
    import xarray as xr

    scene, store, _ = swept
    ds = xr.open_zarr(store)
    assert main(["sweep", "--summary", str(store), "--json"]) == 0
    s = json.loads(capsys.readouterr().out)["simulation"]
    status = ds["sim_status"].values
    assert s["duration"] == DURATION and s["tau"] == TAU
    assert s["status_counts"] == {k: int(np.sum(status == v)) for k, v in STATUS_CODES.items()}
    done = status == STATUS_CODES["completed"]
    dist = np.hypot(ds["sim_object_dx"].values, ds["sim_object_dy"].values)
    j = int(np.flatnonzero(done)[np.argmax(dist[done])])
    assert s["farthest_push"]["index"] == j
    assert s["farthest_push"]["distance"] == pytest.approx(dist[j], rel=1e-15)
    assert main(["sweep", "--summary", str(store)]) == 0
    assert "farthest completed push" in capsys.readouterr().out


def test_resume_with_other_torques_is_refused(swept, client):
    scene, store, _ = swept
    with pytest.raises(snakecg.InputError, match="other arguments"):
        snakecg.sweep(scene, grid=GRID, store=store, client=client, progress=False,
                      simulate={"duration": DURATION, "tau": [0.0, 0.0, 0.0]})
    with pytest.raises(snakecg.InputError, match="other arguments"):
        snakecg.sweep(scene, grid=GRID, store=store, client=client, progress=False)


@pytest.mark.parametrize("argv,fragment", [
    (["--simulate", "0.5"], "--simulate SECONDS and --tau TAU go together"),
    (["--tau", "0.1,0,0"], "--simulate SECONDS and --tau TAU go together"),
    (["--simulate", "0.5", "--tau", "0.1,0"], "--tau has 2 values, expected 3"),
    (["--simulate", "0.5", "--tau", "0.1,nan,0"], "--tau must be finite"),
    (["--simulate", "-1", "--tau", "0.1,0,0"], "--simulate"),
    (["--simulate", "100", "--tau", "0.1,0,0"], "--simulate"),
])
def test_bad_simulation_options_are_one_line(tmp_path, capsys, argv, fragment):
    store = tmp_path / "x.zarr"
    try:
        code = main(["sweep", "--joints", "3", "--range", "30", "--step", "30", "--out",
                     str(store), *argv])
    except SystemExit as exc:  # argparse's own refusal of an option's value
        code = exc.code
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1 and fragment in err, err
    assert "Traceback" not in err and not store.exists()


@pytest.mark.parametrize("spec,fragment", [
    ({"duration": 0.5}, "keys 'duration'"),
    ({"duration": 0, "tau": TAU}, "simulate['duration']"),
    ({"duration": float("inf"), "tau": TAU}, "simulate['duration']"),
    ({"duration": 0.5, "tau": [1, 2]}, "simulate['tau'] must be 3"),
    ({"duration": 0.5, "tau": "abc"}, "simulate['tau'] must be 3"),
])
def test_bad_simulation_argument_is_refused_before_any_work(tmp_path, spec, fragment):
    store = tmp_path / "y.zarr"
    with pytest.raises(snakecg.InputError, match=fragment.replace("[", r"\[").replace("]", r"\]")):
        snakecg.sweep(snakecg.Scene(snakecg.Robot(joints=3)), grid=GRID, store=store,
                      progress=False, simulate=spec)
    assert not store.exists()
