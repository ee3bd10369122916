# SPDX-License-Identifier: Apache-2.0
# ifsfx.fractaldb: the in-memory dataset equals `ifsfx dataset render`'s files image for image;
# the same seed gives the same images and the shards of a DataLoader's workers hold each image
# once; the readers' errors name the file and line; the search finds the reference's categories;
# rendering releases the GIL and Ctrl-C stops it.
import os
import pickle
import signal
import threading
import time

import numpy as np
import pytest

import ifsfx
from ifsfx import fractaldb
from conftest import STOP_BOUND, cli_image, run_cli

EXPECTED_TESTS = 11

# Three small categories written as the search writes them, named out of order.
MAPS = {
    "00002": [[0.5, 0.1, 0, 0.5, 0, 0], [0.4, 0, 0.2, 0.5, 0.5, 0.3]],
    "00000": [[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 0.5, 0], [0.5, 0, 0, 0.5, 0.25, 0.5]],
    "00001": [[0.6, -0.3, 0.3, 0.6, 0, 0], [0.3, 0, 0, 0.3, 0.7, 0.1]],
}
SMALL = dict(size=(96, 80), padding=4, iterations=6000)


@pytest.fixture(scope="module")
def categories(tmp_path_factory):
    folder = tmp_path_factory.mktemp("cats")
    (folder / "csv1").mkdir()
    for name, maps in MAPS.items():
        text = fractaldb.Category(np.array(maps, dtype=float), name=name).text
        sub = folder / ("csv1" if name == "00002" else "")
        (sub / f"{name}.csv").write_text(text)
    (folder.parent / "w.csv").write_text("1,1,1,1,1,1\n0.8,1,1,1,1,1\n")
    return folder


def dataset(categories, **kwargs):
    settings = dict(SMALL, weights=str(categories.parent / "w.csv"), instances=2)
    settings.update(kwargs)
    return fractaldb.Dataset(str(categories), **settings)


def test_images_equal_the_files_of_the_command(cli, categories, tmp_path):
    for draw in ("patch_gray", "point_color"):
        out = tmp_path / draw
        done = run_cli(cli, "dataset", "render", str(categories), "--weights",
                       str(categories.parent / "w.csv"), "--instances", "2", "--size", "96x80",
                       "--padding", "4", "--iterations", "6000", "--draw", draw, "-q", "-o",
                       str(out))
        assert done.returncode == 0, done.stderr
        data = dataset(categories, draw=draw)
        assert data.classes == ["00000", "00001", "00002"]
        files = sorted(str(p.relative_to(out)) for p in out.rglob("*.png"))
        assert files == sorted(data.path(i) for i in range(len(data)))
        assert len(files) == 3 * 2 * (2 if draw.startswith("patch") else 1) * 4
        for i, (image, label) in enumerate(data):
            assert image.shape == (80, 96, 3) and image.dtype == np.uint8
            assert label == data.key(i)[0]
            assert np.array_equal(image, ifsfx.read_image(str(out / data.path(i)))), data.path(i)
            assert np.array_equal(image, data[i][0])


def test_a_category_csv_is_a_preset_of_render_as_on_the_command_line(cli, categories, tmp_path):
    path = str(categories / "00001.csv")
    preset = ifsfx.load_preset(path)
    assert preset.name == "00001" and len(preset) == 2
    assert preset.description == "FractalDB category 00001"
    assert np.allclose(preset.maps, MAPS["00001"])
    for mode in ("measure", "tops"):
        image = ifsfx.render(path, mode=mode, size=(96, 80))
        assert np.array_equal(image, cli_image(cli, tmp_path, "render", path, "--mode", mode,
                                               "--size", "96x80", name=f"{mode}.png")), mode


def test_the_same_seed_gives_the_same_images_and_the_seed_moves_the_patches(categories):
    a, b = dataset(categories, seed=3), dataset(categories, seed=3)
    other = dataset(categories, seed=4)
    assert all(np.array_equal(a[i][0], b[i][0]) for i in range(0, len(a), 5))
    assert not np.array_equal(a[0][0], other[0][0])
    points = dataset(categories, seed=3, draw="point_gray")
    assert np.array_equal(points[9][0], dataset(categories, seed=4, draw="point_gray")[9][0])
    # rgb=True swaps red and blue; grey pictures have neither.
    colour = dataset(categories, draw="patch_color")
    assert np.array_equal(dataset(categories, draw="patch_color", rgb=True)[5][0],
                          colour[5][0][:, :, ::-1])


def test_worker_shards_hold_every_image_once(categories):
    data = dataset(categories)
    every = [(label, image.tobytes()) for image, label in data]
    assert len(every) == len(data) == 48
    shards = [list(data.shard(k, 3)) for k in range(3)]
    assert [len(data.shard(k, 3)) for k in range(3)] == [len(s) for s in shards]
    merged = [(label, image.tobytes()) for shard in shards for image, label in shard]
    assert sorted(merged) == sorted(every)
    with pytest.raises(ValueError, match=r"^shard: worker index in 0\.\.count-1"):
        data.shard(3, 3)


def test_a_dataset_pickles_for_spawned_workers(categories):
    data = dataset(categories, draw="patch_color", seed=7, rgb=True)
    again = pickle.loads(pickle.dumps(data))
    assert len(again) == len(data) and again.classes == data.classes
    assert (again.draw, again.size, again.padding, again.seed, again.rgb) == \
        ("patch_color", (96, 80), (4, 4), 7, True)
    assert all(np.array_equal(again[i][0], data[i][0]) for i in (0, 17, 47))
    c = data.categories[2]
    c2 = pickle.loads(pickle.dumps(c))
    assert c2.name == c.name and c2.text == c.text


