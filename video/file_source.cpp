// SPDX-License-Identifier: Apache-2.0
#include "video/file_source.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "video/av_util.h"

namespace ifsfx::video {

using detail::check_av;

void silence_libav_log() {
  av_log_set_level(AV_LOG_QUIET);
}

namespace {

// Matroska keeps a stream's length only as a "DURATION" tag, "HH:MM:SS.nnnnnnnnn".
double matroska_duration(const AVStream* stream) {
  const AVDictionaryEntry* tag = av_dict_get(stream->metadata, "DURATION", nullptr, 0);
  if (tag == nullptr) return -1;
  int h = 0, m = 0;
  double s = 0;
  if (std::sscanf(tag->value, "%d:%d:%lf", &h, &m, &s) != 3) return -1;
  return h * 3600.0 + m * 60.0 + s;
}

// The display matrix a phone writes, else the older `rotate` tag; upright without either.
Orientation orientation_of(const AVStream* stream, const std::string& what) {
  std::size_t size = 0;
  const std::uint8_t* matrix = av_stream_get_side_data(stream, AV_PKT_DATA_DISPLAYMATRIX, &size);
  if (matrix != nullptr && size >= 9 * sizeof(std::int32_t)) {
    std::int32_t m[9];
    std::memcpy(m, matrix, sizeof m);
    return orientation_from_matrix(m, what);
  }
  if (const AVDictionaryEntry* tag = av_dict_get(stream->metadata, "rotate", nullptr, 0))
    return orientation_from_rotate_tag(tag->value, what);
  return {};
}

}  // namespace

struct FileSource::Impl {
  std::filesystem::path path;
  std::unique_ptr<AVFormatContext, detail::InputContextDeleter> format;
  std::unique_ptr<AVCodecContext, detail::CodecContextDeleter> codec;
  std::unique_ptr<AVPacket, detail::PacketDeleter> packet{av_packet_alloc()};
  std::unique_ptr<AVFrame, detail::FrameDeleter> frame{av_frame_alloc()};
  std::unique_ptr<SwsContext, detail::SwsDeleter> sws;
  AVStream* stream = nullptr;
  Rational rate{25, 1};          // nominal: the rate the frames' clock ticks at
  Rational average_rate{25, 1};  // frames per second on average (what a frame count needs)
  Orientation orientation;
  std::int64_t announced_frames = -1;  // from the container, for the truncation check
  double announced_seconds = -1;       // the video stream's own length, when stored
  std::int64_t start_pts = AV_NOPTS_VALUE;
  std::int64_t decoded = 0;
  std::int64_t next_pts = 0;  // where a frame without a timestamp goes: after the last one
  double last_timestamp = -1;
  double last_duration = 0;  // seconds the last frame is shown, 0 when not known
  int corrupt_packets = 0;
  bool draining = false;  // the demuxer is exhausted; the decoder is being flushed
  bool finished = false;
  bool audio = false;
  bool pending = false;  // `frame` holds a decoded frame not yet handed out (after a seek)

  std::string what() const { return path.string(); }

  // The next decoded AVFrame, or false at the end of the stream.
  bool decode_next() {
    if (pending) {
      pending = false;
      return true;
    }
    for (;;) {
      const int got = avcodec_receive_frame(codec.get(), frame.get());
      if (got == 0) return true;
      if (got == AVERROR_EOF) return false;
      if (got != AVERROR(EAGAIN)) {
        // A frame the decoder could not rebuild: count it and keep going, as players do.
        ++corrupt_packets;
        continue;
      }
      if (draining) return false;
      const int r = av_read_frame(format.get(), packet.get());
      if (r == AVERROR_EOF || (r < 0 && avio_feof(format->pb))) {
        draining = true;
        avcodec_send_packet(codec.get(), nullptr);
        continue;
      }
      check_av(r, ErrorKind::io, what(), "cannot read the file");
      if (packet->stream_index == stream->index) {
        if (packet->flags & AV_PKT_FLAG_CORRUPT) {  // cut short: decoding it would show garbage
          ++corrupt_packets;
          av_packet_unref(packet.get());
          continue;
        }
        const int sent = avcodec_send_packet(codec.get(), packet.get());
        if (sent < 0 && sent != AVERROR(EAGAIN)) ++corrupt_packets;
      }
      av_packet_unref(packet.get());
    }
  }

