#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# Per-frame time of StealMap.apply from Python on frames of one size (a video's): the map keeps
# its remap table between calls (python/steal.h), so only the first frame pays for it.
#   PYTHONPATH=build/release/python python3 bench/python_apply_bench.py [--size 1920x1080]
# Prints the median and best of --frames applies, and the first apply of a freshly loaded map
# (the table built and used once: what every frame cost before the cache). Run it with the
# PYTHONPATH of another build to compare (docs/python.md has the figures).
import argparse
import os
import statistics
import tempfile
import time

import numpy as np

import ifsfx


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--size", default="1920x1080", help="map and frame size WxH")
    parser.add_argument("--frames", type=int, default=60, help="applies timed")
    parser.add_argument("--threads", type=int, default=0, help="0 = all cores")
    args = parser.parse_args()
    w, h = (int(v) for v in args.size.split("x"))
    T = ifsfx.steal_map("barnsley-fern", size=(w, h))
    frame = np.random.default_rng(1).integers(0, 256, (h, w, 3), dtype=np.uint8)

    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "t.map")
        T.save(path)
        firsts = []
        for _ in range(5):
            fresh = ifsfx.load_steal_map(path)
            start = time.perf_counter()
            fresh.apply(frame, threads=args.threads)
            firsts.append(time.perf_counter() - start)

    T.apply(frame, threads=args.threads)  # warm-up
    times = []
    for _ in range(args.frames):
        start = time.perf_counter()
        T.apply(frame, threads=args.threads)
        times.append(time.perf_counter() - start)
    print(f"module {ifsfx.__file__}")
    print(f"StealMap.apply {w}x{h} BGR uint8, threads={args.threads}, load {os.getloadavg()[0]:.1f}")
    print(f"  repeated apply, same map:   median {statistics.median(times) * 1e3:.2f} ms, "
          f"best {min(times) * 1e3:.2f} ms per frame ({args.frames} frames)")
    print(f"  first apply of a fresh map: median {statistics.median(firsts) * 1e3:.2f} ms, "
          f"best {min(firsts) * 1e3:.2f} ms (5 maps)")


if __name__ == "__main__":
    main()
