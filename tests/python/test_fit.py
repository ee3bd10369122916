# SPDX-License-Identifier: Apache-2.0
# ifsfx.fit is `ifsfx fit`: for a path its .to_toml() is the file the command writes, byte for
# byte; an array (the picture's pixels, a bool mask, RGB order) gives the same maps; every bad
# argument is a ValueError or an OSError with the command's message; Ctrl-C stops it.
import numpy as np
import pytest

import ifsfx
from conftest import STOP_BOUND, interrupted_after, run_cli

EXPECTED_TESTS = 14

# A budget that ends the fit reproducibly (no time cap) in about a second.
BUDGET = dict(max_seconds=0, max_evaluations=2000, size=40)
BUDGET_ARGS = ["--max-seconds", "0", "--max-evaluations", "2000", "--size", "40"]


@pytest.fixture(scope="module")
def shape(tmp_path_factory):
    """A black disc and bar on white (BGR uint8, 80×64), its bool mask, and its PNG."""
    y, x = np.mgrid[0:64, 0:80]
    mask = ((x - 40) ** 2 + (y - 32) ** 2 < 500) | ((y >= 10) & (y < 20) & (x >= 5) & (x < 30))
    image = np.full((64, 80, 3), 255, np.uint8)
    image[mask] = 0
    image[~mask] = (255, 230, 200)  # light, but not grey: the channel order matters to the grey
    path = tmp_path_factory.mktemp("fit") / "disc.png"
    ifsfx.write_image(str(path), image)
    return image, mask, path


def cli_fit(cli, tmp_path, target, *args):
    out = tmp_path / "cli.toml"
    done = run_cli(cli, "fit", str(target), "-o", str(out), *args)
    assert done.returncode == 0, done.stderr
    return out.read_text(encoding="utf-8")


def test_a_path_fits_the_command_toml_byte_for_byte(cli, tmp_path, shape):
    _, _, path = shape
    ifs = ifsfx.fit(str(path), 3, seed=2, **BUDGET)
    assert ifs.to_toml() == cli_fit(cli, tmp_path, path, "-n", "3", "--seed", "2", *BUDGET_ARGS)
    assert ifs.name == "disc" and len(ifs) == 3 and ifs.contraction < 1
    assert ifs.description.startswith(f"fitted by ifsfx fit to {path}: IoU ")
    # and with --init moments and --invert on a light shape
    inverted = 255 - shape[0]
    ifsfx.write_image(str(tmp_path / "light.png"), inverted)
    moments = ifsfx.fit(tmp_path / "light.png", 2, init="moments", invert=True, **BUDGET)
    assert moments.to_toml() == cli_fit(cli, tmp_path, tmp_path / "light.png", "-n", "2",
                                        "--init", "moments", "--invert", *BUDGET_ARGS)


def test_an_array_gives_the_maps_of_its_picture(cli, tmp_path, shape):
    image, mask, path = shape
    from_file = ifsfx.fit(path, 3, **BUDGET)
    from_array = ifsfx.fit(image, 3, threads=1, **BUDGET)
    np.testing.assert_array_equal(from_array.maps, from_file.maps)
    assert from_array.name == "fitted"
    assert from_array.description.startswith("fitted by ifsfx fit to array 80x64: IoU ")
    # the TOML is the command's but for the name and description lines
    toml = cli_fit(cli, tmp_path, path, "-n", "3", *BUDGET_ARGS).splitlines()
    assert from_array.to_toml().splitlines()[2:] == toml[2:]
    named = ifsfx.fit(image, 3, name="leaf", **BUDGET)
    assert named.name == "leaf" and named.to_toml().startswith('name = "leaf"\n')
    # a bool mask is the shape itself; RGB order with rgb=True
    np.testing.assert_array_equal(ifsfx.fit(mask, 3, **BUDGET).maps, from_file.maps)
    rgb = np.ascontiguousarray(image[:, :, ::-1])
    np.testing.assert_array_equal(ifsfx.fit(rgb, 3, rgb=True, **BUDGET).maps, from_file.maps)


def test_the_threshold_keyword_is_the_command_flag(cli, tmp_path, shape):
    _, _, path = shape
    ifs = ifsfx.fit(path, 2, threshold=0.5, **BUDGET)
    assert ifs.to_toml() == cli_fit(cli, tmp_path, path, "-n", "2", "--threshold", "0.5",
                                    *BUDGET_ARGS)


@pytest.mark.parametrize("kwargs, message", [
    (dict(n=0), "n: the number of maps must be in 1..32 (got 0)"),
    (dict(n=33), "n: the number of maps must be in 1..32 (got 33)"),
    (dict(init="grow"), "init: search or moments (got 'grow')"),
    (dict(size="40x50"), "--size: the working raster is square (got 40x50)"),
    (dict(size="big"), "--size: expected S or SxS (got 'big')"),
    (dict(size=1.5), "size: the working raster is S or \"SxS\" (got 1.5)"),
    (dict(max_seconds=-1), "max_seconds: must be in [0, 1000000] (got -1)"),
    (dict(max_evaluations=1), "max_evaluations: must be in 2..100000000 (got 1)"),
    (dict(threshold=1.5), "threshold: must be in [0, 1] (got 1.5)"),
    (dict(reseed_share=-0.1), "reseed_share: must be in [0, 0.15] (got -0.1)"),
    (dict(grow_share=0.2), "grow_share: must be in [0, 0.15] (got 0.2)"),
])
def test_bad_keywords_are_value_errors_with_the_command_messages(shape, kwargs, message):
    with pytest.raises(ValueError) as e:
        ifsfx.fit(shape[0], **{"n": 3, **BUDGET, **kwargs})
    assert message in str(e.value)


def test_bad_targets_are_value_errors_or_os_errors(tmp_path):
    with pytest.raises(FileNotFoundError, match="nothing.png"):
        ifsfx.fit(str(tmp_path / "nothing.png"), **BUDGET)
    (tmp_path / "junk.png").write_bytes(b"not a picture")
    with pytest.raises(OSError, match="junk.png"):
        ifsfx.fit(str(tmp_path / "junk.png"), **BUDGET)
    with pytest.raises(ValueError, match="target: the shape is empty"):  # nothing to fit
        ifsfx.fit(np.full((32, 32), 255, np.uint8), **BUDGET)
    with pytest.raises(ValueError, match=r"target: an image is an H×W or H×W×C array"):
        ifsfx.fit(np.zeros((4, 4), np.int64), **BUDGET)
    with pytest.raises(ValueError, match=r"target: an image is .* \(got list\)"):
        ifsfx.fit([[0, 1], [1, 0]], **BUDGET)


def test_sigint_during_a_fit_raises_keyboard_interrupt(shape):
    # The fit polls its stop flag between candidates and refinement steps.
    latency = interrupted_after(0.3, lambda: ifsfx.fit(
        shape[0], 8, size=128, max_seconds=0, max_evaluations=10**8, threads=1))
    print(f"fit: KeyboardInterrupt {latency * 1000:.0f} ms after SIGINT")
    assert latency < STOP_BOUND, f"KeyboardInterrupt {latency:.3f} s after SIGINT"
