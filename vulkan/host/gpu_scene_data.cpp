#include "gpu_scene_data.hpp"

#include <cstring>
#include <span>
#include <type_traits>
#include <vector>

#include "vri/error.hpp"
#include "volume/macro_cells.hpp"

namespace vri::vulkan {

namespace {

// Bytes rounded up to whole 32-bit words (an array the shader reads as uint[]).
std::size_t word_bytes(std::size_t bytes) { return (bytes + 3) / 4 * 4; }

int type_code(const GridVolume& volume) {
  return volume.visit([](auto v) {
    using T = typename decltype(v)::value_type;
    if constexpr (std::is_same_v<T, std::uint8_t>) return 0;
    else if constexpr (std::is_same_v<T, std::uint16_t>) return 1;
    else if constexpr (std::is_same_v<T, std::int16_t>) return 2;
    else return 3;
  });
}

template <class T>
std::span<const std::byte> as_bytes_of(const std::vector<T>& v) {
  return std::as_bytes(std::span<const T>(v));
}

}  // namespace

void check_shader_addressable(std::uint64_t voxels) {
  constexpr std::uint64_t kMost = 0xffffffffULL / 3;  // 3 gradient floats a voxel, one uint offset
  if (voxels > kMost)
    throw Error("vulkan: a volume of " + std::to_string(voxels) + " voxels is beyond the shaders' 32-bit offsets (at most " +
                std::to_string(kMost) + "); use --backend cpu");
}

namespace {

// The samples' bytes in whole words, once the shaders can address them all.
std::size_t addressable_word_bytes(const GridVolume& volume) {
  check_shader_addressable(volume.size());
  return word_bytes(volume.bytes());
}

}  // namespace

GpuVolume::GpuVolume(std::shared_ptr<const VulkanDevice> device, const GridVolume& volume)
    : samples(std::move(device), addressable_word_bytes(volume), "the volume's samples"), type(type_code(volume)) {
  volume.visit([&](auto v) { samples.upload(std::as_bytes(v)); });
}

GpuShading::GpuShading(std::shared_ptr<const VulkanDevice> device, const Lighting& lighting,
                       const HeadlightShader& shader, const GridVolume& volume)
    : gradients(std::move(device),
                std::as_bytes(std::span<const float>(shader.gradients().data(), 3 * volume.size())),
                "the gradient field (lighting)"),
      ka(static_cast<float>(lighting.ambient)),
      kd(static_cast<float>(lighting.diffuse)),
      ks(static_cast<float>(lighting.specular)),
      shininess(static_cast<float>(lighting.shininess)),
      flat(static_cast<float>(shader.flat_threshold())) {
}

ShadingParams shading_params(const std::optional<GpuShading>& s, int mode) {
  if (!s) return {};
  return {mode, s->ka, s->kd, s->ks, s->shininess, s->flat};
}

namespace {

std::vector<std::uint32_t> empty_bits(const GridVolume& volume, const EmptySpace* space) {
  if (!space) return {0u};
  const MacroCells cells(volume);
  std::vector<std::uint32_t> bits((cells.count() + 31) / 32, 0u);
  for (std::size_t i = 0; i < cells.count(); ++i)
    if (space->empty(i)) bits[i / 32] |= 1u << (i % 32);
  return bits;
}

}  // namespace

GpuEmptySpace::GpuEmptySpace(std::shared_ptr<const VulkanDevice> device, const GridVolume& volume,
                             const EmptySpace* space)
    : bits(std::move(device), as_bytes_of(empty_bits(volume, space)), "the empty macro cells") {
  params = {0, {1, 1, 1}};  // off
  if (!space) return;
  params.skip = 1;
  const MacroCells cells(volume);
  for (int a = 0; a < 3; ++a) params.macro[a] = cells.dims()[a];
}

Bindings table_march_inputs(const GpuVolume& volume, const std::array<std::optional<GpuArray>, 3>& tables,
                            const std::optional<GpuShading>& shading, const GpuEmptySpace& empty) {
  const auto or_volume = [&](const std::optional<GpuArray>& a) -> const GpuArray& { return a ? *a : volume.samples; };
  Bindings b;
  b.add(volume.samples).add(or_volume(tables[0])).add(or_volume(tables[1])).add(or_volume(tables[2]));
  b.add(shading ? shading->gradients : volume.samples).add(nullptr /* the rays */);
  b.add(&empty.bits);
  return b;
}

GpuTransferFunction::GpuTransferFunction(std::shared_ptr<const VulkanDevice> device, const FloatTransferFunction& tf)
    : values(device, sizeof(float) * 10 * static_cast<std::size_t>(tf.segments()), "the transfer function"),
      bins(device, sizeof(int) * FloatTransferFunction::kBins, "the transfer function's bins"),
      segments(tf.segments()),
      lo(tf.lo()),
      scale(tf.scale()) {
  if (tf.breakpoint_count() != segments) throw Error("vulkan: a transfer function with unmatched breakpoints");
  const std::size_t n = static_cast<std::size_t>(segments);
  std::vector<float> v(10 * n);
  std::memcpy(v.data(), tf.breakpoints(), n * sizeof(float));
  std::memcpy(v.data() + n, tf.s_ref(), n * sizeof(float));
  for (int c = 0; c < 4; ++c) {
    std::memcpy(v.data() + (2 + c) * n, tf.value(c), n * sizeof(float));
    std::memcpy(v.data() + (6 + c) * n, tf.slope(c), n * sizeof(float));
  }
  values.upload(as_bytes_of(v));
  bins.upload(std::as_bytes(std::span<const int>(tf.first(), FloatTransferFunction::kBins)));
}

}  // namespace vri::vulkan
