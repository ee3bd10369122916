// SPDX-License-Identifier: Apache-2.0
#include "ifs/image_io.h"

#include <cctype>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "ifs/detail/image_formats.h"
#include "ifs/error.h"
#include "ifs/utf8.h"

namespace ifsfx {
namespace fs = std::filesystem;

std::string detail::lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

namespace {

bool float_format(const std::string& ext) {
  return ext == ".exr" || ext == ".hdr";
}

// Bits per channel: 8 or 16, and 16 only where the format holds it (floats ignore it).
void check_bits(const fs::path& path, int bits) {
  if (bits != 8 && bits != 16)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: bits per channel must be 8 or 16 (got {})", path.string(), bits));
  const std::string ext = detail::lower_extension(path);
  const bool can_16 = ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".ppm" ||
                      ext == ".pgm" || ext == ".pnm";
  if (bits == 16 && !can_16 && !float_format(ext))
    throw Error(
        ErrorKind::unsupported,
        fmt::format("{}: 16 bits per channel needs .png or .tif (got '{}')", path.string(), ext));
}

// The pixels converted to the depth the file will hold.
cv::Mat to_file_depth(const cv::Mat& image, int cv_depth) {
  if (image.depth() == cv_depth) return image;
  const auto full = [](int depth) {
    return depth == CV_8U ? 255.0 : depth == CV_16U ? 65535.0 : 1.0;
  };
  cv::Mat out;
  image.convertTo(out, CV_MAKETYPE(cv_depth, image.channels()),
                  full(cv_depth) / full(image.depth()));
  return out;
}

// What every format stores: the writer, the caller's metadata made valid UTF-8 first (a Latin-1
// comment or file name must not fail the run) and, since formats without free-form attributes
// (TIFF, JPEG) keep only standard tags, the whole set as JSON in the image description too,
// which every format stores.
detail::ImageAttributes attributes_of(const WriteOptions& options) {
  detail::ImageAttributes attributes{{"Software", "ifsfx"}};
  for (const auto& [key, value] : options.metadata)
    attributes.emplace_back(valid_utf8(key), valid_utf8(value));
  if (!options.metadata.empty()) {
    nlohmann::json all = nlohmann::json::object();
    for (auto at = attributes.begin() + 1; at != attributes.end(); ++at)
      all[at->first] = at->second;
    attributes.emplace_back("ImageDescription", std::string(detail::kMetadataTag) + all.dump());
  }
  return attributes;
}

}  // namespace

void check_writable_image(const fs::path& path, const OutputOptions& output, int bits) {
  if (path.empty()) throw Error(ErrorKind::invalid_argument, "output: no file name given");
  if (!detail::oiio_can_write(path))
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: no image writer for extension '{}' (use .png, .tif, .exr, .jpg)",
                            path.string(), path.extension().string()));
  check_bits(path, bits);
  check_output(path, output);
}

void write_image(const fs::path& path, const cv::Mat& image, const WriteOptions& options) {
  check_writable_image(path, options.output, options.bits);
  OutputFile out(path, options.output);
  write_image(out, image, options);
  out.commit();
}

void write_image(OutputFile& file, const cv::Mat& image, const WriteOptions& options) {
  const fs::path& path = file.target();
  if (image.empty())
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: empty image", path.string()));
  check_bits(path, options.bits);

  const std::string ext = detail::lower_extension(path);
  const int cv_depth = float_format(ext) ? CV_32F : options.bits == 16 ? CV_16U : CV_8U;
  const cv::Mat pixels = to_file_depth(image, cv_depth);
  detail::write_oiio(path, file.temporary(), pixels, options.smallest, attributes_of(options));
}

std::string encode_image(const cv::Mat& image, const std::string& extension,
                         const WriteOptions& options) {
  const fs::path name = "image" + extension;  // what picks the format, and names it in messages
  if (image.empty())
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: empty image", name.string()));
  check_bits(name, options.bits);
  const std::string ext = detail::lower_extension(name);
  const int cv_depth = float_format(ext) ? CV_32F : options.bits == 16 ? CV_16U : CV_8U;
  std::vector<unsigned char> bytes;
  detail::write_oiio(name, name, to_file_depth(image, cv_depth), options.smallest,
                     attributes_of(options), &bytes);
  return {bytes.begin(), bytes.end()};
}

}  // namespace ifsfx
