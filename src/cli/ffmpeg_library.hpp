#pragma once
// FFmpeg's functions for the MP4 writer (video_writer.hpp), loaded with
// dlopen on first use instead of linked: linked, libavcodec and its codec
// libraries (about 130 shared objects) would load at every start of `vri`,
// costing tens of milliseconds and more address space than a tight
// `ulimit -v` leaves (tests/cli/output_safety_test.cpp). The headers fix the
// major versions (libavformat.so.59, ... on Debian 12), so the functions'
// types are the headers' own.
#if VRI_HAVE_FFMPEG
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/opt.h>
#include <libswscale/swscale.h>
}

namespace vri::cli {

#define VRI_FFMPEG_FUNCTIONS(X)                                                                                    \
  X(av_strerror) X(av_log_set_level) X(av_malloc) X(av_free) X(av_freep) X(av_opt_set) X(av_frame_alloc)            \
  X(av_frame_free) X(av_frame_get_buffer) X(av_frame_make_writable) X(av_packet_alloc) X(av_packet_free)           \
  X(av_packet_rescale_ts) X(avcodec_find_encoder_by_name) X(avcodec_find_encoder) X(avcodec_alloc_context3)         \
  X(avcodec_free_context) X(avcodec_open2) X(avcodec_parameters_from_context) X(avcodec_send_frame)                \
  X(avcodec_receive_packet) X(avformat_alloc_output_context2) X(avformat_free_context) X(avformat_new_stream)       \
  X(avformat_write_header) X(av_interleaved_write_frame) X(av_write_trailer) X(avio_alloc_context)                  \
  X(avio_context_free) X(avio_flush) X(sws_getContext) X(sws_freeContext) X(sws_scale)

struct FFmpeg {
#define VRI_FFMPEG_POINTER(name) decltype(&::name) name = nullptr;
  VRI_FFMPEG_FUNCTIONS(VRI_FFMPEG_POINTER)
#undef VRI_FFMPEG_POINTER
};

// The functions, loaded once; vri::Error naming the library that is missing.
const FFmpeg& ffmpeg();

}  // namespace vri::cli
#endif
