// SPDX-License-Identifier: Apache-2.0
#include "video/file_sink.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <string_view>

#include <fmt/format.h>

extern "C" {
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
}

#include "engine/palette.h"
#include "video/audio_remux.h"
#include "video/av_util.h"

namespace ifsfx::video {

using detail::check_av;

namespace {

const AVOutputFormat* guess_container(const std::filesystem::path& path) {
  const AVOutputFormat* format = av_guess_format(nullptr, path.c_str(), nullptr);
  if (format == nullptr || format->video_codec == AV_CODEC_ID_NONE)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: unknown movie container extension '{}' (use .mp4, .mkv, .avi, "
                            ".mov, ...)",
                            path.string(), path.extension().string()));
  // FFmpeg's image muxer reads printf patterns in the name itself, bypassing the output policy:
  // image sequences go through ImageSequenceSink instead.
  if (std::string_view(format->name).starts_with("image2"))
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: a still image format; write an image sequence with a pattern "
                            "such as {}_%04d{}",
                            path.string(), path.stem().string(), path.extension().string()));
  return format;
}

// The encoder for `codec` — an encoder name ("libx264") or a codec name ("h264") — or the
// container's default one.
const AVCodec* find_encoder(const std::filesystem::path& path, const AVOutputFormat* format,
                            const std::string& codec) {
  const AVCodec* encoder = nullptr;
  if (codec.empty()) {
    encoder = avcodec_find_encoder(format->video_codec);
    if (encoder == nullptr)
      throw Error(ErrorKind::unsupported,
                  fmt::format("{}: no encoder for the container's default codec {} (pick one "
                              "with codec)",
                              path.string(), avcodec_get_name(format->video_codec)));
  } else {
    encoder = avcodec_find_encoder_by_name(codec.c_str());
    if (encoder == nullptr) {
      if (const AVCodecDescriptor* d = avcodec_descriptor_get_by_name(codec.c_str()))
        encoder = avcodec_find_encoder(d->id);
    }
    if (encoder == nullptr || encoder->type != AVMEDIA_TYPE_VIDEO)
      throw Error(ErrorKind::unsupported,
                  fmt::format("codec: unknown video encoder (got '{}'; `ffmpeg -encoders` lists "
                              "them)",
                              codec));
  }
  if (avformat_query_codec(format, encoder->id, FF_COMPLIANCE_NORMAL) == 0)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: the {} container cannot carry {} video", path.string(),
                            format->name, avcodec_get_name(encoder->id)));
  return encoder;
}

// The pixel format to encode in: exact BGR for lossless encoders (so FFV1 round-trips frames bit
// for bit), 4:2:0 for lossy ones as ffmpeg would pick for a 4:2:0 input, else the encoder's first.
AVPixelFormat pick_pixel_format(const AVCodec* encoder) {
  const AVPixelFormat* formats = encoder->pix_fmts;
  if (formats == nullptr) return AV_PIX_FMT_YUV420P;
  auto supports = [&](AVPixelFormat f) {
    for (const AVPixelFormat* p = formats; *p != AV_PIX_FMT_NONE; ++p)
      if (*p == f) return true;
    return false;
  };
  const AVCodecDescriptor* d = avcodec_descriptor_get(encoder->id);
  const bool lossless =
      d != nullptr && (d->props & AV_CODEC_PROP_LOSSLESS) && !(d->props & AV_CODEC_PROP_LOSSY);
  if (lossless) {
    for (AVPixelFormat f : {AV_PIX_FMT_BGR0, AV_PIX_FMT_BGR24, AV_PIX_FMT_RGB24, AV_PIX_FMT_GBRP,
                            AV_PIX_FMT_0RGB32, AV_PIX_FMT_RGB32})
      if (supports(f)) return f;
  }
  // JPEG-based codecs (MJPEG) code full-range YUV; FFmpeg's MJPEG encoder refuses limited range.
  std::array<AVPixelFormat, 2> yuv420{AV_PIX_FMT_YUV420P, AV_PIX_FMT_YUVJ420P};
  if (encoder->id == AV_CODEC_ID_MJPEG) std::swap(yuv420[0], yuv420[1]);
  for (AVPixelFormat f : yuv420)
    if (supports(f)) return f;
  // GIF: a palette of the picture's own colours (engine/palette.h), not a fixed 3-3-2 one.
  if (supports(AV_PIX_FMT_PAL8)) return AV_PIX_FMT_PAL8;
  return formats[0];
}

