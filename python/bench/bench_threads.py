"""Two Python threads sampling at once against one: with the GIL released
the pair takes about the time of one on two idle cores (a lock would make it
twice). A measurement, not a test: run on a quiet machine with
/usr/bin/python3 python/bench/bench_threads.py (after make demo)."""

import os
import threading
import time

import pds


def best_of(runs, f):
    best = float("inf")
    for _ in range(runs):
        start = time.perf_counter()
        f()
        best = min(best, time.perf_counter() - start)
    return best


def one():
    pds.generate("bridson", radius=0.0025, seed=1, threads=1)


def two():
    threads = [threading.Thread(target=one) for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()


if __name__ == "__main__":
    single, pair = best_of(5, one), best_of(5, two)
    print(f"load {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores: one call {single * 1e3:.1f} ms, "
          f"two threads {pair * 1e3:.1f} ms, ratio {pair / single:.2f} (1 = fully parallel, 2 = serialised)")
