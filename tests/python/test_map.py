"""wavecontact.map: every point is solve_contact's on its load line, bit for bit, on this
machine's threads and on a Dask LocalCluster of two worker processes, one of them killed
mid-run; bad grids are refused before any work."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import wavecontact as wc

GRID = dict(H1=1.0, b1=10.0, E=1.0, m=[0.0, 2.0, 10.0], H2=[0.02, 0.05], n=[8, 16], pa_over_pstar=[0.1, 0.4, 1.2])


def same(a, b):
    """Equal arrays, NaN equal to NaN (beyond reach), bit for bit."""
    return np.array_equal(np.asarray(a), np.asarray(b), equal_nan=a.dtype.kind == "f")


def assert_same_result(a, b):
    for column in wc.MapResult.columns:
        assert same(a[column], b[column]), column
    for axis in ("m", "H2", "n", "P", "pa_over_pstar"):
        assert same(getattr(a, axis), getattr(b, axis)), axis


def test_points_are_solve_contact_on_their_line():
    r = wc.map(**GRID)
    assert r.status.shape == (3, 2, 2, 3)
    for i, m in enumerate(GRID["m"]):
        for j, H2 in enumerate(GRID["H2"]):
            for k, n in enumerate(GRID["n"]):
                surface = wc.Surface(wc.WavinessParams(1.0, 10.0, m, 1.0), [wc.Harmonic(H2, n)])
                contacts = wc.solve_contact(surface, np.array(GRID["pa_over_pstar"]) * np.pi)
                for l, c in enumerate(contacts):
                    where = (i, j, k, l)
                    assert r.status[where] == "solved", where
                    assert r.zones[where] == c.zones_per_period, where
                    assert r.contact_fraction[where] == c.contact_fraction, where
                    assert r.p0[where] == c.pressure(0.0), where
                    assert r.max_p[where] == c.max_pressure, where
                    assert r.error_estimate[where] == c.error_estimate, where
    assert np.all(r.P == np.array(GRID["pa_over_pstar"]) * np.pi)


def test_threads_change_nothing():
    assert_same_result(wc.map(**GRID, threads=1), wc.map(**GRID, threads=3))


def test_the_wave_curve_alone():
    r = wc.map(1.0, 10.0, 1.0, m=[0.5, 3.0], P=[0.5, 2.0])
    assert r.status.shape == (2, 1, 1, 2) and np.all(r.H2 == 0) and np.all(r.n == 0)
    c = wc.solve_contact(wc.Surface(wc.WavinessParams(1.0, 10.0, 3.0, 1.0)), [0.5, 2.0])
    assert [x.contact_fraction for x in c] == list(r.contact_fraction[1, 0, 0])


@pytest.mark.parametrize(
    "change, message",
    [
        (dict(pa_over_pstar=[0.5, 0.1]), "ascending"),
        (dict(pa_over_pstar=[]), "non-empty"),
        (dict(n=[7]), "n = 7"),
        (dict(H2=None), "H2 and n go together"),
        (dict(P=[1.0]), "exactly one of pa_over_pstar, P"),
        (dict(m=[-1.0]), "m = -1"),
    ],
)
def test_bad_grids_are_refused(change, message):
    with pytest.raises(ValueError, match=message):
        wc.map(**dict(GRID, **change))


@pytest.fixture(scope="module")
def cluster():
    import distributed  # Debian's python3-distributed (scripts/install-deps.sh)

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as c:
        with distributed.Client(c) as client:
            yield client


def test_dask_gives_the_same_bits(cluster):
    assert_same_result(wc.map(**GRID, client=cluster), wc.map(**GRID))


def test_dask_refuses_before_any_task(cluster):
    with pytest.raises(ValueError, match="ascending"):
        wc.map(**dict(GRID, pa_over_pstar=[0.5, 0.1]), client=cluster)


def test_a_killed_worker_loses_nothing(cluster):
    """One worker process killed (SIGKILL) while its tasks run: the scheduler runs them again
    elsewhere; every point once, the same bits."""
    grid = dict(GRID, m=list(np.linspace(0.0, 10.0, 8)), n=[16, 32], pa_over_pstar=[0.05, 0.3, 1.0, 1.8])
    expected = wc.map(**grid)
    pids = list(cluster.run(os.getpid).values())
    killed = []

    def kill_one():
        # Once tasks are running on the workers.
        deadline = time.time() + 30
        while time.time() < deadline and not any(cluster.processing().values()):
            time.sleep(0.01)
        time.sleep(0.2)
        os.kill(pids[0], signal.SIGKILL)
        killed.append(time.time())

    killer = threading.Thread(target=kill_one)
    killer.start()
    result = wc.map(**grid, client=cluster)
    finished = time.time()
    killer.join()
    assert killed and killed[0] < finished, "the map ended before a worker was killed"
    assert_same_result(result, expected)
