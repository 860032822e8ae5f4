"""hotlap.fe against `hotlap fe`: the same library call, the same summary (a coarse tyre)."""

import pytest

import hotlap
from conftest import REPO, read_json


def coarse_config(tmp_path):
    """The shipped FE tyre file with a very coarse, mass-scaled mesh (as the C++ FE tests)."""
    text = (REPO / "data" / "fe" / "paper_235_75r15.yaml").read_text()
    for old, new in [
        ("meridional_elements_half: 10", "meridional_elements_half: 5"),
        ("circumferential_elements_contact: 24", "circumferential_elements_contact: 8"),
        ("circumferential_elements_rest: 60", "circumferential_elements_rest: 16"),
        ("mass_scaling_min_step_s: 0", "mass_scaling_min_step_s: 1.2e-5"),
        ("config_file: ../abs/", "config_file: %s/" % (REPO / "data" / "abs")),
    ]:
        assert old in text, old
        text = text.replace(old, new)  # every ABS file named (the FE stop's and the lumped one's)
    path = tmp_path / "coarse.yaml"
    path.write_text(text)
    return path


def test_fe_equals_the_command_line(cli, tmp_path):
    config = coarse_config(tmp_path)
    cli("fe", "inflate", "--config", config, "--out", tmp_path / "cli", "--threads", 1,
        "--json", tmp_path / "cli.json")
    expected = read_json(tmp_path / "cli.json")
    got = hotlap.fe("inflate", str(config), str(tmp_path / "py"), threads=1)
    for summary in (expected, got):
        summary.pop("performance")
        summary.pop("config")
    assert got == expected
    assert (tmp_path / "py" / "inflate_history.csv").exists()


def test_fe_refuses_an_ensemble_of_another_step(tmp_path):
    with pytest.raises(ValueError, match="--ensemble"):
        hotlap.fe("inflate", str(coarse_config(tmp_path)), str(tmp_path / "o"), ensemble=2)
    with pytest.raises(ValueError, match="perturb"):
        hotlap.fe("abs", str(coarse_config(tmp_path)), str(tmp_path / "o"), ensemble=2,
                  perturb="sideways")
