#!/usr/bin/env python3
"""Statistics of FE ABS ensembles run in shards, and the equivalence of two of them.

An ensemble too large for one run is run as shards (`hotlap fe abs --ensemble N --first-member K
--perturb sum-order|round-off`: members K..K+N-1, the same bits as in one large run). This
tool joins the shards of each group (their `--json` files), refusing shards of another
perturbation, duration, configuration or ABS overrides and members counted twice, and prints each
figure's n, mean, standard error (sd / sqrt n, the sample sd) and spread, as `hotlap fe abs
--ensemble` computes them (sim::CalcEnsembleStat). With two groups it prints, per figure, the
equivalence bound |difference of the means| + 2 sqrt(se_a^2 + se_b^2) (sim::EquivalenceBound)
against the acceptance's margins (4 percentage points below slip 0.135, 0.02 on the 99th
percentile of slip; docs/fe-tyre.md, "ABS stop") and the members each group would need for the
bound to fall below the margin at the spread seen, were the means equal.

    /usr/bin/python3 tools/fe_ensemble_stats.py LABEL=A1.json[,A2.json...] [LABEL=B1.json[,...]] \\
        [--json OUT.json]
"""

import json
import math
import sys

MARGINS = {"fraction_below_0_135": 0.04, "slip_p99": 0.02}
KEYS = ["fraction_below_0_135", "slip_p99", "slip_mean", "slip_max", "cycles_per_s",
        "first_release_s", "distance_m", "mean_deceleration_mps2"]


def join_shards(label, paths):
    """The members of the shards in `paths`, keyed by member index, and what they share."""
    members, shared = {}, None
    for path in paths:
        with open(path) as f:
            summary = json.load(f)
        e = summary["abs_ensemble"]
        this = {"perturbation": e["perturbation"], "duration_s": e["duration_s"],
                "config": summary.get("config"), "abs_overrides": summary.get("abs_overrides", {})}
        if shared is None:
            shared = this
        elif this != shared:
            sys.exit(f"{label}: {path} is another ensemble ({this} against {shared})")
        first = e.get("first_member", 0)
        for k, m in enumerate(e["member_figures"]):
            index = m.get("member", first + k)
            if index in members:
                sys.exit(f"{label}: member {index} is in two shards ({path})")
            members[index] = m
    return members, shared


def stat(values):
    n = len(values)
    if n == 0:
        return {"n": 0}
    mean = sum(values) / n
    # Equal values have no spread (as sim::CalcEnsembleStat: not the mean's rounding).
    spread = n > 1 and min(values) < max(values)
    sd = math.sqrt(sum((v - mean) ** 2 for v in values) / (n - 1)) if spread else 0.0
    return {"n": n, "mean": mean, "sd": sd, "standard_error": sd / math.sqrt(n),
            "min": min(values), "max": max(values)}


def main(argv):
    args, out = [], None
    it = iter(argv[1:])
    for a in it:
        if a == "--json":
            out = next(it, None)
        else:
            args.append(a)
    if not 1 <= len(args) <= 2 or any("=" not in a for a in args) or (out is None and "--json" in argv):
        sys.exit(__doc__)
    groups = []
    for a in args:
        label, paths = a.rsplit("=", 1)
        members, shared = join_shards(label, paths.split(","))
        stats = {k: stat([m[k] for m in members.values() if m.get(k) is not None]) for k in KEYS}
        groups.append({"label": label, "members": sorted(members), **shared, "figures": stats})
        print(f"{label}: {len(members)} members ({shared['perturbation']}, {shared['duration_s']} s)")
        for k in KEYS:
            s = stats[k]
            if s["n"]:
                print(f"  {k:<24} {s['mean']:.5g} +- {s['standard_error']:.2g} "
                      f"({s['min']:.4g} .. {s['max']:.4g}, n {s['n']}, sd {s['sd']:.3g})")
    result = {"groups": groups}
    if len(groups) == 2:
        a, b = (g["figures"] for g in groups)
        result["equivalence"] = {}
        print(f"{groups[0]['label']} against {groups[1]['label']}:")
        for k in KEYS:
            if not (a[k]["n"] and b[k]["n"]):
                continue
            diff = a[k]["mean"] - b[k]["mean"]
            bound = abs(diff) + 2 * math.hypot(a[k]["standard_error"], b[k]["standard_error"])
            row = {"difference": diff, "bound": bound}
            line = f"  {k:<24} difference {diff:+.4g}, bound {bound:.4g}"
            if k in MARGINS:
                margin = MARGINS[k]
                # Members per group for 2 sqrt(2) sd / sqrt(n) < margin, at the pooled sd.
                sd = math.sqrt((a[k]["sd"] ** 2 + b[k]["sd"] ** 2) / 2)
                needed = math.ceil((2 * math.sqrt(2) * sd / margin) ** 2)
                row.update({"margin": margin, "within": bound < margin, "members_needed": needed})
                line += (f" against {margin:g}: {'within' if bound < margin else 'NOT within'}"
                         f" (equal means would need {needed} members a group at this spread)")
            result["equivalence"][k] = row
            print(line)
    if out:
        with open(out, "w") as f:
            json.dump(result, f, indent=1)
        print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv)
