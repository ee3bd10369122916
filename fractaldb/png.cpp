// SPDX-License-Identifier: Apache-2.0
// The PNG files of a FractalDB dataset (encode_png, fractaldb/dataset.h), written here rather
// than by the image writers (ifs/image_io.h): a dataset is a million small pictures of one or
// 129 colours, for which an indexed-colour PNG of packed rows is the fastest to write and the
// smallest, and decodes to the reference's RGB pixels.
#include <zlib.h>

#include <array>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "fractaldb/dataset.h"
#include "ifs/error.h"

namespace ifsfx::fractaldb {
namespace {

void put32(std::string& out, std::uint32_t v) {
  const char bytes[4] = {static_cast<char>(v >> 24), static_cast<char>(v >> 16),
                         static_cast<char>(v >> 8), static_cast<char>(v)};
  out.append(bytes, 4);
}

void chunk(std::string& out, const char type[4], const std::string& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t start = out.size();
  out.append(type, 4);
  out += data;
  const auto* bytes = reinterpret_cast<const Bytef*>(out.data() + start);
  put32(out, static_cast<std::uint32_t>(crc32(0, bytes, static_cast<uInt>(out.size() - start))));
}

// Eight canvas bytes (0 or 1) as one byte of a 1-bit row: the first pixel in the highest bit, or
// with `reversed` the last (a multiply gathers bit 0 of each byte; docs/dataset.md).
std::uint8_t pack8(const std::uint8_t* p, bool reversed) {
  std::uint64_t v = 0;
  std::memcpy(&v, p, 8);
  return static_cast<std::uint8_t>(
      (v * (reversed ? 0x0102040810204080ULL : 0x8040201008040201ULL)) >> 56);
}

// The filtered scanlines (filter byte 0, then the row) of the flip.
void scanlines(const cv::Mat& canvas, int flip, DrawType draw, bool rgb,
               std::vector<std::uint8_t>& data, std::vector<std::uint8_t>& row) {
  const int width = canvas.cols, height = canvas.rows;
  const bool bits = !rgb && !is_colour(draw);
  const std::size_t row_bytes = rgb    ? 3 * static_cast<std::size_t>(width)
                                : bits ? (static_cast<std::size_t>(width) + 7) / 8
                                       : static_cast<std::size_t>(width);
  data.resize((row_bytes + 1) * static_cast<std::size_t>(height));
  const bool upside_down = flip == 0 || flip == 2, mirrored = flip >= 2;
  const auto colours = palette(draw);
  row.resize(static_cast<std::size_t>(width));
  for (int r = 0; r < height; ++r) {
    const std::uint8_t* src = canvas.ptr<std::uint8_t>(upside_down ? height - 1 - r : r);
    std::uint8_t* out = data.data() + static_cast<std::size_t>(r) * (row_bytes + 1);
    *out++ = 0;  // filter: none
    if (bits) {
      int c = 0, byte = 0;
      for (; c + 8 <= width; c += 8, ++byte)
        out[byte] = mirrored ? pack8(src + width - 8 - c, true) : pack8(src + c, false);
      if (c < width) {
        std::uint8_t last = 0;
        for (int i = 0; c + i < width; ++i)
          last |=
              static_cast<std::uint8_t>((src[mirrored ? width - 1 - c - i : c + i] & 1) << (7 - i));
        out[byte] = last;
      }
      continue;
    }
    const std::uint8_t* pixels = src;
    if (mirrored) {
      for (int c = 0; c < width; ++c) row[static_cast<std::size_t>(c)] = src[width - 1 - c];
      pixels = row.data();
    }
    if (!rgb) {
      std::memcpy(out, pixels, static_cast<std::size_t>(width));
      continue;
    }
    for (int c = 0; c < width; ++c) std::memcpy(out + 3 * c, colours[pixels[c]].data(), 3);
  }
}

}  // namespace

struct PngEncoder::State {
  z_stream z{};
  std::vector<std::uint8_t> raw, row;
  std::string idat, out;
};

PngEncoder::PngEncoder() : state_(std::make_unique<State>()) {
  if (deflateInit2(&state_->z, 1, Z_DEFLATED, 15, 8, Z_RLE) != Z_OK)
    throw Error(ErrorKind::io, "PNG: cannot start zlib (out of memory)");
}

PngEncoder::~PngEncoder() {
  deflateEnd(&state_->z);
}

const std::string& PngEncoder::encode(const cv::Mat& canvas, int flip, DrawType draw, bool rgb) {
  if (canvas.type() != CV_8UC1 || canvas.empty() || flip < 0 || flip >= kFlips)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("flip: a canvas (CV_8UC1) has flips 0..3 (got type {}, flip {})",
                            canvas.type(), flip));
  State& s = *state_;
  scanlines(canvas, flip, draw, rgb, s.raw, s.row);
  const auto colours = palette(draw);
  const bool bits = !rgb && !is_colour(draw);

  std::string& out = s.out;
  out.assign("\x89PNG\r\n\x1a\n", 8);
  std::string header;
  put32(header, static_cast<std::uint32_t>(canvas.cols));
  put32(header, static_cast<std::uint32_t>(canvas.rows));
  header += static_cast<char>(bits ? 1 : 8);  // bit depth
  header += static_cast<char>(rgb ? 2 : 3);   // colour type: RGB, or indexed
  header.append(3, '\0');                     // deflate, adaptive filters, no interlace
  chunk(out, "IHDR", header);
  if (!rgb) {
    std::string entries;
    for (const auto& c : colours) entries.append(reinterpret_cast<const char*>(c.data()), 3);
    chunk(out, "PLTE", entries);
  }
  z_stream& z = s.z;
  deflateReset(&z);
  s.idat.resize(deflateBound(&z, static_cast<uLong>(s.raw.size())));
  z.next_in = s.raw.data();
  z.avail_in = static_cast<uInt>(s.raw.size());
  z.next_out = reinterpret_cast<Bytef*>(s.idat.data());
  z.avail_out = static_cast<uInt>(s.idat.size());
  const int status = deflate(&z, Z_FINISH);
  if (status != Z_STREAM_END) throw Error(ErrorKind::io, "PNG: zlib could not compress a picture");
  s.idat.resize(z.total_out);
  chunk(out, "IDAT", s.idat);
  chunk(out, "IEND", {});
  return out;
}

std::string encode_png(const cv::Mat& canvas, int flip, DrawType draw, bool rgb) {
  PngEncoder encoder;
  return encoder.encode(canvas, flip, draw, rgb);
}

}  // namespace ifsfx::fractaldb
