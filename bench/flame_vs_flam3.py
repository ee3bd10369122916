#!/usr/bin/env python3
# SPDX-License-Identifier: Apache-2.0
"""ifsfx's flame renderer against flam3-render (issue 31 items 3 and 4).

For each flame — `flam3-genome` random genomes made at run time, and every <flame> of the .flame
files under the directories given (e.g. Fractorium's Data/examples, by path: other people's art
is never copied into the repository) — at one size and quality:

  flam3-render and ifsfx (bench/flame_render) with seeds 1 to N each (--seeds, 3 by default),

then prints per flame flam3's own seed-to-seed spread (SSIM of the luminances and mean RGB
distance, bench/flame_compare, the mean over every pair of flam3's pictures: one pair alone is
a noisy estimate) and the similarity of ifsfx's pictures to flam3's (the mean over every pair of
one of each), the CPU seconds of each whole command (the child's getrusage, the mean of each
program's runs) and the speed ratio flam3/ifsfx. A line passes when ifsfx is within flam3's
spread: SSIM ≥ flam3's − 0.02 and colour distance ≤ flam3's + 1.0, or, where the pairs differ
much among themselves (a picture that is mostly noise), within twice the standard error of the
difference of the two means.

  bench/flame_vs_flam3.py [--genomes 20] [--size 256] [--quality 50] [--threads 2]
                          [--seeds 3] [--bin build/release/bench] [--keep DIR]
                          [DIR_OR_FILE ...]

--keep DIR keeps each line's pictures (NAME-flam3-SEED.png, NAME-ifsfx-SEED.png) and the flame as
rendered (NAME.flame, resized), for bench/flame_ab.sh.
"""
import argparse
import itertools
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

SSIM_TOL, COLOUR_TOL = 0.02, 1.0
Z_ONLY = ("flatten", "zscale", "ztranslate", "zcone", "zblur")
EMBER_ONLY = ("var_color", "name", "animate", "motion_frequency", "motion_function")
# Ember's z parameters of 2-D variations: nothing in the plane (ifsfx ignores them too).
EMBER_Z_PARAMETERS = ("waves2_freqz", "waves2_scalez")


