"""16 quasi-steady-state cases on 2 local dask workers against the same 16 run serially, in one
run (issue 23's goal: at least 1.8 times faster).

    PYTHONPATH=build/python /usr/bin/python3 bench/sweep_bench.py

Each case is five QSS laps of Darlington at 0.5 m with another air temperature. The cluster's
start (two worker processes importing hotlap) is timed apart: a real sweep pays it once. Run it
on an idle 2-core machine.
"""

import os
import tempfile
import time

import dask
from distributed import Client, LocalCluster

import hotlap.sweep as sweep

CASES = [{"case": "c%02d" % k, "method": "qss", "laps": 5, "step_m": 0.5, "ambient_temp_C": 10.0 + 2.0 * k}
         for k in range(16)]


def main():
    with tempfile.TemporaryDirectory() as tmp:
        started = time.perf_counter()
        serial = sweep.sweep(CASES, os.path.join(tmp, "serial"), shard=(1, 1), progress=None)
        serial_s = time.perf_counter() - started
        started = time.perf_counter()
        with dask.config.set({"distributed.scheduler.allowed-failures": 2}):
            cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
        client = Client(cluster)
        client.run(lambda: __import__("hotlap"))  # the workers import the package once
        startup_s = time.perf_counter() - started
        started = time.perf_counter()
        parallel = sweep.sweep(CASES, os.path.join(tmp, "dask"), scheduler=client, progress=None)
        parallel_s = time.perf_counter() - started
        client.close()
        cluster.close()
    assert serial["by_status"] == parallel["by_status"] == {"ok": 16}
    print("16 QSS cases serial:        %.2f s" % serial_s)
    print("16 QSS cases on 2 workers:  %.2f s (cluster start %.2f s apart)" % (parallel_s, startup_s))
    print("speed-up: %.2f (goal >= 1.8); with the start: %.2f" % (serial_s / parallel_s, serial_s / (parallel_s + startup_s)))


if __name__ == "__main__":
    main()
