#include "video/file_sink.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <system_error>

#include <fmt/format.h>

extern "C" {
#include <libavutil/opt.h>
#include <libavutil/pixdesc.h>
}

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
                              "with --codec)",
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
  return formats[0];
}

std::filesystem::path part_path(const std::filesystem::path& path) {
  std::filesystem::path p = path;
  p += ".part";
  return p;
}

}  // namespace

std::string resolve_encoder(const std::filesystem::path& path, const std::string& codec) {
  return find_encoder(path, guess_container(path), codec)->name;
}

struct FileSink::Impl {
  std::filesystem::path path;
  std::filesystem::path temp;
  std::unique_ptr<AVFormatContext, detail::OutputContextDeleter> format;
  std::unique_ptr<AVCodecContext, detail::CodecContextDeleter> codec;
  std::unique_ptr<AVFrame, detail::FrameDeleter> frame{av_frame_alloc()};
  std::unique_ptr<AVPacket, detail::PacketDeleter> packet{av_packet_alloc()};
  std::unique_ptr<SwsContext, detail::SwsDeleter> sws;
  std::unique_ptr<detail::AudioCopy> audio;
  AVStream* stream = nullptr;
  double audio_origin = 0;
  std::int64_t written = 0;
  double first_timestamp = 0;
  std::int64_t last_pts = -1;
  bool closed = false;

  std::string what() const { return path.string(); }

  // Sends one frame (nullptr: flush) and writes every packet the encoder has ready.
  void encode(AVFrame* f) {
    check_av(avcodec_send_frame(codec.get(), f), ErrorKind::io, what(), "encoder refused a frame");
    for (;;) {
      const int r = avcodec_receive_packet(codec.get(), packet.get());
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
      check_av(r, ErrorKind::io, what(), "encoding failed");
      av_packet_rescale_ts(packet.get(), codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      check_av(av_interleaved_write_frame(format.get(), packet.get()), ErrorKind::io, what(),
               "cannot write");
    }
  }

  double seconds(std::int64_t frames) const {
    return static_cast<double>(frames) * av_q2d(codec->time_base);
  }

  void discard_temp() noexcept {
    format.reset();
    std::error_code ec;
    std::filesystem::remove(temp, ec);
  }
};

FileSink::FileSink(const std::filesystem::path& path, const FileSinkOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.path = path;
  s.temp = part_path(path);
  if (options.size.width <= 0 || options.size.height <= 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frame size must be positive (got {}x{})", s.what(),
                            options.size.width, options.size.height));
  if (options.frame_rate.num <= 0 || options.frame_rate.den <= 0)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frame rate must be positive (got {}/{})", s.what(),
                            options.frame_rate.num, options.frame_rate.den));
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorKind::io, fmt::format("{}: is a folder", s.what()));
  const AVOutputFormat* container = guess_container(path);
  const AVCodec* encoder = find_encoder(path, container, options.codec);

  AVFormatContext* raw = nullptr;
  check_av(avformat_alloc_output_context2(&raw, container, nullptr, path.c_str()),
           ErrorKind::unsupported, s.what(), "cannot create the container");
  s.format.reset(raw);

  s.codec.reset(avcodec_alloc_context3(encoder));
  AVCodecContext* c = s.codec.get();
  c->width = options.size.width;
  c->height = options.size.height;
  c->time_base = AVRational{options.frame_rate.den, options.frame_rate.num};
  c->framerate = AVRational{options.frame_rate.num, options.frame_rate.den};
  c->sample_aspect_ratio = AVRational{1, 1};
  c->pix_fmt = pick_pixel_format(encoder);
  if (c->pix_fmt == AV_PIX_FMT_YUVJ420P) c->color_range = AVCOL_RANGE_JPEG;
  c->thread_count = options.threads;
  if (encoder->id == AV_CODEC_ID_MPEG4) {
    c->flags |= AV_CODEC_FLAG_QSCALE;
    c->global_quality = 3 * FF_QP2LAMBDA;
  }
  if (container->flags & AVFMT_GLOBALHEADER) c->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  check_av(avcodec_open2(c, encoder, nullptr), ErrorKind::unsupported, s.what(),
           fmt::format("cannot open the {} encoder at {}x{}", encoder->name, c->width, c->height));

  s.stream = avformat_new_stream(raw, nullptr);
  if (s.stream == nullptr) throw Error(ErrorKind::io, fmt::format("{}: out of memory", s.what()));
  s.stream->time_base = c->time_base;
  s.stream->avg_frame_rate = c->framerate;
  s.stream->r_frame_rate = c->framerate;
  check_av(avcodec_parameters_from_context(s.stream->codecpar, c), ErrorKind::io, s.what(),
           "cannot set the stream parameters");

  if (options.audio_from) {
    s.audio = std::make_unique<detail::AudioCopy>(*options.audio_from, raw, s.what());
    if (s.audio->empty()) s.audio.reset();
  }
  s.audio_origin = options.audio_origin;

  s.frame->format = c->pix_fmt;
  s.frame->width = c->width;
  s.frame->height = c->height;
  check_av(av_frame_get_buffer(s.frame.get(), 0), ErrorKind::io, s.what(), "out of memory");
  s.sws.reset(sws_getContext(c->width, c->height, AV_PIX_FMT_BGR24, c->width, c->height, c->pix_fmt,
                             SWS_BICUBIC, nullptr, nullptr, nullptr));
  if (!s.sws)
    throw Error(ErrorKind::unsupported, fmt::format("{}: cannot convert BGR to {}", s.what(),
                                                    av_get_pix_fmt_name(c->pix_fmt)));
  // Open the temporary file last: every check that can fail without touching the disk is done.
  check_av(avio_open(&raw->pb, s.temp.c_str(), AVIO_FLAG_WRITE), ErrorKind::io, s.what(),
           fmt::format("cannot write {}", s.temp.string()));
  try {
    check_av(avformat_write_header(raw, nullptr), ErrorKind::io, s.what(),
             "cannot write the header");
  } catch (...) {
    s.discard_temp();
    throw;
  }
}

