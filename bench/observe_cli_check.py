"""Issue 26's acceptance through the command line (docs/observer.md, "From the command line").

For each seed, makes two `hotlap synth` logs of the same laps with the same stochastic truth
(`--process-noise default`: the model plus the random-walk process noise the observer assumes,
seeded by `--seed`), one with noise-free sensors (the truth) and one with 0.5 degC sensors, both
without lag; blanks 20% of the disc cells of the measured log in runs of 0.5 s on average (a
seeded two-state chain); runs `hotlap observe --json` on it, started 3 degC off the true carcass
temperature; and scores the estimates against the truth from the end of the first lap: RMS error
and the share of samples inside the 1-sigma band per state, the wear at the end, and the mean
normalised innovation squared of every used reading (from the JSON summaries) against its
two-sided 95% chi-square bounds. The carcass and wear columns of the measured log are never read.

With --check it exits 1 unless the numbers meet issue 26's acceptance: carcass RMS error under
1 degC after the first lap and wear within 10% at the end, for every seed; the 1-sigma bands of
tread, carcass and disc holding the truth 65-72% of the (scored) time over all seeds together; the
pooled mean NIS within its 95% bounds. --deterministic makes the truth without process noise (the
filter is then cautious: bands too wide, NIS below its bounds; --check fails, as it should).

Run: /usr/bin/python3 bench/observe_cli_check.py [--laps 30] [--seeds 8] [--check]
     [--hotlap build/hotlap]
"""

import argparse
import csv
import json
import math
import os
import random
import subprocess
import sys
import tempfile
import time as clock

CORNERS = ("fl", "fr", "rl", "rr")
STATES = (("tread_temp", "C"), ("carcass_temp", "C"), ("wear", "mm"), ("disc_temp", "C"), ("calliper_temp", "C"))


def load(path):
    with open(path) as f:
        rows = list(csv.reader(line for line in f if not line.startswith("#")))
    header = rows[0]
    return {c: [float(r[i]) if r[i] else math.nan for r in rows[1:]] for i, c in enumerate(header)}


def mean_nis_bounds95(n):
    """Two-sided 95% bounds of the mean of n chi-square(1) values (Wilson-Hilferty)."""
    z = 1.959963984540054
    a = 2.0 / (9.0 * n)
    return tuple((1.0 - a + s * z * math.sqrt(a)) ** 3 for s in (-1.0, 1.0))


def run_seed(args, seed, d):
    truth, measured, dropped, est, js = (os.path.join(d, f"{n}{seed}") for n in ("truth.csv", "meas.csv", "drop.csv", "est.csv", "o.json"))
    common = [args.hotlap, "synth", "--laps", str(args.laps), "--rate-hz", "100", "--lag-s", "0", "--seed", str(seed)]
    if not args.deterministic:
        common += ["--process-noise", "default"]
    subprocess.run(common + ["--noise-C", "0", "--wear-noise-mm", "0", "--out", truth], check=True, stdout=subprocess.DEVNULL)
    subprocess.run(common + ["--noise-C", "0.5", "--out", measured], check=True, stdout=subprocess.DEVNULL)
    rng = random.Random(seed)
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
    started = clock.monotonic()
    run = subprocess.run([args.hotlap, "observe", "--telemetry", dropped, "--out", est, "--carcass-temp-C", "63", "--json", js],
                         check=True, capture_output=True, text=True)
    wall = clock.monotonic() - started
    with open(js) as f:
        summary = json.load(f)
    return load(truth), load(est), summary, blanked / cells, wall, run.stdout


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--laps", type=int, default=3)
    parser.add_argument("--seeds", type=int, default=1)
    parser.add_argument("--check", action="store_true", help="exit 1 unless issue 26's acceptance numbers hold")
    parser.add_argument("--deterministic", action="store_true", help="truth without process noise")
    parser.add_argument("--hotlap", default=os.path.join(os.path.dirname(__file__), "..", "build", "hotlap"))
    args = parser.parse_args()
    se = {q: 0.0 for q, _ in STATES}
    inside = {q: 0 for q, _ in STATES}
    n = 0
    nis_sum = nis_used = 0.0
    worst_carcass = worst_wear = 0.0
    warnings = rejected = 0
    observed_s = wall_s = 0.0
    with tempfile.TemporaryDirectory() as d:
        for seed in range(1, args.seeds + 1):
            t, e, summary, blanked, wall, stdout = run_seed(args, seed, d)
            time = t["time_s"]
            lap = (time[-1] - time[0]) / args.laps
            observed_s += time[-1] - time[0]
            wall_s += wall
            scored = [k for k in range(len(time)) if time[k] - time[0] >= lap]
            n += len(scored) * len(CORNERS)
            for c in CORNERS:
                for q, unit in STATES:
                    truth_c, est_c, sd_c = t[f"{q}_{c}_{unit}"], e[f"{q}_{c}_{unit}"], e[f"{q}_{c}_sd_{unit}"]
                    corner_se = 0.0
                    for k in scored:
                        dq = est_c[k] - truth_c[k]
                        corner_se += dq * dq
                        inside[q] += abs(dq) <= sd_c[k]
                    se[q] += corner_se
                    if q == "carcass_temp":
                        worst_carcass = max(worst_carcass, math.sqrt(corner_se / len(scored)))
                w, we = t[f"wear_{c}_mm"][-1], e[f"wear_{c}_mm"][-1]
                worst_wear = max(worst_wear, abs(we - w) / w)
                for s in summary["corners"][c]["sensors"].values():
                    nis_sum += s["mean_nis"] * s["used"]
                    nis_used += s["used"]
                    rejected += s["rejected"]
            warnings += len(summary["disagreements"])
            summary_line = [line for line in stdout.splitlines() if "real time" in line][-1]
            print(f"seed {seed}: disc cells blanked {blanked:.3f}; {summary_line}")
    print(f"{args.seeds} seed(s) x {args.laps} laps, truth {'deterministic' if args.deterministic else 'with process noise'}; scored from the end of the first lap")
    for q, unit in STATES:
        print(f"{q:14s} RMS error {math.sqrt(se[q] / n):.4g} {unit}, inside 1 sigma {inside[q] / n:.3f}")
    nis = nis_sum / nis_used
    lo, hi = mean_nis_bounds95(nis_used)
    print(f"worst corner carcass RMS {worst_carcass:.4g} C; worst wear error at the end {100 * worst_wear:.3g}%")
    print(f"pooled mean NIS {nis:.4f} over {int(nis_used)} readings, 95% bounds [{lo:.4f}, {hi:.4f}]; {rejected} rejected, {warnings} warnings")
    print(f"observe ran at {observed_s / wall_s:.0f} times real time (wall clock, reading and writing CSV)")
    if not args.check:
        return 0
    failures = []
    if not worst_carcass < 1.0:
        failures.append(f"carcass RMS {worst_carcass:.3g} C is not under 1 C")
    if not worst_wear < 0.1:
        failures.append(f"wear error {100 * worst_wear:.3g}% is not within 10%")
    for q in ("tread_temp", "carcass_temp", "disc_temp"):
        share = inside[q] / n
        if not 0.65 <= share <= 0.72:
            failures.append(f"{q} 1-sigma band holds the truth {100 * share:.1f}% of the time, not 65-72%")
    if not lo < nis < hi:
        failures.append(f"pooled mean NIS {nis:.4f} is outside its 95% bounds [{lo:.4f}, {hi:.4f}]")
    for f in failures:
        print("FAIL:", f)
    print("acceptance: " + ("FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