  // After the last frame: a short or damaged stream is an error, raised once everything that
  // decoded has been handed out.
  // The next frame, its image converted to BGR only when `convert`.
  std::optional<Frame> next(bool convert) {
    if (finished) return std::nullopt;
    if (!decode_next()) {
      finished = true;
      check_complete();
      return std::nullopt;
    }
    AVFrame* f = frame.get();
    if (f->width != codec->width || f->height != codec->height)
      throw Error(ErrorKind::unsupported,
                  fmt::format("{}: frame size changes mid-stream ({}x{} to {}x{})", what(),
                              codec->width, codec->height, f->width, f->height));
    Frame out;
    out.index = decoded;
    // The frame's own time, exact on the stream's clock: a variable-rate movie keeps its timing.
    const AVRational tb = stream->time_base;
    out.time_base = {tb.num, tb.den};
    const std::int64_t pts = f->best_effort_timestamp;
    if (pts != AV_NOPTS_VALUE) {
      if (start_pts == AV_NOPTS_VALUE) {
        start_pts = stream->start_time != AV_NOPTS_VALUE ? std::min(stream->start_time, pts) : pts;
      }
      out.pts = pts - start_pts;
    } else {
      out.pts = next_pts;  // no timestamp: right after the previous frame
    }
    out.duration = std::max<std::int64_t>(0, f->pkt_duration);
    const std::int64_t period = av_rescale_q(1, av_inv_q(AVRational{rate.num, rate.den}), tb);
    next_pts = out.pts + (out.duration > 0 ? out.duration : std::max<std::int64_t>(1, period));
    out.timestamp = static_cast<double>(out.pts) * av_q2d(tb);
    if (convert) {
      out.image.create(f->height, f->width, CV_8UC3);
      sws.reset(sws_getCachedContext(sws.release(), f->width, f->height,
                                     static_cast<AVPixelFormat>(f->format), f->width, f->height,
                                     AV_PIX_FMT_BGR24, SWS_BICUBIC, nullptr, nullptr, nullptr));
      if (!sws)
        throw Error(ErrorKind::unsupported,
                    fmt::format("{}: cannot convert pixel format {} to BGR", what(),
                                av_get_pix_fmt_name(static_cast<AVPixelFormat>(f->format))));
      std::uint8_t* dst[4] = {out.image.data, nullptr, nullptr, nullptr};
      const int dst_stride[4] = {static_cast<int>(out.image.step), 0, 0, 0};
      sws_scale(sws.get(), f->data, f->linesize, 0, f->height, dst, dst_stride);
      out.image = orientation.apply(out.image);
    }
    av_frame_unref(f);
    ++decoded;
    last_timestamp = out.timestamp;
    last_duration = static_cast<double>(out.duration) * av_q2d(tb);
    return out;
  }

  // The presentation times of the next `limit` video packets (all when limit < 0) in decode
  // order, AV_NOPTS_VALUE for a packet without one, by demuxing only: no decoding.
  std::vector<std::int64_t> packet_times(std::int64_t limit) {
    std::vector<std::int64_t> times;
    while (limit < 0 || static_cast<std::int64_t>(times.size()) < limit) {
      const int r = av_read_frame(format.get(), packet.get());
      if (r < 0) break;  // the end (or an unreadable tail: the sequential decode will say)
      const bool ours = packet->stream_index == stream->index &&
                        !(packet->flags & (AV_PKT_FLAG_DISCARD | AV_PKT_FLAG_CORRUPT));
      const std::int64_t pts = packet->pts;
      av_packet_unref(packet.get());
      if (ours) times.push_back(pts);
    }
    return times;
  }

  // The presentation time of frame `index` (the index-th smallest packet time, decode order
  // being at most 16 frames away from presentation order in every codec libav knows), and the
  // time of the first frame; nothing when the stream ends before or has packets without times.
  // Reads from the current position of a fresh demuxer: the start of the file.
  struct FrameTimes {
    std::int64_t target = 0;
    std::int64_t first = 0;
  };
  std::optional<FrameTimes> frame_time(std::int64_t index) {
    constexpr std::int64_t max_reorder = 16;
    std::vector<std::int64_t> times = packet_times(index + max_reorder + 1);
    if (static_cast<std::int64_t>(times.size()) <= index ||
        std::find(times.begin(), times.end(), AV_NOPTS_VALUE) != times.end())
      return std::nullopt;
    const std::int64_t first = *std::min_element(times.begin(), times.end());
    std::nth_element(times.begin(), times.begin() + index, times.end());
    return FrameTimes{times[static_cast<std::size_t>(index)], first};
  }

  // The demuxer to the keyframe at or before `ts` (INT64_MIN: the start), the decoder emptied.
  bool seek_file(std::int64_t ts) {
    // The start: the keyframe at or before the stream's start time (or 0).
    if (ts == INT64_MIN) ts = stream->start_time != AV_NOPTS_VALUE ? stream->start_time : 0;
    const int r = av_seek_frame(format.get(), stream->index, ts, AVSEEK_FLAG_BACKWARD);
    if (r < 0) return false;
    avcodec_flush_buffers(codec.get());
    return true;
  }

