// SPDX-License-Identifier: Apache-2.0
#include "engine/palette.h"

#include <algorithm>
#include <array>
#include <cstdint>

#include <fmt/format.h>

#include "ifs/error.h"

namespace ifsfx::engine {

namespace {

constexpr int kColours = 256;
constexpr int kBits = 5;  // histogram bins per channel: 32, so 32768 in all
constexpr int kBins = 1 << (3 * kBits);
// Ordered dithering spreads a pixel over palette entries this many levels apart (of 255): about
// the spacing of a 256-colour palette over a photograph's colours.
constexpr double kDither = 12;

std::uint32_t key_of(const cv::Vec3b& c) {
  return (static_cast<std::uint32_t>(c[0]) << 16) | (static_cast<std::uint32_t>(c[1]) << 8) | c[2];
}

int bin_of(int b, int g, int r) {
  return ((b >> (8 - kBits)) << (2 * kBits)) | ((g >> (8 - kBits)) << kBits) | (r >> (8 - kBits));
}

// The image's own colours, in increasing order of key, when there are no more than 256.
bool own_colours(const cv::Mat& bgr, std::vector<std::uint32_t>& keys) {
  std::vector<std::uint64_t> seen(std::size_t{1} << 18, 0);  // one bit per 24-bit colour
  for (int r = 0; r < bgr.rows; ++r) {
    const auto* p = bgr.ptr<cv::Vec3b>(r);
    for (int c = 0; c < bgr.cols; ++c) {
      const std::uint32_t k = key_of(p[c]);
      std::uint64_t& word = seen[k >> 6];
      const std::uint64_t bit = std::uint64_t{1} << (k & 63);
      if (word & bit) continue;
      word |= bit;
      keys.push_back(k);
      if (keys.size() > kColours) return false;
    }
  }
  std::sort(keys.begin(), keys.end());
  return true;
}

IndexedImage exact_image(const cv::Mat& bgr, const std::vector<std::uint32_t>& keys) {
  IndexedImage out;
  out.exact = true;
  for (const std::uint32_t k : keys)
    out.palette.emplace_back(static_cast<uchar>(k >> 16), static_cast<uchar>(k >> 8),
                             static_cast<uchar>(k));
  out.indices.create(bgr.size(), CV_8UC1);
  for (int r = 0; r < bgr.rows; ++r) {
    const auto* p = bgr.ptr<cv::Vec3b>(r);
    auto* q = out.indices.ptr<std::uint8_t>(r);
    for (int c = 0; c < bgr.cols; ++c)
      q[c] = static_cast<std::uint8_t>(std::lower_bound(keys.begin(), keys.end(), key_of(p[c])) -
                                       keys.begin());
  }
  return out;
}

// A histogram cell: its bin's coordinates (5 bits a channel), population and colour sums, and
// whether all its pixels have one colour (`key`).
struct Cell {
  std::array<int, 3> at;
  std::uint64_t count = 0;
  std::array<std::uint64_t, 3> sum{};
  std::uint32_t key = 0;
  bool mixed = false;
};

// A colour covering this share of the picture or more (a texture's black background, a flat
// area) gets a palette entry of its own, exactly.
constexpr double kReservedShare = 0.01;
constexpr std::size_t kMaxReserved = 32;

// Cells [begin, end) of a median-cut box.
struct Box {
  std::size_t begin = 0, end = 0;
  std::uint64_t count = 0;
  int widest = 0;  // the channel of the longest side
  int length = 0;  // that side's length, in bins
};

Box make_box(const std::vector<Cell>& cells, std::size_t begin, std::size_t end) {
  Box b{begin, end, 0, 0, 0};
  std::array<int, 3> lo{99, 99, 99}, hi{-1, -1, -1};
  for (std::size_t i = begin; i < end; ++i) {
    b.count += cells[i].count;
    for (int ch = 0; ch < 3; ++ch) {
      lo[ch] = std::min(lo[ch], cells[i].at[ch]);
      hi[ch] = std::max(hi[ch], cells[i].at[ch]);
    }
  }
  for (int ch = 0; ch < 3; ++ch)
    if (hi[ch] - lo[ch] > b.length) b.length = hi[ch] - lo[ch], b.widest = ch;
  return b;
}

// The palette: the picture's frequent single colours exactly (kReservedShare), then Heckbert's
// median cut of the rest over the 5-bit histogram — the box with the most pixels times its
// longest side is cut across that side where half its pixels lie — until there are 256 entries.
// `reserved` gets, per histogram bin, the entry of its exact colour (−1: none).
std::vector<cv::Vec3b> make_palette(const cv::Mat& bgr, std::vector<int>& reserved) {
  std::vector<Cell> histogram(kBins);
  for (int r = 0; r < bgr.rows; ++r) {
    const auto* p = bgr.ptr<cv::Vec3b>(r);
    for (int c = 0; c < bgr.cols; ++c) {
      Cell& cell = histogram[static_cast<std::size_t>(bin_of(p[c][0], p[c][1], p[c][2]))];
      const std::uint32_t k = key_of(p[c]);
      if (cell.count == 0) cell.key = k;
      cell.mixed = cell.mixed || cell.key != k;
      ++cell.count;
      for (int ch = 0; ch < 3; ++ch) cell.sum[ch] += p[c][ch];
    }
  }
  const auto total = static_cast<double>(bgr.total());
  std::vector<int> frequent;
  for (int i = 0; i < kBins; ++i) {
    const Cell& cell = histogram[static_cast<std::size_t>(i)];
    if (!cell.mixed && static_cast<double>(cell.count) >= kReservedShare * total)
      frequent.push_back(i);
  }
  std::stable_sort(frequent.begin(), frequent.end(), [&](int a, int b) {
    return histogram[static_cast<std::size_t>(a)].count >
           histogram[static_cast<std::size_t>(b)].count;
  });
  if (frequent.size() > kMaxReserved) frequent.resize(kMaxReserved);
  std::vector<cv::Vec3b> palette;
  reserved.assign(kBins, -1);
  for (const int i : frequent) {
    const std::uint32_t k = histogram[static_cast<std::size_t>(i)].key;
    reserved[static_cast<std::size_t>(i)] = static_cast<int>(palette.size());
    palette.emplace_back(static_cast<uchar>(k >> 16), static_cast<uchar>(k >> 8),
                         static_cast<uchar>(k));
  }
  std::vector<Cell> cells;
  for (int i = 0; i < kBins; ++i) {
    if (histogram[static_cast<std::size_t>(i)].count == 0 ||
        reserved[static_cast<std::size_t>(i)] >= 0)
      continue;
    Cell cell = histogram[static_cast<std::size_t>(i)];
    cell.at = {i >> (2 * kBits), (i >> kBits) & 31, i & 31};
    cells.push_back(cell);
  }
  if (cells.empty()) return palette;
  const std::size_t room = kColours - palette.size();
  std::vector<Box> boxes{make_box(cells, 0, cells.size())};
  while (boxes.size() < room) {
    std::size_t pick = boxes.size();
    std::uint64_t best = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      const std::uint64_t score = boxes[i].count * static_cast<std::uint64_t>(boxes[i].length);
      if (boxes[i].end - boxes[i].begin >= 2 && score > best) best = score, pick = i;
    }
    if (pick == boxes.size()) break;  // every box is one cell
    const Box box = boxes[pick];
    const int ch = box.widest;
    const auto first = cells.begin() + static_cast<std::ptrdiff_t>(box.begin);
    const auto last = cells.begin() + static_cast<std::ptrdiff_t>(box.end);
    // Cells are distinct bins: ordering by the channel, then the bin, is a total order.
    std::sort(first, last, [ch](const Cell& a, const Cell& b) {
      return a.at[ch] != b.at[ch] ? a.at[ch] < b.at[ch] : a.at < b.at;
    });
    std::uint64_t below = 0;
    std::size_t cut = box.begin;
    while (cut + 1 < box.end && 2 * (below + cells[cut].count) <= box.count)
      below += cells[cut++].count;
    if (cut == box.begin) ++cut;
    boxes[pick] = make_box(cells, box.begin, cut);
    boxes.push_back(make_box(cells, cut, box.end));
  }
  for (const Box& b : boxes) {
    std::array<std::uint64_t, 3> sum{};
    for (std::size_t i = b.begin; i < b.end; ++i)
      for (int ch = 0; ch < 3; ++ch) sum[ch] += cells[i].sum[ch];
    cv::Vec3b colour;
    for (int ch = 0; ch < 3; ++ch)
      colour[ch] = static_cast<uchar>((sum[ch] + b.count / 2) / b.count);
    palette.push_back(colour);
  }
  return palette;
}

// The palette entry nearest the centre of a lookup bin of kLookupBits a channel (squared
// distance, lowest index on a tie).
constexpr int kLookupBits = 6;

std::uint8_t nearest(const std::vector<cv::Vec3b>& palette, int bin) {
  const int step = 1 << (8 - kLookupBits), mask = (1 << kLookupBits) - 1;
  const int centre[3] = {((bin >> (2 * kLookupBits)) & mask) * step + step / 2,
                         ((bin >> kLookupBits) & mask) * step + step / 2,
                         (bin & mask) * step + step / 2};
  int best = 0, best_distance = 1 << 30;
  for (std::size_t i = 0; i < palette.size(); ++i) {
    int d = 0;
    for (int ch = 0; ch < 3; ++ch) {
      const int e = palette[i][ch] - centre[ch];
      d += e * e;
    }
    if (d < best_distance) best_distance = d, best = static_cast<int>(i);
  }
  return static_cast<std::uint8_t>(best);
}

IndexedImage dithered_image(const cv::Mat& bgr) {
  // Bayer's 8×8 threshold matrix, as (b + 0.5) / 64 − 0.5 in [−0.5, 0.5).
  static constexpr std::array<std::array<int, 8>, 8> bayer{{{0, 32, 8, 40, 2, 34, 10, 42},
                                                            {48, 16, 56, 24, 50, 18, 58, 26},
                                                            {12, 44, 4, 36, 14, 46, 6, 38},
                                                            {60, 28, 52, 20, 62, 30, 54, 22},
                                                            {3, 35, 11, 43, 1, 33, 9, 41},
                                                            {51, 19, 59, 27, 49, 17, 57, 25},
                                                            {15, 47, 7, 39, 13, 45, 5, 37},
                                                            {63, 31, 55, 23, 61, 29, 53, 21}}};
  IndexedImage out;
  std::vector<int> reserved;
  out.palette = make_palette(bgr, reserved);
  out.indices.create(bgr.size(), CV_8UC1);
  std::vector<int> lookup(std::size_t{1} << (3 * kLookupBits), -1);
  const int shift = 8 - kLookupBits;
  for (int r = 0; r < bgr.rows; ++r) {
    const auto* p = bgr.ptr<cv::Vec3b>(r);
    auto* q = out.indices.ptr<std::uint8_t>(r);
    for (int c = 0; c < bgr.cols; ++c) {
      // A frequent colour is kept exactly, undithered.
      const int exact = reserved[static_cast<std::size_t>(bin_of(p[c][0], p[c][1], p[c][2]))];
      if (exact >= 0 && out.palette[static_cast<std::size_t>(exact)] == p[c]) {
        q[c] = static_cast<std::uint8_t>(exact);
        continue;
      }
      const int offset = static_cast<int>(std::lround(
          (bayer[static_cast<std::size_t>(r & 7)][static_cast<std::size_t>(c & 7)] + 0.5) / 64.0 *
              kDither -
          kDither / 2));
      const int bin = (std::clamp(p[c][0] + offset, 0, 255) >> shift) << (2 * kLookupBits) |
                      (std::clamp(p[c][1] + offset, 0, 255) >> shift) << kLookupBits |
                      std::clamp(p[c][2] + offset, 0, 255) >> shift;
      int& entry = lookup[static_cast<std::size_t>(bin)];
      if (entry < 0) entry = nearest(out.palette, bin);
      q[c] = static_cast<std::uint8_t>(entry);
    }
  }
  return out;
}

}  // namespace

IndexedImage to_indexed(const cv::Mat& bgr) {
  if (bgr.empty() || bgr.type() != CV_8UC3)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("palette: needs a non-empty 8-bit BGR image (got {}x{}, type {})",
                            bgr.cols, bgr.rows, bgr.type()));
  std::vector<std::uint32_t> keys;
  if (own_colours(bgr, keys)) return exact_image(bgr, keys);
  return dithered_image(bgr);
}

}  // namespace ifsfx::engine
