#include "ifs/image_io.h"

#include <algorithm>
#include <fstream>
#include <system_error>

#include <OpenImageIO/imageio.h>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/utf8.h"

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

bool float_format(const std::string& ext) {
  return ext == ".exr" || ext == ".hdr";
}

// Bits per channel: 8 or 16, and 16 only where the format holds it (floats ignore it).
void check_bits(const fs::path& path, int bits) {
  if (bits != 8 && bits != 16)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: bits per channel must be 8 or 16 (got {})", path.string(), bits));
  const std::string ext = lower_extension(path);
  const bool can_16 = ext == ".png" || ext == ".tif" || ext == ".tiff" || ext == ".ppm" ||
                      ext == ".pgm" || ext == ".pnm";
  if (bits == 16 && !can_16 && !float_format(ext))
    throw Error(
        ErrorKind::unsupported,
        fmt::format("{}: 16 bits per channel needs .png or .tif (got '{}')", path.string(), ext));
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

// Colour divided by alpha where alpha > 0 (associated → straight), in place of depth kept.
void unpremultiply(cv::Mat& image) {
  const double full = image.depth() == CV_8U ? 255.0 : image.depth() == CV_16U ? 65535.0 : 1.0;
  cv::Mat f;
  image.convertTo(f, CV_32F, 1.0 / full);
  for (int r = 0; r < f.rows; ++r) {
    auto* px = f.ptr<cv::Vec4f>(r);
    for (int c = 0; c < f.cols; ++c)
      if (px[c][3] > 0)
        for (int k = 0; k < 3; ++k) px[c][k] = std::min(1.0f, px[c][k] / px[c][3]);
  }
  f.convertTo(image, image.depth(), full);
}

// Colour multiplied by alpha (straight → associated), for formats that store it so (OpenEXR).
cv::Mat premultiplied(const cv::Mat& image) {
  cv::Mat out = image.clone();
  for (int r = 0; r < out.rows; ++r) {
    auto* px = out.ptr<cv::Vec4f>(r);
    for (int c = 0; c < out.cols; ++c)
      for (int k = 0; k < 3; ++k) px[c][k] *= px[c][3];
  }
  return out;
}

// One line of a reader's message (OpenImageIO joins several with newlines and may end one with
// the file's name, which the caller's message starts with already).
std::string one_line(std::string text, const fs::path& path) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  const std::string named = fmt::format(" (\"{}\")", path.string());
  if (text.ends_with(named)) text.resize(text.size() - named.size());
  for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at))
    text.replace(at, 1, "; ");
  return text;
}

// A PNG is a signature and chunks up to IEND: one that ends early is cut short. Checked before
// libpng sees it, which would print its own complaint on stderr. Empty when complete (or not a
// PNG).
std::string png_truncation(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char head[8];
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!in.read(reinterpret_cast<char*>(head), 8) || !std::equal(head, head + 8, kSignature))
    return {};
  std::error_code ec;
  const auto size = static_cast<std::uintmax_t>(fs::file_size(path, ec));
  std::uintmax_t at = 8;
  for (;;) {
    unsigned char chunk[8];
    if (!in.read(reinterpret_cast<char*>(chunk), 8))
      return fmt::format("cut short: {} bytes, ending before its IEND chunk", size);
    const std::uintmax_t length =
        (std::uintmax_t{chunk[0]} << 24) | (chunk[1] << 16) | (chunk[2] << 8) | chunk[3];
    const std::string type(reinterpret_cast<const char*>(chunk + 4), 4);
    const std::uintmax_t end = at + 12 + length;  // length, type, data, CRC
    if (end > size)
      return fmt::format("cut short: {} bytes, ending inside its {} chunk", size, type);
    if (type == "IEND") return {};
    at = end;
    in.seekg(static_cast<std::streamoff>(at));
  }
}

// A reader's complaint that does not touch the picture: JPEG data after the end of the image.
bool harmless(const std::string& why) {
  return why.find("extraneous bytes before marker") != std::string::npos;
}

}  // namespace

