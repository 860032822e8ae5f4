import numpy as np
import pytest

import hotlap
from conftest import EXAMPLE_LOG, read_csv, read_json


def test_replay_equals_the_command_lines_channels_and_summary(cli, tmp_path):
    cli("replay", "--telemetry", EXAMPLE_LOG, "--out", tmp_path / "r.csv", "--json", tmp_path / "r.json")
    expected = read_csv(tmp_path / "r.csv")
    summary = read_json(tmp_path / "r.json")
    got = hotlap.replay(hotlap.load_car("gen7"), str(EXAMPLE_LOG))
    assert list(got["channels"]) == list(expected)
    for name, values in expected.items():
        np.testing.assert_array_equal(got["channels"][name], values, err_msg=name)
    for key in ("samples", "duration_s", "corners", "car"):
        assert got["summary"][key] == summary[key], key


def test_replay_of_a_dict_of_arrays_equals_the_file():
    log = read_csv(EXAMPLE_LOG)
    car = hotlap.load_car("gen7")
    from_dict = hotlap.replay(car, log)
    from_file = hotlap.replay(car, str(EXAMPLE_LOG))
    for name, values in from_file["channels"].items():
        np.testing.assert_array_equal(from_dict["channels"][name], values, err_msg=name)


def test_a_log_without_an_input_raises_the_command_lines_message(cli, tmp_path):
    log = read_csv(EXAMPLE_LOG)
    del log["fz_rr_N"]
    path = tmp_path / "short.csv"
    with open(path, "w") as f:
        f.write(",".join(log) + "\n")
        for row in zip(*log.values()):
            f.write(",".join("" if np.isnan(v) else repr(float(v)) for v in row) + "\n")
    message = cli("replay", "--telemetry", path, "--out", tmp_path / "o.csv", check=False).stderr
    with pytest.raises(ValueError) as error:
        hotlap.replay(hotlap.load_car("gen7"), str(path))
    assert "missing column 'fz_rr_N'" in str(error.value)
    assert str(error.value) in message
    with pytest.raises(ValueError, match=r"<telemetry dict>: missing column 'fz_rr_N'"):
        hotlap.replay(hotlap.load_car("gen7"), log)


def test_qss_lap_equals_the_command_line(cli, tmp_path):
    cli("lap", "--method", "qss", "--laps", 2, "--out", tmp_path / "q", "--json", tmp_path / "q.json")
    expected = read_json(tmp_path / "q.json")
    channels = read_csv(tmp_path / "q" / "lap.csv")
    got = hotlap.qss_lap(hotlap.load_car("gen7"), hotlap.load_track("darlington"), laps=2)
    for key, value in expected.items():
        if key in ("out_csv", "out_report"):
            continue
        assert got["summary"][key] == value, key
    for name, values in channels.items():
        np.testing.assert_array_equal(got["channels"][name], values, err_msg=name)


def test_a_caution_lap_and_the_gas_equal_the_command_line(cli, tmp_path):
    # From a run's settled temperatures (docs/vehicle.md), so that a caution cools.
    cli("lap", "--method", "qss", "--laps", 3, "--step-m", 4, "--caution-laps", 2,
        "--carcass-temp-C", 130, "--rim-temp-C", 75, "--out", tmp_path / "q", "--json",
        tmp_path / "q.json")
    expected = read_json(tmp_path / "q.json")
    got = hotlap.qss_lap(hotlap.load_car("gen7"), hotlap.load_track("darlington"), laps=3,
                         step_m=4, caution_laps="2", carcass_temp_C=130, rim_temp_C=75)
    assert got["summary"]["laps"] == expected["laps"]
    # Behind the pace car (110 km/h) the lap is slow and the right front's gas cools.
    laps = got["summary"]["laps"]
    assert laps[1]["top_speed_mps"] == pytest.approx(110 / 3.6, rel=1e-6)
    assert laps[1]["corners"]["fr"]["mean_gas_temp_C"] < laps[0]["corners"]["fr"]["mean_gas_temp_C"]
    for name in ("gas_temp_fr_C", "rim_temp_fr_C", "pressure_fr_kPa", "disc_bulk_temp_fl_C"):
        assert name in got["channels"], name
    audit = laps[0]["corners"]["fl"]["energy_audit"]
    assert abs(audit["tyre_closure"]) < 1e-9
    assert audit["heat_over_work"] <= 1.0
    with pytest.raises(ValueError, match="caution_laps"):
        hotlap.qss_lap(hotlap.load_car("gen7"), hotlap.load_track("darlington"), laps=3,
                       caution_laps="4")


