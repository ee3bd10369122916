// SPDX-License-Identifier: Apache-2.0
#include "farm/segment_join.h"

#include <algorithm>
#include <memory>

#include <fmt/format.h>

#include "ifs/error.h"
#include "ifs/output_file.h"
#include "video/audio_remux.h"
#include "video/av_util.h"

namespace ifsfx::farm {

namespace {

using video::detail::check_av;

struct Segment {
  std::unique_ptr<AVFormatContext, video::detail::InputContextDeleter> format;
  AVStream* stream = nullptr;
};

Segment open_segment(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw Error(ErrorKind::not_found, fmt::format("{}: segment missing", path.string()));
  AVFormatContext* raw = nullptr;
  check_av(avformat_open_input(&raw, path.c_str(), nullptr, nullptr), ErrorKind::unsupported,
           path.string(), "not a movie file FFmpeg can read");
  Segment s;
  s.format.reset(raw);
  check_av(avformat_find_stream_info(raw, nullptr), ErrorKind::unsupported, path.string(),
           "cannot read the streams");
  const int index = av_find_best_stream(raw, AVMEDIA_TYPE_VIDEO, -1, -1, nullptr, 0);
  if (index < 0)
    throw Error(ErrorKind::unsupported, fmt::format("{}: no video stream", path.string()));
  s.stream = raw->streams[index];
  return s;
}

// A stream copy needs one encoding throughout: same codec, size, pixel format and headers.
void check_same_encoding(const AVCodecParameters* a, const AVCodecParameters* b,
                         const std::filesystem::path& path) {
  const bool extradata_equal =
      a->extradata_size == b->extradata_size &&
      (a->extradata_size == 0 ||
       std::equal(a->extradata, a->extradata + a->extradata_size, b->extradata));
  if (a->codec_id != b->codec_id || a->width != b->width || a->height != b->height ||
      a->format != b->format || !extradata_equal)
    throw Error(ErrorKind::unsupported,
                fmt::format("{}: encoded unlike the first segment ({} {}x{} vs {} {}x{}{}); "
                            "the segments cannot be joined by stream copy",
                            path.string(), avcodec_get_name(b->codec_id), b->width, b->height,
                            avcodec_get_name(a->codec_id), a->width, a->height,
                            extradata_equal ? "" : ", other codec headers"));
}

// The output's container and its one video stream, encoded as the first segment is.
struct Output {
  std::unique_ptr<AVFormatContext, video::detail::OutputContextDeleter> format;
  AVStream* video = nullptr;
};

Output open_output(const std::filesystem::path& path, const Segment& first,
                   const std::string& what) {
  AVFormatContext* raw = nullptr;
  check_av(avformat_alloc_output_context2(&raw, nullptr, nullptr, path.c_str()),
           ErrorKind::unsupported, what, "unknown container");
  Output out{.format = decltype(Output::format)(raw)};
  if (std::string_view(raw->oformat->name) == "avi")
    raw->avoid_negative_ts = AVFMT_AVOID_NEG_TS_DISABLED;  // as the file sink does
  AVStream* video = avformat_new_stream(raw, nullptr);
  if (video == nullptr) throw Error(ErrorKind::io, fmt::format("{}: out of memory", what));
  check_av(avcodec_parameters_copy(video->codecpar, first.stream->codecpar), ErrorKind::io, what,
           "cannot copy the video parameters");
  video->codecpar->codec_tag = 0;
  video->time_base = first.stream->time_base;
  video->avg_frame_rate = first.stream->avg_frame_rate;
  video->r_frame_rate = first.stream->r_frame_rate;
  out.video = video;
  return out;
}

// The segments' packets on one clock: the first segment's time base, time 0 at its first frame
// (the earliest presentation time it holds).
class Timeline {
 public:
  explicit Timeline(const AVStream* first)
      : tb_(first->time_base),
        origin_(first->start_time != AV_NOPTS_VALUE ? first->start_time : 0) {}

  AVRational time_base() const { return tb_; }
  double origin_seconds() const { return static_cast<double>(origin_) * av_q2d(tb_); }
  // Where the last frame ends, in seconds.
  double seconds() const { return static_cast<double>(end_) * av_q2d(tb_); }

