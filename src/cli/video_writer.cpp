#include "video_writer.hpp"

#include <algorithm>
#include <cstring>
#include <string>

#include "vri/error.hpp"
#include "vri/io.hpp"

#include "ffmpeg_library.hpp"

namespace vri::cli {

#if VRI_HAVE_FFMPEG

namespace {

std::string av_error(int code) {
  char text[AV_ERROR_MAX_STRING_SIZE] = {};
  ffmpeg().av_strerror(code, text, sizeof text);
  return text;
}

void check(int code, const char* what) {
  if (code < 0) throw Error(std::string("video: ") + what + ": " + av_error(code));
}

// A seekable file in memory for libavformat: the mp4 muxer seeks back to
// write the sizes of its boxes.
struct MemoryFile {
  std::vector<std::byte> bytes;
  std::size_t pos = 0;

#if LIBAVFORMAT_VERSION_MAJOR >= 61  // FFmpeg 7 made the data const
  static int write(void* opaque, const std::uint8_t* data, int size) {
#else
  static int write(void* opaque, std::uint8_t* data, int size) {
#endif
    auto* f = static_cast<MemoryFile*>(opaque);
    if (f->pos + size > f->bytes.size()) f->bytes.resize(f->pos + size);
    std::memcpy(f->bytes.data() + f->pos, data, std::size_t(size));
    f->pos += std::size_t(size);
    return size;
  }
  static std::int64_t seek(void* opaque, std::int64_t offset, int whence) {
    auto* f = static_cast<MemoryFile*>(opaque);
    const auto size = static_cast<std::int64_t>(f->bytes.size());
    if (whence & AVSEEK_SIZE) return size;
    const std::int64_t base = (whence & 3) == SEEK_CUR ? std::int64_t(f->pos) : (whence & 3) == SEEK_END ? size : 0;
    if (base + offset < 0) return AVERROR(EINVAL);
    f->pos = std::size_t(base + offset);
    return std::int64_t(f->pos);
  }
};

}  // namespace

struct VideoWriter::State {
  int width = 0, height = 0;  // the images'
  AVFormatContext* format = nullptr;
  AVCodecContext* codec = nullptr;
  AVStream* stream = nullptr;
  AVIOContext* io = nullptr;
  SwsContext* scale = nullptr;
  AVFrame* frame = nullptr;
  AVPacket* packet = nullptr;
  MemoryFile file;
  std::vector<std::uint8_t> rgb;  // the padded RGB of one frame
  std::int64_t next_pts = 0;

  ~State() {
    ffmpeg().av_packet_free(&packet);
    ffmpeg().av_frame_free(&frame);
    ffmpeg().sws_freeContext(scale);
    ffmpeg().avcodec_free_context(&codec);
    if (io) ffmpeg().av_freep(&io->buffer);
    ffmpeg().avio_context_free(&io);
    ffmpeg().avformat_free_context(format);
  }

  // Every packet the encoder has ready, into the file.
  void drain() {
    for (;;) {
      const int r = ffmpeg().avcodec_receive_packet(codec, packet);
      if (r == AVERROR(EAGAIN) || r == AVERROR_EOF) return;
      check(r, "encoding");
      // Each frame lasts one tick of 1/fps: said on the packet, else MP4
      // gives the last frame no duration (the video a frame short: issue 51).
      if (packet->duration <= 0) packet->duration = 1;
      ffmpeg().av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
      packet->stream_index = stream->index;
      check(ffmpeg().av_interleaved_write_frame(format, packet), "writing");
    }
  }
};

bool video_supported() { return true; }

VideoWriter::VideoWriter(int width, int height, int fps) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw Error("video: frames of " + std::to_string(width) + "x" + std::to_string(height) + " cannot be encoded");
  if (fps < 1 || fps > 240) throw Error("--fps must be 1..240, not " + std::to_string(fps));
  ffmpeg().av_log_set_level(AV_LOG_QUIET);  // loads FFmpeg; errors come back as codes, said in one line
  state_ = std::make_unique<State>();     // freed through FFmpeg, so only once it is loaded
  State& s = *state_;
  s.width = width;
  s.height = height;
  const int w = width + (width & 1), h = height + (height & 1);  // yuv420p halves both
  check(ffmpeg().avformat_alloc_output_context2(&s.format, nullptr, "mp4", nullptr), "the mp4 muxer");
  const AVCodec* encoder = ffmpeg().avcodec_find_encoder_by_name("libx264");
  if (!encoder) encoder = ffmpeg().avcodec_find_encoder(AV_CODEC_ID_MPEG4);
  if (!encoder) throw Error("video: this FFmpeg has neither libx264 nor an MPEG-4 encoder");
  s.codec = ffmpeg().avcodec_alloc_context3(encoder);
  s.codec->width = w;
  s.codec->height = h;
  s.codec->pix_fmt = AV_PIX_FMT_YUV420P;
  s.codec->time_base = {1, fps};
  s.codec->framerate = {fps, 1};
  s.codec->gop_size = fps;
  s.codec->thread_count = 1;  // the same bytes on every run
  if (std::strcmp(encoder->name, "libx264") == 0) {
    ffmpeg().av_opt_set(s.codec->priv_data, "crf", "18", 0);
    ffmpeg().av_opt_set(s.codec->priv_data, "preset", "medium", 0);
  } else {
    s.codec->flags |= AV_CODEC_FLAG_QSCALE;
    s.codec->global_quality = FF_QP2LAMBDA * 2;
  }
  if (s.format->oformat->flags & AVFMT_GLOBALHEADER) s.codec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
  check(ffmpeg().avcodec_open2(s.codec, encoder, nullptr), "opening the encoder");
  s.stream = ffmpeg().avformat_new_stream(s.format, nullptr);
  if (!s.stream) throw Error("video: cannot add a stream");
  s.stream->time_base = s.codec->time_base;
  check(ffmpeg().avcodec_parameters_from_context(s.stream->codecpar, s.codec), "stream parameters");

