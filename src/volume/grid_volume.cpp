#include "vri/volume.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <mutex>
#include <string>

#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "volume/macro_cells.hpp"

namespace vri {

namespace {

// Point i of a grid on axis a, as GridVolume::box_hi computes it.
double point(Vec3 origin, Vec3 spacing, int a, int i) { return origin[a] + i * spacing[a]; }

}  // namespace

std::uint64_t GridVolume::checked_sample_count(std::array<std::int64_t, 3> dims) {
  for (int a = 0; a < 3; ++a) {
    if (dims[a] < 2)
      throw Error("volume dims must each be at least 2, got " + std::to_string(dims[a]));
    if (dims[a] > (std::int64_t{1} << 24))
      throw Error("volume dim " + std::to_string(dims[a]) + " is absurdly large");
  }
  // Three dims of up to 2^24 each can overflow 64 bits: multiply with a check.
  std::uint64_t n = 0;
  const bool wraps = __builtin_mul_overflow(static_cast<std::uint64_t>(dims[0]), static_cast<std::uint64_t>(dims[1]), &n) ||
                     __builtin_mul_overflow(n, static_cast<std::uint64_t>(dims[2]), &n);
  if (wraps || n > kMaxSamples)
    throw Error("volume of " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) + "x" +
                std::to_string(dims[2]) + " samples exceeds the limit of " +
                std::to_string(kMaxSamples) + " samples");
  return n;
}

namespace {

// Owned samples, charged to the process's memory budget for as long as any
// copy of the volume lives (every copy shares them).
struct ChargedSamples {
  explicit ChargedSamples(GridVolume::Samples v)
      : values(std::move(v)),
        charge(MemoryCharge::process_only(
            std::visit([](const auto& s) { return std::uint64_t(s.size() * sizeof(s[0])); }, values),
            "the volume's samples")) {}
  GridVolume::Samples values;
  MemoryCharge charge;
};

// Owned samples moved behind a shared owner, and the view of them.
std::pair<GridVolume::SampleView, std::shared_ptr<const void>> shared_samples(GridVolume::Samples values) {
  auto owner = std::make_shared<const ChargedSamples>(std::move(values));
  const GridVolume::SampleView view =
      std::visit([](const auto& v) -> GridVolume::SampleView { return std::span(v); }, owner->values);
  return {view, std::move(owner)};
}

}  // namespace

struct GridVolume::Cache {
  std::once_flag once;
  std::unique_ptr<const MacroRanges> macro_ranges;
};

const MacroRanges& GridVolume::macro_ranges() const {
  std::call_once(cache_->once,
                 [&] { cache_->macro_ranges = std::make_unique<const MacroRanges>(compute_macro_ranges(*this)); });
  return *cache_->macro_ranges;
}

GridVolume::GridVolume(std::array<int, 3> dims, Samples values, Vec3 spacing, Vec3 origin)
    : GridVolume(dims, shared_samples(std::move(values)), spacing, origin) {}

GridVolume::GridVolume(std::array<int, 3> dims, SampleView values, std::shared_ptr<const void> owner, Vec3 spacing,
                       Vec3 origin)
    : GridVolume(dims, std::pair(values, std::move(owner)), spacing, origin) {}

GridVolume::GridVolume(std::array<int, 3> dims, std::pair<SampleView, std::shared_ptr<const void>> shared,
                       Vec3 spacing, Vec3 origin)
    : dims_(dims), values_(shared.first), owner_(std::move(shared.second)), cache_(std::make_shared<Cache>()) {
  const std::uint64_t n = checked_sample_count({dims[0], dims[1], dims[2]});
  if (size() != n)
    throw Error("volume has " + std::to_string(size()) + " samples, dims need " + std::to_string(n));
  set_spacing(spacing);
  set_origin(origin);
  visit([this](auto v) {
    const auto bad = std::find_if(v.begin(), v.end(), [](auto x) { return !std::isfinite(static_cast<float>(x)); });
    if (bad != v.end()) throw Error("volume sample " + std::to_string(bad - v.begin()) + " is not finite");
    const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
    min_ = static_cast<float>(*lo);
    max_ = static_cast<float>(*hi);
  });
}

namespace {

bool is_stored(ScalarType type) {
  return type == ScalarType::UInt8 || type == ScalarType::UInt16 || type == ScalarType::Int16 ||
         type == ScalarType::Float32;
}

// Storage of `count` samples of a stored type.
GridVolume::Samples storage_for(ScalarType type, std::uint64_t count) {
  switch (type) {
    case ScalarType::UInt8: return std::vector<std::uint8_t>(count);
    case ScalarType::UInt16: return std::vector<std::uint16_t>(count);
    case ScalarType::Int16: return std::vector<std::int16_t>(count);
    default: return std::vector<float>(count);
  }
}

}  // namespace

