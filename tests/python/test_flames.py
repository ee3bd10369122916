# SPDX-License-Identifier: Apache-2.0
# Fractal flames from Python (docs/flames.md): ifsfx.render_flame and ifsfx.render of a flame
# file give the pixels `ifsfx render FILE.flame` writes.
import numpy as np
import pytest

import ifsfx
from conftest import cli_image

EXPECTED_TESTS = 3

PALETTE = "".join(f"{i:02X}00{255 - i:02X}" for i in range(256))
FLAME = f"""<flame name="spiral" size="80 60" center="0 0" scale="20" quality="4" estimator_radius="0">
  <xform weight="0.5" color="0" linear="0.8" swirl="0.2" coefs="0.6 0.2 -0.2 0.6 0.5 0"/>
  <xform weight="0.5" color="1" spherical="1" coefs="0.5 0 0 0.5 -0.5 0.2"/>
  <palette count="256" format="RGB">{PALETTE}</palette>
</flame>
"""


@pytest.fixture
def flame_file(tmp_path):
    path = tmp_path / "spiral.flame"
    path.write_text(FLAME)
    return str(path)


def test_render_flame_at_its_own_size_equals_the_cli(cli, tmp_path, flame_file):
    a = ifsfx.render_flame(flame_file, seed=2, alpha=True)
    b = cli_image(cli, tmp_path, "render", flame_file, "--seed", "2")
    assert a.shape == (60, 80, 4)
    np.testing.assert_array_equal(a, b)
    assert a[:, :, :3].max() > 0
    assert ifsfx.render_flame(flame_file, seed=2).shape == (60, 80, 3)


def test_render_of_a_flame_is_the_measure_at_the_size_given(cli, tmp_path, flame_file):
    a = ifsfx.render(flame_file, size=(64, 48), quality=3, seed=5, alpha=True)
    b = cli_image(cli, tmp_path, "render", flame_file, "--size", "64x48", "--quality", "3",
                  "--seed", "5")
    assert a.shape == (48, 64, 4)
    np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(ifsfx.render_flame(flame_file, size="64x48", quality=3, seed=5,
                                                     alpha=True), a)


def test_every_mode_of_a_flame_equals_the_cli_and_load_preset_gives_a_flame(cli, tmp_path,
                                                                           flame_file, photo):
    flame = ifsfx.load_preset(flame_file)
    assert isinstance(flame, ifsfx.Flame) and len(flame) == 2 and flame.size == (80, 60)
    for mode in ("attractor", "tops"):
        a = ifsfx.render(flame, mode=mode, size=(64, 48), quality=4, seed=5)
        b = cli_image(cli, tmp_path, "render", flame_file, "--mode", mode, "--size", "64x48",
                      "--quality", "4", "--seed", "5", name=f"{mode}.png")
        np.testing.assert_array_equal(a, b)
        assert a.max() > 0
    image, path = photo
    a = ifsfx.render(flame_file, mode="steal", source=path, size=(64, 48), quality=4)
    b = cli_image(cli, tmp_path, "render", flame_file, "--mode", "steal", "--source", str(path),
                  "--size", "64x48", "--quality", "4", name="steal.png")
    np.testing.assert_array_equal(a, b)
    with pytest.raises(ValueError, match="must have as many maps as spiral"):
        ifsfx.render(flame_file, mode="steal", source=path, colouring="sierpinski-triangle")


def test_render_of_a_flame_takes_its_own_size_and_quality_unless_given(cli, tmp_path, flame_file):
    # The measure at the file's 80x60 and quality 4, as `ifsfx render FILE.flame` with no flags;
    # the other modes at its size too (an IFS stays at 1024x1024).
    a = ifsfx.render(flame_file, seed=2, alpha=True)
    np.testing.assert_array_equal(a, cli_image(cli, tmp_path, "render", flame_file, "--seed", "2"))
    tops = ifsfx.render(flame_file, mode="tops", quality=2)
    assert tops.shape == (60, 80, 4)
    np.testing.assert_array_equal(tops, cli_image(cli, tmp_path, "render", flame_file, "--mode",
                                                  "tops", "--quality", "2", name="tops.png"))


def test_an_exact_descent_asked_of_a_flame_is_refused(flame_file):
    with pytest.raises(ValueError, match="exact: the exact descent follows inverse maps"):
        ifsfx.render(flame_file, mode="tops", exact=True, size=(16, 12))
    with pytest.raises(ValueError, match="exact: the exact descent follows inverse maps"):
        ifsfx.Filter(flame_file, exact=True)
    assert ifsfx.render(flame_file, mode="tops", exact=False, size=(16, 12)).shape == (12, 16, 4)
    ifsfx.Filter(flame_file)  # the default: the chaos game, no refusal


def test_a_flames_background_given_replaces_its_own_as_the_cli_does(cli, tmp_path, flame_file):
    # "transparent" is flam3-render's transparency=1: the empty plane clear, the cover as alpha;
    # a colour is opaque, and shows where nothing lands.
    clear = ifsfx.render_flame(flame_file, seed=2, alpha=True, background="transparent")
    np.testing.assert_array_equal(clear, cli_image(cli, tmp_path, "render", flame_file, "--seed",
                                                   "2", "--background", "transparent"))
    own = ifsfx.render_flame(flame_file, seed=2, alpha=True)
    assert (own[:, :, 3] == 255).all()
    empty = clear[:, :, 3] == 0  # (a density that rounds to alpha 0 shows a trace of colour)
    assert empty.mean() > 0.1 and (clear[:, :, 3] == 255).any()
    white = ifsfx.render_flame(flame_file, seed=2, background="white")
    assert (white[empty] >= 250).all() and (own[empty][:, :3] <= 5).all()
    with pytest.raises(ValueError, match='background: "transparent" needs alpha=True'):
        ifsfx.render_flame(flame_file, background="transparent")
    with pytest.raises(ValueError, match="background: a flame's background is transparent"):
        ifsfx.render_flame(flame_file, background="mauve")
    # ifsfx.render of a flame's measure takes the same keyword; its camera and tone mapping are
    # the file's, so keywords that would change them are refused, not ignored.
    np.testing.assert_array_equal(ifsfx.render(flame_file, seed=2, background="transparent"),
                                  clear)
    for keyword, value in (("gamma", 3.0), ("brightness", 8.0), ("supersample", 2),
                           ("margin", 0.2), ("view", (0, 0, 1, 1))):
        with pytest.raises(ValueError, match=f"{keyword}: a flame's measure takes its own"):
            ifsfx.render(flame_file, **{keyword: value})
    with pytest.raises(ValueError, match="source: only with mode steal"):
        ifsfx.render(flame_file, source=np.zeros((4, 4, 3), np.uint8))
    with pytest.raises(ValueError, match="background: only with mode tops or steal"):
        ifsfx.render(flame_file, mode="attractor", background="white")
