#include "gpu_discrete_tf.hpp"

#include <span>
#include <vector>

namespace vri::vulkan {

namespace {

void put(std::vector<float>& out, const TfSample& s) {
  for (double v : {s.r, s.g, s.b, s.tau}) out.push_back(static_cast<float>(v));
}

std::vector<float> samples_of(const DiscreteTf& tf) {
  std::vector<float> out;
  for (int i = 0; i < tf.size(); ++i) put(out, tf[i]);
  return out;
}

std::vector<int> sub_begin_of(const DiscreteTf& tf) {
  std::vector<int> out;
  for (int k = 0; k <= tf.size(); ++k) out.push_back(tf.sub_begin(k));
  return out;
}

// 12 floats a sub-piece (discrete_tf.glsl's SubPiece); one unused one when
// there are none (a buffer is never empty).
std::vector<float> subs_of(const DiscreteTf& tf) {
  std::vector<float> out;
  for (int k = 0; k + 1 < tf.size(); ++k)
    for (const SubPiece& s : tf.sub_pieces(k)) {
      for (double v : {s.u0 - k, s.u1 - k, s.u1 - s.u0, 0.0}) out.push_back(static_cast<float>(v));
      put(out, s.p);
      put(out, s.q);
    }
  if (out.empty()) out.resize(12, 0.0f);
  return out;
}

template <class T>
std::span<const std::byte> bytes_of(const std::vector<T>& v) {
  return std::as_bytes(std::span<const T>(v));
}

}  // namespace

GpuDiscreteTf::GpuDiscreteTf(const std::shared_ptr<const VulkanDevice>& device, const DiscreteTf& tf)
    : samples(device, bytes_of(samples_of(tf)), "the table's transfer function"),
      sub_begin(device, bytes_of(sub_begin_of(tf)), "the table's transfer function"),
      subs(device, bytes_of(subs_of(tf)), "the table's transfer function") {}

}  // namespace vri::vulkan
