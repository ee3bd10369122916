# SPDX-License-Identifier: Apache-2.0
# SuperIFS textures from the module equal the command's frames, byte for byte, and the iterator
# gives the frames of `ifsfx texture --frames N` in order.
import numpy as np

import ifsfx
from conftest import cli_image, run_cli

EXPECTED_TESTS = 3


def test_texture_equals_the_cli_png(cli, tmp_path):
    a = ifsfx.texture("paper-fig4", size=(64, 48), seed=5)
    b = cli_image(cli, tmp_path, "texture", "paper-fig4", "--size", "64x48", "--seed", "5")
    assert a.shape == (48, 64)
    np.testing.assert_array_equal(a, b)


def test_steal_texture_equals_the_cli_png(cli, tmp_path, photo):
    image, path = photo
    a = ifsfx.texture("carpet-lace", size=(64, 48), mode="steal", source=image, buffers=2)
    b = cli_image(cli, tmp_path, "texture", "carpet-lace", "--size", "64x48", "--mode", "steal",
                  "--source", str(path), "-V", "2")
    np.testing.assert_array_equal(a, b)


def test_textures_iterates_the_cli_sequence_with_crossfade(cli, tmp_path):
    frames = list(ifsfx.textures("paper-fig4", size=(48, 32), mode="tops", frames=4, crossfade=2))
    assert len(frames) == 4
    done = run_cli(cli, "texture", "paper-fig4", "--size", "48x32", "--mode", "tops", "--frames",
                   "4", "--crossfade", "2", "-q", "-o", str(tmp_path / "t_%02d.png"))
    assert done.returncode == 0, done.stderr
    for j, frame in enumerate(frames):
        np.testing.assert_array_equal(frame, ifsfx.read_image(str(tmp_path / f"t_{j + 1:02d}.png")))
    np.testing.assert_array_equal(frames[3], ifsfx.texture("paper-fig4", size=(48, 32),
                                                           mode="tops", frame=3, crossfade=2))
