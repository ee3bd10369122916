#include "video/image_sequence.h"

#include <system_error>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/image_io.h"

namespace ifsfx::video {

namespace {

struct Pattern {
  std::size_t at = 0;   // position of '%'
  std::size_t end = 0;  // one past the 'd'
  int width = 0;        // zero-padded width, 0 for plain %d
};

std::optional<Pattern> find_number(const std::string& text) {
  const std::size_t at = text.find('%');
  if (at == std::string::npos) return std::nullopt;
  Pattern p;
  p.at = at;
  std::size_t i = at + 1;
  if (i < text.size() && text[i] == '0') {
    ++i;
    if (i >= text.size() || text[i] < '1' || text[i] > '9') return std::nullopt;
    p.width = text[i] - '0';
    ++i;
  }
  if (i >= text.size() || text[i] != 'd') return std::nullopt;
  p.end = i + 1;
  if (text.find('%', p.end) != std::string::npos) return std::nullopt;
  return p;
}

cv::Mat to_bgr8(const cv::Mat& image) {
  cv::Mat eight;
  switch (image.depth()) {
    case CV_8U:
      eight = image;
      break;
    case CV_16U:
      image.convertTo(eight, CV_8U, 1.0 / 257);
      break;
    default:
      image.convertTo(eight, CV_8U, 255);
      break;
  }
  cv::Mat bgr;
  switch (eight.channels()) {
    case 1:
      cv::cvtColor(eight, bgr, cv::COLOR_GRAY2BGR);
      break;
    case 4:
      cv::cvtColor(eight, bgr, cv::COLOR_BGRA2BGR);
      break;
    case 3:
      bgr = eight;
      break;
    default:
      throw Error(
          ErrorKind::unsupported,
          fmt::format("image sequence: {} channels are not a colour image", eight.channels()));
  }
  return bgr;
}

bool is_file(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::is_regular_file(p, ec);
}

}  // namespace

bool is_sequence_pattern(const std::string& path) {
  return find_number(path).has_value();
}

void check_output_name(const std::string& name, const std::string& what) {
  if (name.find('%') != std::string::npos && !find_number(name))
    throw Error(ErrorKind::parse,
                fmt::format("{}: an image sequence pattern holds one %d or %0Nd with N 1..9 and no "
                            "other '%' (got '{}')",
                            what, name));
}

std::filesystem::path sequence_path(const std::string& pattern, std::int64_t index) {
  const auto p = find_number(pattern);
  if (!p)
    throw Error(
        ErrorKind::parse,
        fmt::format("{}: an image sequence needs one %d or %0Nd and no other '%'", pattern));
  return pattern.substr(0, p->at) + fmt::format("{:0{}d}", index, p->width) +
         pattern.substr(p->end);
}

ImageSequenceSource::ImageSequenceSource(const std::string& pattern,
                                         const ImageSequenceOptions& options)
    : pattern_(pattern), fps_(options.fps) {
  if (!(options.fps > 0))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frame rate must be positive (got {})", pattern, options.fps));
  first_ = -1;
  for (std::int64_t i = 0; i <= 4 && first_ < 0; ++i)
    if (is_file(sequence_path(pattern, i))) first_ = i;
  if (first_ < 0)
    throw Error(ErrorKind::not_found, fmt::format("{}: no frame found (looked for {} to {})",
                                                  pattern, sequence_path(pattern, 0).string(),
                                                  sequence_path(pattern, 4).string()));
  while (is_file(sequence_path(pattern, first_ + count_))) ++count_;
  size_ = read_image(sequence_path(pattern, first_)).pixels.size();
}

std::optional<Frame> ImageSequenceSource::read() {
  if (next_ >= count_) return std::nullopt;
  const auto path = sequence_path(pattern_, first_ + next_);
  Frame frame;
  frame.image = to_bgr8(read_image(path).pixels);
  if (frame.image.size() != size_)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: frame is {}x{}, the sequence started at {}x{}", path.string(),
                            frame.image.cols, frame.image.rows, size_.width, size_.height));
  frame.index = next_;
  frame.timestamp = static_cast<double>(next_) / fps_;
  ++next_;
  return frame;
}

bool ImageSequenceSource::skip() {
  if (next_ >= count_) return false;
  ++next_;
  return true;
}

std::vector<std::filesystem::path> ImageSequenceSource::files() const {
  std::vector<std::filesystem::path> out;
  for (std::int64_t i = 0; i < count_; ++i) out.push_back(sequence_path(pattern_, first_ + i));
  return out;
}

ImageSequenceSink::ImageSequenceSink(const std::string& pattern,
                                     const ImageSequenceSinkOptions& options)
    : pattern_(pattern), options_(options) {
  check_writable_image(sequence_path(pattern, options.first), options.output);
  for (std::int64_t k = 1; k < options.expected; ++k)
    check_output(sequence_path(pattern, options.first + k), options.output);
}

void ImageSequenceSink::write(const Frame& frame) {
  OutputFile file(
      sequence_path(pattern_, options_.first + static_cast<std::int64_t>(staged_.size())),
      options_.output);
  write_image(file, frame.image);
  staged_.push_back(std::move(file));
}

void ImageSequenceSink::close() {
  for (OutputFile& file : staged_) file.commit();
  staged_.clear();
}

std::filesystem::path ImageSequenceSink::abandon() noexcept {
  staged_.clear();  // each removes its temporary file
  return {};
}

}  // namespace ifsfx::video
