// SPDX-License-Identifier: Apache-2.0
// PNG through libpng, for the light `ifsfx` (ifs/detail/image_formats.h). libpng reports errors
// by longjmp: the one function that calls setjmp (encode) holds no C++ object, everything it uses
// lives in its caller.
#include <png.h>
#include <zlib.h>

#include <cerrno>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "ifs/detail/image_formats.h"
#include "ifs/error.h"

namespace ifsfx::detail {
namespace fs = std::filesystem;

namespace {

// What a failed write leaves for the message: the system's error, or libpng's own complaint.
struct WriteState {
  std::FILE* file = nullptr;
  int error_number = 0;
  char message[256] = {};
};

[[noreturn]] void on_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<WriteState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message);
  std::longjmp(png_jmpbuf(png), 1);
}

// Libraries never print: libpng's warnings (none for what we write) are dropped.
void on_warning(png_structp, png_const_charp) {}

void on_write(png_structp png, png_bytep data, std::size_t size) {
  auto* state = static_cast<WriteState*>(png_get_io_ptr(png));
  if (std::fwrite(data, 1, size, state->file) != size) {
    state->error_number = errno != 0 ? errno : EIO;
    png_error(png, "short write");
  }
}

void on_flush(png_structp png) {
  auto* state = static_cast<WriteState*>(png_get_io_ptr(png));
  if (std::fflush(state->file) != 0) {
    state->error_number = errno != 0 ? errno : EIO;
    png_error(png, "flush failed");
  }
}

struct Layout {
  png_uint_32 width, height;
  int bit_depth, colour_type;
  bool smallest;
};

// Header, text, rows, end: false after libpng reported an error (the message in its WriteState).
bool encode(png_structp png, png_infop info, const Layout& layout, png_bytepp rows, png_textp text,
            int text_count) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_IHDR(png, info, layout.width, layout.height, layout.bit_depth, layout.colour_type,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  // OpenImageIO writes the image's origin (0, 0) as an oFFs chunk: so does this writer, so that
  // both binaries' PNGs are the same bytes (`ifsfx studio` renders in ifsfx-full and promises the
  // bytes of `ifsfx render`, tests/studio/studio_server_test.sh).
  png_set_oFFs(png, info, 0, 0, PNG_OFFSET_PIXEL);
  if (text_count > 0) png_set_text(png, info, text, text_count);
  // The fastest write filters every row by its left neighbour alone (PNG_FILTER_SUB) instead of
  // trying the five filters per row: half the time of a 1080p write; files 1 % (fern) to 8 %
  // (Sierpinski) larger for 1080p measure renders, 11 % for a frame-filling stolen photo.
  png_set_compression_level(png, layout.smallest ? 9 : 1);
  // zlib's default strategy, as OpenImageIO chooses (libpng's own is Z_FILTERED for filtered rows):
  // the same compressed bytes as OpenImageIO's writer.
  png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
  if (!layout.smallest) png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_write_info(png, info);
  if (layout.bit_depth == 16) png_set_swap(png);  // OpenCV's words are little-endian, PNG's big
  if (layout.colour_type & PNG_COLOR_MASK_COLOR) png_set_bgr(png);
  png_write_image(png, rows);
  png_write_end(png, info);
  return true;
}

bool ascii(const std::string& text) {
  for (const char ch : text)
    if (static_cast<unsigned char>(ch) >= 0x80) return false;
  return true;
}

}  // namespace

void write_png(const fs::path& target, const fs::path& file, const cv::Mat& pixels, bool smallest,
               const ImageAttributes& attributes) {
  const int channels = pixels.channels();
  if (channels < 1 || channels > 4 || (pixels.depth() != CV_8U && pixels.depth() != CV_16U))
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: PNG holds 1 to 4 channels of 8 or 16 bits (got {} of depth {})",
                            target.string(), channels, pixels.depth()));
  static constexpr int kColourTypes[] = {PNG_COLOR_TYPE_GRAY, PNG_COLOR_TYPE_GRAY_ALPHA,
                                         PNG_COLOR_TYPE_RGB, PNG_COLOR_TYPE_RGB_ALPHA};
  const Layout layout{static_cast<png_uint_32>(pixels.cols), static_cast<png_uint_32>(pixels.rows),
                      pixels.depth() == CV_16U ? 16 : 8, kColourTypes[channels - 1], smallest};

  std::vector<png_bytep> rows(static_cast<std::size_t>(pixels.rows));
  for (int r = 0; r < pixels.rows; ++r)
    rows[static_cast<std::size_t>(r)] = const_cast<png_bytep>(pixels.ptr<png_byte>(r));
  // Text chunks under the names OpenImageIO reads them back by; tEXt is Latin-1, so text that is
  // not ASCII goes in an iTXt chunk, which holds UTF-8.
  std::vector<png_text> text;
  for (const auto& [key, value] : attributes) {
    png_text chunk{};
    chunk.key = const_cast<char*>(key == "ImageDescription" ? "Description" : key.c_str());
    chunk.text = const_cast<char*>(value.c_str());
    if (ascii(value)) {
      chunk.compression = PNG_TEXT_COMPRESSION_NONE;
      chunk.text_length = value.size();
    } else {
      chunk.compression = PNG_ITXT_COMPRESSION_NONE;
      chunk.itxt_length = value.size();
    }
    text.push_back(chunk);
  }

  WriteState state;
  state.file = std::fopen(file.c_str(), "wb");
  if (state.file == nullptr)
    throw Error(ErrorKind::io, fmt::format("{}: cannot write ({})", target.string(),
                                           std::generic_category().message(errno)));
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &state, on_error, on_warning);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  bool ok = info != nullptr;
  if (ok) {
    png_set_write_fn(png, &state, on_write, on_flush);
    ok = encode(png, info, layout, rows.data(), text.data(), static_cast<int>(text.size()));
  }
  png_destroy_write_struct(png ? &png : nullptr, info ? &info : nullptr);
  // Buffered bytes meet a full disk only here.
  if (std::fclose(state.file) != 0 && ok) {
    ok = false;
    state.error_number = errno != 0 ? errno : EIO;
  }
  if (!ok) {
    const std::string why = state.error_number != 0
                                ? std::generic_category().message(state.error_number)
                            : state.message[0] != '\0' ? std::string(state.message)
                                                       : std::string("out of memory");
    throw Error(ErrorKind::io, fmt::format("{}: cannot write ({})", target.string(), why));
  }
}

}  // namespace ifsfx::detail