// Muxer options: animated images (GIF, WebP) loop for ever, as browsers and viewers expect of
// them (FFmpeg's WebP muxer would play once). Other containers have no say in looping.
AVDictionary* muxer_options(const AVOutputFormat* container) {
  AVDictionary* options = nullptr;
  const std::string_view name = container->name;
  if (name == "gif" || name == "webp") av_dict_set(&options, "loop", "0", 0);
  return options;
}

// The chroma block of a pixel format: 2×2 for 4:2:0, 2×1 for 4:2:2, 1×1 for 4:4:4 and RGB.
cv::Size chroma_block(AVPixelFormat format) {
  int w_shift = 0, h_shift = 0;
  if (av_pix_fmt_get_chroma_sub_sample(format, &w_shift, &h_shift) < 0) return {1, 1};
  return {1 << w_shift, 1 << h_shift};
}

FrameTiming timing_for(const std::filesystem::path& path, const AVOutputFormat* container,
                       const AVCodec* encoder, FrameTiming requested) {
  // AVI counts frames instead of storing times, raw streams store none, and MPEG-1/2 video knows
  // only a list of rates: none of them can place a frame at an arbitrary time.
  const bool no_times = std::string_view(container->name) == "avi" ||
                        (container->flags & AVFMT_NOTIMESTAMPS) ||
                        encoder->supported_framerates != nullptr;
  if (requested == FrameTiming::keep && no_times)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: {} cannot keep each frame's time (timing keep); use .mkv or "
                            ".mp4, or timing constant",
                            path.string(),
                            encoder->supported_framerates != nullptr
                                ? fmt::format("{} video", encoder->name)
                                : fmt::format("the {} container", container->name)));
  if (requested != FrameTiming::automatic) return requested;
  return no_times ? FrameTiming::constant : FrameTiming::keep;
}

// The clock kept timestamps are written on: the source's own, where the encoder takes it.
AVRational keep_time_base(const AVCodec* encoder, Rational source, Rational rate) {
  if (!source.positive()) return AVRational{rate.den, rate.num};  // cameras: the rate's grid
  AVRational tb{source.num, source.den};
  // MPEG-4 part 2 codes the clock in 16 bits: a coarser tick of the same clock (1/90000 becomes
  // 1/45000), at most 1/65535 s off.
  if (encoder->id == AV_CODEC_ID_MPEG4 && tb.den > 65535) {
    const int divide = (tb.den + 65534) / 65535;
    tb.den = std::max(1, tb.den / divide);
  }
  return tb;
}

// The nearest rate an encoder bound to a list of rates (MPEG-1/2) offers; `rate` otherwise.
Rational supported_rate(const AVCodec* encoder, Rational rate) {
  if (encoder->supported_framerates == nullptr) return rate;
  const int i =
      av_find_nearest_q_idx(AVRational{rate.num, rate.den}, encoder->supported_framerates);
  return {encoder->supported_framerates[i].num, encoder->supported_framerates[i].den};
}

}  // namespace

bool is_movie_name(const std::filesystem::path& path) noexcept {
  const AVOutputFormat* format = av_guess_format(nullptr, path.c_str(), nullptr);
  return format != nullptr && format->video_codec != AV_CODEC_ID_NONE &&
         !std::string_view(format->name).starts_with("image2");
}

