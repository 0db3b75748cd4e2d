"""Long runs release the GIL and stop on Ctrl-C between chunks (``KeyboardInterrupt``)."""

import _thread
import signal
import threading
import time

import pytest
import slippery_walker as sw


@pytest.fixture(autouse=True)
def python_handles_ctrl_c():
    """Python's own SIGINT handler, as in an interactive session. A process started in the
    background by a non-interactive shell inherits SIGINT ignored, and then
    ``_thread.interrupt_main`` does nothing (its documentation): the tests would fail for a
    reason that is not the module's."""
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    yield
    signal.signal(signal.SIGINT, previous)

# 2000 points of 20 s walks: about 23 s of work on this machine (a 20 s walk of the active
# walker takes about 12 ms, measured in docs/python.md), far longer than the 0.2 s after
# which the interrupt comes.
LONG_GRID = {"mu0": [0.05 + 0.5 * k / 2000 for k in range(2000)]}


def test_ctrl_c_stops_a_grid_between_chunks():
    timer = threading.Timer(0.2, _thread.interrupt_main)
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        sw.walk_points(LONG_GRID, duration=20.0)
    elapsed = time.monotonic() - start
    timer.cancel()
    # A chunk is 16 walks (~0.2 s); 1 s leaves room for a loaded machine while staying far
    # below the whole grid's 23 s.
    assert elapsed < 1.0, elapsed


def test_ctrl_c_stops_a_sweep_between_chunks():
    timer = threading.Timer(0.2, _thread.interrupt_main)
    timer.start()
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        sw.sweep(mu0_from=0.0, mu0_to=1.0, mu0_step=0.0005, duration=20.0)
    timer.cancel()
    assert time.monotonic() - start < 1.0


def test_another_python_thread_runs_while_a_grid_is_walked():
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    t = threading.Thread(target=tick)
    t.start()
    try:
        before = len(ticks)
        sw.walk_points({"mu0": LONG_GRID["mu0"][:32]}, duration=20.0)
        during = len(ticks) - before
    finally:
        done.set()
        t.join()
    # 32 walks, two chunks, about 0.4 s. With the GIL held through a chunk the ticker could
    # run only between the two chunks and around the call (a few ticks); released, it ticks
    # about once per millisecond, hundreds of times. 50 lies between the two.
    assert during > 50, during
