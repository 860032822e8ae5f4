"""Issue 26's acceptance through the command line (docs/observer.md, "From the command line").

Makes two `hotlap synth` logs of the same laps, one without noise (the truth) and one with 0.5 degC
sensors, both without lag; blanks 20% of the disc cells of the measured log in runs of 0.5 s on
average (a seeded two-state chain); runs `hotlap observe` on it; and scores the estimates against
the truth from the end of the first lap: RMS error and the share of samples inside the 1-sigma
band per state, and the wear at the end. The carcass and wear columns of the measured log are
never read by the observer.

Run: /usr/bin/python3 bench/observe_cli_check.py [--laps N] [--hotlap build/hotlap]
"""

import argparse
import csv
import math
import os
import random
import subprocess
import tempfile

CORNERS = ("fl", "fr", "rl", "rr")


def load(path):
    with open(path) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    header = rows[0]
    return {c: [float(r[i]) if r[i] else math.nan for r in rows[1:]] for i, c in enumerate(header)}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--laps", type=int, default=3)
    parser.add_argument("--hotlap", default=os.path.join(os.path.dirname(__file__), "..", "build", "hotlap"))
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as d:
        truth, measured, dropped, est = (os.path.join(d, n) for n in ("truth.csv", "meas.csv", "drop.csv", "est.csv"))
        common = [args.hotlap, "synth", "--laps", str(args.laps), "--rate-hz", "100", "--lag-s", "0"]
        subprocess.run(common + ["--noise-C", "0", "--wear-noise-mm", "0", "--out", truth], check=True, stdout=subprocess.DEVNULL)
        subprocess.run(common + ["--noise-C", "0.5", "--out", measured], check=True, stdout=subprocess.DEVNULL)
        rng = random.Random(1)
        with open(measured) as f:
            lines = [line for line in f if not line.startswith("#")]
        header = lines[0].strip().split(",")
        disc = [i for i, c in enumerate(header) if c.startswith("disc_temp_")]
        out_state = [False] * len(disc)
        blanked = cells = 0
        with open(dropped, "w") as f:
            f.write(lines[0])
            for line in lines[1:]:
                cell = line.rstrip("\n").split(",")
                for j, i in enumerate(disc):
                    leave = 1.0 / 50.0  # 100 Hz, mean dropout 0.5 s
                    out_state[j] = rng.random() >= leave if out_state[j] else rng.random() < leave * 0.25
                    if out_state[j]:
                        cell[i] = ""
                        blanked += 1
                    cells += 1
                f.write(",".join(cell) + "\n")
        # The observer starts 3 degC off the true carcass temperature (the car file says 60).
        run = subprocess.run([args.hotlap, "observe", "--telemetry", dropped, "--out", est, "--carcass-temp-C", "63"],
                             check=True, capture_output=True, text=True)
        print(run.stdout.strip().splitlines()[-1])
        t, e = load(truth), load(est)
    time = t["time_s"]
    lap = (time[-1] - time[0]) / args.laps
    print(f"disc cells blanked: {blanked / cells:.3f}")
    for q, unit in (("tread_temp", "C"), ("carcass_temp", "C"), ("wear", "mm"), ("disc_temp", "C"), ("calliper_temp", "C")):
        se = n = inside = 0
        for c in CORNERS:
            truth_c, est_c, sd_c = t[f"{q}_{c}_{unit}"], e[f"{q}_{c}_{unit}"], e[f"{q}_{c}_sd_{unit}"]
            for k in range(len(time)):
                if time[k] - time[0] < lap:
                    continue
                d = est_c[k] - truth_c[k]
                se += d * d
                n += 1
                inside += abs(d) <= sd_c[k]
        print(f"{q:14s} RMS error after lap 1 {math.sqrt(se / n):.4g} {unit}, inside 1 sigma {inside / n:.3f}")
    for c in CORNERS:
        w, we = t[f"wear_{c}_mm"][-1], e[f"wear_{c}_mm"][-1]
        print(f"{c} wear at the end: truth {w:.5f} mm, estimate {we:.5f} mm, error {abs(we - w) / w:.2e} relative")


if __name__ == "__main__":
    main()
