"""Writes the MoTeC i2 CSV fixture and the hotlap CSV of the same numbers (tests/logs/motec_csv_test.cc).

From data/telemetry/darlington_example.csv, every fifth row (10 Hz), rounded as i2 writes them.
Run from the repository root: /usr/bin/python3 tests/data/motec/make_fixture.py
"""
import csv

ROWS = list(csv.DictReader(l for l in open("data/telemetry/darlington_example.csv") if not l.startswith("#")))[::5]
BEACONS = [9.65, 19.35]
CORNERS = ["FL", "FR", "RL", "RR"]

# (MoTeC name, MoTeC unit, hotlap column, value from a row as text)
def f(x, d):
    return f"{float(x):.{d}f}"

CHANNELS = [("Time", "s", "time_s", lambda r: f(r["time_s"], 3)),
            ("Distance", "m", "distance_m", lambda r: f(r["distance_m"], 2)),
            ("Ground Speed", "km/h", "speed_kph", lambda r: f(float(r["speed_mps"]) * 3.6, 3)),
            ("Air Temp", "degC", "ambient_temp_C", lambda r: f(r["ambient_temp_C"], 1)),
            ("Track Temp", "degC", "track_temp_C", lambda r: f(r["track_temp_C"], 1))]
for c in CORNERS:
    l = c.lower()
    CHANNELS += [(f"Tyre Force X {c}", "N", f"fx_{l}_N", lambda r, l=l: f(r[f"fx_{l}_N"], 1)),
                 (f"Tyre Force Y {c}", "N", f"fy_{l}_N", lambda r, l=l: f(r[f"fy_{l}_N"], 1)),
                 (f"Tyre Load {c}", "kN", f"fz_{l}_kN", lambda r, l=l: f(float(r[f"fz_{l}_N"]) / 1000, 4)),
                 (f"Slip Angle {c}", "deg", f"slip_angle_{l}_deg", lambda r, l=l: f(r[f"slip_angle_{l}_deg"], 4)),
                 (f"Slip Ratio {c}", "", f"slip_ratio_{l}", lambda r, l=l: f(r[f"slip_ratio_{l}"], 5)),
                 (f"Brake Temp {c}", "degC", f"disc_temp_{l}_C", lambda r: "350.0")]
# Not in the shipped map: carried through under their MoTeC names.
CHANNELS += [("G Force Lat", "g", "G Force Lat", lambda r: "1.250"),
             ("Engine RPM", "rpm", "Engine RPM", lambda r: "8000")]

def lap(t):
    return 1 + sum(b <= t for b in BEACONS)

def q(cells):
    return ",".join(f'"{c}"' for c in cells)

duration = float(ROWS[-1]["time_s"])
with open("tests/data/motec/darlington_i2.csv", "w", newline="") as out:
    out.write(q(["Format", "MoTeC CSV File"]) + ",,," + q(["Workbook", "hotlap.mtc"]) + "\r\n")
    out.write(q(["Venue", "Darlington"]) + ",," + q(["Worksheet", "Tyres"]) + "\r\n")
    out.write(q(["Vehicle", "Gen7 #48"]) + ",," + q(["Vehicle Desc", ""]) + "\r\n")
    out.write(q(["Driver", "A. Driver"]) + ",," + q(["Engine ID", ""]) + "\r\n")
    out.write(q(["Device", "M150"]) + "\r\n")
    out.write(q(["Comment", ""]) + ",," + q(["Session", "Practice 1"]) + "\r\n")
    out.write(q(["Log Date", "14/03/2026"]) + ",," + q(["Origin Time", "0.000", "s"]) + "\r\n")
    out.write(q(["Log Time", "10:32:05"]) + ",," + q(["Start Time", "0.000", "s"]) + "\r\n")
    out.write(q(["Sample Rate", "10.000", "Hz"]) + ",," + q(["End Time", f"{duration:.3f}", "s"]) + "\r\n")
    out.write(q(["Duration", f"{duration:.3f}", "s"]) + ",," + q(["Start Distance", "0", "m"]) + "\r\n")
    out.write(q(["Range", "entire outing"]) + "\r\n")
    out.write(q(["Beacon Markers"] + [f"{b:.3f}" for b in BEACONS]) + "\r\n")
    out.write("\r\n\r\n")
    out.write(q([c[0] for c in CHANNELS]) + "\r\n")
    out.write(q([c[1] for c in CHANNELS]) + "\r\n")
    out.write("\r\n")
    for r in ROWS:
        out.write(q([c[3](r) for c in CHANNELS]) + "\r\n")

with open("tests/data/motec/darlington_i2_equivalent.csv", "w", newline="") as out:
    out.write("# the hotlap CSV of the same numbers as darlington_i2.csv\n")
    out.write(",".join([c[2] for c in CHANNELS] + ["lap"]) + "\n")
    for r in ROWS:
        out.write(",".join([c[3](r) for c in CHANNELS] + [str(lap(float(r["time_s"])))]) + "\n")
