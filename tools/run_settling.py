#!/usr/bin/python3
"""Lap means of a multi-lap run's temperatures and pressures, and the exponential each settles to.

Reads the CSV `hotlap lap --method qss --laps N --out DIR` writes (DIR/lap.csv) and prints, per
corner and channel, the time-weighted mean of laps 10, 20 and 30 (or of the laps given with
--laps) and the asymptote and time constant of T(t) = A + B exp(-t / tau) through them
(equally spaced laps: r = (m3 - m2) / (m2 - m1) = exp(-dt / tau)). With --json, the same figures
as JSON. Usage: tools/run_settling.py DIR/lap.csv [--laps 10,20,30] [--json OUT]
"""
import argparse
import csv
import json
import math
import sys


def read(path):
    with open(path) as f:
        rows = [line for line in f if not line.startswith("#")]
    reader = csv.reader(rows)
    names = next(reader)
    cols = {n: [] for n in names}
    for r in reader:
        for n, v in zip(names, r):
            cols[n].append(float(v) if v else float("nan"))
    return cols


def lap_mean(cols, name, lap):
    t, v, laps = cols["time_s"], cols[name], cols["lap"]
    idx = [i for i, l in enumerate(laps) if int(l) == lap]
    if len(idx) < 2:
        raise SystemExit(f"lap {lap} not in the run")
    s = 0.0
    for a, b in zip(idx[:-1], idx[1:]):
        s += 0.5 * (v[a] + v[b]) * (t[b] - t[a])
    return s / (t[idx[-1]] - t[idx[0]]), t[idx[0]], t[idx[-1]]


def settle(m, times):
    d1, d2 = m[1] - m[0], m[2] - m[1]
    dt = times[1] - times[0]
    if d1 == 0.0 or d2 / d1 <= 0.0 or d2 / d1 >= 1.0:
        return None, None
    r = d2 / d1
    tau = -dt / math.log(r)
    asym = m[2] + d2 * r / (1.0 - r)
    return asym, tau


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("csv")
    ap.add_argument("--laps", default="10,20,30")
    ap.add_argument("--json")
    a = ap.parse_args()
    laps = [int(x) for x in a.laps.split(",")]
    cols = read(a.csv)
    out = {}
    channels = ["tread_temp", "carcass_temp", "gas_temp", "rim_temp", "disc_temp", "disc_bulk_temp",
                "pressure"]
    print(f"{'channel':<16}{'corner':<7}" + "".join(f"{'lap ' + str(l):>10}" for l in laps) +
          f"{'asymptote':>11}{'tau min':>9}")
    for ch in channels:
        for c in ["fl", "fr", "rl", "rr"]:
            unit = "kPa" if ch == "pressure" else "C"
            name = f"{ch}_{c}_{unit}"
            if name not in cols:
                continue
            means, mids = [], []
            for l in laps:
                m, t0, t1 = lap_mean(cols, name, l)
                means.append(m)
                mids.append(0.5 * (t0 + t1))
            asym, tau = settle(means, mids)
            out.setdefault(ch, {})[c] = {"lap_means": means, "asymptote": asym,
                                         "time_constant_s": tau}
            a_s = f"{asym:11.1f}" if asym is not None else f"{'-':>11}"
            t_s = f"{tau / 60:9.2f}" if tau is not None else f"{'-':>9}"
            print(f"{ch:<16}{c:<7}" + "".join(f"{m:10.1f}" for m in means) + a_s + t_s)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(out, f, indent=1)


if __name__ == "__main__":
    sys.exit(main())