GridVolume::Samples GridVolume::decode(ScalarType type, Endian endian, std::uint64_t count,
                                       const std::function<void(std::span<std::byte>)>& fill) {
  const std::size_t size = scalar_type_size(type);
  // The stored samples, plus the file's bytes for a type converted to float.
  check_allocation(count, (is_stored(type) ? 0 : size) + scalar_type_size(is_stored(type) ? type : ScalarType::Float32),
                   "a volume of " + std::to_string(count) + " samples");
  if (!is_stored(type)) {  // converted to float
    std::vector<std::byte> bytes(count * size);
    fill(bytes);
    return decode_samples(bytes, type, endian, count);
  }
  Samples out = storage_for(type, count);
  const auto bytes = std::visit([](auto& v) { return std::as_writable_bytes(std::span(v)); }, out);
  fill(bytes);
  if ((endian == Endian::Big) != (std::endian::native == std::endian::big))
    for (std::size_t i = 0; i + size <= bytes.size(); i += size) std::reverse(bytes.begin() + i, bytes.begin() + i + size);
  return out;
}

ScalarType GridVolume::type() const {
  constexpr ScalarType types[] = {ScalarType::UInt8, ScalarType::UInt16, ScalarType::Int16, ScalarType::Float32};
  return types[values_.index()];
}

std::size_t GridVolume::size() const {
  return visit([](auto v) { return v.size(); });
}

std::size_t GridVolume::bytes() const {
  return visit([](auto v) { return v.size_bytes(); });
}

void GridVolume::set_spacing(Vec3 spacing) {
  for (int a = 0; a < 3; ++a)
    if (!(spacing[a] > 0) || !std::isfinite(spacing[a]))
      throw Error("volume spacing must be positive and finite");
  spacing_ = spacing;
  if (brick_) set_origin(brick_->whole_origin);  // a part moves with its offset
}

void GridVolume::set_origin(Vec3 origin) {
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(origin[a])) throw Error("volume origin must be finite");
  if (!brick_) {
    origin_ = origin;
    return;
  }
  brick_->whole_origin = origin;  // a part sits at its offset in the whole grid
  for (int a = 0; a < 3; ++a) origin_[a] = point(origin, spacing_, a, brick_->offset[a]);
}

Vec3 GridVolume::box_hi() const {
  return {origin_.x + (dims_[0] - 1) * spacing_.x, origin_.y + (dims_[1] - 1) * spacing_.y,
          origin_.z + (dims_[2] - 1) * spacing_.z};
}

void GridVolume::set_brick(const Brick& b) {
  for (int a = 0; a < 3; ++a)
    if (!(b.offset[a] >= 0 && b.offset[a] + dims_[a] <= b.whole_dims[a] && 0 <= b.own_lo[a] &&
          b.own_lo[a] < b.own_hi[a] && b.own_hi[a] <= b.whole_dims[a] - 1))
      throw Error("a brick must lie in its whole grid");
  brick_ = b;
  min_ = b.whole_min;
  max_ = b.whole_max;
  set_origin(b.whole_origin);
}

Vec3 GridVolume::whole_lo() const { return brick_ ? brick_->whole_origin : origin_; }

Vec3 GridVolume::whole_hi() const {
  if (!brick_) return box_hi();
  const Brick& b = *brick_;
  return {point(b.whole_origin, spacing_, 0, b.whole_dims[0] - 1), point(b.whole_origin, spacing_, 1, b.whole_dims[1] - 1),
          point(b.whole_origin, spacing_, 2, b.whole_dims[2] - 1)};
}

std::optional<Interval> GridVolume::clip(const Ray& ray) const {
  auto iv = clip_to_box(ray, whole_lo(), whole_hi());
  if (iv && clip_.active() && !clip_.cut(ray, iv->t0, iv->t1)) return std::nullopt;
  if (!iv || !brick_) return iv;
  const Brick& b = *brick_;
  // The owned window from the split planes alone: (plane - o) / d, the same
  // double on both sides of a plane.
  for (int a = 0; a < 3; ++a) {
    const bool split_lo = b.own_lo[a] > 0, split_hi = b.own_hi[a] < b.whole_dims[a] - 1;
    const double lo = point(b.whole_origin, spacing_, a, b.own_lo[a]);
    const double hi = point(b.whole_origin, spacing_, a, b.own_hi[a]);
    const double o = ray.origin[a], d = ray.dir[a];
    if (d == 0) {  // parallel to the planes: owned if o lies in [lo, hi)
      if ((split_lo && o < lo) || (split_hi && !(o < hi))) return std::nullopt;
      continue;
    }
    if (d > 0 ? split_lo : split_hi) iv->own0 = std::max(iv->own0, ((d > 0 ? lo : hi) - o) / d);
    if (d > 0 ? split_hi : split_lo) iv->own1 = std::min(iv->own1, ((d > 0 ? hi : lo) - o) / d);
  }
  if (!(iv->own1 > iv->own0) || iv->own1 <= iv->t0 || iv->own0 >= iv->t1) return std::nullopt;
  return iv;
}

double GridVolume::voxel_unit() const {
  return std::min({spacing_.x, spacing_.y, spacing_.z});
}

}  // namespace vri
