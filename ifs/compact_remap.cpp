// SPDX-License-Identifier: Apache-2.0
// The compacted remap table and its 8-bit kernel. The arithmetic is cv::remap's for 8-bit
// sources (imgwarp.cpp, remapBilinear with FixedPtCast<int, uchar, 15>): four neighbours weighted
// by products of 1/32-pixel fractions scaled to 2^15, summed in integers, rounded by +2^14 and
// shifted down 15 bits. OpenCV's table stores the (0,0) weight 2^15 as 32767 and gives the
// missing 1 to the far neighbour; |p11 − p00| ≤ 255 < 2^14 makes that round to the same byte.
#include "ifs/detail/compact_remap.h"

#include <algorithm>
#include <array>
#include <cstring>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "ifs/error.h"
#include "ifs/parallel.h"

namespace ifsfx::detail {

namespace {

constexpr int kSteps = 32;  // cv::INTER_TAB_SIZE: fractions are in 1/32 pixel
constexpr int kWeightSide = kSteps + 1;
constexpr int kShift = 15;     // cv::INTER_REMAP_COEF_BITS
constexpr int kPartRows = 64;  // output rows converted or compacted by one worker at a time

// Weights of (x0,y0), (x0+1,y0), (x0,y0+1), (x0+1,y0+1) for fractions fx, fy in 0..32. The
// 33rd step lets a pixel on the last column or row read its square one pixel to the left or up
// with the whole weight on the far side: the same sum, never a read off the source.
using Weights = std::array<std::int32_t, 4>;
constexpr std::array<Weights, kWeightSide * kWeightSide> make_weights() {
  std::array<Weights, kWeightSide * kWeightSide> table{};
  constexpr int scale = (1 << kShift) / (kSteps * kSteps);
  for (int fy = 0; fy <= kSteps; ++fy)
    for (int fx = 0; fx <= kSteps; ++fx)
      table[static_cast<std::size_t>(fy * kWeightSide + fx)] = {
          (kSteps - fx) * (kSteps - fy) * scale, fx * (kSteps - fy) * scale,
          (kSteps - fx) * fy * scale, fx * fy * scale};
  return table;
}
constexpr auto kWeights = make_weights();

enum class Reads { source, nothing, partly };

// What cv::remap's bilinear path reads for a pixel at (sx + fx/32, sy + fy/32); on `source`,
// moves a square hanging off the last column or row (with a zero weight there) back inside.
Reads classify_bilinear(int& sx, int& sy, int& fx, int& fy, cv::Size src, RemapBorder border) {
  const int w = src.width, h = src.height;
  if (border == RemapBorder::transparent)
    return sx >= 0 && sx < w - 1 && sy >= 0 && sy < h - 1 ? Reads::source : Reads::nothing;
  if (sx >= w || sx + 1 < 0 || sy >= h || sy + 1 < 0) return Reads::nothing;
  if (sx < 0 || sy < 0 || (sx == w - 1 && fx != 0) || (sy == h - 1 && fy != 0))
    return Reads::partly;
  if (sx == w - 1) sx = w - 2, fx = kSteps;
  if (sy == h - 1) sy = h - 2, fy = kSteps;
  return Reads::source;
}

template <int cn>
void bilinear_run(const std::uint8_t* src, std::size_t row, const std::uint32_t* pixel,
                  const std::uint16_t* weight, int n, std::uint8_t* out) {
  for (int k = 0; k < n; ++k, out += cn) {
    const std::uint8_t* p = src + std::size_t{pixel[k]} * cn;
    const Weights& w = kWeights[weight[k]];
    for (int c = 0; c < cn; ++c)
      out[c] = static_cast<std::uint8_t>((p[c] * w[0] + p[cn + c] * w[1] + p[row + c] * w[2] +
                                          p[row + cn + c] * w[3] + (1 << (kShift - 1))) >>
                                         kShift);
  }
}

template <int cn>
void nearest_run(const std::uint8_t* src, const std::uint32_t* pixel, int n, std::uint8_t* out) {
  for (int k = 0; k < n; ++k, out += cn) std::memcpy(out, src + std::size_t{pixel[k]} * cn, cn);
}

template <int cn>
void fill(std::uint8_t* out, int n, const std::array<std::uint8_t, 4>& value) {
  for (int k = 0; k < n; ++k, out += cn) std::memcpy(out, value.data(), cn);
}

template <int cn>
void remap_rows_cn(const CompactRemap& table, const cv::Mat& source, cv::Mat& out, cv::Range rows,
                   const std::optional<cv::Scalar>& background) {
  std::array<std::uint8_t, 4> bg{};
  if (background)
    for (int c = 0; c < cn; ++c)
      bg[static_cast<std::size_t>(c)] = cv::saturate_cast<std::uint8_t>((*background)[c]);
  const auto* src = source.ptr<std::uint8_t>();
  const std::size_t row = source.step[0];
  for (int r = rows.start; r < rows.end; ++r) {
    auto* dst = out.ptr<std::uint8_t>(r);
    const auto y = static_cast<std::size_t>(r);
    std::uint32_t e = table.row_entries[y];
    int col = 0;
    for (std::uint32_t i = table.row_runs[y]; i < table.row_runs[y + 1]; ++i) {
      const CompactRemap::Run run = table.runs[i];
      if (background) fill<cn>(dst + col * cn, run.begin - col, bg);
      const int n = run.end - run.begin;
      if (table.bilinear)
        bilinear_run<cn>(src, row, &table.pixel[e], &table.weight[e], n, dst + run.begin * cn);
      else
        nearest_run<cn>(src, &table.pixel[e], n, dst + run.begin * cn);
      e += static_cast<std::uint32_t>(n);
      col = run.end;
    }
    if (background) fill<cn>(dst + col * cn, table.size.width - col, bg);
  }
}

// The table's entries for output rows [r0, r1): row offsets local to the part, so that parts
// built on different workers are joined by adding the entries before them.
struct Part {
  std::vector<std::uint32_t> row_runs, row_entries;  // r1 − r0 offsets each
  std::vector<CompactRemap::Run> runs;
  std::vector<std::uint32_t> pixel;
  std::vector<std::uint16_t> weight;
};

// Compacts rows [r0, r1) into `part`; false where a bilinear square lies partly on the source
// under a constant border (cv::remap's general border handling is needed).
bool compact_rows(const cv::Mat& xy, const cv::Mat& frac, cv::Size source_size, RemapBorder border,
                  int r0, int r1, Part& part) {
  const bool bilinear = !frac.empty();
  const auto w = static_cast<std::uint32_t>(source_size.width);
  for (int r = r0; r < r1; ++r) {
    part.row_runs.push_back(static_cast<std::uint32_t>(part.runs.size()));
    part.row_entries.push_back(static_cast<std::uint32_t>(part.pixel.size()));
    const auto* p = xy.ptr<cv::Vec2s>(r);
    const auto* f = bilinear ? frac.ptr<std::uint16_t>(r) : nullptr;
    bool in_run = false;
    for (int c = 0; c < xy.cols; ++c) {
      int sx = p[c][0], sy = p[c][1], fx = 0, fy = 0;
      Reads reads = Reads::nothing;
      if (f) {
        const int index = f[c] & (kSteps * kSteps - 1);
        fx = index % kSteps, fy = index / kSteps;
        reads = classify_bilinear(sx, sy, fx, fy, source_size, border);
        if (reads == Reads::partly) return false;
      } else if (sx >= 0 && sx < source_size.width && sy >= 0 && sy < source_size.height) {
        reads = Reads::source;
      }
      if (reads == Reads::nothing) {
        in_run = false;
        continue;
      }
      if (!in_run) part.runs.push_back({c, c});
      in_run = true;
      ++part.runs.back().end;
      part.pixel.push_back(static_cast<std::uint32_t>(sy) * w + static_cast<std::uint32_t>(sx));
      part.weight.push_back(static_cast<std::uint16_t>(fy * kWeightSide + fx));
    }
  }
  return true;
}

}  // namespace

void fixed_point_maps(cv::Size size, bool nearest, int threads,
                      const std::function<void(int row, cv::Vec2f* out)>& fill_row, cv::Mat& xy,
                      cv::Mat& frac) {
  xy.create(size, CV_16SC2);
  if (nearest)
    frac.release();
  else
    frac.create(size, CV_16UC1);
  parallel_rows(size.height, kPartRows, threads, [&](cv::Range rows) {
    cv::Mat band(rows.size(), size.width, CV_32FC2);
    for (int r = rows.start; r < rows.end; ++r) fill_row(r, band.ptr<cv::Vec2f>(r - rows.start));
    cv::Mat band_xy = xy.rowRange(rows), band_frac;
    if (!nearest) band_frac = frac.rowRange(rows);
    cv::convertMaps(band, cv::Mat(), band_xy, band_frac, CV_16SC2, nearest);
  });
}

std::optional<CompactRemap> compact_remap(const cv::Mat& xy, const cv::Mat& frac,
                                          cv::Size source_size, RemapBorder border, int threads) {
  if (xy.type() != CV_16SC2 ||
      (!frac.empty() && (frac.type() != CV_16UC1 || frac.size() != xy.size())))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("remap table: needs CV_16SC2 pixels and an empty or CV_16UC1 fraction "
                            "of one size (got types {} and {})",
                            xy.type(), frac.type()));
  if (source_size.width < 2 || source_size.height < 2) return std::nullopt;
  // Fixed bands of rows, compacted on the workers and joined in row order: the same table for
  // any thread count (the prepare of a superIFS frame or an animated filter is on its path).
  const auto parts = static_cast<std::size_t>((xy.rows + kPartRows - 1) / kPartRows);
  std::vector<Part> part(parts);
  std::vector<char> whole(parts, 1);
  parallel_rows(xy.rows, kPartRows, threads, [&](cv::Range rows) {
    const auto k = static_cast<std::size_t>(rows.start / kPartRows);
    whole[k] = compact_rows(xy, frac, source_size, border, rows.start, rows.end, part[k]) ? 1 : 0;
  });
  if (std::find(whole.begin(), whole.end(), 0) != whole.end()) return std::nullopt;

