"""The GIL is released while the library works, and nothing leaks."""

import os
import threading

import numpy as np
import pytest

import pds


def test_python_runs_while_the_library_samples():
    # Held through the call, the GIL would stop this thread from counting
    # between `started` and `done`; released, it counts all along.
    started, done = threading.Event(), threading.Event()

    def work():
        started.set()
        pds.generate("bridson", radius=0.0025, seed=1, threads=1)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    started.wait()
    ticks = 0
    while not done.is_set():
        ticks += 1
    worker.join()
    assert ticks > 1000


def rss_kib():
    with open("/proc/self/statm") as f:
        pages = int(f.read().split()[1])
    import resource

    return pages * resource.getpagesize() // 1024


@pytest.mark.serial
def test_no_memory_growth_over_a_thousand_calls():
    def calls(n):
        for i in range(n):
            pts = pds.generate("random", count=2000, seed=i)  # 32 KiB a call
            pds.qmc.PoissonDisk(2, radius=0.1, seed=i).fill_space()
            pds.radial_power(pts, max_frequency=4)
            try:
                pds.generate("bridson", count=5)
            except ValueError:
                pass

    calls(200)  # warm up: allocator pools, caches
    before = rss_kib()
    calls(1000)
    grown = rss_kib() - before
    assert grown < 4096, f"RSS grew by {grown} KiB over 1,000 calls (a leaked array would be 32,000)"