FileSink::~FileSink() {
  if (impl_->closed) return;
  try {
    close();
  } catch (...) {
    impl_->discard_temp();
  }
}

void FileSink::write(const Frame& frame) {
  Impl& s = *impl_;
  if (s.closed) throw Error(ErrorKind::io, fmt::format("{}: written after close", s.what()));
  const cv::Mat& image = frame.image;
  if (image.type() != CV_8UC3 || image.cols != s.codec->width || image.rows != s.codec->height)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frames must be {}x{} 8-bit BGR (got {}x{}, type {})", s.what(),
                            s.codec->width, s.codec->height, image.cols, image.rows, image.type()));
  if (s.written == 0) {
    s.first_timestamp = frame.timestamp;
    if (s.audio) s.audio->set_origin(s.audio_origin + frame.timestamp);
  }
  check_av(av_frame_make_writable(s.frame.get()), ErrorKind::io, s.what(), "out of memory");
  const std::uint8_t* src[4] = {image.data, nullptr, nullptr, nullptr};
  const int src_stride[4] = {static_cast<int>(image.step), 0, 0, 0};
  sws_scale(s.sws.get(), src, src_stride, 0, image.rows, s.frame->data, s.frame->linesize);
  // Timestamps are kept (on the grid of the frame rate), so a source with gaps in time keeps its
  // timing and its sync with the audio; they only ever move forward.
  const std::int64_t pts =
      std::llround((frame.timestamp - s.first_timestamp) / av_q2d(s.codec->time_base));
  s.last_pts = std::max(pts, s.last_pts + 1);
  s.frame->pts = s.last_pts;
  s.encode(s.frame.get());
  ++s.written;
  // Audio up to the end of this frame: the muxer interleaves it, and a file closed after this frame
  // has its sound up to there.
  if (s.audio) s.audio->copy_until(s.seconds(s.last_pts + 1));
}

void FileSink::close() {
  Impl& s = *impl_;
  if (s.closed) return;
  s.closed = true;
  try {
    if (s.written == 0)
      throw Error(ErrorKind::io, fmt::format("{}: no frame to write; nothing was saved", s.what()));
    s.encode(nullptr);
    if (s.audio) s.audio->copy_until(s.seconds(s.last_pts + 1));
    check_av(av_write_trailer(s.format.get()), ErrorKind::io, s.what(), "cannot finish the file");
    check_av(avio_closep(&s.format->pb), ErrorKind::io, s.what(), "cannot finish the file");
    s.format.reset();
    std::error_code ec;
    std::filesystem::rename(s.temp, s.path, ec);
    if (ec)
      throw Error(ErrorKind::io, fmt::format("{}: cannot rename {} into place ({})", s.what(),
                                             s.temp.string(), ec.message()));
  } catch (...) {
    s.discard_temp();
    throw;
  }
}

std::string FileSink::name() const {
  return impl_->path.string();
}

std::int64_t FileSink::frames_written() const {
  return impl_->written;
}

std::string FileSink::codec_name() const {
  return impl_->codec->codec->name;
}

}  // namespace ifsfx::video
