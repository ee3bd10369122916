#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
# PNG helpers of the studio's server test (standard library only):
#   studio_png.py same-pixels PNG RGBA W H   exit 0 when the raw RGBA rows (the studio's
#       "format": "rgba") are the PNG's pixels as 8-bit RGBA (grey and RGB widened, alpha 255)
#   studio_png.py write PNG W H              a black 8-bit grey PNG of W x H pixels
#   studio_png.py similar A B C TOLERANCE    exit 0 when C is as like A as B is, less TOLERANCE:
#       two renders of one flame (A and B: flam3-render with two seeds, C: ifsfx), by the SSIM of
#       their luminances (bench/flame_compare.cpp's: Gaussian window σ = 1.5, K1 = 0.01, K2 =
#       0.03, alpha ignored as OpenCV's IMREAD_COLOR ignores it); prints both
import math
import struct
import sys
import zlib


def chunks(data):
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit("not a PNG")
    at = 8
    while at < len(data):
        (length,) = struct.unpack(">I", data[at:at + 4])
        yield data[at + 4:at + 8], data[at + 8:at + 8 + length]
        at += 12 + length


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    return a if pa <= pb and pa <= pc else b if pb <= pc else c


def rgba_of_png(data):
    idat = b""
    for kind, body in chunks(data):
        if kind == b"IHDR":
            w, h, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    if depth != 8 or interlace:
        sys.exit(f"only 8-bit non-interlaced PNGs (got depth {depth}, interlace {interlace})")
    channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
    raw = zlib.decompress(idat)
    stride = w * channels
    rows, previous, at = [], bytearray(stride), 0
    for _ in range(h):
        kind, line = raw[at], bytearray(raw[at + 1:at + 1 + stride])
        at += 1 + stride
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            line[i] = (line[i] + (0, a, b, (a + b) // 2, paeth(a, b, c))[kind]) & 255
        rows.append(line)
        previous = line
    out = bytearray()
    for line in rows:
        for x in range(w):
            p = line[x * channels:(x + 1) * channels]
            if channels == 1:
                out += bytes((p[0], p[0], p[0], 255))
            elif channels == 2:
                out += bytes((p[0], p[0], p[0], p[1]))
            elif channels == 3:
                out += bytes((p[0], p[1], p[2], 255))
            else:
                out += p
    return w, h, bytes(out)


def luminance(path):
    w, h, rgba = rgba_of_png(open(path, "rb").read())
    # OpenCV's BGR2GRAY weights, as bench/flame_compare.cpp reads the pictures, of the picture
    # as it shows over black (a flame's PNG with alpha has straight colour; flam3's is opaque)
    return w, h, [(0.299 * rgba[i] + 0.587 * rgba[i + 1] + 0.114 * rgba[i + 2]) * rgba[i + 3] / 255
                  for i in range(0, len(rgba), 4)]


def blur(v, w, h):
    """cv::GaussianBlur(11x11, σ = 1.5) with its reflect-101 border."""
    taps = [math.exp(-(k * k) / (2 * 1.5 * 1.5)) for k in range(-5, 6)]
    taps = [t / sum(taps) for t in taps]

    def reflect(i, n):
        while i < 0 or i >= n:
            i = -i if i < 0 else 2 * n - 2 - i
        return i
    rows = [sum(taps[k] * v[y * w + reflect(x + k - 5, w)] for k in range(11))
            for y in range(h) for x in range(w)]
    return [sum(taps[k] * rows[reflect(y + k - 5, h) * w + x] for k in range(11))
            for y in range(h) for x in range(w)]


def ssim(a, b, w, h):
    c1, c2 = (0.01 * 255) ** 2, (0.03 * 255) ** 2
    ma, mb = blur(a, w, h), blur(b, w, h)
    aa = blur([x * x for x in a], w, h)
    bb = blur([x * x for x in b], w, h)
    ab = blur([x * y for x, y in zip(a, b)], w, h)
    total = 0.0
    for i in range(w * h):
        va, vb, cov = aa[i] - ma[i] ** 2, bb[i] - mb[i] ** 2, ab[i] - ma[i] * mb[i]
        total += ((2 * ma[i] * mb[i] + c1) * (2 * cov + c2)
                  / ((ma[i] ** 2 + mb[i] ** 2 + c1) * (va + vb + c2)))
    return total / (w * h)


def png_chunk(kind, body):
    return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))


if sys.argv[1] == "same-pixels":
    w, h, pixels = rgba_of_png(open(sys.argv[2], "rb").read())
    rgba = open(sys.argv[3], "rb").read()
    if (w, h) != (int(sys.argv[4]), int(sys.argv[5])):
        sys.exit(f"PNG is {w}x{h}")
    if rgba != pixels:
        diff = sum(1 for a, b in zip(rgba, pixels) if a != b)
        sys.exit(f"{diff} of {len(pixels)} bytes differ (RGBA has {len(rgba)})")
elif sys.argv[1] == "write":
    w, h = int(sys.argv[3]), int(sys.argv[4])
    raw = b"".join(b"\x00" + bytes(w) for _ in range(h))
    data = (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 0))
            + png_chunk(b"IDAT", zlib.compress(raw)) + png_chunk(b"IEND", b""))
    open(sys.argv[2], "wb").write(data)
elif sys.argv[1] == "similar":
    (w, h, a), (wb, hb, b), (wc, hc, c) = (luminance(p) for p in sys.argv[2:5])
    if (w, h) != (wb, hb) or (w, h) != (wc, hc):
        sys.exit(f"sizes differ: {w}x{h}, {wb}x{hb}, {wc}x{hc}")
    spread, ours = ssim(a, b, w, h), ssim(a, c, w, h)
    print(f"SSIM of two flam3 seeds {spread:.3f}, flam3 and ifsfx {ours:.3f}")
    sys.exit(0 if ours >= spread - float(sys.argv[5]) else 1)
else:
    sys.exit("usage: studio_png.py same-pixels PNG RGBA W H | write PNG W H | similar A B C TOL")
