// `vri turntable -o x.mp4`, read back with FFmpeg's own demuxer and decoder:
// N frames of the image's size (an odd width padded by one column), and the
// first frame the render it encodes, to the codec's loss.
#include <gtest/gtest.h>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cli/cli_support.hpp"
#include "vri/io.hpp"

namespace vri::test {
namespace {

struct Decoded {
  int frames = 0, width = 0, height = 0;
  double seconds = 0;  // the stream's duration
  std::string codec;
  std::vector<std::uint8_t> first_rgb;
};

Decoded decode(const std::filesystem::path& file) {
  Decoded d;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0) return d;
  avformat_find_stream_info(format, nullptr);
  const AVCodec* decoder = nullptr;
  const int index = av_find_best_stream(format, AVMEDIA_TYPE_VIDEO, -1, -1, &decoder, 0);
  AVCodecContext* codec = avcodec_alloc_context3(decoder);
  avcodec_parameters_to_context(codec, format->streams[index]->codecpar);
  avcodec_open2(codec, decoder, nullptr);
  d.codec = decoder->name;
  const AVStream* stream = format->streams[index];
  d.seconds = double(stream->duration) * av_q2d(stream->time_base);
  AVPacket* packet = av_packet_alloc();
  AVFrame* frame = av_frame_alloc();
  auto receive = [&] {
    while (avcodec_receive_frame(codec, frame) == 0) {
      if (d.frames++ == 0) {
        d.width = frame->width;
        d.height = frame->height;
        SwsContext* sws = sws_getContext(frame->width, frame->height, AVPixelFormat(frame->format), frame->width,
                                         frame->height, AV_PIX_FMT_RGB24, SWS_BICUBIC, nullptr, nullptr, nullptr);
        d.first_rgb.resize(std::size_t(frame->width) * frame->height * 3);
        std::uint8_t* dst[1] = {d.first_rgb.data()};
        const int stride[1] = {3 * frame->width};
        sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, stride);
        sws_freeContext(sws);
      }
    }
  };
  while (av_read_frame(format, packet) >= 0) {
    if (packet->stream_index == index) avcodec_send_packet(codec, packet);
    av_packet_unref(packet);
    receive();
  }
  avcodec_send_packet(codec, nullptr);
  receive();
  av_frame_free(&frame);
  av_packet_free(&packet);
  avcodec_free_context(&codec);
  avformat_close_input(&format);
  return d;
}

TEST(TurntableVideo, DecodesToTheRenderedFrames) {
  TempDir dir;
  const std::string scene = source_path("scenes/neghip.json");
  const std::string flags = " --method preint1 --width 63 --height 48 --threads 1 -q";
  const ProcessResult r = run("turntable " + scene + " --frames 12 --fps 24 -o " + (dir / "o.mp4").string() + flags, dir);
  ASSERT_EQ(r.code, 0) << r.err;
  ASSERT_EQ(run("render " + scene + " -o " + (dir / "f0.npy").string() + flags, dir).code, 0);
  const Decoded d = decode(dir / "o.mp4");
  EXPECT_EQ(d.frames, 12);
  EXPECT_NEAR(d.seconds, 12 / 24.0, 1e-9);  // the last frame shown its 1/24 s too
  EXPECT_EQ(d.width, 64);  // padded to even for yuv420p
  EXPECT_EQ(d.height, 48);
  // The encoder named in the summary made what the decoder reads.
  const bool h264 = r.err.find("(libx264)") != std::string::npos;
  EXPECT_EQ(d.codec, h264 ? "h264" : "mpeg4") << r.err;
  // Frame 0 against the .npy over the scene's black background, in luma
  // (yuv420p keeps it at full resolution; chroma is halved both ways): the
  // mean error within 1.5 of 255 (0.76 with Debian 12's libx264), none over 40 (19.7).
  const NpyArray npy = read_npy(dir / "f0.npy");
  double sum = 0, worst = 0;
  auto luma = [](auto r, auto g, auto b) { return 0.299 * r + 0.587 * g + 0.114 * b; };
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 63; ++x) {
      const float* p = &npy.data[(std::size_t(y) * 63 + x) * 4];
      const std::uint8_t* q = &d.first_rgb[(std::size_t(y) * 64 + x) * 3];
      auto byte = [](float v) { return std::round(std::clamp(v, 0.f, 1.f) * 255); };
      const double err = std::abs(luma(byte(p[0]), byte(p[1]), byte(p[2])) - luma(q[0], q[1], q[2]));
      sum += err;
      worst = std::max(worst, err);
    }
  std::printf("frame 0 luma error: mean %.2f, max %.1f (of 255)\n", sum / (48 * 63), worst);
  EXPECT_LT(sum / (48 * 63), 1.5);
  EXPECT_LT(worst, 40);
}

TEST(TurntableVideo, SameBytesEveryRun) {
  TempDir dir;
  const std::string args = "turntable " + source_path("scenes/neghip.json") +
                           " --frames 3 --method preint1 --width 32 --height 32 -q -o ";
  ASSERT_EQ(run(args + (dir / "a.mp4").string(), dir).code, 0);
  ASSERT_EQ(run(args + (dir / "b.mp4").string() + " --threads 1", dir).code, 0);
  EXPECT_EQ(slurp(dir / "a.mp4"), slurp(dir / "b.mp4"));
}

}  // namespace
}  // namespace vri::test
