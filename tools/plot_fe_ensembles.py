#!/usr/bin/env python3
"""The FE ABS stop's ensembles side by side: each ensemble's mean of the fraction of time below
slip 0.135 and of the 99th percentile of slip (after the first control cycle), with error bars
of two standard errors, and the acceptance's equivalence margins drawn about the first ensemble's
mean (docs/fe-tyre.md, "ABS stop").

    /usr/bin/python3 tools/plot_fe_ensembles.py OUT.svg LABEL=A.json[,A2.json...] [LABEL=...]

Each JSON is `hotlap fe abs --ensemble N --json` output; an ensemble run in shards
(`--first-member`) is its shards' files, joined as tools/fe_ensemble_stats.py joins them.
Writes one SVG with two panels.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fe_ensemble_stats import join_shards, stat  # noqa: E402

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# (key, axis label, scale, margin) of the panels: the acceptance's margins.
PANELS = [
    ("fraction_below_0_135", "time below slip 0.135 after the first cycle, %", 100.0, 4.0),
    ("slip_p99", "99th percentile of slip after the first cycle", 1.0, 0.02),
]


def main(argv):
    if len(argv) < 3 or any("=" not in a for a in argv[2:]):
        sys.exit(__doc__)
    out = argv[1]
    runs = []
    for arg in argv[2:]:
        label, paths = arg.rsplit("=", 1)
        members, _ = join_shards(label, paths.split(","))
        figures = {key: stat([m[key] for m in members.values() if m.get(key) is not None])
                   for key, *_ in PANELS}
        runs.append((label, {"figures": figures}))
    fig, axes = plt.subplots(1, len(PANELS), figsize=(10, 3.8))
    for ax, (key, title, scale, margin) in zip(axes, PANELS):
        for i, (label, e) in enumerate(runs):
            s = e["figures"][key]
            ax.errorbar(i, scale * s["mean"], yerr=2 * scale * s["standard_error"], fmt="o",
                        capsize=4, color="#4e79a7")
            ax.annotate(f"n={s['n']}", (i, scale * s["mean"]), textcoords="offset points",
                        xytext=(8, -3), fontsize=8)
        first = scale * runs[0][1]["figures"][key]["mean"]
        ax.axhspan(first - margin, first + margin, color="#f28e2b", alpha=0.15,
                   label=f"first ensemble's mean +- the margin ({margin:g})")
        ax.set_xticks(range(len(runs)))
        ax.set_xticklabels([r[0] for r in runs], fontsize=8)
        ax.set_xlim(-0.5, len(runs) - 0.5)
        ax.set_title(title, fontsize=9)
        ax.legend(fontsize=7, loc="best")
        ax.grid(axis="y", alpha=0.3)
    fig.suptitle("FE ABS stop: ensemble means with two standard errors", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, format="svg", metadata={"Date": None})
    print(f"wrote {out}")


if __name__ == "__main__":
    main(sys.argv)
