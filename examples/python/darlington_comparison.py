"""The NASCAR paper's comparison: the Gen-7-like car's minimum-time lap of Darlington without and
with the front discs held at or below 500 degC, with the solver's progress printed.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/darlington_comparison.py [--quick]

--quick solves on a 15 m mesh (seconds) instead of the main job's 3 m one (about a minute here:
in Python the two laps are solved one after the other).
"""

import sys

import hotlap


def main(quick=False):
    car, track = hotlap.load_car("gen7"), hotlap.load_track("darlington")
    mesh = dict(step_m=15.0, coarse_step_m=0.0) if quick else {}

    def progress(label, iteration, objective_s, infeasibility, optimality):
        if iteration % 10 == 0:
            print("  %-18s iteration %3d  lap %.4f s  infeasibility %.1e" % (label, iteration, objective_s, infeasibility))
        return True  # False would stop the solve

    result = hotlap.optimal_lap(car, track, compare_disc_limit_C=500.0, progress=progress, **mesh)
    s = result["summary"]
    free, limited = s["unconstrained"], s["constrained"]
    print("free lap     %.4f s, peak front disc %.0f C" % (free["lap_time_s"], max(free["corners"][c]["peak_disc_temp_C"] for c in ("fl", "fr"))))
    print("limited lap  %.4f s, peak front disc %.0f C" % (limited["lap_time_s"], max(limited["corners"][c]["peak_disc_temp_C"] for c in ("fl", "fr"))))
    print("the limit costs %.1f ms" % (1e3 * s["delta_s"]))


if __name__ == "__main__":
    main(quick="--quick" in sys.argv[1:])
