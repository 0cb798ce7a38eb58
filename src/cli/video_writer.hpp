#pragma once
// MP4 video of rendered frames (`vri turntable -o x.mp4`, issue 20) through
// FFmpeg's libraries from Debian (libavformat, libavcodec, libswscale):
// H.264 by libx264 at constant quality (crf 18) when the libavcodec has it,
// else MPEG-4 part 2; yuv420p, so an odd width or height is padded by one
// repeated column or row. The file is built in memory and handed over whole,
// so it is staged like every output (OutputTransaction): no partial file.
#include <cstddef>
#include <memory>
#include <vector>

#include "vri/geometry.hpp"
#include "vri/image.hpp"

namespace vri::cli {

// Whether this vri was built with FFmpeg.
bool video_supported();

class VideoWriter {
 public:
  // vri::Error without FFmpeg, for a bad size or frame rate, or if no encoder opens.
  VideoWriter(int width, int height, int fps);
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // The next frame, composited over `background` as a PNG is (png.hpp).
  void add(const Image& image, Vec3 background);
  // Flushes the encoder and returns the MP4 file's bytes.
  std::vector<std::byte> finish();
  // The encoder's name (libx264 or mpeg4).
  const char* codec() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace vri::cli
