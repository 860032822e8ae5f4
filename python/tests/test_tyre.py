import numpy as np
import pytest

import hotlap
from conftest import LEFT_TIR, read_csv


def test_tyre_forces_equal_the_command_lines_sweep(cli, tmp_path):
    out = tmp_path / "sweep.csv"
    cli("tyre", "eval", "--model", "mf", "--params", LEFT_TIR, "--fz-N", 6000,
        "--sweep", "slip-angle-deg=-12:12:0.5", "--sweep", "slip-ratio=-0.2:0.2:0.05", "--out", out)
    expected = read_csv(out)
    model = hotlap.load_tyre(str(LEFT_TIR))
    got = hotlap.tyre_forces(model, fz_N=6000.0, slip_angle_deg=expected["slip_angle_deg"],
                             slip_ratio=expected["slip_ratio"])
    assert expected["fy_N"].size == 49 * 9
    for key in ("fx_N", "fy_N", "mz_Nm", "mx_Nm", "my_Nm"):
        # The CSV holds the shortest text that reads back to the same double.
        np.testing.assert_array_equal(got[key], expected[key], err_msg=key)


def test_inputs_broadcast_and_keep_their_shape():
    model = hotlap.load_tyre(str(LEFT_TIR))
    alpha = np.linspace(-8.0, 8.0, 17)
    fz = np.array([3000.0, 6000.0, 9000.0])[:, None]
    got = hotlap.tyre_forces(model, fz_N=fz, slip_angle_deg=alpha)
    assert got["fy_N"].shape == (3, 17)
    # Odd in slip angle about zero camber (to the model's own small asymmetry), growing with load.
    assert got["fy_N"][1, 8] == pytest.approx(0.0, abs=50.0)
    assert np.all(np.abs(got["fy_N"][2, 12:]) > np.abs(got["fy_N"][0, 12:]))
    one = hotlap.tyre_forces(model, fz_N=6000.0, slip_angle_deg=4.0)
    assert one["fy_N"].shape == ()
    assert float(one["fy_N"]) == got["fy_N"][1, 12]


def test_bad_input_raises_value_error():
    model = hotlap.load_tyre(str(LEFT_TIR))
    with pytest.raises(ValueError, match=r"fz_N\[1\] = -5 N; the load must be > 0"):
        hotlap.tyre_forces(model, fz_N=np.array([100.0, -5.0]))
    with pytest.raises(ValueError, match="unknown input"):
        hotlap.tyre_forces(model, fz_N=1000.0, slip_angle=0.1)
    # Points no tyre is at, as `hotlap tyre eval` refuses them.
    with pytest.raises(ValueError, match="a tread is above absolute zero"):
        hotlap.tyre_forces(model, fz_N=1000.0, tread_temp_C=-300.0)
    with pytest.raises(ValueError, match="a pressure is not negative"):
        hotlap.tyre_forces(model, fz_N=1000.0, pressure_kPa=-10.0)
    with pytest.raises(ValueError, match="broadcast"):
        hotlap.tyre_forces(model, fz_N=np.ones(3), slip_ratio=np.ones(4))
    with pytest.raises(ValueError, match="nope.tir"):
        hotlap.load_tyre("nope.tir")


def test_tyres_load_by_built_in_name():
    by_name = hotlap.load_tyre("gen7/left")
    by_path = hotlap.load_tyre(str(LEFT_TIR))
    assert by_name.kind == "mf"
    a = hotlap.tyre_forces(by_name, fz_N=5000.0, slip_angle_deg=3.0)
    b = hotlap.tyre_forces(by_path, fz_N=5000.0, slip_angle_deg=3.0)
    assert float(a["fy_N"]) == float(b["fy_N"])
    assert hotlap.load_tyre("brush_example").kind == "brush"
    with pytest.raises(ValueError, match="built-in: .*'gen7/left'"):
        hotlap.load_tyre("gen7/middle")