  CompactRemap table;
  table.size = xy.size();
  table.source_size = source_size;
  table.bilinear = !frac.empty();
  // Where each part's entries start in the joined table.
  std::vector<std::size_t> run_base(parts + 1, 0), entry_base(parts + 1, 0);
  for (std::size_t k = 0; k < parts; ++k) {
    run_base[k + 1] = run_base[k] + part[k].runs.size();
    entry_base[k + 1] = entry_base[k] + part[k].pixel.size();
  }
  table.row_runs.resize(static_cast<std::size_t>(xy.rows) + 1);
  table.row_entries.resize(static_cast<std::size_t>(xy.rows) + 1);
  table.runs.resize(run_base[parts]);
  table.pixel.resize(entry_base[parts]);
  table.weight.resize(entry_base[parts]);
  parallel_for(parts, threads, [&](std::size_t k, int) {
    const Part& p = part[k];
    const std::size_t row0 = k * kPartRows;
    for (std::size_t i = 0; i < p.row_runs.size(); ++i) {
      table.row_runs[row0 + i] = static_cast<std::uint32_t>(run_base[k] + p.row_runs[i]);
      table.row_entries[row0 + i] = static_cast<std::uint32_t>(entry_base[k] + p.row_entries[i]);
    }
    std::copy(p.runs.begin(), p.runs.end(),
              table.runs.begin() + static_cast<std::ptrdiff_t>(run_base[k]));
    std::copy(p.pixel.begin(), p.pixel.end(),
              table.pixel.begin() + static_cast<std::ptrdiff_t>(entry_base[k]));
    std::copy(p.weight.begin(), p.weight.end(),
              table.weight.begin() + static_cast<std::ptrdiff_t>(entry_base[k]));
  });
  table.row_runs.back() = static_cast<std::uint32_t>(run_base[parts]);
  table.row_entries.back() = static_cast<std::uint32_t>(entry_base[parts]);
  return table;
}

bool compact_remap_supports(int type) {
  return CV_MAT_DEPTH(type) == CV_8U && CV_MAT_CN(type) <= 4;
}

void remap_rows(const CompactRemap& table, const cv::Mat& source, cv::Mat& out, cv::Range rows,
                const std::optional<cv::Scalar>& background) {
  if (!compact_remap_supports(source.type()) || source.size() != table.source_size ||
      !source.isContinuous() || out.type() != source.type() || out.size() != table.size)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("remap table: needs a continuous 8-bit {}x{} source and a {}x{} output "
                            "of its type (got {}x{} type {}, {}x{} type {})",
                            table.source_size.width, table.source_size.height, table.size.width,
                            table.size.height, source.cols, source.rows, source.type(), out.cols,
                            out.rows, out.type()));
  switch (source.channels()) {
    case 1:
      return remap_rows_cn<1>(table, source, out, rows, background);
    case 2:
      return remap_rows_cn<2>(table, source, out, rows, background);
    case 3:
      return remap_rows_cn<3>(table, source, out, rows, background);
    default:
      return remap_rows_cn<4>(table, source, out, rows, background);
  }
}

}  // namespace ifsfx::detail
