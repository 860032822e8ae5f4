"""Tyre forces from NumPy against the C++ batch rate, measured in the same run (issue 22's goal:
at least 80%).

    PYTHONPATH=build/python /usr/bin/python3 bench/python_tyre_bench.py [build/magic_formula_bench]

Times hotlap.tyre_forces on 2^20 points of the Gen-7-like car's left.tir (best of five), then runs
magic_formula_bench's BM_TyreForcesMillionPoints (the same points, already operating points in
SI, evaluated by CalcTyreForcesBatch in C++: the batch rate itself) and prints both rates and their ratio. Run it on an idle
machine: both sides are single-threaded.
"""

import json
import os
import subprocess
import sys
import time

import numpy as np

import hotlap

N = 1 << 20


def main(bench_binary):
    i = np.arange(N, dtype=np.int64)
    fz = 2000.0 + 8000.0 * (i % 1000) / 999.0
    alpha = -10.0 + 20.0 * ((i * 7) % 1001) / 1000.0
    kappa = -0.2 + 0.4 * ((i * 13) % 1003) / 1002.0
    model = hotlap.load_tyre("gen7/left")  # a built-in name, or a path to a .tir or .yaml file
    best = float("inf")
    for _ in range(5):
        started = time.perf_counter()
        hotlap.tyre_forces(model, fz_N=fz, slip_angle_deg=alpha, slip_ratio=kappa, speed_mps=20.0)
        best = min(best, time.perf_counter() - started)
    python_rate = N / best
    out = subprocess.run(
        [bench_binary, "--benchmark_filter=BM_TyreForcesMillionPoints",
         "--benchmark_format=json", "--benchmark_repetitions=5", "--benchmark_report_aggregates_only=true"],
        capture_output=True, text=True, check=True).stdout
    runs = json.loads(out)["benchmarks"]
    cpp_rate = max(r["items_per_second"] for r in runs if r.get("aggregate_name") in ("mean", "median", None))
    print("hotlap.tyre_forces from NumPy: %.3g points/s (%d points, best of 5: %.1f ms)" % (python_rate, N, best * 1e3))
    print("C++ CalcTyreForcesBatch:       %.3g points/s" % cpp_rate)
    print("ratio Python / C++: %.2f (goal >= 0.80)" % (python_rate / cpp_rate))


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join("build", "magic_formula_bench"))
