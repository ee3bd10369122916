// SPDX-License-Identifier: Apache-2.0
// --seamless, --tiles and --tile-offset (cli/option_groups.h), in a file of their own: the light
// ifsfx's `render` registers them without the other groups, which name the video stack's types.
#include "cli/option_groups.h"

namespace ifsfx::app {

void add_seamless_options(CLI::App& cmd, SeamlessArgs& args) {
  cmd.add_flag("--seamless", args.seamless,
               "The picture is one period of a doubly periodic texture, which tiles with no "
               "seam: the maps act on the torus of the tile (the view), each followed by the "
               "wrap back into it");
  cmd.add_option("--tiles", args.tiles,
                 "With --seamless: show KxL periods (the picture is K·W x L·H, the tile "
                 "repeated)")
      ->default_str("1x1");
  cmd.add_option("--tile-offset", args.offset,
                 "With --seamless: where the picture starts in the period, X,Y as fractions of "
                 "the tile (right, down), rounded to whole pixels; default: the preset's offset, "
                 "else 0,0");
}

}  // namespace ifsfx::app