std::string resolve_encoder(const std::filesystem::path& path, const std::string& codec) {
  return find_encoder(path, guess_container(path), codec)->name;
}

cv::Size encodable_size(const std::filesystem::path& path, const std::string& codec,
                        cv::Size size) {
  const cv::Size block =
      chroma_block(pick_pixel_format(find_encoder(path, guess_container(path), codec)));
  return {std::max(block.width, size.width / block.width * block.width),
          std::max(block.height, size.height / block.height * block.height)};
}

FrameTiming resolve_timing(const std::filesystem::path& path, const std::string& codec,
                           FrameTiming requested) {
  const AVOutputFormat* container = guess_container(path);
  return timing_for(path, container, find_encoder(path, container, codec), requested);
}

struct FileSink::Impl {
  std::filesystem::path path;
  std::optional<OutputFile> out;  // the temporary file written, under the output policy
  std::unique_ptr<AVFormatContext, detail::OutputContextDeleter> format;
  std::unique_ptr<AVCodecContext, detail::CodecContextDeleter> codec;
  std::unique_ptr<AVFrame, detail::FrameDeleter> frame{av_frame_alloc()};
  std::unique_ptr<AVPacket, detail::PacketDeleter> packet{av_packet_alloc()};
  std::unique_ptr<SwsContext, detail::SwsDeleter> sws;
  std::unique_ptr<detail::AudioCopy> audio;
  AVStream* stream = nullptr;
  double audio_origin = 0;
  bool source_clock = false;
  FrameTiming timing = FrameTiming::keep;
  Rational rate;              // the nominal rate: one frame's length where a frame has none
  std::int64_t received = 0;  // frames given to write()
  std::int64_t written = 0;   // frames encoded
  std::int64_t repeated = 0;
  std::int64_t dropped = 0;
  Frame first;                 // the first frame's time (no image): output time 0
  std::int64_t last_pts = -1;  // the last frame encoded, on the codec's clock
  std::int64_t end_pts = 0;    // where the last frame encoded ends, on the codec's clock
  std::map<std::int64_t, std::int64_t> durations;  // frames in the encoder: pts → duration
  // Constant timing: the frame held back until the next one says how long it lasts.
  cv::Mat pending;
  std::int64_t pending_slot = 0, pending_end = 0;
  bool closed = false;

  std::string what() const { return path.string(); }

  // Sends one frame (nullptr: flush) and writes every packet the encoder has ready, each with the
  // duration of its frame (so the last frame lasts as long as the source's did).
  void encode(AVFrame* f) {
    check_av(avcodec_send_frame(codec.get(), f), ErrorKind::io, what(), "encoder refused a frame");
    for (;;) {
      const int r = avcodec_receive_packet(codec.get(), packet.get());
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
      check_av(r, ErrorKind::io, what(), "encoding failed");
      if (const auto d = durations.find(packet->pts); d != durations.end()) {
        packet->duration = d->second;
        durations.erase(d);
      }
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      check_av(av_interleaved_write_frame(format.get(), packet.get()), ErrorKind::io, what(),
               "cannot write");
    }
  }

  double seconds(std::int64_t ticks) const {
    return static_cast<double>(ticks) * av_q2d(codec->time_base);
  }

  // The time of frame `f` after the first frame, on the codec's clock: exact (from pts) where
  // the frame has a clock, else from its timestamp in seconds.
  std::int64_t ticks(const Frame& f) const {
    if (f.time_base.positive() && f.time_base.num == first.time_base.num &&
        f.time_base.den == first.time_base.den)
      return av_rescale_q(f.pts - first.pts, {f.time_base.num, f.time_base.den}, codec->time_base);
    return std::llround((f.timestamp - first.timestamp) / av_q2d(codec->time_base));
  }

