import numpy as np
import pytest

import hotlap
from conftest import EXAMPLE_LOG, read_json


def test_fit_equals_the_command_lines_summary(cli, tmp_path):
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    log = tmp_path / "log.csv"  # a "measured" log with brake temperatures (the example has none)
    cli("synth", "--car", "gen7", "--laps", 1, "--out", log)
    cli("fit", "brake", "--telemetry", log, "--corners", "fl", "--threads", 1,
        "--out", tmp_path / "cli" / "car.yaml", "--json", tmp_path / "fit.json")
    expected = read_json(tmp_path / "fit.json")
    got = hotlap.fit(hotlap.load_car("gen7"), str(log), kind="brake", corners="fl",
                     threads=1, out=str(tmp_path / "py" / "car.yaml"))
    summary = got["summary"]
    for key in ("corners", "joint_family_size", "options"):
        assert summary[key] == expected[key], key
    assert (tmp_path / "py" / "car.yaml").exists()
    fl = got["channels"]["fl"]
    assert fl["disc_temp_measured_C"].shape == got["time_s"].shape
    finite = np.isfinite(fl["disc_temp_measured_C"])
    assert finite.sum() > 1000
    rms = np.sqrt(np.mean((fl["disc_temp_model_C"][finite] - fl["disc_temp_measured_C"][finite]) ** 2))
    assert rms < 20.0


def test_fit_rejects_bad_options():
    car = hotlap.load_car("gen7")
    with pytest.raises(ValueError, match="kind 'tires'"):
        hotlap.fit(car, str(EXAMPLE_LOG), kind="tires")
    with pytest.raises(ValueError, match="zz"):
        hotlap.fit(car, str(EXAMPLE_LOG), corners="zz")
    with pytest.raises(ValueError, match="loss_scale"):
        hotlap.fit(car, str(EXAMPLE_LOG), loss_scale=0.0)