def test_readers_name_the_file_and_line_of_bad_input(tmp_path):
    bad = tmp_path / "00005.csv"
    bad.write_text("0.5,0,0,0.5,0,0,0.5\n0.5,0,0,0.5,0.5,oops,0.5\n")
    with pytest.raises(ValueError, match=rf"^{bad}:2: column 6 \(f\): expected a number \(got 'oops'\)$"):
        fractaldb.read_category(bad)
    bad.write_text("0.5,0,0,0.5,0,0,0.5\n0.5,0,0,0.5,0.5,0\n")
    with pytest.raises(ValueError, match=rf"^{bad}:2: a category row a,b,c,d,e,f,p is 7 numbers"):
        fractaldb.read_category(str(bad))
    bad.write_text("1.2,0,0,1.2,0,0,1\n")
    with pytest.raises(ValueError, match=rf"^{bad}: the maps do not contract on average .*"
                                         r"FractalDB's search drops such an IFS"):
        fractaldb.read_category(bad)
    with pytest.raises(FileNotFoundError, match="missing.csv: no such file"):
        fractaldb.read_category(tmp_path / "missing.csv")
    (tmp_path / "w.csv").write_text("1,1,1,1,1\n")
    with pytest.raises(ValueError, match=r"w\.csv:1: a weight row wa,wb,wc,wd,we,wf is 6"):
        fractaldb.read_weights(tmp_path / "w.csv")
    with pytest.raises(ValueError, match=r"^maps: an \(N, 6\) array"):
        fractaldb.Category(np.zeros((2, 5)))
    with pytest.raises(ValueError, match=r"^c:1: column 7 \(p\): a probability must be ≥ 0"):
        fractaldb.Category([[0.5, 0, 0, 0.5, 0, 0]], probabilities=[-1], name="c")


def test_dataset_arguments_are_checked(categories):
    with pytest.raises(ValueError, match=r"^draw: must be one of point_gray, point_color"):
        dataset(categories, draw="patch")
    with pytest.raises(ValueError, match=r"^padding: must be ≥ 0 and leave pixels inside 96x80"):
        dataset(categories, padding=48)
    with pytest.raises(ValueError, match=r"^weights: a step K"):
        dataset(categories, weights=np.ones((2, 5)))
    with pytest.raises(ValueError, match=r"^categories: a path"):
        fractaldb.Dataset(3)
    data = dataset(categories)
    with pytest.raises(IndexError, match=r"the dataset has 48 images \(got 48\)"):
        data[48]
    assert np.array_equal(data[-1][0], data[47][0])
    assert data.key(47) == (2, 1, 1, 3) and data.path(47) == "00002/00002_01_count_1_flip3.png"


def test_weights_tables_and_categories_read_back():
    table = fractaldb.weights_table(0.4)
    assert table.shape == (25, 6)
    assert table[0].tolist() == [0.2, 1, 1, 1, 1, 1] and table[2].tolist() == [1] * 6
    c = fractaldb.Category([[0.5, 0, 0, 0.5, 0, 0], [0.5, 0, 0, 0.5, 0.5, 0]], name="x")
    assert c.probabilities == [0.5, 0.5] and len(c) == 2 and c.contraction_rate < 0
    assert c.text.startswith("5.000000000000000000e-01,0.000000000000000000e+00,")


def test_search_finds_the_published_first_category(cli, tmp_path):
    found = fractaldb.search(1)
    assert found[0].name == "00000"
    # data/csv_rate0.2_category1000/csv0/00000.csv of the reference repository, first value.
    assert found[0].text.startswith("1.724223243171234543e-01,-7.311756060787280020e-01,")
    done = run_cli(cli, "dataset", "search", "-n", "1", "-q", "-o", str(tmp_path))
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "00000.csv").read_text() == found[0].text


def test_two_threads_iterate_at_once_and_get_the_single_thread_images(categories):
    data = dataset(categories, draw="patch_color")
    alone = [image for image, _ in data]
    results = [None, None]

    def run(k):
        results[k] = [image for image, _ in data.shard(0, 1)]

    threads = [threading.Thread(target=run, args=(k,)) for k in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for got in results:
        assert all(np.array_equal(a, b) for a, b in zip(got, alone)) and len(got) == len(alone)


def test_another_python_thread_runs_while_an_image_renders(categories):
    data = dataset(categories, size=(1024, 1024), iterations=3_000_000)
    ticks = 0
    done = threading.Event()

    def render():
        data[0]
        data[40]  # another category and weight: a second walk
        done.set()

    worker = threading.Thread(target=render)
    start = time.monotonic()
    worker.start()
    while not done.is_set():
        ticks += 1  # pure Python: runs only while the rendering does not hold the GIL
        time.sleep(0.005)
    worker.join()
    seconds = time.monotonic() - start
    assert seconds > 0.05, f"rendering took {seconds:.3f} s: too short to tell"
    assert ticks >= 0.25 * seconds / 0.005, f"{ticks} ticks in {seconds:.3f} s"


def test_sigint_stops_a_search_and_an_iteration_promptly(categories):
    for work in (lambda: fractaldb.search(1000),
                 lambda: [None for _ in dataset(categories, instances=100000)]):
        sent = []

        def send():
            sent.append(time.monotonic())
            os.kill(os.getpid(), signal.SIGINT)

        timer = threading.Timer(0.3, send)
        timer.start()
        try:
            work()
        except KeyboardInterrupt:
            latency = time.monotonic() - sent[0]
        else:
            raise AssertionError("the work finished before the interrupt")
        finally:
            timer.cancel()
        assert latency < STOP_BOUND, f"KeyboardInterrupt {latency:.3f} s after SIGINT"
