"""Reading logs of every format from Python: hotlap.read_log, log_info, convert_log, and the
channel_map and lap arguments of replay, against a MoTeC .ld log written here with the struct
module from the format's public description (independently of the library's own writer)."""

import csv
import struct

import numpy as np
import pytest

import hotlap
from conftest import REPO, read_csv, read_json

MOTEC = REPO / "tests" / "data" / "motec" / "darlington_i2.csv"
EQUIVALENT = REPO / "tests" / "data" / "motec" / "darlington_i2_equivalent.csv"

HEADER, EVENT, CHANNEL = 1762, 1154, 124


def _text(buf, at, width, text):
    data = text.encode("latin-1")
    assert len(data) <= width
    buf[at:at + len(data)] = data


def write_ld(path, channels, venue="Darlington", driver="A. Driver"):
    """channels: (name, unit, rate_hz, kind, (shift, mul, scale, dec), values); kind 'i16',
    'i32' or 'f32'. value = (raw / scale * 10**-dec + shift) * mul."""
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
    _text(event, 64, 64, "Practice 1")
    descriptors, samples = bytearray(), bytearray()
    for k, (name, unit, rate, kind, (shift, mul, scale, dec), values) in enumerate(channels):
        raw = [(v / mul - shift) * scale / 10.0 ** -dec for v in values]
        code, size, fmt = {"i16": (3, 2, "h"), "i32": (5, 4, "i"), "f32": (7, 4, "f")}[kind]
        if kind != "f32":
            raw = [int(round(r)) for r in raw]
        at = list_at + CHANNEL * k
        d = bytearray(CHANNEL)
        struct.pack_into("<IIIIHHHHhhhh", d, 0, at - CHANNEL if k else 0,
                         at + CHANNEL if k + 1 < len(channels) else 0,
                         data_at + len(samples), len(values), 0, code, size, rate,
                         shift, mul, scale, dec)
        _text(d, 32, 32, name)
        _text(d, 72, 12, unit)
        descriptors += d
        samples += struct.pack("<%d%s" % (len(raw), fmt), *raw)
    with open(path, "wb") as f:
        f.write(head + event + descriptors + samples)


def darlington_ld(tmp_path):
    """The i2 export's channels as a .ld log (temperatures at 1 Hz, the rest at 10 Hz) with its
    beacons in a companion .ldx."""
    rows = [r for r in csv.reader(open(MOTEC)) if r]
    first = next(i for i, r in enumerate(rows) if r[0] == "Time")
    names, units = rows[first], rows[first + 1]
    data = np.array([[float(c) for c in r] for r in rows[first + 2:]])
    beacons = next(r for r in rows if r[0] == "Beacon Markers")[1:]
    channels = []
    for c in range(1, len(names)):
        name, values = names[c], data[:, c]
        if "Temp" in name:
            channels.append((name, units[c], 1, "i16", (0, 1, 1, 1), values[::10]))
        elif name in ("Distance", "Ground Speed") or name.startswith("Slip"):
            channels.append((name, units[c], 10, "i32", (0, 1, 2, 5), values))
        else:
            channels.append((name, units[c], 10, "f32", (0, 1, 1, 0), values))
    path = tmp_path / "darlington.ld"
    write_ld(path, channels)
    markers = "".join('<Marker Time="%d"/>' % round(float(t) * 1e6) for t in beacons if t)
    (tmp_path / "darlington.ldx").write_text(
        '<LDXFile><Layers><Layer><MarkerBlock><MarkerGroup Name="Beacons">%s</MarkerGroup>'
        "</MarkerBlock></Layer></Layers></LDXFile>\n" % markers)
    return path


def test_read_log_of_a_ld_log(tmp_path):
    log = hotlap.read_log(darlington_ld(tmp_path))
    assert log["format"] == "MoTeC .ld"
    assert log["metadata"]["Venue"] == "Darlington"
    assert log["metadata"]["Session"] == "Practice 1"
    assert log["metadata"]["laps"] == "3"
    channels = log["channels"]
    assert len(channels["time_s"]) == 291
    expected = read_csv(EQUIVALENT)
    np.testing.assert_allclose(channels["speed_mps"] * 3.6, expected["speed_kph"], rtol=0, atol=1e-9)
    np.testing.assert_allclose(channels["fy_fl_N"], expected["fy_fl_N"], rtol=1e-6)
    np.testing.assert_allclose(channels["ambient_temp_C"][:-9], 25.0)
    lap2 = hotlap.read_log(tmp_path / "darlington.ld", lap=2)["channels"]
    assert len(lap2["time_s"]) == 97
    assert lap2["time_s"][0] == pytest.approx(9.7)


def test_replay_of_a_ld_log_equals_the_equivalent_csv(tmp_path):
    car = hotlap.load_car("gen7")
    ld = hotlap.replay(car, darlington_ld(tmp_path))
    csv_log = hotlap.replay(car, str(EQUIVALENT))
    for name, values in csv_log["channels"].items():
        np.testing.assert_allclose(ld["channels"][name], values, rtol=1e-6, atol=1e-6, err_msg=name)
    one_lap = hotlap.replay(car, tmp_path / "darlington.ld", lap=2)
    assert one_lap["summary"]["samples"] == 97


def test_lap_and_channel_map_on_replay(tmp_path):
    car = hotlap.load_car("gen7")
    assert hotlap.replay(car, str(MOTEC), lap=3)["summary"]["samples"] == 97
    mapping = tmp_path / "map.yaml"
    mapping.write_text("channels:\n  Ground Speed: speed\n")
    with pytest.raises(ValueError) as error:
        hotlap.replay(car, str(MOTEC), channel_map=mapping)
    assert "missing column" in str(error.value) and "map.yaml" in str(error.value)
    with pytest.raises(ValueError) as error:
        hotlap.replay(car, str(MOTEC), lap=9)
    assert "no such lap" in str(error.value)
    # A dict of arrays with a lap column takes lap= too.
    log = read_csv(EQUIVALENT)
    assert hotlap.replay(car, log, lap=2)["summary"]["samples"] == 97


def test_log_info_and_convert_equal_the_command_line(cli, tmp_path):
    ld = darlington_ld(tmp_path)
    cli("log", "info", ld, "--json", tmp_path / "info.json")
    info = hotlap.log_info(ld)
    expected = read_json(tmp_path / "info.json")
    # The data folder may be found by another route from Python: compare the map by its name.
    assert info.pop("channel_map").endswith("motec_channels.yaml")
    assert expected.pop("channel_map").endswith("motec_channels.yaml")
    assert info == expected
    assert [lap["rows"] for lap in info["laps"]] == [97, 97, 97]
    air = next(c for c in info["channels"] if c["name"] == "Air Temp")
    assert (air["rate_hz"], air["samples"], air["column"]) == (1, 30, "ambient_temp_C")

    cli("log", "convert", ld, "--lap", "2", "--out", tmp_path / "cli.csv")
    hotlap.convert_log(ld, tmp_path / "py.csv", lap=2)
    def lines(name):
        return [l for l in (tmp_path / name).read_text().splitlines() if not l.startswith("# channel map")]

    assert lines("py.csv") == lines("cli.csv")
    assert len(lines("py.csv")) > 97


def test_a_truncated_ld_raises_with_the_offset(tmp_path):
    ld = darlington_ld(tmp_path)
    cut = tmp_path / "cut.ld"
    cut.write_bytes(ld.read_bytes()[:3000])
    with pytest.raises(ValueError) as error:
        hotlap.read_log(cut)
    assert "cut.ld: byte " in str(error.value)
