#pragma once
// GridVolume: a scalar field on nx*ny*nz points, x fastest, trilinear between
// samples; the medium is the closed box B of SPEC §1. The samples keep the
// file's own type for uint8, uint16 and int16 (1 or 2 bytes a sample: a 512³
// uint8 volume holds 128 MiB, not 512), float otherwise; every conversion to
// float is exact, so each reader gets the values a float volume would hold.
// Hot loops dispatch on the type once (visit) and read typed samples.
// The samples are immutable and shared: a copy of a GridVolume shares them,
// and a volume may view memory it does not own (a numpy array from Python).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <variant>
#include <vector>

#include "vri/core/ray.hpp"
#include "vri/core/vec3.hpp"
#include "vri/volume/scalar_type.hpp"

namespace vri {

struct MacroRanges;  // volume/macro_cells.hpp

class GridVolume {
 public:
  // Largest accepted volume: 2^30 samples (4 GiB as float). Bigger requests are
  // refused before any allocation so absurd dims fail cleanly.
  static constexpr std::uint64_t kMaxSamples = std::uint64_t{1} << 30;

  // The storage types, x fastest.
  using Samples = std::variant<std::vector<std::uint8_t>, std::vector<std::uint16_t>,
                               std::vector<std::int16_t>, std::vector<float>>;

  // The same types viewed in place.
  using SampleView = std::variant<std::span<const std::uint8_t>, std::span<const std::uint16_t>,
                                  std::span<const std::int16_t>, std::span<const float>>;

  // Checks dims >= 2, the sample count == nx*ny*nz, every value finite,
  // spacing > 0; throws vri::Error otherwise.
  GridVolume(std::array<int, 3> dims, Samples values, Vec3 spacing = {1, 1, 1}, Vec3 origin = {0, 0, 0});
  // The same checks on samples viewed without a copy; `owner` keeps their
  // memory alive as long as any copy of the volume lives.
  GridVolume(std::array<int, 3> dims, SampleView values, std::shared_ptr<const void> owner,
             Vec3 spacing = {1, 1, 1}, Vec3 origin = {0, 0, 0});

  // Throws vri::Error unless dims describe an acceptable volume; returns the sample count.
  static std::uint64_t checked_sample_count(std::array<std::int64_t, 3> dims);

  // `count` samples of a file's `type`, decoded straight into the storage:
  // `fill` writes exactly count * scalar_type_size(type) bytes into the span it
  // is given, which is the storage itself where the type is kept (byte
  // order swapped in place after), else a buffer converted to float.
  static Samples decode(ScalarType type, Endian endian, std::uint64_t count,
                        const std::function<void(std::span<std::byte>)>& fill);

  const std::array<int, 3>& dims() const { return dims_; }
  Vec3 spacing() const { return spacing_; }
  Vec3 origin() const { return origin_; }
  void set_spacing(Vec3 spacing);
  void set_origin(Vec3 origin);

  // The storage type (UInt8, UInt16, Int16 or Float32), the sample count and
  // the bytes the samples take.
  ScalarType type() const;
  std::size_t size() const;
  std::size_t bytes() const;

