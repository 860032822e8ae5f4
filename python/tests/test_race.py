"""hotlap.race against `hotlap race`, and its refusals."""

import pytest

import hotlap
from conftest import read_json


def test_race_equals_the_command_line(cli, tmp_path):
    args = dict(laps=60, stages="20,40", fall_off_laps=6, step_m=4.0)
    cli("race", "--laps", 60, "--stages", "20,40", "--fall-off-laps", 6, "--step-m", 4,
        "--json", tmp_path / "race.json")
    expected = read_json(tmp_path / "race.json")
    got = hotlap.race(hotlap.load_car("gen7"), hotlap.load_track("darlington"), **args)
    assert got == expected
    assert got["plan"]["race_time_s"] <= min(p["race_time_s"] for p in got["fixed_plans"]) + 1e-6


def test_race_refuses_bad_rules():
    car, track = hotlap.load_car("gen7"), hotlap.load_track("darlington")
    with pytest.raises(ValueError, match="less than one lap's burn"):
        hotlap.race(car, track, fuel_capacity_kg=0.5)
    with pytest.raises(ValueError, match="stages"):
        hotlap.race(car, track, laps=100, stages="150")
    with pytest.raises(ValueError, match="fall-off laps"):
        hotlap.race(car, track, fall_off_laps=1)
