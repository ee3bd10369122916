// SPDX-License-Identifier: Apache-2.0
// Barnsley's fern coloured by stealing the colours of a photo (paper §4, Fig. 1): the steal map of
// the fern, with exact top addresses, applied to the photo. The same picture as
//   ifsfx render barnsley-fern --mode steal --exact --source PHOTO --size WxH -o OUT
// with a black background instead of a transparent one.
//   fern_steal PHOTO OUT.png [WxH]      (default size 640x480)
#include <cstdio>
#include <exception>

#include "ifs/error.h"
#include "ifs/image_io.h"
#include "ifs/preset.h"
#include "ifs/steal_map.h"

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::fputs("usage: fern_steal PHOTO OUT.png [WxH]\n", stderr);
    return 2;
  }
  cv::Size size{640, 480};
  char tail = 0;
  if (argc == 4 && (std::sscanf(argv[3], "%dx%d%c", &size.width, &size.height, &tail) != 2 ||
                    size.width <= 0 || size.height <= 0)) {
    std::fprintf(stderr, "fern_steal: size: WxH in pixels (got '%s')\n", argv[3]);
    return 2;
  }
  try {
    // The shipped preset (built into the library) and the default colouring IFS: the photo
    // tiled into as many pieces as the fern has maps.
    const ifsfx::IfsPreset fern = ifsfx::load_ifs("barnsley-fern");
    const ifsfx::Ifs colouring = ifsfx::default_colouring(fern.ifs.size());
    ifsfx::StealMapStats stats;
    const ifsfx::StealMap map =
        ifsfx::compute_steal_map(fern.ifs, colouring, size, {}, &stats);  // the exact descent
    const cv::Mat photo = ifsfx::read_image(argv[1]).pixels;
    ifsfx::write_image(argv[2], ifsfx::apply(map, photo));
    std::printf("%s: %dx%d, coverage %.4f\n", argv[2], size.width, size.height, stats.coverage);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fern_steal: %s\n", e.what());
    return 1;
  }
  return 0;
}