  // f(std::span<const T>) with the samples as stored.
  template <class F>
  decltype(auto) visit(F&& f) const {
    return std::visit([&](auto v) -> decltype(auto) { return f(v); }, values_);
  }

  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims_[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims_[1]) * k);
  }
  // One sample as float (a dispatch each: not for hot loops).
  float value(std::size_t index) const {
    return std::visit([index](auto v) { return static_cast<float>(v[index]); }, values_);
  }
  float at(int i, int j, int k) const { return value(index(i, j, k)); }

  float min_value() const { return min_; }
  float max_value() const { return max_; }

  // The min and max over each macro cell (macro_cells.hpp), computed on first
  // use and shared by every copy of this volume: the samples never change, so
  // every integrator made for it - one per transfer-function edit in the
  // viewer - reuses them. Thread-safe.
  const MacroRanges& macro_ranges() const;

  Vec3 box_lo() const { return origin_; }
  Vec3 box_hi() const;

  // Sort-last rendering (distributed/, docs/DISTRIBUTED.md): this volume may
  // hold a part of a larger grid - the points offset .. offset + dims - 1 of
  // it - and own the cells own_lo .. own_hi - 1 of the whole grid (its brick;
  // the rest are a ghost layer). Rays are then clipped to the whole grid's
  // box, so every sample stands where it stands on one machine, and a method
  // integrates only the pieces of a ray whose front lies in the owned box
  // (Interval::own0, own1): half open across the split planes, so each piece
  // has one owner. origin() is whole_origin + offset spacing (set_origin sets
  // the whole grid's), min_value() and max_value() are the whole grid's.
  struct Brick {
    std::array<int, 3> whole_dims, offset;
    Vec3 whole_origin;
    std::array<int, 3> own_lo, own_hi;  // cells of the whole grid
    float whole_min, whole_max;
  };
  // Throws vri::Error unless the part and the owned cells lie in the whole grid.
  void set_brick(const Brick& brick);
  const std::optional<Brick>& brick() const { return brick_; }
  // The whole grid's box (this volume's own unless a part).
  Vec3 whole_lo() const;
  Vec3 whole_hi() const;
  // The box rays are clipped to (clip): every grid method's footprint.
  Box whole_box() const { return {whole_lo(), whole_hi()}; }
  // The ray clipped to the whole grid's box with the part this volume owns;
  // nullopt where it misses the box or owns none of it.
  std::optional<Interval> clip(const Ray& ray) const;
  // min(sx, sy, sz): the unit of step sizes (SPEC §1).
  double voxel_unit() const;

  // Trilinear value at a world point; points outside B are clamped onto it.
  double sample(Vec3 p) const {
    return visit([&](auto v) { return sample(v.data(), p); });
  }
  // The same on the typed samples (visit's span data), for loops that dispatched once.
  template <class T>
  double sample(const T* values, Vec3 p) const {
    return sample_grid(values, grid_position(p));
  }
  // The same at grid position u (index units: grid_position), for walks
  // that step in it; clamped onto the grid.
  template <class T>
  double sample_grid(const T* values, Vec3 u) const;

  // Index units of a world point: (p - origin) / spacing.
  Vec3 grid_position(Vec3 p) const {
    return {(p.x - origin_.x) / spacing_.x, (p.y - origin_.y) / spacing_.y, (p.z - origin_.z) / spacing_.z};
  }
  // The cell that trilinear interpolation at grid position u reads (u
  // clamped onto the grid; the last cell on the upper faces), and u's
  // fractions in it.
  struct GridCell {
    std::array<int, 3> index;
    double f[3];
  };
  GridCell cell_at(Vec3 u) const {
    GridCell c;
    for (int a = 0; a < 3; ++a) {
      const double v = std::clamp(u[a], 0.0, double(dims_[a] - 1));
      c.index[a] = std::min(static_cast<int>(v), dims_[a] - 2);
      c.f[a] = v - c.index[a];
    }
    return c;
  }

 private:
  GridVolume(std::array<int, 3> dims, std::pair<SampleView, std::shared_ptr<const void>> shared, Vec3 spacing,
             Vec3 origin);

  std::array<int, 3> dims_;
  SampleView values_;
  std::shared_ptr<const void> owner_;
  Vec3 spacing_, origin_;
  float min_ = 0, max_ = 0;
  std::optional<Brick> brick_;
  struct Cache;  // what is derived from the samples once (grid_volume.cpp)
  std::shared_ptr<Cache> cache_;
};

// The 8 corners of the cell whose first corner is `t` (strides 1, sy, sz), in
// float as a float volume holds them, x fastest: c000 c100 c010 c110 c001 ...
template <class T>
std::array<float, 8> corners_as_float(const T* t, std::size_t sy, std::size_t sz) {
  return {float(t[0]),  float(t[1]),      float(t[sy]),      float(t[sy + 1]),
          float(t[sz]), float(t[sz + 1]), float(t[sz + sy]), float(t[sz + sy + 1])};
}

template <class T>
double GridVolume::sample_grid(const T* values, Vec3 u) const {
  const GridCell cell = cell_at(u);
  const auto& c = cell.index;
  const auto& f = cell.f;
  const std::size_t sy = dims_[0], sz = std::size_t(dims_[0]) * dims_[1];
  const auto v = corners_as_float(values + index(c[0], c[1], c[2]), sy, sz);  // differences below in float
  const double c00 = v[0] + f[0] * (v[1] - v[0]);
  const double c10 = v[2] + f[0] * (v[3] - v[2]);
  const double c01 = v[4] + f[0] * (v[5] - v[4]);
  const double c11 = v[6] + f[0] * (v[7] - v[6]);
  const double c0 = c00 + f[1] * (c10 - c00);
  const double c1 = c01 + f[1] * (c11 - c01);
  return c0 + f[2] * (c1 - c0);
}

}  // namespace vri
