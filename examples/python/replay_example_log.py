"""The four tyre and four brake thermal models over the shipped Darlington example log, from the
log read into NumPy arrays (any source of arrays works the same: a MoTeC export, a database).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/replay_example_log.py
"""

import csv
import os

import numpy as np

import hotlap


def read_log(path):
    """The CSV as {column: array}; empty cells become NaN (not measured)."""
    with open(path) as f:
        rows = [line for line in csv.reader(f) if line and not line[0].startswith("#")]
    header, data = rows[0], rows[1:]
    return {name: np.array([float(r[i]) if r[i] else np.nan for r in data]) for i, name in enumerate(header)}


def main():
    log = read_log(os.path.join(hotlap.data_dir(), "telemetry", "darlington_example.csv"))
    result = hotlap.replay(hotlap.load_car("gen7"), log)
    summary = result["summary"]
    print("%d samples, %.1f s of log" % (summary["samples"], summary["duration_s"]))
    print("corner  tread peak C  disc peak C  wear mm")
    for corner, s in summary["corners"].items():
        print("%-6s  %12.1f  %11.1f  %7.4f" % (corner, s["tread_temp_C"]["peak"], s["disc_temp_C"]["peak"], s["wear_mm"]))
    tread = result["channels"]["tread_temp_fl_C"]
    print("front-left tread: %.1f C at the start, %.1f C at the end" % (tread[0], tread[-1]))


if __name__ == "__main__":
    main()
