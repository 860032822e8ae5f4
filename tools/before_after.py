#!/usr/bin/env python3
"""Every CLI and Python output the same before and after a change (issue 43's acceptance).

    tools/before_after.py run BUILD_DIR OUT_DIR [--only NAME,...]
    tools/before_after.py compare BEFORE_DIR AFTER_DIR [--rtol X]

`run` runs the example commands below (readers, replay, the QSS lap, synth, fits, observe, ABS, the
FE tyre's inflation, a race, a coarse optimal lap and a coarse stint with --threads 1, and the same
runs from Python) with BUILD_DIR's `hotlap` and Python module, each in a folder of its own under
OUT_DIR: what it writes, its standard output and error and its exit status. `compare` compares two
such folders file by file: byte for byte for every command but the optimal laps, once timings ("in
0.52 s", "done in", wall-clock keys of the JSON summaries) and the repository's path are masked;
the optimal laps' numbers within a relative tolerance (--rtol, default 1e-4: the solver's), their
text exactly.
It prints one line a command and exits 1 if any differs.

To take the "before" of a change: build the commit before it (scripts/build.sh), `run` into a
folder kept aside; after the change, build, `run` again and `compare`.
"""

import argparse
import difflib
import json
import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent

# Commands that write into files the later ones read (synth's logs) come first.
# Each: (name, kind, argv). kind 'exact' compares byte for byte (timings masked), 'optimal'
# within the tolerance. In argv, {repo} is the repository root; `py` runs Python code with the
# build's module; a command runs in its own folder, so relative paths are its outputs, and
# ../NAME/FILE is an earlier command's.
TELEMETRY = "{repo}/data/telemetry/darlington_example.csv"
I2 = "{repo}/tests/data/motec/darlington_i2.csv"
CHANNEL_MAP = "{repo}/tests/data/motec_channels.yaml"

