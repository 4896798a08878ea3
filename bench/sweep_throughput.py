"""Sweep throughput (issue 29): 200 short level-2 runs (sphere3d, subdivisions=2) as one
elasticlab.sweep, serially in this process and on a Dask LocalCluster of worker processes,
in alternating pairs (serial, Dask, serial, Dask, ...) so that a change in the machine's load
falls on both. Prints one line per run, the ratio of each pair, and the load average.

    PYTHONPATH=build/release/python python3 bench/sweep_throughput.py [--pairs 3] [--workers 2]

Not a test: the figures go to docs/performance.md ("Sweeps"). The cluster is started once,
before the first pair, and its start-up is reported apart; the table of every run is checked
against the serial one (same rows, wall time aside).
"""

import argparse
import os
import time

import dask
import distributed
import numpy as np

import elasticlab as el

GRID = {"pressure": el.linear(10, 40, 20), "ks": el.log(400, 3200, 10)}  # 200 points
FIXED = {"subdivisions": 2}
DURATION = 2.0  # s of simulated time per run: 667 rk4 steps of a 130-particle sphere


def run(executor):
    start = time.perf_counter()
    df = el.sweep("sphere3d", GRID, duration=DURATION, executor=executor, progress=False, **FIXED)
    return time.perf_counter() - start, df


def same(a, b):
    for c in a.columns:
        if c != "wall_seconds":
            assert a[c].equals(b[c]), c


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=3)
    parser.add_argument("--workers", type=int, default=2)
    args = parser.parse_args()
    print(f"cores {os.cpu_count()}, load average at start {os.getloadavg()}")
    t0 = time.perf_counter()
    with dask.config.set({"distributed.worker.multiprocessing-method": "forkserver"}), \
            distributed.LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                                     dashboard_address=None, silence_logs=40) as cluster, \
            distributed.Client(cluster) as client:
        print(f"cluster of {args.workers} worker processes up in {time.perf_counter() - t0:.2f} s")
        reference = None
        ratios = []
        for pair in range(args.pairs):
            serial, a = run(None)
            parallel, b = run(client)
            reference = a if reference is None else reference
            same(a, reference)
            same(b, reference)
            ratios.append(serial / parallel)
            # The runs' own wall time against the elapsed time (x workers): how much of the time
            # was spent inside the runs (the rest: scheduling, transfers, the CPU taken by others).
            busy_serial = a["wall_seconds"].sum() / serial
            busy_dask = b["wall_seconds"].sum() / (parallel * args.workers)
            print(f"pair {pair + 1}: serial {serial:.2f} s, dask {parallel:.2f} s, speed-up {serial / parallel:.2f}x; "
                  f"inside the runs {100 * busy_serial:.0f} % / {100 * busy_dask:.0f} %; "
                  f"load average {os.getloadavg()[0]:.1f}; {len(a)} runs, {int(a['steps'].sum())} steps, "
                  f"{(a.status == 'ok').sum()} ok")
        print(f"speed-up: median {np.median(ratios):.2f}x, min {min(ratios):.2f}x, max {max(ratios):.2f}x "
              f"over {len(ratios)} pairs; load average at the end {os.getloadavg()}")


if __name__ == "__main__":
    main()