  constexpr int kBuffer = 1 << 16;
  auto* buffer = static_cast<unsigned char*>(ffmpeg().av_malloc(kBuffer));
  s.io = ffmpeg().avio_alloc_context(buffer, kBuffer, 1, &s.file, nullptr, &MemoryFile::write, &MemoryFile::seek);
  if (!s.io) {
    ffmpeg().av_free(buffer);
    throw Error("video: out of memory");
  }
  s.format->pb = s.io;
  check(ffmpeg().avformat_write_header(s.format, nullptr), "the mp4 header");

  s.scale = ffmpeg().sws_getContext(w, h, AV_PIX_FMT_RGB24, w, h, AV_PIX_FMT_YUV420P, SWS_BICUBIC, nullptr, nullptr, nullptr);
  s.frame = ffmpeg().av_frame_alloc();
  s.packet = ffmpeg().av_packet_alloc();
  if (!s.scale || !s.frame || !s.packet) throw Error("video: out of memory");
  s.frame->format = AV_PIX_FMT_YUV420P;
  s.frame->width = w;
  s.frame->height = h;
  check(ffmpeg().av_frame_get_buffer(s.frame, 0), "a frame buffer");
  s.rgb.resize(std::size_t(w) * h * 3);
}

VideoWriter::~VideoWriter() = default;

const char* VideoWriter::codec() const { return state_->codec->codec->name; }

void VideoWriter::add(const Image& image, Vec3 background) {
  State& s = *state_;
  if (image.width() != s.width || image.height() != s.height) throw Error("video: frames differ in size");
  const std::vector<std::uint8_t> rgba = composite_rgba8(image, background);
  const int w = s.codec->width, h = s.codec->height;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {  // the padding repeats the last column and row
      const std::uint8_t* p = &rgba[(std::size_t(std::min(y, s.height - 1)) * s.width + std::min(x, s.width - 1)) * 4];
      std::memcpy(&s.rgb[(std::size_t(y) * w + x) * 3], p, 3);
    }
  check(ffmpeg().av_frame_make_writable(s.frame), "a frame buffer");
  const std::uint8_t* src[1] = {s.rgb.data()};
  const int stride[1] = {3 * w};
  ffmpeg().sws_scale(s.scale, src, stride, 0, h, s.frame->data, s.frame->linesize);
  s.frame->pts = s.next_pts++;
  check(ffmpeg().avcodec_send_frame(s.codec, s.frame), "encoding");
  s.drain();
}

std::vector<std::byte> VideoWriter::finish() {
  State& s = *state_;
  check(ffmpeg().avcodec_send_frame(s.codec, nullptr), "flushing the encoder");
  s.drain();
  check(ffmpeg().av_write_trailer(s.format), "the mp4 index");
  ffmpeg().avio_flush(s.io);
  return std::move(s.file.bytes);
}

#else  // without FFmpeg

struct VideoWriter::State {};

bool video_supported() { return false; }

VideoWriter::VideoWriter(int, int, int) {
  throw Error("this vri was built without video output (it needs libavformat-dev, libavcodec-dev and "
              "libswscale-dev); write the frames to a folder instead");
}
VideoWriter::~VideoWriter() = default;
const char* VideoWriter::codec() const { return ""; }
void VideoWriter::add(const Image&, Vec3) {}
std::vector<std::byte> VideoWriter::finish() { return {}; }

#endif

}  // namespace vri::cli