COMMANDS = [
    # Readers.
    ("track_darlington", "exact",
     ["hotlap", "track", "info", "--track", "darlington", "--json", "t.json", "--out", "t.csv"]),
    ("track_tum", "exact",
     ["hotlap", "track", "info", "--track", "{repo}/data/tracks/catalunya.csv", "--json", "t.json"]),
    ("track_fastest_lap", "exact",
     ["hotlap", "track", "info", "--track", "{repo}/data/tracks/catalunya-fl.xml", "--json",
      "t.json"]),
    ("log_info_csv", "exact", ["hotlap", "log", "info", TELEMETRY, "--json", "l.json"]),
    ("log_info_i2", "exact", ["hotlap", "log", "info", I2, "--json", "l.json"]),
    ("log_convert_i2", "exact", ["hotlap", "log", "convert", I2, "--out", "log.csv"]),
    ("tyre_eval_mf", "exact",
     ["hotlap", "tyre", "eval", "--model", "mf", "--params", "gen7/left", "--slip-angle-deg", "3",
      "--json", "e.json"]),
    ("tyre_eval_brush_sweep", "exact",
     ["hotlap", "tyre", "eval", "--model", "brush", "--params", "brush_example", "--sweep",
      "slip-angle-deg=-6:6:1", "--out", "sweep.csv"]),
    ("tyre_eval_unitire_sweep", "exact",
     ["hotlap", "tyre", "eval", "--model", "unitire", "--params", "unitire_example", "--sweep",
      "slip-ratio=-0.2:0.2:0.05", "--sweep", "tread-temp-C=40:100:30", "--out", "sweep.csv",
      "--json", "e.json"]),
    # Replay.
    ("replay", "exact",
     ["hotlap", "replay", "--telemetry", TELEMETRY, "--out", "r.csv", "--json", "r.json",
      "--report", "r.html", "--heat-flows"]),
    ("replay_i2_set", "exact",
     ["hotlap", "replay", "--telemetry", I2, "--out", "r.csv", "--json", "r.json", "--set",
      "chassis.mass_kg=1600", "--tread-temp-C", "70"]),
    # The QSS lap.
    ("lap_qss", "exact", ["hotlap", "lap", "--method", "qss", "--out", "lap", "--json", "l.json"]),
    ("lap_qss_stint", "exact",
     ["hotlap", "lap", "--laps", "3", "--caution-laps", "2", "--line", "centre", "--step-m", "2",
      "--out", "lap", "--json", "l.json"]),
    ("lap_qss_start", "exact",
     ["hotlap", "lap", "--set", "chassis.mass_kg=1600", "--tread-temp-C", "80", "--disc-temp-C",
      "300", "--rim-temp-C", "50", "--step-m", "2", "--out", "lap", "--json", "l.json"]),
    ("lap_qss_refused", "exact", ["hotlap", "lap", "--laps", "0", "--out", "lap"]),
    # Synthetic logs (the fits' and observer's inputs).
    ("synth", "exact",
     ["hotlap", "synth", "--laps", "2", "--step-m", "2", "--rate-hz", "20", "--out", "s.csv",
      "--json", "s.json"]),
    ("synth_process_noise", "exact",
     ["hotlap", "synth", "--process-noise", "default", "--seed", "3", "--step-m", "2",
      "--rate-hz", "20", "--out", "s.csv"]),
    # Fits.
    ("fit_tyre", "exact",
     ["hotlap", "fit", "tyre", "--telemetry", "../synth/s.csv", "--corners", "fl,rr",
      "--threads", "1", "--out", "fitted.yaml", "--report", "report", "--json", "f.json"]),
    ("fit_brake", "exact",
     ["hotlap", "fit", "brake", "--telemetry", "../synth/s.csv", "--corners", "fl",
      "--threads", "1", "--out", "fitted.yaml", "--report", "report", "--json", "f.json"]),
    ("fit_contact_length", "exact",
     ["hotlap", "fit", "contact-length", "--telemetry", "../synth/s.csv", "--threads", "1",
      "--out", "fitted.yaml", "--json", "f.json"]),
    ("fit_refused", "exact",
     ["hotlap", "fit", "tyre", "--telemetry", "../synth/s.csv", "--out", "fitted.txt"]),
    # The observer.
    ("observe", "exact",
     ["hotlap", "observe", "--telemetry", TELEMETRY, "--out", "est.csv", "--json", "o.json"]),
    ("observe_synth_lag", "exact",
     ["hotlap", "observe", "--telemetry", "../synth_process_noise/s.csv", "--p5-scale", "--out",
      "est.csv", "--json", "o.json"]),
    ("observe_i2_lap", "exact",
     ["hotlap", "observe", "--telemetry", I2, "--sensor-lag-s", "0.3", "--set",
      "brakes.fl.duct_factor=0.8", "--out", "est.csv", "--json", "o.json"]),
    ("observe_stream", "exact",
     ["sh", "-c", "cat ../synth/s.csv | \"$HOTLAP\" observe --telemetry - --out - --json o.json"
      " > est.csv"]),
    # ABS.
    ("abs", "exact", ["hotlap", "abs", "--out", "abs", "--json", "a.json"]),
    ("abs_no_abs", "exact", ["hotlap", "abs", "--no-abs", "--drum", "--out", "abs"]),
    # The finite-element tyre's file read and its inflation (one thread: the same sums).
    ("fe_inflate", "exact",
     ["hotlap", "fe", "inflate", "--config", "{repo}/data/fe/paper_235_75r15.yaml", "--threads",
      "1", "--out", "fe", "--json", "fe.json"]),
    # Race strategy.
    ("race", "exact",
     ["hotlap", "race", "--laps", "120", "--stages", "40,80", "--tyre-sets", "5",
      "--fall-off-laps", "12", "--races", "200", "--step-m", "4", "--json", "r.json",
      "--report", "r.html"]),
    # A coarse optimal lap.
    ("optimise_coarse", "optimal",
     ["hotlap", "optimise", "--step-m", "12", "--coarse-step-m", "0", "--threads", "1", "--out",
      "opt", "--json", "o.json"]),
    # The F1 car of the peer benchmark on a banked track (its planar warning), and refused.
    ("optimise_f1", "optimal",
     ["hotlap", "optimise", "--car", "f1-2014", "--track", "darlington", "--mesh-points", "100",
      "--out", "f1", "--json", "f1.json"]),
    ("optimise_f1_refused", "exact",
     ["hotlap", "optimise", "--car", "f1-2014", "--disc-limit-C", "500", "--out", "f1"]),
    # A coarse stint of two optimal laps.
    ("stint_coarse", "optimal",
     ["hotlap", "stint", "--laps", "2", "--step-m", "12", "--coarse-step-m", "0", "--threads",
      "1", "--out", "st", "--json", "s.json"]),
    # Python.
    ("py_qss_lap", "exact", ["py", """
car = hotlap.load_car("gen7", {"chassis.mass_kg": 1600})
r = hotlap.qss_lap(car, hotlap.load_track(), laps=2, step_m=2.0, tread_temp_C=70.0,
                   caution_laps="2")
dump(r)
"""]),
    ("py_qss_lap_centre", "exact", ["py", """
r = hotlap.qss_lap(hotlap.load_car(), hotlap.load_track(), line="centre", step_m=2.0)
dump(r)
"""]),
    ("py_replay", "exact", ["py", """
r = hotlap.replay(hotlap.load_car(), REPO + "/data/telemetry/darlington_example.csv",
                  heat_flows=True, disc_temp_C=200.0)
dump(r)
"""]),
    ("py_logs", "exact", ["py", """
dump({"info": hotlap.log_info(REPO + "/tests/data/motec/darlington_i2.csv"),
      "log": hotlap.read_log(REPO + "/data/telemetry/darlington_example.csv")})
hotlap.convert_log(REPO + "/tests/data/motec/darlington_i2.csv", "converted.csv")
"""]),
    ("py_fit_tyre", "exact", ["py", """
r = hotlap.fit(hotlap.load_car(), "../synth/s.csv", kind="tyre", corners="fl", threads=1,
               out="fitted/car.yaml")
dump(r)
"""]),
    ("py_fit_brake", "exact", ["py", """
r = hotlap.fit(hotlap.load_car(), "../synth/s.csv", kind="brake", corners="rr", threads=1)
dump(r)
"""]),
    ("py_fit_refused", "exact", ["py", """
try:
    hotlap.fit(hotlap.load_car(), "../synth/s.csv", kind="wheel")
except Exception as e:
    print(type(e).__name__, e)
"""]),
    ("py_race", "exact", ["py", """
r = hotlap.race(hotlap.load_car(), hotlap.load_track(), laps=120, stages="40,80", tyre_sets=5,
                fall_off_laps=12, races=200, step_m=4.0)
dump(r)
"""]),
    ("py_stint", "optimal", ["py", """
r = hotlap.stint(hotlap.load_car(), hotlap.load_track(), laps=2, step_m=12.0, coarse_step_m=0.0,
                 threads=1)
dump(r)
"""]),
    ("py_optimal_lap", "optimal", ["py", """
r = hotlap.optimal_lap(hotlap.load_car(), hotlap.load_track(), step_m=12.0, coarse_step_m=0.0,
                       threads=1)
dump(r)
"""]),
]

