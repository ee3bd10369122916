# SPDX-License-Identifier: Apache-2.0
# ifsfx.Filter is `ifsfx filter` frame by frame: on the frames of a PNG image sequence (no codec
# loss) its arrays are the files the command writes, byte for byte, with a fixed map and with a
# drift; frame indices, output size and RGB order; every bad argument a ValueError with the
# command's message; Ctrl-C stops a map being built, and the filter works after it.
import numpy as np
import pytest

import ifsfx
from conftest import STOP_BOUND, interrupted_after, run_cli

EXPECTED_TESTS = 18

COUNT = 5


@pytest.fixture(scope="module")
def clip(tmp_path_factory):
    """COUNT frames of 64×48 BGR, moving, and their PNG image sequence."""
    folder = tmp_path_factory.mktemp("clip")
    y, x = np.mgrid[0:48, 0:64]
    frames = []
    for i in range(COUNT):
        frame = np.stack([(x * 4 + i * 16) % 256, (y * 5) % 256, ((x ^ y) * 3 + i * 40) % 256],
                         axis=-1).astype(np.uint8)
        ifsfx.write_image(str(folder / f"in_{i:04d}.png"), frame)
        frames.append(frame)
    return frames, folder


def cli_frames(cli, tmp_path, clip, *args):
    """`ifsfx filter in_%04d.png -o out_%04d.png ARGS`, the frames read back."""
    _, folder = clip
    done = run_cli(cli, "filter", str(folder / "in_%04d.png"), "-o",
                   str(tmp_path / "out_%04d.png"), "-q", *args)
    assert done.returncode == 0, done.stderr
    return [ifsfx.read_image(str(tmp_path / f"out_{i:04d}.png")) for i in range(COUNT)]


CASES = {
    "fixed": ([], {}),
    "drift": (["--animate", "drift", "--keyframe-interval", "2", "--drift-speed", "3",
               "--seed", "4"],
              dict(animate="drift", keyframe_interval=2, drift_speed=3, seed=4)),
    "look": (["--preset", "maple-leaf", "--mix", "0.25", "--background", "original",
              "--interpolation", "nearest", "--view", "-1,-0.5,1,1.5", "--chaos", "--quality",
              "4"],
             dict(preset="maple-leaf", mix=0.25, background="original", interpolation="nearest",
                  view=(-1, -0.5, 1, 1.5), exact=False, quality=4)),
    "loop": (["--animate", "drift", "--loop", "4", "--keyframe-interval", "2", "--fps", "10",
              "--background", "#204080"],
             dict(animate="drift", loop=4, keyframe_interval=2, fps=10, background="#204080")),
}


@pytest.mark.parametrize("case", list(CASES))
def test_frames_equal_the_command_image_sequence(cli, tmp_path, clip, case):
    args, kwargs = CASES[case]
    frames, _ = clip
    expected = cli_frames(cli, tmp_path, clip, *args)
    f = ifsfx.Filter(**kwargs)
    got = [f(frame) for frame in frames]
    for i in range(COUNT):
        assert got[i].shape == (48, 64, 3) and got[i].dtype == np.uint8
        np.testing.assert_array_equal(got[i], expected[i], err_msg=f"{case}: frame {i}")
    assert f.index == COUNT and f.frame_size == (64, 48) and f.size == (64, 48)
    if case in ("drift", "loop"):
        assert not np.array_equal(got[1], got[3]), "the drift moves the maps"
    if case == "loop":  # frame 4 is frame 0 again, coloured from another frame
        np.testing.assert_array_equal(f(frames[0], index=4), got[0])