void check_writable_image(const fs::path& path, const OutputOptions& output, int bits) {
  if (path.empty()) throw Error(ErrorKind::invalid_argument, "output: no file name given");
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out) {
    (void)OIIO::geterror();
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: no image writer for extension '{}' (use .png, .tif, .exr, .jpg)",
                            path.string(), path.extension().string()));
  }
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

  const std::string ext = lower_extension(path);
  const bool is_float_format = float_format(ext);
  int cv_depth = CV_8U;
  OIIO::TypeDesc format = OIIO::TypeDesc::UINT8;
  if (is_float_format) {
    cv_depth = CV_32F;
    format = OIIO::TypeDesc::FLOAT;
  } else if (options.bits == 16) {
    cv_depth = CV_16U;
    format = OIIO::TypeDesc::UINT16;
  }
  cv::Mat pixels = to_rgb_order(to_file_depth(image, cv_depth));
  if (!pixels.isContinuous()) pixels = pixels.clone();

  // The libraries' alpha is straight (colour not multiplied by it): say so to formats that store
  // it straight (PNG, TIFF), so nothing divides the colour again; OpenEXR stores it multiplied.
  if (pixels.channels() == 4 && is_float_format) pixels = premultiplied(pixels);
  OIIO::ImageSpec spec(pixels.cols, pixels.rows, pixels.channels(), format);
  if (pixels.channels() == 4) {
    spec.alpha_channel = 3;
    if (!is_float_format) spec.attribute("oiio:UnassociatedAlpha", 1);
  }
  if (is_float_format) spec.attribute("compression", "zip");
  if (ext == ".png") {
    spec.attribute("png:compressionLevel", options.smallest ? 9 : 1);
    // The fastest write also filters every row by its left neighbour alone (libpng's
    // PNG_FILTER_SUB) instead of trying the five filters per row: half the time of a 1080p
    // write; files 1 % (fern) to 8 % (Sierpinski) larger for 1080p measure renders, 11 % for a
    // frame-filling stolen photo.
    constexpr int kPngFilterSub = 0x10;
    if (!options.smallest) spec.attribute("png:filter", kPngFilterSub);
  }
  spec.attribute("Software", "ifsfx");
  // Metadata is made valid UTF-8 first: a Latin-1 comment or file name must not fail the run.
  std::vector<std::pair<std::string, std::string>> metadata;
  for (const auto& [key, value] : options.metadata)
    metadata.emplace_back(valid_utf8(key), valid_utf8(value));
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  // Formats without free-form attributes (TIFF, JPEG) keep only standard tags: carry the whole
  // set as JSON in the image description too, which every format stores.
  if (!metadata.empty()) {
    nlohmann::json all = nlohmann::json::object();
    for (const auto& [key, value] : metadata) all[key] = value;
    spec.attribute("ImageDescription", std::string(kMetadataTag) + all.dump());
  }

  // The format is the target's; the bytes go to the output's temporary file.
  auto out = OIIO::ImageOutput::create(path.string());
  bool ok = out && out->open(file.temporary().string(), spec);
  ok = ok && out->write_image(format, pixels.data);
  ok = out && out->close() && ok;
  if (!ok) {
    const std::string why = out ? out->geterror() : OIIO::geterror();
    throw Error(ErrorKind::io, fmt::format("{}: cannot write ({})", path.string(),
                                           why.empty() ? "unknown error" : why));
  }
}

ImageFile read_image(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec))
    throw Error(ErrorKind::not_found, fmt::format("{}: no such file", path.string()));
  if (const std::string cut = png_truncation(path); !cut.empty())
    throw Error(ErrorKind::io,
                fmt::format("{}: corrupt or truncated image ({})", path.string(), cut));
  // Straight alpha where the file stores it so (PNG, TIFF): OpenImageIO would otherwise multiply
  // the colour by alpha, and a half-transparent red would come out dark red.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in) {
    const std::string why = one_line(OIIO::geterror(), path);
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
  // A reader may fill what it could not decode (libjpeg paints the rest of a cut JPEG grey) and
  // still succeed, leaving only a message behind: that is a damaged file too.
  const std::string why = one_line(in->geterror(), path);
  if (!ok || (!why.empty() && !harmless(why)))
    throw Error(ErrorKind::io, fmt::format("{}: corrupt or truncated image ({})", path.string(),
                                           why.empty() ? "unknown error" : why));
  if (keep == 4 && spec.get_int_attribute("oiio:UnassociatedAlpha", 0) == 0)
    unpremultiply(pixels);  // OpenEXR and associated TIFF: colour back to straight
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
      for (const auto& item : all.items()) {
        if (!item.value().is_string()) continue;
        const std::string& key = item.key();
        const bool known = std::any_of(file.metadata.begin(), file.metadata.end(),
                                       [&](const auto& kv) { return kv.first == key; });
        if (!known) file.metadata.emplace_back(key, item.value().get<std::string>());
      }
  }
  return file;
}

}  // namespace ifsfx
