# SPDX-License-Identifier: Apache-2.0
# A StealMap keeps the remap table of its last apply (source size and options), so that the
# frames of a video are not each made ready again: every apply still gives the bytes of the
# library's one-shot apply (render mode steal, or a freshly loaded map), whatever came before it,
# and two threads applying one map to sources of two sizes get the right bytes.
import threading

import numpy as np

import ifsfx

EXPECTED_TESTS = 2

SMALL = dict(size=(96, 64), seed=3)


def sources(photo):
    image, _ = photo
    small = np.ascontiguousarray(image[::2, ::3])
    return image, small


def test_successive_applies_equal_the_one_shot_apply(photo, tmp_path):
    image, small = sources(photo)
    T = ifsfx.steal_map("barnsley-fern", **SMALL)
    T.save(str(tmp_path / "t.map"))

    def one_shot(source, **kwargs):  # a map applied once, as `ifsfx apply` does
        return ifsfx.load_steal_map(str(tmp_path / "t.map")).apply(source, **kwargs)

    big_ref = ifsfx.render("barnsley-fern", mode="steal", source=image, alpha=False, **SMALL)
    small_ref = ifsfx.render("barnsley-fern", mode="steal", source=small, alpha=False, **SMALL)
    assert not np.array_equal(big_ref, small_ref)
    for source, expected in [(image, big_ref), (image, big_ref), (small, small_ref),
                             (image, big_ref), (small, small_ref), (small, small_ref)]:
        np.testing.assert_array_equal(T.apply(source), expected)
    nearest = one_shot(image, interpolation="nearest")
    white = one_shot(image, background="white")
    deep = image.astype(np.uint16) * 257
    deep_white = one_shot(deep, background="white")
    assert not np.array_equal(nearest, big_ref) and not np.array_equal(white, big_ref)
    for _ in range(2):
        np.testing.assert_array_equal(T.apply(image, interpolation="nearest"), nearest)
        np.testing.assert_array_equal(T.apply(image, background="white"), white)
        np.testing.assert_array_equal(T.apply(deep, background="white"), deep_white)
        np.testing.assert_array_equal(ifsfx.apply(T, image), big_ref)
        np.testing.assert_array_equal(T.apply(image, threads=1), big_ref)


def test_two_threads_applying_one_map_to_two_sizes_get_the_right_bytes(photo):
    image, small = sources(photo)
    T = ifsfx.steal_map("barnsley-fern", **SMALL)
    expected = {image.shape: T.apply(image), small.shape: T.apply(small)}
    wrong = []

    def work(source):
        for _ in range(30):
            if not np.array_equal(T.apply(source), expected[source.shape]):
                wrong.append(source.shape)

    threads = [threading.Thread(target=work, args=(s,)) for s in (image, small)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert wrong == []