def test_loading_reports_what_is_wrong():
    with pytest.raises(ValueError, match="no-such-car"):
        hotlap.load_car("no-such-car")
    with pytest.raises(ValueError, match="no-such-track"):
        hotlap.load_track("no-such-track")
    assert hotlap.load_track("darlington").length_m == pytest.approx(2198.0, abs=1.0)
    assert hotlap.load_car().name == "gen7"
    assert issubclass(hotlap.NumericalError, RuntimeError)


def test_load_car_with_overrides_equals_the_command_lines_set(cli, tmp_path):
    overrides = {"chassis.mass_kg": 1650, "brakes.fl.duct_factor": 0.5}
    sets = [arg for key, value in overrides.items() for arg in ("--set", "%s=%s" % (key, value))]
    cli("lap", "--method", "qss", "--step-m", 2, *sets, "--out", tmp_path / "q", "--json", tmp_path / "q.json")
    expected = read_json(tmp_path / "q.json")
    car = hotlap.load_car("gen7", overrides=overrides)
    assert car.overrides == {"chassis.mass_kg": 1650.0, "brakes.fl.duct_factor": 0.5}
    assert hotlap.load_car().overrides == {}
    track = hotlap.load_track("darlington")
    got = hotlap.qss_lap(car, track, step_m=2)
    for key, value in expected.items():
        if key in ("out_csv", "out_report"):
            continue
        assert got["summary"][key] == value, key
    assert expected["overrides"] == car.overrides
    plain = hotlap.qss_lap(hotlap.load_car(), track, step_m=2)
    assert got["summary"]["lap_time_s"] > plain["summary"]["lap_time_s"]


def test_load_car_overrides_are_refused_with_the_command_lines_messages(cli, tmp_path):
    message = cli("lap", "--set", "chassis.mass=1600", "--out", tmp_path / "o", check=False).stderr
    with pytest.raises(ValueError) as error:
        hotlap.load_car(overrides={"chassis.mass": 1600})
    assert "did you mean 'chassis.mass_kg'?" in str(error.value)
    assert str(error.value) in message
    with pytest.raises(ValueError, match=r"override 'chassis.mass_kg=50': .* must be in \[100, 5000\] kg"):
        hotlap.load_car(overrides={"chassis.mass_kg": 50})
    with pytest.raises(ValueError, match="is not a number"):
        hotlap.load_car(overrides={"chassis.mass_kg": "1600"})
    with pytest.raises(ValueError, match="must be a dict"):
        hotlap.load_car(overrides=[("chassis.mass_kg", 1600)])
    with pytest.raises(ValueError, match="is not a number"):
        hotlap.load_car(overrides={"chassis.mass_kg": True})
    # NumPy's scalars are numbers (np.arange, a pandas column): the same car as Python's.
    plain = hotlap.load_car(overrides={"chassis.mass_kg": 1600.0})
    for value in (np.int64(1600), np.float32(1600.0), np.float64(1600.0)):
        car = hotlap.load_car(overrides={"chassis.mass_kg": value})
        assert hotlap.qss_lap(car, hotlap.load_track(), step_m=4)["summary"]["lap_time_s"] == \
            hotlap.qss_lap(plain, hotlap.load_track(), step_m=4)["summary"]["lap_time_s"]


def test_a_line_margin_that_leaves_the_road_is_refused():
    # A negative margin took the line off the road and lapped faster; the command line refused it.
    with pytest.raises(ValueError, match=r"margin from the edges, -3 m, must be > 0"):
        hotlap.qss_lap(hotlap.load_car(), hotlap.load_track(), line_margin_m=-3)
    keys = hotlap.override_keys("gen7")
    assert "chassis.mass_kg" in keys and "brakes.rr.duct_factor" in keys
    assert "tyre_forces.fl.file" not in keys


