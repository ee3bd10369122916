// SPDX-License-Identifier: Apache-2.0
// Internal helpers shared by the FFmpeg-backed sources and sinks: RAII owners for libav objects
// and the translation of libav error codes into ifsfx::Error (foreign errors are translated where
// they enter, docs/style.md rule 4). Not part of the public interface.
#pragma once

#include <string>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/avutil.h>
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include "ifs/error.h"

namespace ifsfx::video::detail {

// The thread count handed to a decoder or encoder for a requested worker count: 0 stays 0
// (libavcodec's own choice, at most 16), others are checked as resolve_threads() checks them
// (at most kMaxThreads) and capped at 16, since each codec thread holds frames of its own.
int codec_threads(int requested);

// libav's message for an AVERROR code, e.g. "Invalid data found when processing input".
std::string av_message(int code);

// Throws Error{kind, "<what>: <rule> (<libav message>)"} when code < 0; returns code otherwise.
int check_av(int code, ErrorKind kind, const std::string& what, const std::string& rule);

struct InputContextDeleter {
  void operator()(AVFormatContext* c) const { avformat_close_input(&c); }
};
struct OutputContextDeleter {
  void operator()(AVFormatContext* c) const {
    if (c == nullptr) return;
    if (c->pb != nullptr && !(c->oformat->flags & AVFMT_NOFILE)) avio_closep(&c->pb);
    avformat_free_context(c);
  }
};
struct CodecContextDeleter {
  void operator()(AVCodecContext* c) const { avcodec_free_context(&c); }
};
struct FrameDeleter {
  void operator()(AVFrame* f) const { av_frame_free(&f); }
};
struct PacketDeleter {
  void operator()(AVPacket* p) const { av_packet_free(&p); }
};
struct SwsDeleter {
  void operator()(SwsContext* s) const { sws_freeContext(s); }
};

}  // namespace ifsfx::video::detail
