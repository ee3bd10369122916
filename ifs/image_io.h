// SPDX-License-Identifier: Apache-2.0
// Still images, read and written through OpenImageIO (the light `ifsfx` binary writes its PNG
// through libpng instead: ifs/detail/image_formats.h says why). Images in the libraries are cv::Mat
// in OpenCV's channel order (BGR, BGRA, or one grey channel) of depth CV_8U, CV_16U or CV_32F
// (floats in [0, 1]). Alpha is straight: the colour of a half-transparent pixel is its full colour,
// not multiplied by alpha.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "ifs/output_file.h"

namespace ifsfx {

struct WriteOptions {
  // Bits per channel of integer formats: 8 or 16 (PNG, TIFF); ignored for OpenEXR (half float).
  int bits = 8;
  // PNG: zlib level 9 and libpng's choice of filter per row, the smallest files, instead of
  // level 1 and the "sub" filter, the fastest to write (bench/README.md).
  bool smallest = false;
  // String attributes stored in the image's metadata, e.g. {"ifsfx:preset", <preset text>}.
  // Bytes that are not UTF-8 are read as Latin-1 (valid_utf8): metadata never fails a write.
  std::vector<std::pair<std::string, std::string>> metadata;
  // The output policy: inputs refused as the output, the stop request (ifs/output_file.h).
  OutputOptions output;
};

// Writes `image` to `path`, the format chosen by extension (.png, .tif/.tiff, .exr, .jpg, and
// whatever else OpenImageIO writes), through the output policy (OutputFile): written to a fresh
// temporary file beside the target and renamed over it only once complete. Throws
// Error{unsupported} for an unknown extension, what OutputFile throws, and Error{io} naming the
// path otherwise.
void write_image(const std::filesystem::path& path, const cv::Mat& image,
                 const WriteOptions& options = {});
// Writes `image` into the temporary file of `out` (the format by out.target()'s extension)
// without committing it: for files that must appear together (an image sequence). options.output
// is not used (the OutputFile has its own).
void write_image(OutputFile& out, const cv::Mat& image, const WriteOptions& options = {});

// The bytes write_image would put in a file named with `extension` (".png", ".jpg", ...), for a
// caller that sends them elsewhere (an HTTP response): the same encoder, conversion, options and
// metadata, so the same bytes; no file is touched. Throws Error{unsupported} or Error{io} as
// write_image does.
std::string encode_image(const cv::Mat& image, const std::string& extension,
                         const WriteOptions& options = {});

// Throws Error{unsupported} if no writer handles `path`'s extension or it cannot hold `bits` per
// channel, Error{invalid_argument} for bits other than 8 or 16, and what check_output throws — the
// checks write_image makes, for use before long work.
void check_writable_image(const std::filesystem::path& path, const OutputOptions& output = {},
                          int bits = 8);

struct ImageFile {
  cv::Mat pixels;  // BGR/BGRA/grey, CV_8U, CV_16U or CV_32F as stored (other depths to CV_32F)
  std::vector<std::pair<std::string, std::string>> metadata;  // string attributes
};

// Reads any image OpenImageIO reads, alpha straight whatever the file stores. Throws
// Error{not_found} or Error{io} naming the path — Error{io} "corrupt or truncated image" also for
// a file the reader could only partly decode (a JPEG or PNG cut short), never a half-grey picture.
ImageFile read_image(const std::filesystem::path& path);

}  // namespace ifsfx