PY_PRELUDE = """
import json, sys
import numpy as np
import hotlap
REPO = {repo!r}
def _plain(x):
    if isinstance(x, dict):
        return {{str(k): _plain(v) for k, v in x.items()}}
    if isinstance(x, (list, tuple)):
        return [_plain(v) for v in x]
    if isinstance(x, np.ndarray):
        return [repr(float(v)) for v in x.ravel()]
    if isinstance(x, float):
        return repr(x)
    if isinstance(x, (np.floating, np.integer)):
        return repr(x.item())
    return x
def dump(x, path="result.json"):
    with open(path, "w") as f:
        json.dump(_plain(x), f, indent=1, sort_keys=True)
        f.write("\\n")
"""


def run(build: Path, out: Path, only):
    hotlap = (build / "hotlap").resolve()
    if not hotlap.exists():
        sys.exit(f"{hotlap}: no such program (build first)")
    env = dict(os.environ, HOTLAP=str(hotlap),
               PYTHONPATH=str((build / "python").resolve()), OMP_NUM_THREADS="1",
               HOTLAP_CACHE_DIR="")  # no cache (`hotlap race`): every run drives its laps
    out.mkdir(parents=True, exist_ok=True)
    # The build's source tree, whose data/ the program finds its built-in cars and tracks in
    # (their paths are printed): masked by `compare` as the repository's root is.
    for line in (build / "CMakeCache.txt").read_text().splitlines():
        if line.startswith("CMAKE_HOME_DIRECTORY:"):
            (out / "source_root.txt").write_text(line.split("=", 1)[1] + "\n")
    for name, _, argv in COMMANDS:
        if only and name not in only:
            continue
        d = out / name
        if d.exists():
            shutil.rmtree(d)
        d.mkdir()
        argv = [a.replace("{repo}", str(REPO)) for a in argv]
        if argv[0] == "py":
            code = PY_PRELUDE.format(repo=str(REPO)) + argv[1]
            argv = ["/usr/bin/python3", "-c", code]
        elif argv[0] == "hotlap":
            argv = [str(hotlap)] + argv[1:]
        started = time.monotonic()
        p = subprocess.run(argv, cwd=d, env=env, capture_output=True, timeout=1200)
        (d / "stdout.txt").write_bytes(p.stdout)
        (d / "stderr.txt").write_bytes(p.stderr)
        (d / "rc.txt").write_text(f"{p.returncode}\n")
        print(f"{name:<26} rc {p.returncode} in {time.monotonic() - started:.1f} s", flush=True)


