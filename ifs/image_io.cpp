#include "ifs/image_io.h"

#include <unistd.h>
#include <algorithm>
#include <random>
#include <system_error>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"

namespace ifsfx {
namespace fs = std::filesystem;

namespace {

// Prefix of the image description that carries ifsfx's metadata as JSON.
constexpr std::string_view kMetadataTag = "ifsfx metadata: ";

std::string lower_extension(const fs::path& path) {
  std::string ext = path.extension().string();
  for (auto& ch : ext) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return ext;
}

// OpenImageIO wants RGB(A) order; the libraries use OpenCV's BGR(A).
cv::Mat to_rgb_order(const cv::Mat& image) {
  cv::Mat out;
  if (image.channels() == 3)
    cv::cvtColor(image, out, cv::COLOR_BGR2RGB);
  else if (image.channels() == 4)
    cv::cvtColor(image, out, cv::COLOR_BGRA2RGBA);
  else
    out = image;
  return out;
}

cv::Mat to_bgr_order(const cv::Mat& image) {
  cv::Mat out;
  if (image.channels() == 3)
    cv::cvtColor(image, out, cv::COLOR_RGB2BGR);
  else if (image.channels() == 4)
    cv::cvtColor(image, out, cv::COLOR_RGBA2BGRA);
  else
    out = image;
  return out;
}

// The pixels converted to the depth the file will hold.
cv::Mat to_file_depth(const cv::Mat& image, int cv_depth) {
  if (image.depth() == cv_depth) return image;
  double scale = 1;
  const auto full = [](int depth) {
    return depth == CV_8U ? 255.0 : depth == CV_16U ? 65535.0 : 1.0;
  };
  scale = full(cv_depth) / full(image.depth());
  cv::Mat out;
  image.convertTo(out, CV_MAKETYPE(cv_depth, image.channels()), scale);
  return out;
}

}  // namespace

void check_writable_image(const fs::path& path) {
  if (path.empty()) throw Error(ErrorKind::invalid_argument, "output: no file name given");
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) {
    (void)OIIO::geterror();
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: no image writer for extension '{}' (use .png, .tif, .exr, .jpg)",
                            path.string(), path.extension().string()));
  }
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw Error(ErrorKind::io,
                fmt::format("{}: folder '{}' does not exist", path.string(), folder.string()));
  if (::access(folder.c_str(), W_OK) != 0)
    throw Error(ErrorKind::io,
                fmt::format("{}: folder '{}' is not writable", path.string(), folder.string()));
}