def test_indices_output_size_and_rgb_order(cli, tmp_path, clip):
    frames, _ = clip
    args = ["--animate", "drift", "--keyframe-interval", "2", "--drift-speed", "3", "--size",
            "40x30"]
    expected = cli_frames(cli, tmp_path, clip, *args)
    f = ifsfx.Filter(animate="drift", keyframe_interval=2, drift_speed=3, size=(40, 30),
                     frame_size=(64, 48))
    assert f.frame_size == (64, 48) and f.size == (40, 30)
    # any order, by index; the counter goes on after the last index given
    np.testing.assert_array_equal(f.apply(frames[3], index=3), expected[3])
    np.testing.assert_array_equal(f(frames[4]), expected[4])
    assert f.index == 5
    f.index = 1
    np.testing.assert_array_equal(f(frames[1]), expected[1])
    rgb = ifsfx.Filter(animate="drift", keyframe_interval=2, drift_speed=3, size="40x30",
                       rgb=True)
    out = rgb(np.ascontiguousarray(frames[0][:, :, ::-1]))
    np.testing.assert_array_equal(out[:, :, ::-1], expected[0])


def test_bgra_frames_keep_their_alpha(clip):
    frames, _ = clip
    alpha = np.arange(48 * 64, dtype=np.uint32).reshape(48, 64, 1).astype(np.uint8)
    bgra = np.concatenate([frames[0], alpha], axis=-1)
    out = ifsfx.Filter()(bgra)
    assert out.shape == (48, 64, 4)
    np.testing.assert_array_equal(out[:, :, 3], alpha[:, :, 0])
    np.testing.assert_array_equal(out[:, :, :3], ifsfx.Filter()(frames[0]))


def test_a_frame_of_another_size_is_a_value_error_with_the_library_message(clip):
    frames, _ = clip
    f = ifsfx.Filter()
    f(frames[0])
    with pytest.raises(ValueError, match=r"source image: must be the size the steal map was "
                                         r"prepared for \(64x48\) \(got 32x48\)"):
        f(frames[0][:, :32])
    assert f.index == 1  # the refused frame took no index
    with pytest.raises(ValueError, match=r"frame: a frame is an H×W×3 \(BGR\) or H×W×4 \(BGRA\) "
                                         r"array of uint8 \(got 48×64×1 array of uint8\)"):
        f(frames[0][:, :, 0])
    with pytest.raises(ValueError, match=r"frame: an image is an H×W or H×W×C array"):
        f(frames[0].astype(np.int32))


@pytest.mark.parametrize("kwargs, error, message", [
    (dict(preset="no-such-fern"), ValueError, "no-such-fern"),
    (dict(preset="missing/fern.toml"), FileNotFoundError, "missing/fern.toml"),
    (dict(animate="spin"), ValueError, "animate: none, drift or superifs (got 'spin')"),
    (dict(interpolation="cubic"), ValueError, "interpolation: bilinear or nearest (got 'cubic')"),
    (dict(background="purple"), ValueError,
     "background: expected black, white, original, #rrggbb or R,G,B (got 'purple')"),
    (dict(mix=2), ValueError, "mix: must be in [0, 1] (got 2)"),
    (dict(loop=10), ValueError,
     'loop: repeats an animation; add animate="drift" or animate="superifs"'),
    (dict(keyframe_interval=0), ValueError, "keyframe interval: must be 1 or more frames (got 0)"),
    (dict(fps=0), ValueError, "fps: must be in (0, 1000] (got 0)"),
    (dict(size="0x5"), ValueError, "size"),
])
def test_bad_settings_are_errors_with_the_command_messages(kwargs, error, message):
    with pytest.raises(error) as e:
        ifsfx.Filter(**kwargs)
    assert message in str(e.value)


def test_sigint_while_the_map_is_built_stops_it_and_the_filter_goes_on(clip):
    # The chaos game at 2000 points a pixel: seconds for a 1024×1024 frame, 0.1 s for 64×48.
    frames, _ = clip
    settings = dict(exact=False, quality=2000, threads=1)
    f = ifsfx.Filter(**settings)
    big = np.zeros((1024, 1024, 3), np.uint8)
    latency = interrupted_after(0.3, lambda: f(big))
    print(f"Filter: KeyboardInterrupt {latency * 1000:.0f} ms after SIGINT")
    assert latency < STOP_BOUND, f"KeyboardInterrupt {latency:.3f} s after SIGINT"
    # A fresh engine: the next frame, of any size, prepares the maps again.
    assert f.frame_size is None and f.index == 0
    np.testing.assert_array_equal(f(frames[0]), ifsfx.Filter(**settings)(frames[0]))
