# SPDX-License-Identifier: Apache-2.0
# Long computations release the GIL (other Python threads run meanwhile, and two renders run at
# once) and stop on Ctrl-C: a SIGINT during a render raises KeyboardInterrupt within half a
# second.
import threading
import time

import numpy as np

import ifsfx
from conftest import STOP_BOUND, interrupted_after

EXPECTED_TESTS = 4

# Seconds of work on one core: far longer than the test waits.
LONG = dict(mode="measure", size=(1024, 1024), quality=20000, threads=1)


def test_sigint_during_a_render_raises_keyboard_interrupt_promptly():
    latency = interrupted_after(0.3, lambda: ifsfx.render("barnsley-fern", **LONG))
    print(f"render: KeyboardInterrupt {latency * 1000:.0f} ms after SIGINT")
    assert latency < STOP_BOUND, f"KeyboardInterrupt {latency:.3f} s after SIGINT"


def test_sigint_during_a_steal_map_raises_keyboard_interrupt_promptly():
    latency = interrupted_after(0.3, lambda: ifsfx.steal_map(
        "barnsley-fern", size=(1024, 1024), exact=False, quality=200000, threads=1))
    print(f"steal_map: KeyboardInterrupt {latency * 1000:.0f} ms after SIGINT")
    assert latency < STOP_BOUND, f"KeyboardInterrupt {latency:.3f} s after SIGINT"


def test_another_python_thread_runs_during_a_render():
    ticks = 0
    done = threading.Event()

    def render():
        ifsfx.render("barnsley-fern", mode="measure", size=(256, 256), quality=3000, threads=1)
        done.set()

    worker = threading.Thread(target=render)
    start = time.monotonic()
    worker.start()
    while not done.is_set():
        ticks += 1  # pure Python: runs only while the render does not hold the GIL
        time.sleep(0.005)
    worker.join()
    seconds = time.monotonic() - start
    assert seconds > 0.2, f"the render took {seconds:.3f} s: too short to tell"
    # Each tick sleeps 5 ms; a quarter of the ticks that fit is plenty on a loaded machine, and
    # far more than the one or two a held GIL would allow.
    assert ticks >= 0.25 * seconds / 0.005, f"{ticks} ticks in {seconds:.3f} s"


def test_two_threads_render_at_once_and_get_the_single_thread_bytes():
    settings = dict(mode="tops", size=(128, 96), exact=False, quality=16, threads=1)
    alone = ifsfx.render("maple-leaf", **settings)
    results = [None, None]

    def render(i):
        results[i] = ifsfx.render("maple-leaf", **settings)

    threads = [threading.Thread(target=render, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        np.testing.assert_array_equal(r, alone)