  // How long frame `f` lasts on the codec's clock: its own duration, else one nominal frame.
  std::int64_t length(const Frame& f) const {
    std::int64_t d = 0;
    if (f.duration > 0 && f.time_base.positive())
      d = av_rescale_q(f.duration, {f.time_base.num, f.time_base.den}, codec->time_base);
    else
      d = av_rescale_q(1, AVRational{rate.den, rate.num}, codec->time_base);
    return std::max<std::int64_t>(1, d);
  }

  // Converts and encodes one picture at `pts`, lasting `duration`; the audio follows up to its end.
  void emit(const cv::Mat& image, std::int64_t pts, std::int64_t duration) {
    check_av(av_frame_make_writable(frame.get()), ErrorKind::io, what(), "out of memory");
    if (codec->pix_fmt == AV_PIX_FMT_PAL8) {
      to_palette(image);
    } else {
      const std::uint8_t* src[4] = {image.data, nullptr, nullptr, nullptr};
      const int src_stride[4] = {static_cast<int>(image.step), 0, 0, 0};
      sws_scale(sws.get(), src, src_stride, 0, image.rows, frame->data, frame->linesize);
    }
    frame->pts = pts;
    durations[pts] = duration;
    // The audio before this frame goes first: an AAC priming packet (before time 0) must reach
    // the muxer before any video, or the shift it makes for it moves the video already written.
    if (audio) audio->copy_until(seconds(pts));
    encode(frame.get());
    ++written;
    last_pts = pts;
    end_pts = pts + duration;
    // Audio up to the end of this frame: the muxer interleaves it, and a file closed after this
    // frame has its sound up to there.
    if (audio) audio->copy_until(seconds(end_pts));
  }

  // A palette picture (GIF): the indices, and the palette as opaque ARGB words (an entry with
  // alpha 0 would be taken for transparency).
  void to_palette(const cv::Mat& image) {
    const engine::IndexedImage indexed = engine::to_indexed(image);
    for (int r = 0; r < image.rows; ++r)
      std::memcpy(frame->data[0] + static_cast<std::ptrdiff_t>(r) * frame->linesize[0],
                  indexed.indices.ptr(r), static_cast<std::size_t>(image.cols));
    auto* palette = reinterpret_cast<std::uint32_t*>(frame->data[1]);
    for (std::size_t i = 0; i < 256; ++i) {
      const cv::Vec3b c = i < indexed.palette.size() ? indexed.palette[i] : cv::Vec3b();
      palette[i] = 0xff000000u | (std::uint32_t{c[2]} << 16) | (std::uint32_t{c[1]} << 8) | c[0];
    }
  }

  // Constant timing: the held-back frame fills the slots from where the output stands up to
  // `until`; none when a later frame took its slot (dropped).
  void flush_pending(std::int64_t until) {
    if (pending.empty()) return;
    const std::int64_t from = std::max(pending_slot, end_pts);
    if (until <= from) ++dropped;
    for (std::int64_t slot = from; slot < until; ++slot) emit(pending, slot, 1);
    if (until - from > 1) repeated += until - from - 1;
    pending.release();
  }

  void discard_temp() noexcept {
    format.reset();
    if (out) out->discard();
  }

  // The frames given flushed, the audio up to the end of the last one, the trailer written and
  // the file closed: a complete movie in the temporary file.
  void finish() {
    // The last frame of a constant-rate output lasts as long as it did in the source.
    flush_pending(std::max(pending_end, std::max(pending_slot, end_pts) + 1));
    encode(nullptr);
    if (audio) audio->copy_until(seconds(end_pts));
    check_av(av_write_trailer(format.get()), ErrorKind::io, what(), "cannot finish the file");
    check_av(avio_closep(&format->pb), ErrorKind::io, what(), "cannot finish the file");
    format.reset();
  }