  // Seeks to the keyframe at or before `target` (`from` on the stream's clock, earlier on each
  // try) and decodes up to the frame at `target`, left pending. False when the landing is not
  // clean: the first frame decoded is not a keyframe at or before the target (a container index
  // by decode time, an open GOP's leading pictures), or the target was passed.
  bool land(std::int64_t from, std::int64_t target, bool at_start) {
    if (!seek_file(from)) return false;
    draining = false;
    finished = false;
    bool first = true;
    while (decode_next()) {
      const std::int64_t pts = frame->best_effort_timestamp;
      const bool clean = pts != AV_NOPTS_VALUE && pts <= target && frame->key_frame != 0;
      if (first && !clean && !at_start) break;
      first = false;
      if (pts == target) {
        pending = true;
        return true;
      }
      av_frame_unref(frame.get());
      if (pts != AV_NOPTS_VALUE && pts > target) break;
    }
    av_frame_unref(frame.get());
    return false;
  }

  void check_complete() const {
    const double period = 1.0 / average_rate.value();
    // A stream with gaps in its timestamps (an AVI index that skips frames) holds fewer frames
    // than its length at its rate: judge by time where the length is known. The last frame lasts
    // its own duration where the file says (a screen recording's still end), else a frame period.
    const bool short_count =
        announced_seconds <= 0 && announced_frames > 0 && decoded < announced_frames - 1;
    const double end = last_timestamp + std::max(period, last_duration);
    const bool short_time = announced_seconds > 0 && end < announced_seconds - 1.5 * period;
    if (!short_count && !short_time && corrupt_packets == 0) return;
    if (decoded == 0)
      throw Error(ErrorKind::io,
                  fmt::format("{}: no frame could be decoded (corrupt file)", what()));
    if (short_count)
      throw Error(ErrorKind::io, fmt::format("{}: truncated or corrupt: decoded {} of {} frames",
                                             what(), decoded, announced_frames));
    if (short_time)
      throw Error(ErrorKind::io,
                  fmt::format("{}: truncated or corrupt: decoded {:.2f} s of {:.2f} s", what(), end,
                              announced_seconds));
    throw Error(ErrorKind::io, fmt::format("{}: corrupt: {} damaged packets ({} frames decoded)",
                                           what(), corrupt_packets, decoded));
  }
};

FileSource::FileSource(const std::filesystem::path& path, const FileSourceOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& s = *impl_;
  s.path = path;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw Error(ErrorKind::not_found, fmt::format("{}: no such file", path.string()));
  if (std::filesystem::is_directory(path, ec))
    throw Error(ErrorKind::unsupported, fmt::format("{}: is a folder, not a movie file", s.what()));
  AVFormatContext* raw = nullptr;
  check_av(avformat_open_input(&raw, path.c_str(), nullptr, nullptr), ErrorKind::unsupported,
           s.what(), "not a movie file FFmpeg can read");
  s.format.reset(raw);
  check_av(avformat_find_stream_info(raw, nullptr), ErrorKind::unsupported, s.what(),
           "cannot read the streams");
  const AVCodec* decoder = nullptr;
  const int index = av_find_best_stream(raw, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  if (index < 0 || decoder == nullptr)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: no video stream that FFmpeg can decode", s.what()));
  s.stream = raw->streams[index];
  for (unsigned i = 0; i < raw->nb_streams; ++i)
    if (raw->streams[i]->codecpar->codec_type == AVMEDIA_TYPE_AUDIO) s.audio = true;
  for (unsigned i = 0; i < raw->nb_streams; ++i)
    if (static_cast<int>(i) != index) raw->streams[i]->discard = AVDISCARD_ALL;

  s.codec.reset(avcodec_alloc_context3(decoder));
  check_av(avcodec_parameters_to_context(s.codec.get(), s.stream->codecpar), ErrorKind::unsupported,
           s.what(), "unusable video stream parameters");
  s.codec->thread_count = detail::codec_threads(options.threads);
  s.codec->thread_type = FF_THREAD_FRAME | FF_THREAD_SLICE;
  check_av(avcodec_open2(s.codec.get(), decoder, nullptr), ErrorKind::unsupported, s.what(),
           fmt::format("cannot open the {} decoder", decoder->name));
  if (s.codec->width <= 0 || s.codec->height <= 0)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: video stream has no frame size", s.what()));

  // The nominal rate as ffmpeg guesses it (the stream's base rate, so that a clip with dropped
  // frames keeps its 30 fps rather than its average); the average for counting frames.
  const AVRational guessed = av_guess_frame_rate(raw, s.stream, nullptr);
  AVRational average = s.stream->avg_frame_rate;
  if (average.num <= 0 || average.den <= 0) average = guessed;
  if (guessed.num > 0 && guessed.den > 0) s.rate = {guessed.num, guessed.den};
  if (average.num > 0 && average.den > 0) s.average_rate = {average.num, average.den};
  s.orientation = orientation_of(s.stream, s.what());
  if (s.stream->nb_frames > 0) s.announced_frames = s.stream->nb_frames;
  if (s.stream->duration != AV_NOPTS_VALUE && s.stream->duration > 0)
    s.announced_seconds = static_cast<double>(s.stream->duration) * av_q2d(s.stream->time_base);
  else
    s.announced_seconds = matroska_duration(s.stream);
}

FileSource::~FileSource() = default;

std::optional<Frame> FileSource::read() {
  return impl_->next(true);
}

bool FileSource::skip() {
  return impl_->next(false).has_value();
}

std::int64_t FileSource::count_frames() {
  Impl& s = *impl_;
  if (s.decoded > 0 || s.finished)
    throw Error(ErrorKind::invalid_argument,
                fmt::format("{}: frames are counted before any is read", s.what()));
  const auto count = static_cast<std::int64_t>(s.packet_times(-1).size());
  if (!s.seek_file(INT64_MIN))
    throw Error(ErrorKind::io, fmt::format("{}: cannot seek back to the start", s.what()));
  return count;
}

bool FileSource::seek(std::int64_t index) {
  Impl& s = *impl_;
  if (index <= 0 || s.decoded > 0 || s.finished) return FrameSource::seek(index - s.decoded);
  const std::optional<Impl::FrameTimes> times = s.frame_time(index);
  if (!times) {
    // No frame there (or no packet times): start again and let a sequential decode tell.
    if (!s.seek_file(INT64_MIN))
      throw Error(ErrorKind::io, fmt::format("{}: cannot seek back to the start", s.what()));
    return FrameSource::seek(index);
  }
  // The origin of Frame::pts, as a sequential decode sets it from the first frame.
  s.start_pts = s.stream->start_time != AV_NOPTS_VALUE
                    ? std::min(s.stream->start_time, times->first)
                    : times->first;
  // Back off one second, then two, four, ... until the landing is clean; the start always is.
  const std::int64_t second =
      std::max<std::int64_t>(1, av_rescale_q(1, AVRational{1, 1}, s.stream->time_base));
  for (std::int64_t back = 0;; back = back == 0 ? second : back * 2) {
    const bool at_start = times->target - back <= times->first;
    if (s.land(at_start ? INT64_MIN : times->target - back, times->target, at_start)) break;
    if (at_start)
      throw Error(ErrorKind::io, fmt::format("{}: frame {} (time {}) not found by decoding from "
                                             "the start",
                                             s.what(), index, times->target));
  }
  s.decoded = index;
  s.next_pts = times->target - s.start_pts;
  return true;
}

cv::Size FileSource::size() const {
  return impl_->orientation.displayed({impl_->codec->width, impl_->codec->height});
}

double FileSource::fps() const {
  return impl_->rate.value();
}

std::int64_t FileSource::frame_count() const {
  if (impl_->announced_frames > 0) return impl_->announced_frames;
  if (impl_->announced_seconds > 0)
    return std::llround(impl_->announced_seconds * impl_->average_rate.value());
  if (impl_->format->duration > 0)
    return std::llround(static_cast<double>(impl_->format->duration) / AV_TIME_BASE *
                        impl_->average_rate.value());
  return -1;
}

std::string FileSource::name() const {
  return impl_->path.string();
}

Rational FileSource::frame_rate() const {
  return impl_->rate;
}

Rational FileSource::time_base() const {
  return {impl_->stream->time_base.num, impl_->stream->time_base.den};
}

const Orientation& FileSource::orientation() const {
  return impl_->orientation;
}

bool FileSource::has_audio() const {
  return impl_->audio;
}

double FileSource::start_time() const {
  const AVStream* st = impl_->stream;
  std::int64_t origin = impl_->start_pts;
  if (origin == AV_NOPTS_VALUE) origin = st->start_time;
  if (origin == AV_NOPTS_VALUE) return 0;
  return static_cast<double>(origin) * av_q2d(st->time_base);
}

const std::filesystem::path& FileSource::path() const {
  return impl_->path;
}

std::optional<AudioTrack> FileSource::audio() const {
  if (!has_audio()) return std::nullopt;
  return AudioTrack{.file = path(), .origin = start_time()};
}

}  // namespace ifsfx::video
