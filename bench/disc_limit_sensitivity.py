#!/usr/bin/python3
"""The disc-limit comparison's sensitivity (docs/validation/optimal-control.md, "Sensitivity").

Runs `hotlap lap --method ocp --compare-disc-limit-C LIMIT` on the Gen-7-like car at the limit and
at tighter ones (--extra-limits-C), and on copies of it with one brake value changed at a time: the left-front duct factor (the front-left disc's and
calliper's convective conductances as a share of the right front's), the heat partition gamma
(all four brakes) and the brake balance (front share). Prints a Markdown table of the lap-time
delta and the free lap's peak front-left disc temperature, and writes the same as JSON.

  /usr/bin/python3 bench/disc_limit_sensitivity.py [--hotlap build/hotlap] [--step-m 3]
      [--limit-C 500] [--car data/cars/gen7] [--json out/sensitivity.json] [--jobs 2]

Each case is two Ipopt solves in one process of its own (Ipopt with MUMPS is not thread-safe);
--jobs runs that many cases at once (one per core).
"""
import argparse
import concurrent.futures
import json
import math
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
CAR = ROOT / "data" / "cars" / "gen7"
SHIPPED_DUCT = 0.75  # brakes/front_left.yaml: 75% of the right front's conductances


def scale_cholesky(text, factor):
    """Scales both convection matrices P = L L' of a brake file by `factor` (L by its root)."""
    root = math.sqrt(factor)

    def one(m):
        return f"{m.group(1)}{float(m.group(2)) * root:.9g}"

    return re.sub(r"(\n  l[1-3][1-3]: )([-0-9.eE+]+)", one, text)


def set_key(text, key, value):
    new, n = re.subn(rf"(\n\s*{key}: )([-0-9.eE+]+)", rf"\g<1>{value}", text, count=1)
    if n != 1:
        sys.exit(f"disc_limit_sensitivity: no '{key}' to change")
    return new


def make_car(base, duct=None, gamma=None, balance=None):
    car = pathlib.Path(tempfile.mkdtemp(prefix="hotlap-sens-")) / "gen7"
    shutil.copytree(base, car)
    if duct is not None:
        f = car / "brakes" / "front_left.yaml"
        f.write_text(scale_cholesky(f.read_text(), duct / SHIPPED_DUCT))
    if gamma is not None:
        for f in (car / "brakes").glob("*.yaml"):
            f.write_text(set_key(f.read_text(), "heat_partition", gamma))
    if balance is not None:
        f = car / "car.yaml"
        f.write_text(set_key(f.read_text(), "front_share", balance))
    return car


def run(hotlap, car, args, limit_C=None):
    out = car.parent / "out"
    js = car.parent / "run.json"
    cmd = [hotlap, "lap", "--method", "ocp", "--compare-disc-limit-C", str(limit_C or args.limit_C),
           "--car", str(car / "car.yaml"), "--ocp-step-m", str(args.step_m),
           "--out", str(out), "--json", str(js)]
    p = subprocess.run(cmd, capture_output=True, text=True)
    if not js.exists():
        return {"error": p.stdout[-500:] + p.stderr[-500:]}
    j = json.loads(js.read_text())
    shutil.rmtree(car.parent)
    return {
        "delta_ms": 1e3 * j["delta_s"],
        "free_lap_s": j["unconstrained"]["lap_time_s"],
        "free_fl_disc_peak_C": j["unconstrained"]["corners"]["fl"]["peak_disc_temp_C"],
        "lift_m": [t["lift_m"] for t in j["unconstrained"]["turns"]],
        "limited_lift_m": [t["lift_m"] for t in j["constrained"]["turns"]],
        "both_converged": j["unconstrained"]["status"] == "converged"
        and j["constrained"]["status"] == "converged",
    }


def metres(value):
    return "-" if value is None else f"{value:.0f}"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--hotlap", default=str(ROOT / "build" / "hotlap"))
    ap.add_argument("--step-m", type=float, default=3.0)
    ap.add_argument("--limit-C", type=float, default=500.0)
    ap.add_argument("--json", default="")
    ap.add_argument("--car", default=str(CAR),
                    help="the car folder to start from (default: the shipped gen7)")
    ap.add_argument("--jobs", type=int, default=1, help="cases run at once (one core each)")
    ap.add_argument("--extra-limits-C", default="450,425",
                    help="limits to run the shipped car at besides --limit-C (comma-separated)")
    args = ap.parse_args()
    cases = [("shipped", {}, None)]
    cases += [(f"shipped, limit {v} degC", {}, float(v))
              for v in args.extra_limits_C.split(",") if v.strip()]
    cases += [(f"duct {v:g}", {"duct": v}, None) for v in (0.6, 0.9)]
    cases += [(f"gamma {v:g}", {"gamma": v}, None) for v in (0.9, 0.98)]
    cases += [(f"balance {v:g}", {"balance": v}, None) for v in (0.55, 0.65)]
    results = {}
    print("| case | delta ms | free lap s | lift into turn 3, free -> limited, m | "
          "free FL disc peak degC | converged |")
    print("|---|---|---|---|---|---|")
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        futures = [pool.submit(run, args.hotlap, make_car(pathlib.Path(args.car), **change), args,
                               limit) for _, change, limit in cases]
        for (name, _, _), future in zip(cases, futures):  # printed in the cases' order
            r = future.result()
            results[name] = r
            if "error" in r:
                print(f"| {name} | failed | | | {r['error'][-120:]!r} |")
            else:
                print(f"| {name} | {r['delta_ms']:.1f} | {r['free_lap_s']:.3f} | "
                      f"{metres(r['lift_m'][-1])} -> {metres(r['limited_lift_m'][-1])} | "
                      f"{r['free_fl_disc_peak_C']:.0f} | {'yes' if r['both_converged'] else 'no'} |")
            sys.stdout.flush()
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(results, indent=2) + "\n")


if __name__ == "__main__":
    main()
