// SPDX-License-Identifier: Apache-2.0
// OpenImageIO's side of ifs/image_io.h for a binary that must not load OpenImageIO: the light
// `ifsfx`, which writes PNG through libpng (ifs/png_writer.cpp: the pixels and text attributes
// OpenImageIO would write) and hands every command that reads an image or writes another format
// to the full binary before it gets here (cli/light_main.cpp). Linked as an object ahead of
// libifs.a, these definitions keep the linker from taking image_io_oiio.o out of the archive;
// anything but PNG asked of them after all is refused, never written or read.
#include <fmt/format.h>

#include "ifs/detail/image_formats.h"
#include "ifs/error.h"
#include "ifs/image_io.h"

namespace ifsfx {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const fs::path& path, const char* what) {
  throw Error(ErrorKind::unsupported,
              fmt::format("{}: this ifsfx binary {} (the full one, ifsfx-full, does)",
                          path.string(), what));
}

bool is_png(const fs::path& path) {
  return detail::lower_extension(path) == ".png";
}

}  // namespace

namespace detail {

bool oiio_can_write(const fs::path& path) {
  if (!is_png(path)) refuse(path, "writes only PNG");
  return true;
}

void write_oiio(const fs::path& target, const fs::path& file, const cv::Mat& pixels, bool smallest,
                const ImageAttributes& attributes, std::vector<unsigned char>* memory) {
  if (!is_png(target)) refuse(target, "writes only PNG");
  if (memory != nullptr) refuse(target, "writes images only to files");
  write_png(target, file, pixels, smallest, attributes);
}

}  // namespace detail

ImageFile read_image(const fs::path& path) {
  refuse(path, "reads no images");
}

}  // namespace ifsfx
