# SPDX-License-Identifier: Apache-2.0
# The module's arrays equal the pixels of the files the command line writes for the same
# settings, byte for byte (docs/python.md): one engine, two doors.
import filecmp

import numpy as np
import pytest

import ifsfx
from conftest import cli_image, run_cli

EXPECTED_TESTS = 10

SMALL = dict(size=(96, 64), quality=8, seed=3)
SMALL_ARGS = ["--size", "96x64", "--quality", "8", "--seed", "3"]


def test_attractor_equals_the_cli_png(cli, tmp_path):
    a = ifsfx.render("barnsley-fern", mode="attractor", **SMALL)
    b = cli_image(cli, tmp_path, "render", "barnsley-fern", "--mode", "attractor", *SMALL_ARGS)
    assert a.shape == (64, 96) and a.dtype == np.uint8
    np.testing.assert_array_equal(a, b)


def test_measure_equals_the_cli_png_with_supersampling_and_a_view(cli, tmp_path):
    a = ifsfx.render("maple-leaf", mode="measure", supersample=2, view=(-1, -0.5, 1, 1.5), **SMALL)
    b = cli_image(cli, tmp_path, "render", "maple-leaf", "--mode", "measure", "--supersample",
                  "2", "--view", "-1,-0.5,1,1.5", *SMALL_ARGS)
    assert a.shape == (64, 96, 3)
    np.testing.assert_array_equal(a, b)


def test_measure_16_bits_equals_the_cli_16_bit_png(cli, tmp_path):
    a = ifsfx.render("sierpinski-triangle", dtype="uint16", **SMALL)
    b = cli_image(cli, tmp_path, "render", "sierpinski-triangle", "--bits", "16", *SMALL_ARGS)
    assert a.dtype == np.uint16
    np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("exact", [True, False])
def test_tops_equals_the_cli_png(cli, tmp_path, exact):
    a = ifsfx.render("barnsley-fern", mode="tops", exact=exact, second_symbol=True, **SMALL)
    b = cli_image(cli, tmp_path, "render", "barnsley-fern", "--mode", "tops", "--second-symbol",
                  "--exact" if exact else "--chaos", *SMALL_ARGS)
    assert a.shape == (64, 96, 4)
    np.testing.assert_array_equal(a, b)


def test_tops_without_alpha_is_the_png_on_the_background_colour():
    # As the CLI writes formats without alpha (JPEG): the background colour off the attractor.
    a = ifsfx.render("barnsley-fern", mode="tops", alpha=False, background="#204080", **SMALL)
    b = ifsfx.render("barnsley-fern", mode="tops", background="#204080", **SMALL)
    assert a.shape == (64, 96, 3)
    np.testing.assert_array_equal(a, b[:, :, :3])
    assert tuple(a[0, 0]) == (0x80, 0x40, 0x20)  # BGR, off the attractor


@pytest.mark.parametrize("exact", [True, False])
def test_steal_from_an_array_equals_the_cli_png_from_its_file(cli, tmp_path, photo, exact):
    image, path = photo
    a = ifsfx.render("barnsley-fern", mode="steal", source=image, exact=exact, **SMALL)
    b = cli_image(cli, tmp_path, "render", "barnsley-fern", "--mode", "steal", "--source",
                  str(path), "--exact" if exact else "--chaos", *SMALL_ARGS)
    assert a.shape == (64, 96, 4)
    np.testing.assert_array_equal(a, b)


def test_saved_steal_map_is_the_cli_file_and_applies_as_render(cli, tmp_path, photo):
    image, path = photo
    T = ifsfx.steal_map("barnsley-fern", size=(96, 64), seed=3)
    T.save(str(tmp_path / "py.map"))
    done = run_cli(cli, "render", "barnsley-fern", "--mode", "steal", "--source", str(path),
                   "--save-map", str(tmp_path / "cli.map"), "-q", "-o", str(tmp_path / "x.png"),
                   *SMALL_ARGS)
    assert done.returncode == 0, done.stderr
    assert filecmp.cmp(tmp_path / "py.map", tmp_path / "cli.map", shallow=False)
    loaded = ifsfx.load_steal_map(str(tmp_path / "cli.map"))
    assert loaded.size == (96, 64)
    np.testing.assert_array_equal(loaded.source_uv, T.source_uv)
    coloured = T.apply(image)
    steal = ifsfx.render("barnsley-fern", mode="steal", source=image, alpha=False, **SMALL)
    np.testing.assert_array_equal(coloured, steal)


def test_rgb_flag_swaps_red_and_blue_in_and_out(photo, tmp_path):
    image, path = photo
    bgr = ifsfx.render("barnsley-fern", mode="steal", source=image, **SMALL)
    rgb = ifsfx.render("barnsley-fern", mode="steal", source=image[:, :, ::-1], rgb=True, **SMALL)
    np.testing.assert_array_equal(rgb, bgr[:, :, [2, 1, 0, 3]])
    # A path is read as the file holds it whatever rgb says; only the result is swapped.
    from_file = ifsfx.render("barnsley-fern", mode="steal", source=str(path), rgb=True, **SMALL)
    np.testing.assert_array_equal(from_file, rgb)
    np.testing.assert_array_equal(ifsfx.read_image(str(path), rgb=True), image[:, :, ::-1])
    T = ifsfx.steal_map("barnsley-fern", size=(96, 64), seed=3)
    np.testing.assert_array_equal(T.apply(image[:, :, ::-1], rgb=True), T.apply(image)[:, :, ::-1])
