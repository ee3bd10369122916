// SPDX-License-Identifier: Apache-2.0
// OpenImageIO's side of ifs/image_io.h: reading and writing every format
// (ifs/detail/image_formats.h).
#include <algorithm>
#include <fstream>
#include <optional>
#include <string_view>
#include <system_error>

// fmt before OpenImageIO: OpenImageIO's headers ask for fmt header-only, which would define fmt's
// tables in this object too, and a binary that needs them from libfmt (the light ifsfx) would
// then pull this object, and OpenImageIO with it, out of libifsfx_ifs.a.
#include <fmt/format.h>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>

#include "ifs/detail/image_formats.h"
#include "ifs/error.h"
#include "ifs/image_io.h"

namespace ifsfx {
namespace fs = std::filesystem;

namespace {

// OpenImageIO wants RGB(A) order; the libraries use OpenCV's BGR(A). Swapping red and blue goes
// either way.
cv::Mat swap_red_blue(const cv::Mat& image) {
  cv::Mat out;
  if (image.channels() == 3)
    cv::cvtColor(image, out, cv::COLOR_BGR2RGB);
  else if (image.channels() == 4)
    cv::cvtColor(image, out, cv::COLOR_BGRA2RGBA);
  else
    out = image;
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

namespace detail {

bool oiio_can_write(const fs::path& path) {
  const bool can = OIIO::ImageOutput::create(path.string()) != nullptr;
  if (!can) (void)OIIO::geterror();  // clears the message OpenImageIO keeps for the thread
  return can;
}

void write_oiio(const fs::path& target, const fs::path& file, const cv::Mat& image, bool smallest,
                const ImageAttributes& attributes, std::vector<unsigned char>* memory) {
  const bool is_float = image.depth() == CV_32F;
  const OIIO::TypeDesc format = is_float                  ? OIIO::TypeDesc::FLOAT
                                : image.depth() == CV_16U ? OIIO::TypeDesc::UINT16
                                                          : OIIO::TypeDesc::UINT8;
  cv::Mat pixels = swap_red_blue(image);
  if (!pixels.isContinuous()) pixels = pixels.clone();
  // The libraries' alpha is straight (colour not multiplied by it): say so to formats that store
  // it straight (TIFF), so nothing divides the colour again; OpenEXR stores it multiplied.
  if (pixels.channels() == 4 && is_float) pixels = premultiplied(pixels);
  OIIO::ImageSpec spec(pixels.cols, pixels.rows, pixels.channels(), format);
  if (pixels.channels() == 4) {
    spec.alpha_channel = 3;
    if (!is_float) spec.attribute("oiio:UnassociatedAlpha", 1);
  }
  if (is_float) spec.attribute("compression", "zip");
  for (const auto& [key, value] : attributes) spec.attribute(key, value);

  // The format is the target's; the bytes go to the output's temporary file.
  auto out = OIIO::ImageOutput::create(target.string());
  if (out && std::string_view(out->format_name()) == "png") {
    spec.attribute("png:compressionLevel", smallest ? 9 : 1);
    // The fastest write also filters every row by its left neighbour alone (libpng's
    // PNG_FILTER_SUB) instead of trying the five filters per row: half the time of a 1080p
    // write; files 1 % (fern) to 8 % (Sierpinski) larger for 1080p measure renders, 11 % for a
    // frame-filling stolen photo. png_writer.cpp makes the same choice.
    constexpr int kPngFilterSub = 0x10;
    if (!smallest) spec.attribute("png:filter", kPngFilterSub);
  }
  // In memory: the same writer and spec through an I/O proxy, so the same bytes as the file.
  std::optional<OIIO::Filesystem::IOVecOutput> proxy;
  if (memory != nullptr) proxy.emplace(*memory);
  bool ok = out && (!proxy || out->set_ioproxy(&*proxy));
  ok = ok && out->open(proxy ? target.string() : file.string(), spec);
  ok = ok && out->write_image(format, pixels.data);
  ok = out && out->close() && ok;
  if (!ok) {
    const std::string why = out ? out->geterror() : OIIO::geterror();
    throw Error(ErrorKind::io, fmt::format("{}: cannot write ({})", target.string(),
                                           why.empty() ? "unknown error" : why));
  }
}

}  // namespace detail

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
  file.pixels = swap_red_blue(pixels);
  std::string description;
  for (const auto& attr : spec.extra_attribs) {
    if (attr.type() != OIIO::TypeDesc::STRING) continue;
    if (attr.name() == "ImageDescription") description = attr.get_string();
    file.metadata.emplace_back(attr.name().string(), attr.get_string());
  }
  if (description.starts_with(detail::kMetadataTag)) {
    const auto all =
        nlohmann::json::parse(description.substr(detail::kMetadataTag.size()), nullptr, false);
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
