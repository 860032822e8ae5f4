#!/usr/bin/env python3
"""Writes a hotlap telemetry CSV (such as `hotlap synth`'s) as a MoTeC .ld log with its .ldx
beacons, under the MoTeC channel names of data/motec_channels.yaml: a logger's file to try the
race engineer's path on (examples/notebooks/race_engineer.ipynb) without a real one.

    /usr/bin/python3 tools/make_example_ld.py IN.csv OUT.ld [--lap-time-s T]

The .ld layout (header, event block, channel descriptors, samples) is the public description
hotlap's reader follows (docs/telemetry-formats.md); every channel is written as 32-bit floats at
the log's rate. Laps are marked in OUT.ldx every T seconds (default: the CSV's `# lap_time_s`).
"""
import argparse
import csv
import math
import struct
import sys

HEADER, EVENT, CHANNEL = 1762, 1154, 124
CORNERS = ["fl", "fr", "rl", "rr"]


def _text(buf, at, width, text):
    data = text.encode("latin-1")[:width]
    buf[at:at + len(data)] = data


def write_ld(path, channels, rate_hz, venue="Darlington", driver="A. Driver", session="Practice 1"):
    """channels: [(MoTeC name, unit, values)], all at rate_hz, written as f32."""
    list_at = HEADER + EVENT
    data_at = list_at + CHANNEL * len(channels)
    head = bytearray(HEADER)
    struct.pack_into("<III", head, 0, 0x40, 0, list_at)
    struct.pack_into("<I", head, 12, data_at)
    struct.pack_into("<I", head, 36, HEADER)
    struct.pack_into("<I", head, 86, len(channels))
    _text(head, 158, 64, driver)
    _text(head, 350, 64, venue)
    event = bytearray(EVENT)
    _text(event, 64, 64, session)
    descriptors, samples = bytearray(), bytearray()
    for k, (name, unit, values) in enumerate(channels):
        at = list_at + CHANNEL * k
        d = bytearray(CHANNEL)
        struct.pack_into("<IIIIHHHHhhhh", d, 0, at - CHANNEL if k else 0,
                         at + CHANNEL if k + 1 < len(channels) else 0,
                         data_at + len(samples), len(values), 0, 7, 4, int(round(rate_hz)),
                         0, 1, 1, 0)
        _text(d, 32, 32, name)
        _text(d, 72, 12, unit)
        descriptors += d
        samples += struct.pack("<%df" % len(values), *values)
    with open(path, "wb") as f:
        f.write(head + event + descriptors + samples)


def write_ldx(path, beacons_s):
    markers = "".join('<Marker Time="%d"/>' % round(t * 1e6) for t in beacons_s)
    with open(path, "w") as f:
        f.write('<LDXFile><Layers><Layer><MarkerBlock><MarkerGroup Name="Beacons">%s</MarkerGroup>'
                "</MarkerBlock></Layer></Layers></LDXFile>\n" % markers)


def read_csv(path):
    meta, lines = {}, []
    for line in open(path):
        if line.startswith("#"):
            key, _, value = line[1:].partition(":")
            meta[key.strip()] = value.strip()
        elif line.strip():
            lines.append(line)
    rows = list(csv.DictReader(lines))
    return meta, {k: [float(r[k]) if r[k] != "" else math.nan for r in rows] for k in rows[0]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("csv")
    ap.add_argument("ld")
    ap.add_argument("--lap-time-s", type=float)
    args = ap.parse_args()
    meta, col = read_csv(args.csv)
    t = col["time_s"]
    rate = (len(t) - 1) / (t[-1] - t[0])
    channels = [("Distance", "m", col["distance_m"]),
                ("Ground Speed", "km/h", [v * 3.6 for v in col["speed_mps"]]),
                ("Air Temp", "C", col["ambient_temp_C"]),
                ("Track Temp", "C", col["track_temp_C"])]
    for c in CORNERS:
        C = c.upper()
        angle = col.get(f"slip_angle_{c}_deg") or [math.degrees(v) for v in col[f"slip_angle_{c}_rad"]]
        channels += [(f"Tyre Force X {C}", "N", col[f"fx_{c}_N"]),
                     (f"Tyre Force Y {C}", "N", col[f"fy_{c}_N"]),
                     (f"Tyre Load {C}", "N", col[f"fz_{c}_N"]),
                     (f"Slip Angle {C}", "deg", angle),
                     (f"Slip Ratio {C}", "", col[f"slip_ratio_{c}"])]
        for quantity, name in (("tread_temp", f"Tyre Temp {C} Centre"), ("disc_temp", f"Brake Temp {C}"),
                               ("calliper_temp", f"Caliper Temp {C}")):
            if f"{quantity}_{c}_C" in col:
                channels.append((name, "C", col[f"{quantity}_{c}_C"]))
        if f"brake_power_{c}_W" in col:  # not in the shipped channel map: give it with --channel-map
            channels.append((f"Brake Power {C}", "W", col[f"brake_power_{c}_W"]))
    write_ld(args.ld, channels, rate)
    lap = args.lap_time_s or float(meta.get("lap_time_s", "nan"))
    beacons = [k * lap for k in range(1, int(t[-1] / lap) + 1) if k * lap < t[-1]] if lap == lap else []
    ldx = args.ld[:-3] + ".ldx" if args.ld.endswith(".ld") else args.ld + ".ldx"
    write_ldx(ldx, beacons)
    print(f"make_example_ld: wrote {args.ld} ({len(channels)} channels, {len(t)} samples at {rate:.0f} Hz) "
          f"and {ldx} ({len(beacons)} beacons)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