def test_paths_may_be_pathlib_paths():
    # Every path argument takes an os.PathLike as well as a str (some refused a pathlib.Path).
    from conftest import LEFT_TIR, REPO
    car_file = REPO / "data" / "cars" / "gen7" / "car.yaml"
    assert hotlap.load_car(car_file).name == hotlap.load_car(str(car_file)).name
    assert "chassis.mass_kg" in hotlap.override_keys(car_file)
    track_file = REPO / "data" / "tracks" / "darlington.yaml"
    assert hotlap.load_track(track_file).length_m == hotlap.load_track("darlington").length_m
    assert hotlap.load_tyre(LEFT_TIR).kind == "mf"


def test_synth_with_tpms_equals_the_command_line(cli, tmp_path):
    """hotlap.synth makes the command line's log (TPMS channels and all) and summary, and leaves
    the car it was given as it was."""
    args = dict(truth="car", tpms_noise_kPa=0.5, tpms_temp_noise_C=0.25, tpms_lag_s=1.5, seed=7,
                rate_hz=20.0)
    cli("synth", "--truth", "car", "--tpms-noise-kPa", 0.5, "--tpms-temp-noise-C", 0.25,
        "--tpms-lag-s", 1.5, "--seed", 7, "--rate-hz", 20, "--out", tmp_path / "cli.csv",
        "--json", tmp_path / "cli.json")
    car, track = hotlap.load_car("gen7"), hotlap.load_track("darlington")
    got = hotlap.synth(car, track, tmp_path / "py.csv", **args)
    expected = read_csv(tmp_path / "cli.csv")
    assert set(got["channels"]) == set(expected)
    for c in ("pressure_fl_kPa", "gas_temp_rr_C", "tread_temp_fl_C"):
        np.testing.assert_array_equal(got["channels"][c], expected[c])
    # The file written from Python is the command line's, line for line.
    assert (tmp_path / "py.csv").read_text() == (tmp_path / "cli.csv").read_text()
    summary, cli_summary = got["summary"], read_json(tmp_path / "cli.json")
    for key in ("laps", "samples", "lap_time_s", "corners"):
        assert summary[key] == cli_summary[key]
    # Without TPMS: the same log less those channels; and the caller's car is unchanged.
    bare = hotlap.synth(car, track, tpms=False, **args)
    assert "pressure_fl_kPa" not in bare["channels"]
    np.testing.assert_array_equal(bare["channels"]["tread_temp_fl_C"],
                                  got["channels"]["tread_temp_fl_C"])
    with pytest.raises(ValueError, match="laps must be >= 1"):
        hotlap.synth(car, track, laps=0)


def test_observe_on_the_cars_models_equals_the_command_line(cli, tmp_path):
    """hotlap.observe writes the command line's estimates and returns them with its summary; on
    a log whose truth is the car's own models with TPMS, models="car" estimates the gas and the
    hot pressure and reads the TPMS consistently."""
    log = tmp_path / "car.csv"
    cli("synth", "--truth", "car", "--laps", 1, "--rate-hz", 20, "--out", log)
    cli("observe", "--telemetry", log, "--models", "car", "--out", tmp_path / "cli.csv",
        "--json", tmp_path / "cli.json")
    car = hotlap.load_car("gen7")
    got = hotlap.observe(car, log, tmp_path / "py.csv", models="car")
    assert (tmp_path / "py.csv").read_text() == (tmp_path / "cli.csv").read_text()
    expected = read_csv(tmp_path / "cli.csv")
    for c in ("gas_temp_fl_C", "pressure_rr_kPa", "pressure_rr_sd_kPa", "carcass_temp_fr_C"):
        # The file holds each value to six significant digits; the arrays hold them whole.
        np.testing.assert_allclose(got["estimates"][c], expected[c], rtol=1e-5)
    summary, cli_summary = got["summary"], read_json(tmp_path / "cli.json")
    assert summary["models"] == cli_summary["models"] == "car"
    assert summary["corners"]["fr"]["pressure_kPa"] == cli_summary["corners"]["fr"]["pressure_kPa"]
    assert summary["corners"]["fr"]["sensors"]["pressure"]["consistent"]
    paper = hotlap.observe(car, log, tmp_path / "paper.csv")["summary"]
    assert paper["models"] == "paper" and "pressure_kPa" not in paper["corners"]["fr"]
    with pytest.raises(ValueError, match="'paper' or 'car'"):
        hotlap.observe(car, log, tmp_path / "x.csv", models="tyre")
