"""wavecontact.map on a Dask LocalCluster of two worker processes: the same bits as the local
run, also with one worker killed mid-run; bad grids refused before any task. A ctest entry of
its own (python_dask_tests)."""
import os
import signal
import threading
import time

import numpy as np
import pytest

import wavecontact as wc
from test_map import GRID, assert_same_result


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
