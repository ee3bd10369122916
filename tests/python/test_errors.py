# SPDX-License-Identifier: Apache-2.0
# The library's errors arrive as Python exceptions with its messages: ValueError for bad input,
# FileNotFoundError (an OSError) for a missing file; the message is the command line's, less
# its "ifsfx: " prefix.
import numpy as np
import pytest

import ifsfx
from conftest import run_cli

EXPECTED_TESTS = 8


def cli_message(cli, *args):
    done = run_cli(cli, *args)
    assert done.returncode != 0
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("ifsfx: ")
    return line[len("ifsfx: "):]


def test_malformed_preset_is_a_value_error_with_the_cli_message(cli, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("maps = [[0.5, 0, 0, 0.5, 0]]\n")
    with pytest.raises(ValueError) as raised:
        ifsfx.load_preset(str(bad))
    assert str(raised.value).startswith(f"{bad}:1:")
    assert str(raised.value) == cli_message(cli, "render", str(bad), "-o",
                                            str(tmp_path / "x.png"))


def test_unknown_preset_name_is_a_value_error_with_the_cli_message(cli, tmp_path):
    with pytest.raises(ValueError) as raised:
        ifsfx.render("barnsley-fernn", size=(8, 8))
    assert str(raised.value) == cli_message(cli, "render", "barnsley-fernn", "-o",
                                            str(tmp_path / "x.png"))
    assert "barnsley-fern" in str(raised.value)  # the closest name is suggested


def test_non_contracting_array_is_a_value_error():
    with pytest.raises(ValueError, match="contract"):
        ifsfx.Ifs(np.array([[1.5, 0, 0, 1.5, 0, 0], [0.5, 0, 0, 0.5, 1, 0]]))


def test_missing_preset_file_is_a_file_not_found_error(tmp_path):
    with pytest.raises(OSError) as raised:
        ifsfx.load_preset(str(tmp_path / "missing.toml"))
    assert isinstance(raised.value, FileNotFoundError)
    assert str(tmp_path / "missing.toml") in str(raised.value)


def test_missing_source_image_is_an_os_error(tmp_path):
    with pytest.raises(OSError, match="missing.png"):
        ifsfx.render("barnsley-fern", mode="steal", source=str(tmp_path / "missing.png"),
                     size=(8, 8))


def test_bad_arguments_are_value_errors_naming_the_keyword():
    with pytest.raises(ValueError, match="^mode: attractor, measure, tops or steal \\(got 'x'\\)$"):
        ifsfx.render("barnsley-fern", mode="x")
    with pytest.raises(ValueError, match="^size: "):
        ifsfx.render("barnsley-fern", size=(0, 8))
    with pytest.raises(ValueError, match="^source: only with mode steal"):
        ifsfx.render("barnsley-fern", source=np.zeros((4, 4, 3), np.uint8))
    with pytest.raises(ValueError, match="^dtype: "):
        ifsfx.render("barnsley-fern", size=(8, 8), dtype="int64")


def test_a_source_of_the_wrong_dtype_is_a_value_error():
    with pytest.raises(ValueError, match="^source: an image is an H×W or H×W×C array"):
        ifsfx.render("barnsley-fern", mode="steal", source=np.zeros((4, 4, 3), np.int64))


def test_presets_lists_the_shipped_names_and_loads_each_kind(tmp_path):
    names = ifsfx.presets()
    assert "barnsley-fern" in names
    fern = ifsfx.load_preset("barnsley-fern")
    assert len(fern) == 4 and fern.maps.shape == (4, 6)
    assert abs(sum(fern.probabilities) - 1) < 1e-12
    toml = tmp_path / "fern.toml"
    toml.write_text(fern.to_toml())
    np.testing.assert_array_equal(ifsfx.load_preset(str(toml)).maps, fern.maps)
    fractint = tmp_path / "mine.ifs"
    fractint.write_text("tri {\n 0.5 0 0 0.5 0 0 0.34\n 0.5 0 0 0.5 1 0 0.33\n"
                        " 0.5 0 0 0.5 0.5 1 0.33\n}\n")
    tri = ifsfx.load_preset(f"{fractint}:tri")
    assert tri.name == "tri" and len(tri) == 3
    from_array = ifsfx.Ifs(tri.maps, probabilities=[0.34, 0.33, 0.33], name="tri")
    np.testing.assert_array_equal(ifsfx.render(from_array, size=(32, 32)),
                                  ifsfx.render(tri, size=(32, 32)))