  // The encoder for `options` in `container`, opened: its size, clock, rate and pixel format.
  void open_encoder(const FileSinkOptions& options, const AVOutputFormat* container,
                    const AVCodec* encoder) {
    codec.reset(avcodec_alloc_context3(encoder));
    AVCodecContext* c = codec.get();
    c->width = options.size.width;
    c->height = options.size.height;
    timing = timing_for(path, container, encoder, options.timing);
    rate = supported_rate(encoder, options.frame_rate);
    c->time_base = timing == FrameTiming::constant
                       ? AVRational{rate.den, rate.num}
                       : keep_time_base(encoder, options.time_base, rate);
    c->framerate = AVRational{rate.num, rate.den};
    c->sample_aspect_ratio = AVRational{1, 1};
    c->pix_fmt = pick_pixel_format(encoder);
    if (const cv::Size fit = encodable_size(path, options.codec, options.size);
        fit != options.size) {
      const cv::Size block = chroma_block(c->pix_fmt);
      throw Error(
          ErrorKind::invalid_argument,
          fmt::format("{}: {} in {} needs a width that is a multiple of {} and a height that "
                      "is a multiple of {} (got {}x{}; {}x{} would do)",
                      what(), encoder->name, av_get_pix_fmt_name(c->pix_fmt), block.width,
                      block.height, c->width, c->height, fit.width, fit.height));
    }
    if (c->pix_fmt == AV_PIX_FMT_YUVJ420P) c->color_range = AVCOL_RANGE_JPEG;
    c->thread_count = detail::codec_threads(options.threads);
    if (encoder->id == AV_CODEC_ID_MPEG4) {
      c->flags |= AV_CODEC_FLAG_QSCALE;
      c->global_quality = 3 * FF_QP2LAMBDA;
    }
    if (container->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
    check_av(
        avcodec_open2(c, encoder, nullptr), ErrorKind::unsupported, what(),
        fmt::format("cannot open the {} encoder at {}x{}", encoder->name, c->width, c->height));
  }

  // The video stream, with the encoder's clock, rate and parameters.
  void add_video_stream() {
    stream = avformat_new_stream(format.get(), nullptr);
    if (stream == nullptr) throw Error(ErrorKind::io, fmt::format("{}: out of memory", what()));
    stream->time_base = codec->time_base;
    stream->avg_frame_rate = codec->framerate;
    stream->r_frame_rate = codec->framerate;
    check_av(avcodec_parameters_from_context(stream->codecpar, codec.get()), ErrorKind::io, what(),
             "cannot set the stream parameters");
  }

  // The frame the encoder takes, and the conversion from BGR into it.
  void prepare_conversion() {
    const AVCodecContext* c = codec.get();
    frame->format = c->pix_fmt;
    frame->width = c->width;
    frame->height = c->height;
    check_av(av_frame_get_buffer(frame.get(), 0), ErrorKind::io, what(), "out of memory");
    if (c->pix_fmt == AV_PIX_FMT_PAL8) return;  // to_palette() instead
    sws.reset(sws_getContext(c->width, c->height, AV_PIX_FMT_BGR24, c->width, c->height, c->pix_fmt,
                             SWS_BICUBIC, nullptr, nullptr, nullptr));
    if (!sws)
      throw Error(ErrorKind::unsupported, fmt::format("{}: cannot convert BGR to {}", what(),
                                                      av_get_pix_fmt_name(c->pix_fmt)));
  }
};

FileSink::FileSink(const std::filesystem::path& path, const FileSinkOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.path = path;
  if (options.size.width <= 0 || options.size.height <= 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frame size must be positive (got {}x{})", s.what(),
                            options.size.width, options.size.height));
  if (options.frame_rate.num <= 0 || options.frame_rate.den <= 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frame rate must be positive (got {}/{})", s.what(),
                            options.frame_rate.num, options.frame_rate.den));
  check_output(path, options.output);
  const AVOutputFormat* container = guess_container(path);
  const AVCodec* encoder = find_encoder(path, container, options.codec);

  AVFormatContext* raw = nullptr;
  check_av(avformat_alloc_output_context2(&raw, container, nullptr, path.c_str()),
           ErrorKind::unsupported, s.what(), "cannot create the container");
  s.format.reset(raw);
  // AVI places frames by count, not time: shifting every stream to make an AAC priming packet's
  // negative time non-negative would move the video by a whole frame after its first one.
  if (std::string_view(container->name) == "avi")
    raw->avoid_negative_ts = AVFMT_AVOID_NEG_TS_DISABLED;

  s.open_encoder(options, container, encoder);
  s.add_video_stream();

  if (options.audio_from) {
    s.audio = std::make_unique<detail::AudioCopy>(*options.audio_from, raw, s.what());
    if (s.audio->empty()) s.audio.reset();
  }
  s.audio_origin = options.audio_origin;
  s.source_clock = options.source_clock;

  s.prepare_conversion();
  // Open the temporary file last: every check that can fail without touching the disk is done.
  s.out.emplace(path, options.output);
  try {
    check_av(avio_open(&raw->pb, s.out->temporary().c_str(), AVIO_FLAG_WRITE), ErrorKind::io,
             s.what(), "cannot write");
    AVDictionary* muxing = muxer_options(container);
    const int header = avformat_write_header(raw, &muxing);
    av_dict_free(&muxing);
    check_av(header, ErrorKind::io, s.what(), "cannot write the header");
  } catch (...) {
    s.discard_temp();
    throw;
  }
}

