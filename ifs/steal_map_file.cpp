// SPDX-License-Identifier: Apache-2.0
// Steal map files: a map computed once colours many frames (`ifsfx render --save-map`,
// `ifsfx apply`). Layout, little-endian:
//   "IFSFXSTM"  8 bytes magic
//   u32 version (1), u32 width, u32 height, u32 reserved (0)
//   width·height (u, v) float32 pairs, row-major, then width·height coverage bytes (0 or 255)
// The file length must match the header exactly, so a truncated file is refused; so is a payload
// the writer cannot have made (a coverage byte other than 0/255, a covered pixel at NaN or ±inf).
#include <array>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/steal_map.h"

namespace ifsfx {

namespace {

static_assert(std::endian::native == std::endian::little,
              "steal map files are written in the host's byte order, assumed little-endian");

constexpr std::array<char, 8> kMagic{'I', 'F', 'S', 'F', 'X', 'S', 'T', 'M'};
constexpr std::uint32_t kVersion = 1;
constexpr std::size_t kHeaderBytes = 8 + 4 * 4;

std::uintmax_t payload_bytes(std::uint32_t w, std::uint32_t h) {
  return static_cast<std::uintmax_t>(w) * h * (2 * sizeof(float) + 1);
}

// What the writer never writes, refused by pixel: a coverage byte other than 0 and 255, or a
// covered pixel whose source point is not a number (it would colour that pixel from nowhere).
void check_payload(const StealMap& map, const std::filesystem::path& path) {
  for (int r = 0; r < map.coverage.rows; ++r) {
    const auto* covered = map.coverage.ptr<std::uint8_t>(r);
    const auto* uv = map.source_uv.ptr<cv::Vec2f>(r);
    for (int c = 0; c < map.coverage.cols; ++c) {
      if (covered[c] != 0 && covered[c] != 255)
        throw Error(ErrorKind::io,
                    fmt::format("{}: corrupt steal map: the coverage of pixel ({}, {}) is {} "
                                "(0 or 255 only)",
                                path.string(), c, r, covered[c]));
      if (covered[c] != 0 && !(std::isfinite(uv[c][0]) && std::isfinite(uv[c][1])))
        throw Error(ErrorKind::io,
                    fmt::format("{}: corrupt steal map: pixel ({}, {}) is covered but its source "
                                "point ({}, {}) is not a finite number",
                                path.string(), c, r, uv[c][0], uv[c][1]));
    }
  }
}

}  // namespace

void save(const StealMap& map, const std::filesystem::path& path, const OutputOptions& output) {
  OutputFile file(path, output);
  save(map, file);
  file.commit();
}

void save(const StealMap& map, OutputFile& file) {
  const std::filesystem::path& path = file.target();
  if (map.empty() || map.source_uv.type() != CV_32FC2 || map.coverage.type() != CV_8UC1 ||
      map.source_uv.size() != map.coverage.size())
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: only a non-empty steal map can be saved", path.string()));
  const auto w = static_cast<std::uint32_t>(map.size().width);
  const auto h = static_cast<std::uint32_t>(map.size().height);
  std::ofstream out(file.temporary(), std::ios::binary | std::ios::trunc);
  const std::array<std::uint32_t, 4> header{kVersion, w, h, 0};
  out.write(kMagic.data(), kMagic.size());
  out.write(reinterpret_cast<const char*>(header.data()), sizeof(header));
  for (int r = 0; r < map.source_uv.rows; ++r)
    out.write(reinterpret_cast<const char*>(map.source_uv.ptr(r)),
              static_cast<std::streamsize>(w * 2 * sizeof(float)));
  for (int r = 0; r < map.coverage.rows; ++r)
    out.write(reinterpret_cast<const char*>(map.coverage.ptr(r)), static_cast<std::streamsize>(w));
  out.close();
  if (!out)
    throw Error(ErrorKind::io, fmt::format("{}: cannot write: {}", path.string(),
                                           std::generic_category().message(errno ? errno : EIO)));
}

StealMap load_steal_map(const std::filesystem::path& path, std::optional<cv::Size> expected_size) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw Error(ErrorKind::not_found, fmt::format("{}: no such steal map file", path.string()));
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw Error(ErrorKind::io, fmt::format("{}: cannot read ({})", path.string(),
                                           std::generic_category().message(errno)));
  const std::uintmax_t length = std::filesystem::file_size(path, ec);
  if (ec)
    throw Error(ErrorKind::io, fmt::format("{}: cannot read ({})", path.string(), ec.message()));
  std::array<char, 8> magic{};
  std::array<std::uint32_t, 4> header{};
  in.read(magic.data(), magic.size());
  in.read(reinterpret_cast<char*>(header.data()), sizeof(header));
  if (!in || magic != kMagic)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: not an ifsfx steal map (no IFSFXSTM header)", path.string()));
  if (header[0] != kVersion)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: steal map version {} is supported (got version {})", path.string(),
                            kVersion, header[0]));
  const std::uint32_t w = header[1], h = header[2];
  if (w == 0 || h == 0 || w > 32768 || h > 32768)
    throw Error(ErrorKind::io,
                fmt::format("{}: corrupt steal map: size must be 1..32768 a side (got {}x{})",
                            path.string(), w, h));
  if (length != kHeaderBytes + payload_bytes(w, h))
    throw Error(ErrorKind::io,
                fmt::format("{}: truncated or corrupt steal map: a {}x{} map has {} bytes (got {})",
                            path.string(), w, h, kHeaderBytes + payload_bytes(w, h), length));
  const cv::Size size(static_cast<int>(w), static_cast<int>(h));
  if (expected_size && *expected_size != size)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: the steal map must be {}x{} here (got {}x{})", path.string(),
                            expected_size->width, expected_size->height, w, h));
  StealMap map;
  map.source_uv.create(size, CV_32FC2);
  map.coverage.create(size, CV_8UC1);
  in.read(reinterpret_cast<char*>(map.source_uv.data),
          static_cast<std::streamsize>(map.source_uv.total() * map.source_uv.elemSize()));
  in.read(reinterpret_cast<char*>(map.coverage.data),
          static_cast<std::streamsize>(map.coverage.total()));
  if (!in) throw Error(ErrorKind::io, fmt::format("{}: read failed", path.string()));
  check_payload(map, path);
  return map;
}

}  // namespace ifsfx
