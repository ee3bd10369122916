// SPDX-License-Identifier: Apache-2.0
#include "python/texture.h"

#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "ifs/error.h"
#include "ifs/timeline.h"
#include "python/arrays.h"
#include "python/errors.h"
#include "python/options.h"
#include "python/render.h"
#include "run/arguments.h"
#include "run/texture_options.h"
#include "superifs/superifs_file.h"
#include "superifs/texture.h"

namespace ifsfx::python {
namespace {

// Frames j = first, first + 1, ... of a sequence: texture j / crossfade blended towards the next
// by (j mod crossfade) / crossfade, as `ifsfx texture --frames N --crossfade K` numbers them.
struct TextureFrames {
  std::shared_ptr<TextureSequence> sequence;
  std::int64_t next = 0;
  std::optional<std::int64_t> end;  // none: endless
  int crossfade = 1;
  int depth = CV_8U;
  bool rgb = false;  // frames in RGB order
};

// The settings `ifsfx texture` checks (check_texture_rules), with the keywords' names. The rules
// ask only whether there is a source, which here may be an array.
void check_texture_args(int buffers, int buffer, int crossfade, TextureMode mode,
                        const py::object& source) {
  app::TextureArgs args;
  args.count = buffers;
  args.buffer = buffer;
  args.crossfade = crossfade;
  args.mode = mode;
  if (!source.is_none()) args.source = "source";
  app::check_texture_rules(args, {.count = "buffers",
                                  .frames = "frames",
                                  .crossfade = "crossfade",
                                  .buffer = "buffer",
                                  .source = "source",
                                  .fps = "fps",
                                  .codec = "codec"});
}

TextureFrames start(const std::string& superpreset, const py::object& size, int buffers, int steps,
                    int buffer, const std::string& mode_name, const py::object& source,
                    std::uint64_t seed, int threads, int crossfade, const py::object& dtype,
                    std::int64_t first, std::optional<std::int64_t> count, bool rgb) {
  const cv::Size pixels = size_arg(size);
  const TextureMode mode = parse_texture_mode(mode_name, "mode");
  check_texture_args(buffers, buffer, crossfade, mode, source);
  if (steps < 0)
    throw Error(ErrorKind::invalid_argument, fmt::format("steps: must be ≥ 0 (got {})", steps));
  if (first < 0)
    throw Error(ErrorKind::invalid_argument, fmt::format("frame: must be ≥ 0 (got {})", first));
  py::object keep;
  TextureOptions options{.sampling = {.seed = seed, .threads = threads},
                         .count = buffers,
                         .steps = steps,
                         .buffer = buffer - 1,
                         .mode = mode};
  if (!source.is_none()) options.source = source_arg(source, keep, "source", rgb).clone();
  const SuperIfsPreset preset =
      run_released([&](const CancelToken&) { return load_superifs(superpreset); });
  // The sequence keeps the token: a later frame's work polls a flag that is never set.
  auto sequence = run_released([&](const CancelToken& cancel) {
    TextureOptions o = options;
    o.sampling.cancel = cancel;
    auto made = std::make_shared<TextureSequence>(preset.super, pixels, o);
    return made;
  });
  return {.sequence = std::move(sequence),
          .next = first,
          .end = count ? std::optional(first + *count) : std::nullopt,
          .crossfade = crossfade,
          .depth = depth_of(dtype, CV_8U),
          .rgb = rgb};
}

py::array frame(TextureFrames& frames) {
  const cv::Mat image = run_released([&](const CancelToken&) {
    return frames.sequence->frame_at(position_of_frame(frames.next, frames.crossfade)).clone();
  });
  ++frames.next;
  return to_array(swap_red_blue(to_depth(image, frames.depth), frames.rgb));
}

}  // namespace

void bind_texture(py::module_& m) {
  const TextureOptions d;
  // What the library leaves to its caller defaults as the command does (run/texture_options.h).
  const app::TextureArgs command{};
  const cv::Size default_size = app::size_option(command.size, "size");
  py::class_<TextureFrames>(m, "TextureFrames",
                            "An iterator over the frames of a texture sequence (textures()).")
      .def("__iter__", [](TextureFrames& self) -> TextureFrames& { return self; })
      .def("__next__", [](TextureFrames& self) {
        if (self.end && self.next >= *self.end) throw py::stop_iteration();
        return frame(self);
      });

  m.def(
      "texture",
      [](const std::string& superpreset, const py::object& size, int buffers, int steps, int buffer,
         const std::string& mode, const py::object& source, std::uint64_t seed, int threads,
         std::int64_t frame_index, int crossfade, const py::object& dtype, bool rgb) {
        TextureFrames frames = start(superpreset, size, buffers, steps, buffer, mode, source, seed,
                                     threads, crossfade, dtype, frame_index, 1, rgb);
        return frame(frames);
      },
      py::arg("superpreset"), py::kw_only(),
      py::arg("size") = py::make_tuple(default_size.width, default_size.height),
      py::arg("buffers") = d.count, py::arg("steps") = d.steps, py::arg("buffer") = command.buffer,
      py::arg("mode") = to_string(command.mode), py::arg("source") = py::none(),
      py::arg("seed") = d.sampling.seed, py::arg("threads") = d.sampling.threads,
      py::arg("frame") = 0, py::arg("crossfade") = command.crossfade, py::arg("dtype") = "uint8",
      py::arg("rgb") = false,
      R"doc(A V-variable superfractal texture, as `ifsfx texture SUPERPRESET -o OUT.png` writes it (frame 0)
or as frame `frame` + 1 of `--frames N --crossfade K -o tex_%04d.png`.

superpreset: a shipped superIFS name (paper-fig4, carpet-lace, ...) or a .super.toml path.
buffers: V, the number of buffers, default 3. steps: burn-in steps, default 0 = enough for
the size. buffer: the buffer shown, 1..V, default 1.
mode: "attractor" (H×W), "tops", "measure" (H×W×3) or "steal" (colours from `source`, an
image array or a path). seed: default 1. threads: default 0 = all cores.
frame, crossfade: frame j shows texture j // crossfade blended towards the next by
(j % crossfade) / crossfade; defaults 0 and 1.
dtype: "uint8" (default), "uint16" or "float32". rgb: False (default): BGR like cv2, True: RGB
(the source too, when an array). The GIL is released; Ctrl-C stops it.)doc");

  m.def(
      "textures",
      [](const std::string& superpreset, const py::object& size, int buffers, int steps, int buffer,
         const std::string& mode, const py::object& source, std::uint64_t seed, int threads,
         std::optional<std::int64_t> frames, int crossfade, const py::object& dtype,
         std::int64_t first, bool rgb) {
        if (frames && *frames < 0)
          throw Error(ErrorKind::invalid_argument,
                      fmt::format("frames: must be ≥ 0 (got {})", *frames));
        return start(superpreset, size, buffers, steps, buffer, mode, source, seed, threads,
                     crossfade, dtype, first, frames, rgb);
      },
      py::arg("superpreset"), py::kw_only(),
      py::arg("size") = py::make_tuple(default_size.width, default_size.height),
      py::arg("buffers") = d.count, py::arg("steps") = d.steps, py::arg("buffer") = command.buffer,
      py::arg("mode") = to_string(command.mode), py::arg("source") = py::none(),
      py::arg("seed") = d.sampling.seed, py::arg("threads") = d.sampling.threads,
      py::arg("frames") = py::none(), py::arg("crossfade") = command.crossfade,
      py::arg("dtype") = "uint8", py::arg("first") = 0, py::arg("rgb") = false,
      R"doc(An iterator over the frames of a texture sequence, one further V-variable step per
`crossfade` frames, from frame `first` (default 0); `frames` of them, default None: endless.
Frame j equals texture(..., frame=j). The burn-in runs here; each frame after it is one step.)doc");
}

}  // namespace ifsfx::python
