"""Lateral force against slip angle of the Gen-7-like car's left-side tyre at three loads, and
longitudinal force against slip ratio, drawn to a PNG.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/tyre_curves.py [OUT.png]
"""

import os
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt
import numpy as np

import hotlap


def main(out="tyre_curves.png"):
    model = hotlap.load_tyre("gen7/left")  # a built-in name, or a path to a .tir or .yaml file
    alpha = np.linspace(-12.0, 12.0, 241)
    kappa = np.linspace(-0.3, 0.3, 241)
    loads = np.array([3000.0, 6000.0, 9000.0])
    lateral = hotlap.tyre_forces(model, fz_N=loads[:, None], slip_angle_deg=alpha, speed_mps=40.0)
    longitudinal = hotlap.tyre_forces(model, fz_N=loads[:, None], slip_ratio=kappa, speed_mps=40.0)
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4))
    for i, fz in enumerate(loads):
        ax1.plot(alpha, lateral["fy_N"][i] / 1e3, label="%.0f N" % fz)
        ax2.plot(kappa, longitudinal["fx_N"][i] / 1e3, label="%.0f N" % fz)
    ax1.set(xlabel="slip angle (deg)", ylabel="Fy (kN)", title="lateral force (ISO signs)")
    ax2.set(xlabel="slip ratio", ylabel="Fx (kN)", title="longitudinal force")
    for ax in (ax1, ax2):
        ax.grid(True)
        ax.legend(title="load")
    fig.tight_layout()
    fig.savefig(out, dpi=100)
    peak = np.abs(lateral["fy_N"]).max(axis=1)
    print("peak |Fy| at %s N: %s N" % (loads.tolist(), np.round(peak).tolist()))
    print("wrote %s" % out)


if __name__ == "__main__":
    main(*sys.argv[1:2])
