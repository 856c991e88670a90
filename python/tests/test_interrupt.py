"""Interruption: a CancelToken set from another thread, Ctrl-C (SIGINT) as KeyboardInterrupt, the progress
callback, and the GIL released while the engine works."""
import os
import signal
import threading
import time

import pytest

import hsx


def grid(n):
    """n vertical and n horizontal lines, alternately complemented, one sample on each: brute force on n = 10
    enumerates for minutes (more than 5 s: measured), which is what these tests stop."""
    hs = []
    for k in range(n):
        hs.append(hsx.HalfPlane((1, 0), k, f"X{k}", complement=k % 2 == 1))
        hs.append(hsx.HalfPlane((0, 1), k, f"Y{k}", complement=k % 2 == 1))
    s = hsx.Scene(hs, domain=((-1, -1), (n, n)))
    for k in range(n):
        s.sample(f"X{k}", at=(k, "1/2"))
        s.sample(f"Y{k}", at=("1/2", k))
    return s


@pytest.fixture(scope="module")
def long_search():
    return hsx.arrange(grid(10))


def start_later(seconds, action):
    t = threading.Timer(seconds, action)
    t.start()
    return t


@pytest.mark.parametrize("method", ["brute-force", "exact", "best-first"])
def test_cancel_token_from_another_thread(long_search, method):
    if method != "brute-force":
        # exact and best-first finish this scene quickly: cancel before they start (checked at the first step)
        token = hsx.CancelToken()
        token.cancel()
        r = hsx.extract(long_search, method=method, cancel=token)
        assert r.stopped_by == "cancelled" and not r.optimal and r.sample_connected
        return
    token = hsx.CancelToken()
    start = time.monotonic()
    timer = start_later(0.3, token.cancel)
    r = hsx.extract(long_search, method=method, max_labellings=10 ** 15, cancel=token)
    timer.join()
    elapsed = time.monotonic() - start
    assert token.cancelled
    assert r.stopped_by == "cancelled" and not r.optimal
    assert elapsed < 5, elapsed  # stopped, not run to its end


def test_ctrl_c_raises_keyboard_interrupt(long_search):
    if threading.current_thread() is not threading.main_thread():
        pytest.skip("signals reach the main thread only")
    timer = start_later(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        hsx.extract(long_search, method="brute-force", max_labellings=10 ** 15)
    timer.join()
    assert time.monotonic() - start < 5
    # the module works normally afterwards
    assert hsx.extract(hsx.arrange(grid(3)), method="exact").optimal


def test_check_stops_on_ctrl_c(long_search):
    timer = start_later(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        hsx.check(long_search, max_labellings=10 ** 15)
    timer.join()
    assert time.monotonic() - start < 10


@pytest.fixture(scope="module")
def long_best_first():
    """A random scene on which best-first runs for more than 3 s (measured: stopped by a 3 s time limit)."""
    return hsx.arrange(hsx.random_scene(11, 1, min_halfspaces=10, max_halfspaces=14, max_samples=12,
                                        polygons=False))


def test_progress_callback(long_best_first):
    seen = []
    r = hsx.extract(long_best_first, method="best-first", time_limit=1.6, progress=seen.append)
    assert r.stopped_by == "time-limit"
    assert len(seen) >= 2  # about twice a second
    assert {"states_expanded", "queue_size", "graph_cuts", "best_energy", "lower_bound"} <= set(seen[-1])
    assert seen[-1]["states_expanded"] >= seen[0]["states_expanded"] > 0


def test_an_exception_in_the_callback_stops_the_search(long_best_first):
    class Stop(Exception):
        pass

    def failing(p):
        raise Stop("from the callback")

    start = time.monotonic()
    with pytest.raises(Stop, match="from the callback"):
        hsx.extract(long_best_first, method="best-first", progress=failing)
    assert time.monotonic() - start < 5


def test_ctrl_c_stops_best_first(long_best_first):
    timer = start_later(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        hsx.extract(long_best_first, method="best-first")
    timer.join()
    assert time.monotonic() - start < 5


def test_the_gil_is_released(long_search):
    """Another Python thread runs while the engine searches."""
    ticks = []
    done = threading.Event()

    def ticker():
        while not done.is_set():
            ticks.append(1)
            time.sleep(0.01)

    t = threading.Thread(target=ticker)
    t.start()
    r = hsx.extract(long_search, method="brute-force", max_labellings=10 ** 15, time_limit=0.5)
    done.set()
    t.join()
    assert r.stopped_by == "time-limit"
    assert len(ticks) >= 10
