#include "frame_encoding.hpp"

#include <turbojpeg.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "vri/error.hpp"
#include "vri/io.hpp"

namespace vri::viewer {

std::vector<std::byte> encode_jpeg(const Image& image, Vec3 background, int quality) {
  const std::vector<std::uint8_t> rgba = composite_rgba8(image, background);
  std::unique_ptr<void, int (*)(tjhandle)> tj(tjInitCompress(), tjDestroy);
  if (!tj) throw Error("libturbojpeg: cannot start the encoder");
  unsigned char* jpeg = nullptr;
  unsigned long size = 0;
  if (tjCompress2(tj.get(), rgba.data(), image.width(), 0, image.height(), TJPF_RGBA, &jpeg, &size, TJSAMP_420,
                  std::clamp(quality, 1, 100), TJFLAG_FASTDCT) != 0) {
    tjFree(jpeg);
    throw Error(std::string("libturbojpeg: ") + tjGetErrorStr2(tj.get()));
  }
  std::vector<std::byte> out(size);
  std::memcpy(out.data(), jpeg, size);
  tjFree(jpeg);
  return out;
}

ErrorMap error_map(const Image& frame, const Image& reference, double tolerance) {
  if (frame.width() != reference.width() || frame.height() != reference.height())
    throw Error("error map: the frame and the reference differ in size");
  const int W = frame.width(), H = frame.height();
  std::vector<std::uint8_t> grey(std::size_t(W) * H);
  ErrorMap m;
  double sum_sq = 0;
  std::size_t over = 0;
  for (std::size_t i = 0; i < grey.size(); ++i) {
    double e = 0;
    for (int c = 0; c < 4; ++c) {
      const double d = std::abs(double(frame.data()[4 * i + c]) - double(reference.data()[4 * i + c]));
      e = std::max(e, d);
      sum_sq += d * d;
    }
    m.max = std::max(m.max, e);
    over += e > tolerance;
    const double v = e <= 1e-6 ? 0.0 : (std::log10(e) + 6.0) / 6.0 * 255.0;
    grey[i] = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 255.0)));
  }
  const double n = double(grey.size());
  m.share_over = n > 0 ? double(over) / n : 0;
  m.rms = n > 0 ? std::sqrt(sum_sq / (4 * n)) : 0;
  m.png = encode_png(grey, W, H, 1);
  return m;
}

}  // namespace vri::viewer
