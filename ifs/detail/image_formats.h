// SPDX-License-Identifier: Apache-2.0
// The image writers behind ifs/image_io.h, for image_io.cpp only. The libraries write every
// format through OpenImageIO (image_io_oiio.cpp). The light `ifsfx`, which runs `render` to PNG
// without loading OpenImageIO (its 260 shared libraries cost more start-up than a small render:
// bench/README.md, "Start-up"), links image_io_without_oiio.cpp in its place, whose write_oiio
// writes PNG through libpng (png_writer.cpp): the same pixels and text attributes.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace ifsfx::detail {

// Prefix of the image description that carries ifsfx's metadata as JSON (formats without
// free-form attributes, TIFF and JPEG, keep it; read_image takes the attributes back from it).
inline constexpr std::string_view kMetadataTag = "ifsfx metadata: ";

// `path`'s extension in lower case, with its dot (".png"): what picks the format.
std::string lower_extension(const std::filesystem::path& path);

// String attributes in the order they are stored: "Software", the caller's metadata (valid
// UTF-8), and "ImageDescription" with all of them as JSON.
using ImageAttributes = std::vector<std::pair<std::string, std::string>>;

// `pixels` (grey, BGR or BGRA with straight alpha, CV_8U or CV_16U) as a PNG in `file`, which
// `target` names in messages: zlib level 9 and libpng's filter choice per row with `smallest`,
// else level 1 and the sub filter. Attributes are text chunks (tEXt, iTXt where not ASCII);
// "ImageDescription" is PNG's "Description", as OpenImageIO names it. Throws Error{io}
// "TARGET: cannot write (REASON)".
void write_png(const std::filesystem::path& target, const std::filesystem::path& file,
               const cv::Mat& pixels, bool smallest, const ImageAttributes& attributes);

// Whether OpenImageIO has a writer for `path`'s extension.
bool oiio_can_write(const std::filesystem::path& path);

// `pixels` (BGR order, the depth the file holds: CV_8U, CV_16U or CV_32F) written by OpenImageIO
// to `file` in the format of `target`'s extension — or, with `memory`, into it instead, the bytes
// the file would hold; `smallest` as write_png's for PNG. Throws Error{io} "TARGET: cannot write
// (...)".
void write_oiio(const std::filesystem::path& target, const std::filesystem::path& file,
                const cv::Mat& pixels, bool smallest, const ImageAttributes& attributes,
                std::vector<unsigned char>* memory = nullptr);

}  // namespace ifsfx::detail
