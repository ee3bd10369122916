// SPDX-License-Identifier: Apache-2.0
#include "video/audio_remux.h"

#include <fmt/format.h>

namespace ifsfx::video::detail {

AudioCopy::AudioCopy(const std::filesystem::path& input, AVFormatContext* output,
                     const std::string& output_name)
    : path_(input), output_(output), output_name_(output_name) {
  AVFormatContext* raw = nullptr;
  check_av(avformat_open_input(&raw, input.c_str(), nullptr, nullptr), ErrorKind::unsupported,
           input.string(), "cannot open for its audio");
  input_.reset(raw);
  check_av(avformat_find_stream_info(raw, nullptr), ErrorKind::unsupported, input.string(),
           "cannot read the streams");
  map_.assign(raw->nb_streams, -1);
  bool any = false;
  for (unsigned i = 0; i < raw->nb_streams; ++i) {
    AVStream* in = raw->streams[i];
    if (in->codecpar->codec_type != AVMEDIA_TYPE_AUDIO) {
      in->discard = AVDISCARD_ALL;
      continue;
    }
    const AVCodecID id = in->codecpar->codec_id;
    if (avformat_query_codec(output->oformat, id, FF_COMPLIANCE_NORMAL) == 0)
      throw Error(
          ErrorKind::unsupported,
          fmt::format("{}: the {} container cannot carry the input's {} audio unchanged (use .mkv)",
                      output_name_, output->oformat->name, avcodec_get_name(id)));
    AVStream* out = avformat_new_stream(output, nullptr);
    if (out == nullptr) throw Error(ErrorKind::io, "audio copy: out of memory");
    check_av(avcodec_parameters_copy(out->codecpar, in->codecpar), ErrorKind::io, input.string(),
             "cannot copy the audio parameters");
    out->codecpar->codec_tag = 0;  // let the output container pick its own tag
    out->time_base = in->time_base;
    av_dict_copy(&out->metadata, in->metadata, 0);
    map_[i] = out->index;
    any = true;
  }
  if (!any) map_.clear();
}

AudioCopy::~AudioCopy() = default;

void AudioCopy::copy_until(double until) {
  if (map_.empty()) return;
  while (!exhausted_) {
    if (!pending_) {
      const int r = av_read_frame(input_.get(), packet_.get());
      if (r < 0) {
        // End of the input's audio (or damage past which it cannot be read): what was copied
        // stays; the video decides whether the input was complete.
        exhausted_ = true;
        return;
      }
      if (map_[static_cast<std::size_t>(packet_->stream_index)] < 0) {
        av_packet_unref(packet_.get());
        continue;
      }
      pending_ = true;
    }
    const AVStream* in = input_->streams[packet_->stream_index];
    const std::int64_t stamp = packet_->pts != AV_NOPTS_VALUE ? packet_->pts : packet_->dts;
    if (stamp == AV_NOPTS_VALUE) {  // cannot place it in time: drop it
      av_packet_unref(packet_.get());
      pending_ = false;
      continue;
    }
    const double t = static_cast<double>(stamp) * av_q2d(in->time_base) - origin_;
    if (t >= until) return;  // not due yet: keep it for a later call
    pending_ = false;
    // A packet that ends before time 0 is not heard; one that reaches it is kept with its negative
    // time (the muxer trims it: an edit list in MP4): an AAC priming packet, or the one before a
    // --frames cut, which the decoder needs for its overlap.
    // A packet without a duration (Matroska's first, the priming one) lasts its frame's samples.
    std::int64_t duration = packet_->duration;
    if (duration <= 0 && in->codecpar->sample_rate > 0)
      duration = av_rescale_q(av_get_audio_frame_duration2(in->codecpar, packet_->size),
                              AVRational{1, in->codecpar->sample_rate}, in->time_base);
    const double length = static_cast<double>(duration) * av_q2d(in->time_base);
    if (t + length < -1e-6) {
      av_packet_unref(packet_.get());
      continue;
    }
    // Shift by the origin on the input's clock, then into the output stream's time base.
    const std::int64_t shift = std::llround(origin_ / av_q2d(in->time_base));
    if (packet_->pts != AV_NOPTS_VALUE) packet_->pts -= shift;
    if (packet_->dts != AV_NOPTS_VALUE) packet_->dts -= shift;
    const int out_index = map_[static_cast<std::size_t>(packet_->stream_index)];
    av_packet_rescale_ts(packet_.get(), in->time_base, output_->streams[out_index]->time_base);
    packet_->stream_index = out_index;
    packet_->pos = -1;
    check_av(av_interleaved_write_frame(output_, packet_.get()), ErrorKind::io, output_name_,
             "cannot write audio");
  }
}

}  // namespace ifsfx::video::detail
