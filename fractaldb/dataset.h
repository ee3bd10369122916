// SPDX-License-Identifier: Apache-2.0
// A FractalDB dataset written to a folder as the reference's make_fractaldb.py lays it out
// (fractaldb/render.h; docs/dataset.md): FOLDER/NAME/NAME_WW_count_I_flipT.png, one folder
// per category, which torchvision's ImageFolder loads with the category's index as its label.
//
// Every file goes through the output policy (docs/design.md §8): written to a temporary name and
// renamed into place whole, so a run that is stopped leaves whole files only; a file already
// there is kept, so running the same command again resumes. Each picture depends only on its key
// and the seed, never on the thread count or on what a previous run wrote.
//   fractaldb::write_dataset(spec, "FractalDB-1k", {.threads = 0, .cancel = stop});
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "fractaldb/render.h"
#include "ifs/cancel.h"
#include "ifs/output_file.h"

namespace ifsfx::fractaldb {

struct DatasetProgress {
  std::int64_t done = 0;     // images written or found already there
  std::int64_t skipped = 0;  // of which found already there
  std::int64_t total = 0;
  double seconds = 0;     // since the start
  bool finished = false;  // the last report
};

struct DatasetOptions {
  int threads = 0;  // 0 = all cores; a worker renders one category and weight at a time
  // 24-bit RGB PNGs, as the reference writes them, instead of indexed-colour PNGs (1 bit per
  // pixel for the grey types, 8 for the colour ones) that decode to the same RGB pixels, are
  // 2–3 times smaller and many times faster to write.
  bool rgb_png = false;
  OutputOptions output;  // the inputs no output may replace, and the stop request
  std::function<void(const DatasetProgress&)> progress;  // called from one thread at a time
  double progress_interval = 0.25;                       // seconds between reports
};

struct DatasetStats {
  std::int64_t written = 0, skipped = 0;
};

// Writes the images of `spec` missing under `folder` (made if needed). Throws what check(spec)
// throws, Error{interrupted} on a stop (the files written so far whole), and Error{io} naming a
// file that cannot be written.
DatasetStats write_dataset(const DatasetSpec& spec, const std::filesystem::path& folder,
                           const DatasetOptions& options = {});

// Flips of canvases as PNG files' bytes: indexed colour with the palette of the draw type, or
// 24-bit RGB with `rgb`. Rows unfiltered, zlib's run-length strategy (fast, and smaller than its
// default level 1 on these pictures). One encoder per thread: it keeps its zlib state and
// buffers from one picture to the next (starting zlib costs more than a small picture).
class PngEncoder {
 public:
  PngEncoder();
  ~PngEncoder();
  PngEncoder(const PngEncoder&) = delete;
  PngEncoder& operator=(const PngEncoder&) = delete;

  // The file's bytes, valid until the next call. Throws Error{invalid_argument} for a canvas that
  // is not CV_8UC1 or a flip outside 0..3.
  const std::string& encode(const cv::Mat& canvas, int flip, DrawType draw, bool rgb);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The same with an encoder of its own.
std::string encode_png(const cv::Mat& canvas, int flip, DrawType draw, bool rgb);

}  // namespace ifsfx::fractaldb
