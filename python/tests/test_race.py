"""hotlap.race against `hotlap race`, and its refusals."""

import pytest

import hotlap
from conftest import read_json


def test_race_equals_the_command_line(cli, tmp_path):
    args = dict(laps=60, stages="20,40", fall_off_laps=6, step_m=4.0)
    cli("race", "--laps", 60, "--stages", "20,40", "--fall-off-laps", 6, "--step-m", 4,
        "--no-cache", "--json", tmp_path / "race.json")
    expected = read_json(tmp_path / "race.json")
    got = hotlap.race(hotlap.load_car("gen7"), hotlap.load_track("darlington"), **args)
    assert got == expected
    assert got["plan"]["race_time_s"] <= min(p["race_time_s"] for p in got["fixed_plans"]) + 1e-6


def test_right_side_stops_and_the_cache_as_on_the_command_line(cli, tmp_path):
    cache = tmp_path / "cache"
    args = dict(laps=60, stages="20,40", fall_off_laps=8, step_m=4.0, races=100, policy=False,
                right_side_stops=True, right_tyre_service_s=6.0)
    cli("race", "--laps", 60, "--stages", "20,40", "--fall-off-laps", 8, "--step-m", 4,
        "--races", 100, "--no-policy", "--right-side-stops", "--right-tyre-service-s", 6,
        "--cache-dir", cache, "--json", tmp_path / "race.json")
    expected = read_json(tmp_path / "race.json")
    car, track = hotlap.load_car("gen7"), hotlap.load_track("darlington")
    got = hotlap.race(car, track, cache_dir=cache, **args)  # the command's cache, read
    assert got["fall_off"]["from_cache"] and not expected["fall_off"]["from_cache"]
    for key in ("rules", "plan", "fixed_plans", "side_check", "monte_carlo"):
        assert got[key] == expected[key], key
    assert [s["after_laps"] for s in got["fall_off"]["right_side_stops"]] == [2, 4, 6, 8]
    assert hotlap.race(car, track, **args)["fall_off"]["cache_file"] is None
    assert isinstance(hotlap.default_cache_dir(), str)


def test_race_refuses_bad_rules():
    car, track = hotlap.load_car("gen7"), hotlap.load_track("darlington")
    with pytest.raises(ValueError, match="less than one lap's burn"):
        hotlap.race(car, track, fuel_capacity_kg=0.5)
    with pytest.raises(ValueError, match="stages"):
        hotlap.race(car, track, laps=100, stages="150")
    with pytest.raises(ValueError, match="fall-off laps"):
        hotlap.race(car, track, fall_off_laps=1)