void write_image(const fs::path& path, const cv::Mat& image, const WriteOptions& options) {
  check_writable_image(path);
  if (image.empty())
    throw Error(ErrorKind::invalid_argument, fmt::format("{}: empty image", path.string()));
  if (options.bits != 8 && options.bits != 16)
    throw Error(
        ErrorKind::invalid_argument,
        fmt::format("{}: bits per channel must be 8 or 16 (got {})", path.string(), options.bits));

  const std::string ext = lower_extension(path);
  const bool is_float_format = ext == ".exr" || ext == ".hdr";
  const bool can_16 = ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".ppm" ||
                      ext == ".pgm" || ext == ".pnm";
  int cv_depth = CV_8U;
  OIIO::TypeDesc format = OIIO::TypeDesc::UINT8;
  if (is_float_format) {
    cv_depth = CV_32F;
    format = OIIO::TypeDesc::FLOAT;
  } else if (options.bits == 16 && can_16) {
    cv_depth = CV_16U;
    format = OIIO::TypeDesc::UINT16;
  } else if (options.bits == 16) {
    throw Error(
        ErrorKind::unsupported,
        fmt::format("{}: 16 bits per channel needs .png or .tif (got '{}')", path.string(), ext));
  }
  cv::Mat pixels = to_rgb_order(to_file_depth(image, cv_depth));
  if (!pixels.isContinuous()) pixels = pixels.clone();

  OIIO::ImageSpec spec(pixels.cols, pixels.rows, pixels.channels(), format);
  if (pixels.channels() == 4) spec.alpha_channel = 3;
  if (is_float_format) spec.attribute("compression", "zip");
  if (ext == ".png") spec.attribute("png:compressionLevel", options.smallest ? 9 : 1);
  spec.attribute("Software", "ifsfx");
  for (const auto& [key, value] : options.metadata) spec.attribute(key, value);
  // Formats without free-form attributes (TIFF, JPEG) keep only standard tags: carry the whole
  // set as JSON in the image description too, which every format stores.
  if (!options.metadata.empty()) {
    nlohmann::json all = nlohmann::json::object();
    for (const auto& [key, value] : options.metadata) all[key] = value;
    spec.attribute("ImageDescription", std::string(kMetadataTag) + all.dump());
  }

  // Write beside the target and rename: an interrupted write never leaves a half file.
  std::random_device entropy;
  const fs::path temp = path.parent_path() /
                        fmt::format(".{}.{:08x}.tmp{}", path.filename().string(), entropy(), ext);
  auto out = OIIO::ImageOutput::create(path.string());
  bool ok = out && out->open(temp.string(), spec);
  ok = ok && out->write_image(format, pixels.data);
  ok = out && out->close() && ok;
  if (!ok) {
    const std::string why = out ? out->geterror() : OIIO::geterror();
    std::error_code ec;
    fs::remove(temp, ec);
    throw Error(ErrorKind::io, fmt::format("{}: cannot write ({})", path.string(),
                                           why.empty() ? "unknown error" : why));
  }
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) {
    fs::remove(temp, ec);
    throw Error(ErrorKind::io,
                fmt::format("{}: cannot rename into place ({})", path.string(), ec.message()));
  }
}

ImageFile read_image(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw Error(ErrorKind::not_found, fmt::format("{}: no such file", path.string()));
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    const std::string why = OIIO::geterror();
    throw Error(ErrorKind::io, fmt::format("{}: cannot read as an image ({})", path.string(),
                                           why.empty() ? "unknown format" : why));
  }
  const OIIO::ImageSpec& spec = in->spec();
  const int channels = std::min(spec.nchannels, 4);
  int cv_depth = CV_32F;
  OIIO::TypeDesc format = OIIO::TypeDesc::FLOAT;
  if (spec.format == OIIO::TypeDesc::UINT8) {
    cv_depth = CV_8U;
    format = OIIO::TypeDesc::UINT8;
  } else if (spec.format == OIIO::TypeDesc::UINT16) {
    cv_depth = CV_16U;
    format = OIIO::TypeDesc::UINT16;
  }
  // Two channels are grey + alpha: read the grey one only.
  const int keep = channels == 2 ? 1 : channels;
  cv::Mat pixels(spec.height, spec.width, CV_MAKETYPE(cv_depth, keep));
  const bool ok = in->read_image(0, 0, 0, keep, format, pixels.data);
  if (!ok) {
    const std::string why = in->geterror();
    throw Error(ErrorKind::io,
                fmt::format("{}: corrupt or truncated image ({})", path.string(), why));
  }
  ImageFile file;
  file.pixels = to_bgr_order(pixels);
  std::string description;
  for (const auto& attr : spec.extra_attribs) {
    if (attr.type() != OIIO::TypeDesc::STRING) continue;
    if (attr.name() == "ImageDescription") description = attr.get_string();
    file.metadata.emplace_back(attr.name().string(), attr.get_string());
  }
  if (description.starts_with(kMetadataTag)) {
    const auto all = nlohmann::json::parse(description.substr(kMetadataTag.size()), nullptr, false);
    if (all.is_object())
      for (const auto& [key, value] : all.items()) {
        if (!value.is_string()) continue;
        const bool known = std::any_of(file.metadata.begin(), file.metadata.end(),
                                       [&](const auto& kv) { return kv.first == key; });
        if (!known) file.metadata.emplace_back(key, value.get<std::string>());
      }
  }
  return file;
}

}  // namespace ifsfx
