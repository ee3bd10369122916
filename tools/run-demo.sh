#!/usr/bin/env bash
# Installs what is missing, builds (Release) and runs the main job on built-in defaults: renders
# the shipped presets to stills in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
bash tools/build.sh release
ifsfx=build/release/apps/ifsfx
mkdir -p out
$ifsfx presets
for preset in barnsley-fern maple-leaf sierpinski-triangle heighway-dragon twin-dragon; do
  $ifsfx render "$preset" --mode measure --size 1280x1280 --supersample 2 -o "out/$preset.png"
done
echo "run-demo: images in out/"