def cpu_run(cmd, env=None, stdin=None):
    """Runs cmd; returns (returncode, stderr, CPU seconds of the child)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    p = subprocess.run(cmd, env=env, stdin=stdin, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return p.returncode, p.stderr + p.stdout, cpu


def resized(flame, longest, quality):
    """The <flame> element at `longest` pixels on its longer side (scale following the width,
    as flam3-render's size scale does) and `quality` samples per pixel."""
    w, h = (float(v) for v in flame.get("size", "100 100").split())
    k = longest / max(w, h)
    nw, nh = max(1, round(w * k)), max(1, round(h * k))
    flame.set("size", f"{nw} {nh}")
    flame.set("scale", repr(float(flame.get("scale", "1")) * nw / w))
    flame.set("quality", str(quality))
    for attr in ("temporal_samples", "passes"):
        if attr in flame.attrib:
            flame.set(attr, "1")
    # Ember's per-xform attributes that do not change the picture (flam3-render would warn
    # "unrecognized variation" about them, and ifsfx ignores them too).
    for xf in list(flame.iter("xform")) + list(flame.iter("finalxform")):
        for attr in EMBER_ONLY + EMBER_Z_PARAMETERS:
            xf.attrib.pop(attr, None)
        # Apophysis' Mobius plugin, as Ember writes it, is flam3's mobius under other names
        # (ifsfx reads both as one variation, flame/variations_more.cpp).
        for attr in [a for a in xf.attrib if a == "Mobius" or a.startswith("Mobius_")]:
            xf.set(attr.lower(), xf.attrib.pop(attr))
        # Ember's 3-D variations that are 2-D ones in the plane, as flam3 knows them: linear3D
        # is linear at z = 0; flatten and the z-only ones change nothing (docs/flames.md).
        for prefix in ("", "pre_", "post_"):
            if prefix + "linear3D" in xf.attrib:
                w = float(xf.attrib.pop(prefix + "linear3D"))
                xf.set(prefix + "linear", repr(float(xf.get(prefix + "linear", "0")) + w))
            for name in Z_ONLY:
                for attr in [a for a in xf.attrib if a == prefix + name or a.startswith(prefix + name + "_")]:
                    xf.attrib.pop(attr)
                    # A regular z-only variation adds nothing to the sum, which may then hold no
                    # variation at all: flam3 and ifsfx sum none to (0, 0), as the flame's
                    # flatten does in Ember. A linear of weight 0 writes that sum out.
                    if attr == name and "linear" not in xf.attrib:
                        xf.set("linear", "0")
    return flame


def genomes(count, work):
    out = []
    for seed in range(1, count + 1):
        text = subprocess.run(["flam3-genome"], env=dict(os.environ, seed=str(seed), isaac_seed=str(seed)),
                              stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True).stdout
        for i, f in enumerate(ET.fromstring(text).iter("flame")):
            out.append((f"genome-{seed}" + (f".{i}" if i else ""), f))
    return out


def pack_flames(paths):
    out = []
    files = []
    for p in paths:
        if os.path.isdir(p):
            for root, _, names in os.walk(p):
                files += [os.path.join(root, n) for n in sorted(names) if n.endswith(".flame")]
        else:
            files.append(p)
    for path in sorted(files):
        try:
            root = ET.parse(path).getroot()
        except ET.ParseError as e:
            print(f"# {path}: not XML ({e})")
            continue
        flames = [root] if root.tag == "flame" else list(root.iter("flame"))
        stem = os.path.splitext(os.path.basename(path))[0]
        for i, f in enumerate(flames):
            out.append((f"{stem}:{i}", f))
    return out


def compare(tool, a, b):
    text = subprocess.run([tool, a, b], stdout=subprocess.PIPE, text=True).stdout
    m = re.match(r"ssim (\S+) colour (\S+)", text)
    return (float(m.group(1)), float(m.group(2))) if m else (float("nan"), float("nan"))


def twice_error(a, b, k):
    """Twice the standard error of mean(a[][k]) − mean(b[][k]) (the pairs taken as independent)."""
    def variance_of_mean(pairs):
        values = [v[k] for v in pairs]
        return statistics.variance(values) / len(values) if len(values) > 1 else 0.0
    return 2 * (variance_of_mean(a) + variance_of_mean(b)) ** 0.5


def one(name, flame, args, work):
    path = os.path.join(work, "f.flame")
    ET.ElementTree(resized(flame, args.size, args.quality)).write(path)
    seeds = range(1, args.seeds + 1)
    flam3_pics = [os.path.join(work, f"f3-{seed}.png") for seed in seeds]
    times = []
    for seed, out in zip(seeds, flam3_pics):
        env = dict(os.environ, out=out, format="png", verbose="0", nthreads=str(args.threads),
                   seed=str(seed), isaac_seed=str(seed), transparency="0")
        with open(path) as f:
            rc, err, cpu = cpu_run(["flam3-render"], env=env, stdin=f)
        if rc != 0 or not os.path.exists(out):
            return f"{name:34} flam3-render failed: {err.strip().splitlines()[-1] if err.strip() else rc}"
        if re.search(r"unknown|not recogni|ignor", err, re.I):
            return f"{name:34} flam3-render cannot: {err.strip().splitlines()[0][:60]}"
        times.append(cpu)
    ifsfx_pics, ifsfx_times = [], []
    for seed in seeds:
        out = os.path.join(work, f"ifsfx-{seed}.png")
        rc, err, cpu = cpu_run([os.path.join(args.bin, "flame_render"), path, "-o", out,
                                "--seed", str(seed), "--threads", str(args.threads)])
        if rc != 0:
            return f"{name:34} ifsfx refuses: {err.strip()[:90]}"
        ifsfx_pics.append(out)
        ifsfx_times.append(cpu)
    tool = os.path.join(args.bin, "flame_compare")
    # flam3's spread: the mean over every pair of its seeds' pictures; ifsfx's similarity: the
    # mean over every pair of one ifsfx and one flam3 picture. One pair alone is a noisy estimate
    # where the picture is mostly noise (a flame of scattered circles spans colour 62-85 over
    # flam3's pairs), so the tolerance is at least twice the standard error of the two means'
    # difference.
    spread = [compare(tool, a, b) for a, b in itertools.combinations(flam3_pics, 2)]
    ours = [compare(tool, a, b) for a in ifsfx_pics for b in flam3_pics]
    s_ff, c_ff = statistics.mean(v[0] for v in spread), statistics.mean(v[1] for v in spread)
    s_if, c_if = statistics.mean(v[0] for v in ours), statistics.mean(v[1] for v in ours)
    s_tol = max(SSIM_TOL, twice_error(spread, ours, 0))
    c_tol = max(COLOUR_TOL, twice_error(spread, ours, 1))
    ok = s_if >= s_ff - s_tol and c_if <= c_ff + c_tol
    if args.keep:
        stem = name.replace(":", "_")
        for seed, pic in zip(seeds, flam3_pics):
            shutil.copy(pic, os.path.join(args.keep, f"{stem}-flam3-{seed}.png"))
        for seed, pic in zip(seeds, ifsfx_pics):
            shutil.copy(pic, os.path.join(args.keep, f"{stem}-ifsfx-{seed}.png"))
        shutil.copy(path, os.path.join(args.keep, f"{stem}.flame"))
    return dict(name=name, s_ff=s_ff, c_ff=c_ff, s_if=s_if, c_if=c_if, ok=ok, tol=(s_tol, c_tol),
                t_f=statistics.mean(times), t_i=statistics.mean(ifsfx_times))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("paths", nargs="*")
    ap.add_argument("--genomes", type=int, default=20)
    ap.add_argument("--size", type=int, default=256)
    ap.add_argument("--quality", type=float, default=50)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--bin", default="build/release/bench")
    ap.add_argument("--seeds", type=int, default=3)
    ap.add_argument("--keep")
    args = ap.parse_args()
    if args.seeds < 2:
        sys.exit("flame_vs_flam3: --seeds must be at least 2 (flam3's spread needs a pair)")
    if not shutil.which("flam3-render"):
        sys.exit("flame_vs_flam3: flam3-render is needed (apt-get install flam3-utils)")
    if args.keep:
        os.makedirs(args.keep, exist_ok=True)
    print(f"# {args.size} px longest side, quality {args.quality:g}, {args.threads} thread(s) each, "
          f"seeds 1-{args.seeds} each; "
          f"CPU seconds of each whole command (the mean of its runs); pass: SSIM >= flam3's - {SSIM_TOL}, "
          f"colour <= flam3's + {COLOUR_TOL} (or twice the standard error of the means' difference, if larger)")
    print(f"{'flame':34} {'flam3 vs flam3':>16} {'ifsfx vs flam3':>16} {'flam3 s':>8} {'ifsfx s':>8} {'ratio':>6}")
    rows, skipped = [], 0
    with tempfile.TemporaryDirectory() as work:
        for name, flame in genomes(args.genomes, work) + pack_flames(args.paths):
            r = one(name, flame, args, work)
            if isinstance(r, str):
                print(r)
                skipped += 1
                continue
            rows.append(r)
            print(f"{name:34} {r['s_ff']:7.4f} {r['c_ff']:7.2f}  {r['s_if']:7.4f} {r['c_if']:7.2f}  "
                  f"{r['t_f']:8.2f} {r['t_i']:8.2f} {r['t_f'] / max(r['t_i'], 1e-3):6.1f}  {'pass' if r['ok'] else 'FAIL'}"
                  + (f" (tolerance {r['tol'][0]:.3f}, {r['tol'][1]:.2f})" if r["tol"] != (SSIM_TOL, COLOUR_TOL) else ""),
                  flush=True)
    for label, sel in (("genomes", [r for r in rows if r["name"].startswith("genome-")]),
                       ("packs", [r for r in rows if not r["name"].startswith("genome-")])):
        if sel:
            ratios = [r["t_f"] / max(r["t_i"], 1e-3) for r in sel]
            print(f"# {label}: {sum(r['ok'] for r in sel)}/{len(sel)} within flam3's spread; speed ratio "
                  f"median {statistics.median(ratios):.1f}, min {min(ratios):.1f}, max {max(ratios):.1f}; "
                  f"total CPU flam3 {sum(r['t_f'] for r in sel):.1f} s, ifsfx {sum(r['t_i'] for r in sel):.1f} s")
    print(f"# {skipped} flame(s) not compared (refused or not renderable by flam3-render)")


if __name__ == "__main__":
    main()
