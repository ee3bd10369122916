// SPDX-License-Identifier: Apache-2.0
#include "video/image_sequence.h"

#include <algorithm>
#include <system_error>
#include <vector>

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

bool is_file(const std::filesystem::path& p) {
  std::error_code ec;
  return std::filesystem::is_regular_file(p, ec);
}

// The numbers from `first` up that name a file of `pattern`, ascending. The folder is listed when
// the number is in the file name, so that files past a gap are found; a number in a folder name
// is followed file by file up to the first one missing.
std::vector<std::int64_t> sequence_numbers(const std::string& pattern, std::int64_t first) {
  const Pattern p = *find_number(pattern);
  const std::string head = pattern.substr(0, p.at);
  const std::string tail = pattern.substr(p.end);
  std::vector<std::int64_t> numbers;
  const auto slash = head.find_last_of('/');
  if (tail.find('/') != std::string::npos) {
    for (std::int64_t n = first; is_file(sequence_path(pattern, n)); ++n) numbers.push_back(n);
    return numbers;
  }
  const std::filesystem::path folder = slash == std::string::npos
                                           ? std::filesystem::path(".")
                                           : std::filesystem::path(head.substr(0, slash + 1));
  const std::string stem = slash == std::string::npos ? head : head.substr(slash + 1);
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name.size() <= stem.size() + tail.size() || !name.starts_with(stem) ||
        !name.ends_with(tail))
      continue;
    const std::string digits = name.substr(stem.size(), name.size() - stem.size() - tail.size());
    if (digits.size() > 18 ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
      continue;
    const std::int64_t n = std::stoll(digits);
    // Only the exact spelling the pattern gives (frame_0007, not frame_007 or frame_00007).
    if (n >= first && sequence_path(pattern, n).filename() == name && is_file(entry.path()))
      numbers.push_back(n);
  }
  std::sort(numbers.begin(), numbers.end());
  return numbers;
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
    : pattern_(pattern), fps_(options.fps), rate_(rate_from_fps(options.fps)) {
  if (!rate_.positive())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frame rate must be positive (got {})", pattern, options.fps));
  std::int64_t first = -1;
  for (std::int64_t i = 0; i <= 4 && first < 0; ++i)
    if (is_file(sequence_path(pattern, i))) first = i;
  if (first < 0)
    throw Error(ErrorKind::not_found, fmt::format("{}: no frame found (looked for {} to {})",
                                                  pattern, sequence_path(pattern, 0).string(),
                                                  sequence_path(pattern, 4).string()));
  numbers_ = sequence_numbers(pattern, first);
  // A gap is a lost file far more often than an intended one: say which, unless told to go on.
  if (!options.skip_gaps) {
    std::int64_t missing = 0;
    std::int64_t first_missing = -1;
    for (std::size_t i = 1; i < numbers_.size(); ++i) {
      const std::int64_t gap = numbers_[i] - numbers_[i - 1] - 1;
      if (gap > 0 && first_missing < 0) first_missing = numbers_[i - 1] + 1;
      missing += gap;
    }
    if (missing > 0)
      throw Error(
          ErrorKind::not_found,
          fmt::format("{}: missing from the sequence {} ({} missing between {} and {}; "
                      "skip_gaps goes on without {})",
                      sequence_path(pattern, first_missing).string(), pattern,
                      missing == 1 ? std::string("1 file") : fmt::format("{} files", missing),
                      sequence_path(pattern, numbers_.front()).filename().string(),
                      sequence_path(pattern, numbers_.back()).filename().string(),
                      missing == 1 ? "it" : "them"));
  }
  size_ = read_image(sequence_path(pattern, first)).pixels.size();
}

std::optional<Frame> ImageSequenceSource::read() {
  if (next_ >= numbers_.size()) return std::nullopt;
  const std::int64_t number = numbers_[next_];
  const auto path = sequence_path(pattern_, number);
  Frame frame;
  frame.image = to_bgr8(read_image(path).pixels);
  if (frame.image.size() != size_)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: frame is {}x{}, the sequence started at {}x{}", path.string(),
                            frame.image.cols, frame.image.rows, size_.width, size_.height));
  frame.index = static_cast<std::int64_t>(next_);
  // File N is shown at (N − first)/fps and until the next file's time: over a skipped gap too.
  frame.time_base = time_base();
  frame.pts = number - numbers_.front();
  frame.duration = next_ + 1 < numbers_.size() ? numbers_[next_ + 1] - number : 1;
  frame.timestamp = static_cast<double>(frame.pts) * rate_.den / rate_.num;
  ++next_;
  return frame;
}

bool ImageSequenceSource::skip() {
  if (next_ >= numbers_.size()) return false;
  ++next_;
  return true;
}

std::vector<std::filesystem::path> ImageSequenceSource::files() const {
  std::vector<std::filesystem::path> out;
  for (const std::int64_t number : numbers_) out.push_back(sequence_path(pattern_, number));
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
  commit_together(staged_);
  staged_.clear();
}

std::filesystem::path ImageSequenceSink::abandon() noexcept {
  staged_.clear();  // each removes its temporary file
  return {};
}

}  // namespace ifsfx::video