# Timings: "in 0.52 s", "done in 3 s", "(123 times real time)", Ipopt's and the fits' clocks,
# and JSON keys that hold a wall-clock time. The repository's root is masked so that two
# checkouts compare.
TIME_PATTERNS = [
    (re.compile(r"\bin [0-9.]+(e[-+]?\d+)? ?(s|ms|min)\b"), "in <t> s"),
    (re.compile(r"done in .*"), "done in <t>"),
    (re.compile(r"\([0-9.]+ times real time\)"), "(<n> times real time)"),
    (re.compile(r'"([a-z_]*(?:wall|solve|elapsed|cpu|seconds)[a-z_]*)"(\s*:\s*)("?)[-0-9.e+]+("?)'),
     r'"\1"\2<t>'),
    (re.compile(r"iterations, [0-9.]+ s \(greedy laps [0-9.]+ s\)"),
     "iterations, <t> s (greedy laps <t> s)"),
    (re.compile(r"(Total (CPU|seconds|wall)[^=]*=)\s*[0-9.]+"), r"\1 <t>"),
    (re.compile(r"\b[0-9.]+ s (wall|cpu)\b"), "<t> s \\1"),
    (re.compile(r"(\d+ / )[0-9.]+ s<"), r"\1<t> s<"),  # the optimal lap page's iterations / time
    # The FE solver's progress and its element updates per second.
    (re.compile(r"about [0-9.]+ s left"), "about <t> s left"),
    (re.compile(r"\([0-9.e+]+ per second\)"), "(<n> per second)"),
    (re.compile(r'"element_updates_per_s"(\s*:\s*)[-0-9.e+]+'), r'"element_updates_per_s"\1<n>'),
]
NUMBER = re.compile(rb"[-+]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?")


def masked(data: bytes, repo_roots) -> bytes:
    try:
        text = data.decode()
    except UnicodeDecodeError:
        return data
    for root in repo_roots:
        text = text.replace(root, "<root>")
    for pattern, repl in TIME_PATTERNS:
        text = pattern.sub(repl, text)
    return text.encode()


def numbers_close(a: bytes, b: bytes, rtol: float) -> str:
    """'' when a and b have the same text between their numbers and numbers within rtol."""
    ta, tb = NUMBER.split(a), NUMBER.split(b)
    na, nb = NUMBER.findall(a), NUMBER.findall(b)
    if ta != tb or len(na) != len(nb):
        return "text differs"
    worst = 0.0
    for x, y in zip(na, nb):
        fx, fy = float(x), float(y)
        scale = max(abs(fx), abs(fy), 1e-9)
        if abs(fx - fy) > rtol * scale + 1e-9:
            worst = max(worst, abs(fx - fy) / scale)
    return f"numbers differ by up to {worst:.2e} (relative)" if worst else ""


def source_root(d: Path):
    f = d / "source_root.txt"
    return [f.read_text().strip()] if f.exists() else []


def files_of(d: Path):
    return sorted(str(p.relative_to(d)) for p in d.rglob("*") if p.is_file())


def compare(before: Path, after: Path, rtol: float) -> int:
    bad = 0
    for name, kind, _ in COMMANDS:
        a, b = before / name, after / name
        # The repository's root and each run's own folder (the fitted car names its log).
        roots_a = [str(REPO), str(before.resolve())] + source_root(before)
        roots_b = [str(REPO), str(after.resolve())] + source_root(after)
        if not a.is_dir() or not b.is_dir():
            print(f"{name:<26} MISSING in {'before' if not a.is_dir() else 'after'}")
            bad += 1
            continue
        fa, fb = files_of(a), files_of(b)
        problems = []
        if fa != fb:
            problems.append(f"files differ: {sorted(set(fa) ^ set(fb))}")
        for f in sorted(set(fa) & set(fb)):
            da, db = masked((a / f).read_bytes(), roots_a), masked((b / f).read_bytes(), roots_b)
            if da == db:
                continue
            why = numbers_close(da, db, rtol) if kind == "optimal" else "differs"
            if not why:
                continue
            problems.append(f"{f}: {why}")
            if why in ("differs", "text differs"):
                try:
                    diff = difflib.unified_diff(da.decode().splitlines(),
                                                db.decode().splitlines(), lineterm="", n=0)
                    problems.extend("    " + line[:160] for line in list(diff)[2:8])
                except UnicodeDecodeError:
                    pass
        n = len(fa)
        if problems:
            bad += 1
            print(f"{name:<26} DIFFERS ({n} files)")
            for p in problems:
                print(f"  {p}")
        else:
            print(f"{name:<26} same ({n} files{', within rtol' if kind == 'optimal' else ''})")
    print(f"{len(COMMANDS) - bad} of {len(COMMANDS)} commands the same")
    return 1 if bad else 0


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="what", required=True)
    r = sub.add_parser("run")
    r.add_argument("build", type=Path)
    r.add_argument("out", type=Path)
    r.add_argument("--only", default="", help="comma-separated command names")
    c = sub.add_parser("compare")
    c.add_argument("before", type=Path)
    c.add_argument("after", type=Path)
    c.add_argument("--rtol", type=float, default=1e-4)
    args = parser.parse_args()
    if args.what == "run":
        run(args.build, args.out, set(filter(None, args.only.split(","))))
        return 0
    return compare(args.before, args.after, args.rtol)


if __name__ == "__main__":
    sys.exit(main())