FileSink::~FileSink() {
  abandon();
}

void FileSink::write(const Frame& frame) {
  Impl& s = *impl_;
  if (s.closed) throw Error(ErrorKind::io, fmt::format("{}: written after close", s.what()));
  const cv::Mat& image = frame.image;
  if (image.type() != CV_8UC3 || image.cols != s.codec->width || image.rows != s.codec->height)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frames must be {}x{} 8-bit BGR (got {}x{}, type {})", s.what(),
                            s.codec->width, s.codec->height, image.cols, image.rows, image.type()));
  if (s.received == 0) {
    s.first = frame;
    s.first.image.release();
    if (s.source_clock) {
      s.first.pts = 0;
      s.first.timestamp = 0;
    }
    if (s.audio) s.audio->set_origin(s.audio_origin + frame.timestamp);
  }
  ++s.received;
  const std::int64_t t = s.ticks(frame);
  if (s.timing == FrameTiming::keep) {
    // Its own time; only ever forward (a damaged file's repeated timestamp moves one tick on).
    s.emit(image, std::max(t, s.last_pts + 1), s.length(frame));
    return;
  }
  // Constant rate: the frame before this one covers the slots up to this one's.
  s.flush_pending(t);
  s.pending = image.clone();  // the caller may reuse its buffer (a camera's) for the next frame
  s.pending_slot = t;
  s.pending_end = t + s.length(frame);
}

void FileSink::close() {
  Impl& s = *impl_;
  if (s.closed) return;
  s.closed = true;
  try {
    if (s.received == 0)
      throw Error(ErrorKind::io, fmt::format("{}: no frame to write; nothing was saved", s.what()));
    s.finish();
    s.out->commit();
  } catch (...) {
    s.discard_temp();
    throw;
  }
}

std::filesystem::path FileSink::abandon() noexcept {
  Impl& s = *impl_;
  if (s.closed) return {};
  s.closed = true;
  if (s.received > 0) {
    try {
      s.finish();
      return s.out->keep_partial();
    } catch (...) {
    }
  }
  s.discard_temp();
  return {};
}

std::string FileSink::name() const {
  return impl_->path.string();
}

std::int64_t FileSink::frames_written() const {
  return impl_->written;
}

std::int64_t FileSink::frames_repeated() const {
  return impl_->repeated;
}

std::int64_t FileSink::frames_dropped() const {
  return impl_->dropped;
}

FrameTiming FileSink::timing() const {
  return impl_->timing;
}

std::string FileSink::codec_name() const {
  return impl_->codec->codec->name;
}

}  // namespace ifsfx::video
