// Still images through OpenImageIO. Images in the libraries are cv::Mat in OpenCV's channel order
// (BGR, BGRA, or one grey channel) of depth CV_8U, CV_16U or CV_32F (floats in [0, 1]).
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace ifsfx {

struct WriteOptions {
  // Bits per channel of integer formats: 8 or 16 (PNG, TIFF); ignored for OpenEXR (half float).
  int bits = 8;
  // PNG: zlib level 9, the smallest files, instead of level 1, the fastest to write (about a
  // fifth larger than level 6 for a stolen photo; bench/README.md).
  bool smallest = false;
  // String attributes stored in the image's metadata, e.g. {"ifsfx:preset", <preset text>}.
  std::vector<std::pair<std::string, std::string>> metadata;
};

// Writes `image` to `path`, the format chosen by extension (.png, .tif/.tiff, .exr, .jpg, and
// whatever else OpenImageIO writes). The file appears atomically: it is written to a temporary
// name in the target folder and renamed, so an interrupted write never leaves a half file.
// Throws Error{unsupported} for an unknown extension and Error{io} naming the path otherwise.
void write_image(const std::filesystem::path& path, const cv::Mat& image,
                 const WriteOptions& options = {});

// Throws Error{unsupported} if no writer handles `path`'s extension, and Error{io} if its folder
// is not writable — the checks write_image makes, for use before long work.
void check_writable_image(const std::filesystem::path& path);

struct ImageFile {
  cv::Mat pixels;  // BGR/BGRA/grey, CV_8U, CV_16U or CV_32F as stored (other depths to CV_32F)
  std::vector<std::pair<std::string, std::string>> metadata;  // string attributes
};

// Reads any image OpenImageIO reads. Throws Error{not_found} or Error{io} naming the path.
ImageFile read_image(const std::filesystem::path& path);

}  // namespace ifsfx
