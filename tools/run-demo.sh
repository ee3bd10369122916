#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Installs what is missing, builds (Release) and runs the main job on built-in defaults: filters a
# real movie clip (OpenCV's sample footage, Debian package opencv-doc) through a shipped preset,
# and writes a superfractal still and a few IFS stills. Everything lands in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh release
ifsfx=build/release/cli/ifsfx
clip=/usr/share/doc/opencv-doc/examples/data/vtest.avi
mkdir -p out

# The fractal filter: every frame of the clip coloured through the fern's steal map.
$ifsfx filter "$clip" --preset barnsley-fern -o out/vtest-fern.mp4
# A V-variable superfractal texture (the paper's Fig. 4 superIFS, V = 3), colour-stolen from a
# frame-sized photo, and the attractor itself.
$ifsfx texture paper-fig4 -V 3 --size 1024x1024 --mode steal \
  --source /usr/share/doc/opencv-doc/examples/data/baboon.jpg -o out/paper-fig4-steal.png
$ifsfx texture paper-fig4 -V 3 --size 1024x1024 -o out/paper-fig4.png
# A denser superfractal texture: carpets with holes in different places, V = 3.
$ifsfx texture carpet-lace -V 3 --size 1024x1024 --mode steal \
  --source /usr/share/doc/opencv-doc/examples/data/baboon.jpg -o out/carpet-lace-steal.png
# A seamless tile of it (docs/seamless.md), shown as 3×3 periods: no seam where the tiles meet.
$ifsfx texture carpet-lace -V 3 --seamless --tiles 3x3 --size 512x512 --mode steal \
  --source /usr/share/doc/opencv-doc/examples/data/baboon.jpg -o out/carpet-lace-tiles.png
# IFS stills: the invariant measure, and colour stealing (paper Fig. 1).
$ifsfx render barnsley-fern --mode measure --size 1024x1024 --supersample 2 -o out/fern-measure.png
$ifsfx render barnsley-fern --mode steal --exact --size 1024x1024 \
  --source /usr/share/doc/opencv-doc/examples/data/baboon.jpg -o out/fern-steal.png
# A fractal flame (docs/flames.md) as a preset: the orb stealing the photo's colours through the
# chaos game, and the clip filtered through it.
$ifsfx render docs/images/flame-orb.flame --mode steal --size 384x384 --quality 16 \
  --source /usr/share/doc/opencv-doc/examples/data/baboon.jpg -o out/flame-orb-steal.png
$ifsfx filter "$clip" --preset docs/images/flame-orb.flame --quality 16 -o out/vtest-flame-orb.mp4
# The README's pictures (docs/images/): 256 pixels wide, JPEG, into out/readme/; copy them over
# docs/images/ to refresh the README.
mkdir -p out/readme
small() { ffmpeg -nostdin -loglevel error -y ${3:+-ss "$3"} -i "$1" -vf "scale=${4:-256}:-2" \
  -frames:v 1 -q:v 3 -update 1 "$2"; }  # INPUT OUTPUT [SECONDS [WIDTH]]
small out/fern-steal.png out/readme/fern-steal.jpg
small out/carpet-lace-steal.png out/readme/carpet-lace-steal.jpg
small out/vtest-fern.mp4 out/readme/vtest-fern.jpg 40
small out/carpet-lace-tiles.png out/readme/carpet-lace-tiles.jpg 0 384
small out/flame-orb-steal.png out/readme/flame-orb-steal.jpg
small out/vtest-flame-orb.mp4 out/readme/vtest-flame-orb.jpg 40
echo "run-demo: results in out/ (vtest-fern.mp4, paper-fig4*.png, carpet-lace-*.png, fern-*.png,"
echo "          flame-orb-steal.png, vtest-flame-orb.mp4;"
echo "          the README's pictures in out/readme/)"
