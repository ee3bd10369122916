#!/usr/bin/python3
# SPDX-License-Identifier: Apache-2.0
"""FractalDB images per CPU-second: the reference generator beside ifsfx, in one run.

    bench/fractaldb_vs_reference.py REFERENCE_CHECKOUT [--build build/release]

REFERENCE_CHECKOUT is a checkout of hirokatsukataoka16/FractalDB-Pretrained-ResNet-PyTorch (read
only; nothing is downloaded). Its fractal_renderer/ is copied to a temporary folder, where the one
thing today's NumPy removed is adapted (np.str, gone in NumPy 1.24, becomes str), and run by this
interpreter (Debian's python3 with python3-numpy and python3-pil) on the reference's own category
CSVs (data/csv_rate0.2_category1000) and weights (weights_0.1.csv). ifsfx renders the same
categories and weights, more of them (it is that much faster), and the rates are compared:

  files      `ifsfx dataset render` writing PNGs (patch_gray, 512x512, 100,000 points), the
             reference's make_fractaldb.py likewise: images per CPU-second of each process
             (target: ifsfx >= 300x); also ifsfx writing 24-bit RGB PNGs as the reference does
  memory     ifsfx.fractaldb.Dataset iterated in this process (target >= 1000x the reference's
             file rate, which is all the reference has)
  threads    two Python threads iterating a Dataset's two shards at once against one thread
             iterating all of it, images per wall-second (target >= 1.8x: both cores busy)

and checks what it compares: point_gray pictures equal the reference's pixel for pixel, and every
lit pixel of a patch_gray picture, the reference's and ifsfx's, lies in a 3x3 block one pixel down
and right of a point. Speeds are figures to read, not pass/fail; a failed check exits 1.
"""
import argparse
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run_measured(command, cwd=None):
    """Runs a command; returns the CPU seconds it (and its children) used."""
    before = children_cpu()
    done = subprocess.run(command, cwd=cwd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"fractaldb_vs_reference: {' '.join(command)} failed:\n{done.stderr}")
    return children_cpu() - before


def reference_copy(checkout, work):
    """fractal_renderer/ copied, with np.str (removed from NumPy) read as str."""
    source = os.path.join(checkout, "fractal_renderer")
    if not os.path.isfile(os.path.join(source, "make_fractaldb.py")):
        sys.exit(f"fractaldb_vs_reference: {checkout}: no fractal_renderer/make_fractaldb.py "
                 "(give a checkout of hirokatsukataoka16/FractalDB-Pretrained-ResNet-PyTorch)")
    target = os.path.join(work, "fractal_renderer")
    shutil.copytree(source, target)
    script = os.path.join(target, "make_fractaldb.py")
    with open(script, encoding="utf-8") as f:
        text = f.read()
    adapted, count = re.subn(r"\bnp\.str\b", "str", text)
    with open(script, "w", encoding="utf-8") as f:
        f.write(adapted)
    print(f"reference: {checkout}, fractal_renderer/ copied; np.str -> str in {count} places")
    return target


def pick_categories(checkout, work, count, name):
    """The first `count` category CSVs of the reference's FractalDB-1k, in a folder of their own."""
    data = os.path.join(checkout, "data", "csv_rate0.2_category1000")
    files = sorted((os.path.join(root, f) for root, _, names in os.walk(data) for f in names
                    if f.endswith(".csv")), key=os.path.basename)
    if len(files) < count:
        sys.exit(f"fractaldb_vs_reference: {data}: {len(files)} category CSVs, {count} needed")
    folder = os.path.join(work, name)
    os.makedirs(folder)
    for f in files[:count]:
        shutil.copy(f, folder)
    return folder


def subset_weights(checkout, work, rows, name):
    with open(os.path.join(checkout, "fractal_renderer", "weights", "weights_0.1.csv")) as f:
        lines = [line.strip() for line in f if line.strip()]
    path = os.path.join(work, name)
    with open(path, "w") as f:
        f.write("\n".join(lines[:rows]) + "\n")
    return path, min(rows, len(lines))


def reference_render(renderer, cats, weights, out, draw, instances):
    command = [sys.executable, "make_fractaldb.py", "--load_root", cats, "--save_root", out,
               "--weight_csv", weights, "--draw_type", draw, "--instance", str(instances),
               "--image_size_x", "512", "--image_size_y", "512", "--iteration", "100000"]
    return run_measured(command, cwd=renderer)


def read_rgb(path):
    from PIL import Image
    return np.array(Image.open(path).convert("RGB"))