  // Puts a packet of a segment whose time base is `tb` on the timeline; returns its time in
  // seconds (0 without one).
  double place(AVPacket* packet, AVRational tb) {
    av_packet_rescale_ts(packet, tb, tb_);
    if (packet->pts != AV_NOPTS_VALUE) packet->pts -= origin_;
    if (packet->dts != AV_NOPTS_VALUE) packet->dts -= origin_;
    // Decode order runs on across the seam: the next segment's first packets may be stamped
    // (by a demuxer guessing the decode delay) before the previous segment's last ones.
    if (packet->dts != AV_NOPTS_VALUE && last_dts_ != AV_NOPTS_VALUE && packet->dts <= last_dts_)
      packet->dts = last_dts_ + 1;
    if (packet->pts != AV_NOPTS_VALUE && packet->dts != AV_NOPTS_VALUE && packet->dts > packet->pts)
      packet->pts = packet->dts;
    if (packet->dts != AV_NOPTS_VALUE) last_dts_ = packet->dts;
    if (packet->pts != AV_NOPTS_VALUE)
      end_ = std::max(end_, packet->pts + std::max<std::int64_t>(packet->duration, 0));
    return packet->pts != AV_NOPTS_VALUE ? static_cast<double>(packet->pts) * av_q2d(tb_) : 0;
  }

  // Where the container keeps no packet durations (MP4 gives its stream's), the stream's end:
  // the last frame lasts as long as in the segment.
  void end_segment(const AVStream* stream) {
    if (stream->start_time != AV_NOPTS_VALUE && stream->duration > 0)
      end_ = std::max(
          end_,
          av_rescale_q(stream->start_time + stream->duration, stream->time_base, tb_) - origin_);
  }

 private:
  AVRational tb_;
  std::int64_t origin_;
  std::int64_t end_ = 0;  // where the last frame ends, on tb_
  std::int64_t last_dts_ = AV_NOPTS_VALUE;
};

// Copies a segment's video packets into the output, on the timeline, the audio (if any) up to
// each packet's time.
void copy_packets(Segment& seg, Timeline& timeline, const Output& out,
                  video::detail::AudioCopy* audio, AVPacket* packet, const std::string& what,
                  const CancelToken& cancel, JoinResult& result) {
  const AVRational tb = seg.stream->time_base;
  while (av_read_frame(seg.format.get(), packet) >= 0) {
    if (packet->stream_index != seg.stream->index) {
      av_packet_unref(packet);
      continue;
    }
    const double at = timeline.place(packet, tb);
    if (audio) audio->copy_until(at);
    av_packet_rescale_ts(packet, timeline.time_base(), out.video->time_base);
    packet->stream_index = out.video->index;
    packet->pos = -1;
    check_av(av_interleaved_write_frame(out.format.get(), packet), ErrorKind::io, what,
             "cannot write");
    ++result.video_packets;
    cancel.check("farm join");
  }
}

}  // namespace

JoinResult join_segments(const JoinOptions& options) {
  if (options.segments.empty())
    throw Error(ErrorKind::invalid_argument, "join: no segments to join");
  const std::string what = options.output.string();
  // Under the output policy: never over an input (the movie, a segment), a temporary file of its
  // own, put in place by one rename only when complete.
  OutputOptions policy = options.policy;
  for (const auto& segment : options.segments) policy.inputs.add(segment);
  OutputFile file(options.output, policy);
  const std::filesystem::path& temp = file.temporary();

  Segment first = open_segment(options.segments.front());
  Output out = open_output(options.output, first, what);
  AVFormatContext* raw = out.format.get();
  std::unique_ptr<video::detail::AudioCopy> audio;
  if (options.audio_from) {
    audio = std::make_unique<video::detail::AudioCopy>(*options.audio_from, raw, what);
    if (audio->empty()) audio.reset();
  }

  check_av(avio_open(&raw->pb, temp.c_str(), AVIO_FLAG_WRITE), ErrorKind::io, what,
           fmt::format("cannot write {}", temp.string()));
  JoinResult result;
  try {
    check_av(avformat_write_header(raw, nullptr), ErrorKind::io, what, "cannot write the header");
    std::unique_ptr<AVPacket, video::detail::PacketDeleter> packet(av_packet_alloc());
    Timeline timeline(first.stream);
    if (audio) audio->set_origin(options.audio_origin + timeline.origin_seconds());
    for (std::size_t i = 0; i < options.segments.size(); ++i) {
      Segment seg = i == 0 ? std::move(first) : open_segment(options.segments[i]);
      if (i > 0)
        check_same_encoding(out.video->codecpar, seg.stream->codecpar, options.segments[i]);
      copy_packets(seg, timeline, out, audio.get(), packet.get(), what, policy.cancel, result);
      timeline.end_segment(seg.stream);
    }
    result.seconds = timeline.seconds();
    if (audio) audio->copy_until(result.seconds);
    check_av(av_write_trailer(raw), ErrorKind::io, what, "cannot finish the file");
    check_av(avio_closep(&raw->pb), ErrorKind::io, what, "cannot finish the file");
    out.format.reset();
  } catch (...) {
    out.format.reset();  // closes the temporary file; `file` removes it
    throw;
  }
  file.commit();
  std::error_code ec;
  result.bytes = static_cast<std::int64_t>(std::filesystem::file_size(options.output, ec));
  return result;
}

}  // namespace ifsfx::farm
