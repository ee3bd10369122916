#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# The test setup of the studio's browser test: playwright-core from the npm registry into a folder
# of the build tree (the product never fetches anything). Nothing to do when it is there already;
# without node or npm there is nothing to install and the browser test skips.
# Usage: studio_node_setup.sh DIR
set -euo pipefail
dir=$1
version=1.65.1
[[ -f $dir/node_modules/playwright-core/package.json ]] &&
  grep -q "\"version\": \"$version\"" "$dir/node_modules/playwright-core/package.json" && exit 0
command -v npm >/dev/null || { echo "npm is missing: the browser test will skip"; exit 0; }
mkdir -p "$dir"
npm install --prefix "$dir" --no-audit --no-fund --no-save "playwright-core@$version"