def patch_footprint(point_image):
    """Where 3x3 patches pasted one pixel down and right of the lit points of a y-down picture
    can light pixels (the points' image flipped to y down first by the caller)."""
    lit = point_image[:, :, 0] > 0
    allowed = np.zeros_like(lit)
    h, w = lit.shape
    for dy in (1, 2, 3):
        for dx in (1, 2, 3):
            allowed[dy:, dx:] |= lit[:h - dy, :w - dx]
    return allowed


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("reference", help="checkout of FractalDB-Pretrained-ResNet-PyTorch")
    parser.add_argument("--build", default=os.path.join(os.path.dirname(__file__), "..", "build",
                                                        "release"),
                        help="ifsfx build folder (default: build/release)")
    parser.add_argument("--reference-categories", type=int, default=2,
                        help="categories the reference renders (x 2 weights x 1 instance x 4 "
                             "flips; default 2: 16 images)")
    parser.add_argument("--categories", type=int, default=10,
                        help="categories ifsfx renders (x 25 weights x 10 instances x 4 flips; "
                             "default 10: 10,000 images)")
    args = parser.parse_args()
    build = os.path.abspath(args.build)
    sys.path.insert(0, os.path.join(build, "python"))
    try:
        from ifsfx import fractaldb
        import PIL  # noqa: F401 (the reference draws with it)
    except ImportError as e:
        sys.exit(f"fractaldb_vs_reference: {e} (build ifsfx with its Python module; the reference "
                 "needs python3-numpy and python3-pil)")
    ifsfx = os.path.join(build, "apps", "ifsfx")
    checkout = os.path.abspath(args.reference)
    print(f"machine: {os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.2f} "
          f"{os.getloadavg()[1]:.2f} {os.getloadavg()[2]:.2f}")
    failed = False
    with tempfile.TemporaryDirectory(prefix="fractaldb-bench-") as work:
        renderer = reference_copy(checkout, work)
        ref_cats = pick_categories(checkout, work, args.reference_categories, "ref_cats")
        ref_weights, ref_w = subset_weights(checkout, work, 2, "weights_2.csv")
        cats = pick_categories(checkout, work, args.categories, "cats")
        weights = os.path.join(checkout, "fractal_renderer", "weights", "weights_0.1.csv")

        # ---- files: the reference ----------------------------------------------------------
        out = os.path.join(work, "ref_patch")
        ref_cpu = reference_render(renderer, ref_cats, ref_weights, out, "patch_gray", 1)
        ref_images = args.reference_categories * ref_w * 4
        ref_rate = ref_images / ref_cpu
        print(f"reference  patch_gray 512x512, 100000 points: {ref_images} images in "
              f"{ref_cpu:.2f} CPU-s: {ref_rate:.3f} images/CPU-s ({ref_cpu / ref_images:.3f} "
              "CPU-s an image)")

        # ---- files: ifsfx -------------------------------------------------------------------
        data = fractaldb.Dataset(cats, weights)
        rates = {}
        for label, extra in (("indexed PNG", []), ("RGB PNG", ["--rgb-png"])):
            target = os.path.join(work, "ifsfx_" + label.split()[0])
            cpu = run_measured([ifsfx, "dataset", "render", cats, "--weights", weights,
                                "--threads", "1", "-q", "-o", target] + extra)
            rates[label] = len(data) / cpu
            print(f"ifsfx      patch_gray 512x512, 100000 points, {label}: {len(data)} images in "
                  f"{cpu:.2f} CPU-s: {rates[label]:.0f} images/CPU-s = "
                  f"{rates[label] / ref_rate:.0f}x the reference")
        files_ratio = rates["indexed PNG"] / ref_rate

        # ---- memory: the iterator -------------------------------------------------------------
        start = time.process_time()
        count = sum(1 for _ in data)
        cpu = time.process_time() - start
        memory_rate = count / cpu
        memory_ratio = memory_rate / ref_rate
        print(f"ifsfx      ifsfx.fractaldb.Dataset iterated in memory: {count} images in "
              f"{cpu:.2f} CPU-s: {memory_rate:.0f} images/CPU-s = {memory_ratio:.0f}x the "
              "reference's files")

        # ---- threads ------------------------------------------------------------------------
        threads_data = fractaldb.Dataset(cats, weights, instances=4)
        start = time.monotonic()
        one = sum(1 for _ in threads_data)
        one_rate = one / (time.monotonic() - start)
        counts = [0, 0]

        def drain(k):
            counts[k] = sum(1 for _ in threads_data.shard(k, 2))

        workers = [threading.Thread(target=drain, args=(k,)) for k in range(2)]
        start = time.monotonic()
        for w in workers:
            w.start()
        for w in workers:
            w.join()
        two_rate = sum(counts) / (time.monotonic() - start)
        threads_ratio = two_rate / one_rate
        print(f"ifsfx      two Python threads: {two_rate:.0f} images/s, one: {one_rate:.0f} "
              f"images/s: {threads_ratio:.2f}x (load average now {os.getloadavg()[0]:.2f})")

        # ---- checks -------------------------------------------------------------------------
        # point_gray: the reference's pictures, pixel for pixel.
        out = os.path.join(work, "ref_point")
        reference_render(renderer, ref_cats, ref_weights, out, "point_gray", 1)
        points = fractaldb.Dataset(ref_cats, ref_weights, draw="point_gray", rgb=True)
        same = sum(np.array_equal(image, read_rgb(os.path.join(out, points.path(i))))
                   for i, (image, _) in enumerate(points))
        print(f"check      point_gray: {same} of {len(points)} pictures equal the reference's "
              "pixel for pixel")
        failed |= same != len(points)
        # patch_gray: lit pixels only inside the blocks of the points (the same points).
        patches = fractaldb.Dataset(ref_cats, ref_weights, instances=1, rgb=True)
        inside = 0
        for i in range(len(patches)):
            if patches.key(i)[3] != 1:  # flip 1 is the y-down picture
                continue
            allowed = patch_footprint(points[i][0])
            ours = patches[i][0][:, :, 0] > 0
            theirs = read_rgb(os.path.join(work, "ref_patch", patches.path(i)))[:, :, 0] > 0
            ok = not (ours & ~allowed).any() and not (theirs & ~allowed).any()
            inside += ok
            print(f"check      {patches.path(i)}: lit {theirs.mean():.4f} (reference), "
                  f"{ours.mean():.4f} (ifsfx), all inside the points' blocks: {ok}")
        failed |= inside != len(patches) // 4

    print(f"summary    files {files_ratio:.0f}x (target 300x), memory {memory_ratio:.0f}x "
          f"(target 1000x), two threads {threads_ratio:.2f}x (target 1.8x)")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
