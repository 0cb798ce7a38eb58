#pragma once
// vri/volume.hpp: what is rendered: regular grids (their scalar types, parts and histogram) and tetrahedral meshes.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>
#include <algorithm>
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <variant>

#include "vri/geometry.hpp"
#include "vri/transfer_function.hpp"
#include "vri/memory.hpp"

// ---- scalar_type -----------------------------------------------------------
// ScalarType: the binary sample types vri reads, and their conversion to float.

namespace vri {

enum class ScalarType { UInt8, Int8, UInt16, Int16, UInt32, Int32, Float32, Float64 };
enum class Endian { Little, Big };

// SPEC names: uint8, uint16, int16, float32; also int8, uint32, int32, float64.
// Throws vri::Error for an unknown name.
ScalarType parse_scalar_type(const std::string& name);
std::string scalar_type_name(ScalarType type);
std::size_t scalar_type_size(ScalarType type);

// Converts `count` packed samples to float. Throws if `bytes` is too short.
std::vector<float> decode_samples(std::span<const std::byte> bytes, ScalarType type,
                                  Endian endian, std::uint64_t count);

}  // namespace vri

// ---- grid_volume -----------------------------------------------------------
// GridVolume: a scalar field on nx*ny*nz points, x fastest, trilinear between
// samples; the medium is the closed box B of SPEC §1. The samples keep the
// file's own type for uint8, uint16 and int16 (1 or 2 bytes a sample: a 512³
// uint8 volume holds 128 MiB, not 512), float otherwise; every conversion to
// float is exact, so each reader gets the values a float volume would hold.
// Hot loops dispatch on the type once (visit) and read typed samples.
// The samples are immutable and shared: a copy of a GridVolume shares them,
// and a volume may view memory it does not own (a numpy array from Python).

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
  // The region rays are cut to besides the box (SPEC §12 "clip"): every
  // method's rays on every path, since each clips them here.
  void set_clip(ClipRegion region) { clip_ = std::move(region); }
  const ClipRegion& clip_region() const { return clip_; }
  // The ray clipped to the whole grid's box and the clip region, with the
  // part this volume owns; nullopt where it misses them or owns none of it.
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
  ClipRegion clip_;
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

// ---- grid_part -------------------------------------------------------------
// A part of a grid (distributed rendering: one rank's brick, docs/
// DISTRIBUTED.md): the points lo..hi (inclusive) on each axis, and the
// volume that holds them as a part of the whole grid (GridVolume::Brick).
// Readers take a RegionChooser and read the part alone (io/grid_region.hpp).

namespace vri {

struct GridRegion {
  std::array<int, 3> lo, hi;  // grid points, inclusive
  std::array<int, 3> dims() const { return {hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1}; }
  std::uint64_t points() const {
    const auto d = dims();
    return std::uint64_t(d[0]) * d[1] * d[2];
  }
};

// Chooses the region of a grid of `dims` points, once a reader knows them.
using RegionChooser = std::function<GridRegion(std::array<int, 3> dims)>;

// Throws vri::Error unless `region` lies in a grid of `dims` with 2 points a side at least.
void check_region(const GridRegion& region, std::array<int, 3> dims);

// The region's samples as a part of a grid of `whole_dims` points
// (GridVolume::Brick) owning all its cells until told otherwise, with the
// whole grid's spacing and origin; min and max its own until the whole
// grid's are known.
GridVolume make_part(GridVolume::Samples samples, std::array<int, 3> whole_dims, const GridRegion& region,
                     Vec3 spacing = {1, 1, 1}, Vec3 whole_origin = {0, 0, 0});

// The region of a volume in memory, as a part of it (make_part).
GridVolume cut_region(const GridVolume& volume, const GridRegion& region);

}  // namespace vri

// ---- histogram -------------------------------------------------------------
// The histogram of a volume's scalars, and the transfer function it suggests:
// what `vri info` prints and what the viewer draws its editor over.

namespace vri {

struct Histogram {
  double lo = 0, hi = 0;               // the scalar range; bin i covers lo + i (hi - lo) / bins
  std::vector<std::uint64_t> counts;  // the maximum falls in the last bin
};

Histogram histogram(const GridVolume& volume, int bins = 256);
Histogram histogram(std::span<const float> scalars, int bins = 256);

// A first transfer function for a volume never seen: transparent up to just
// above the background - the most common value when it lies in the lowest
// quarter of the range, where CT and MRI backgrounds lie - then a blue ->
// orange -> white ramp whose densest value stops half the light over a tenth
// of `diagonal` (the box's diagonal, world units).
TransferFunction suggest_transfer_function(const Histogram& h, double diagonal);

}  // namespace vri

// ---- tet_mesh --------------------------------------------------------------
// TetMesh (SPEC §2): points with one scalar each and tetrahedra of four point
// indices; the field is linear inside each tetrahedron and the medium is the
// union of the tetrahedra (it may be non-convex and have holes).
//
// Construction checks and normalises the input once, so every consumer can
// rely on it:
//  - a point index out of range, a non-finite coordinate or scalar (NaN
//    included) is refused with vri::Error naming the tetrahedron or point;
//  - inverted tetrahedra (negative signed volume) are reoriented by swapping
//    two vertices, so every kept tetrahedron has det[b-a, c-a, d-a] > 0;
//  - degenerate tetrahedra (|volume| <= 1e-12 * (longest edge)^3: flat or
//    with repeated points) hold no medium and are dropped; dropped() counts them;
//  - a face shared by more than two tetrahedra is refused (not a 3-manifold).
// Face f of a tetrahedron is the one opposite its vertex f; neighbor(t, f) is
// the tetrahedron across it, or -1 on the boundary.

namespace vri {

class TetMesh {
 public:
  using Tet = std::array<std::int32_t, 4>;

  TetMesh(std::vector<Vec3> points, std::vector<Tet> tets, std::vector<float> scalars);
  // The bytes a mesh of this size holds (and charges to the memory budget).
  static std::uint64_t bytes_for(std::uint64_t points, std::uint64_t tets) {
    return points * (sizeof(Vec3) + sizeof(float)) + tets * (sizeof(Tet) + 4 * sizeof(std::int32_t));
  }

  const std::vector<Vec3>& points() const { return points_; }
  const std::vector<Tet>& tets() const { return tets_; }
  const std::vector<float>& scalars() const { return scalars_; }
  std::size_t size() const { return tets_.size(); }
  std::size_t dropped() const { return dropped_; }

  std::int32_t neighbor(std::size_t tet, int face) const { return neighbors_[4 * tet + face]; }
  // The three vertices of face f (opposite vertex f), ordered so that their
  // normal (b-a) x (c-a) points out of the tetrahedron.
  std::array<std::int32_t, 3> face(std::size_t tet, int face) const;

  Vec3 box_lo() const { return lo_; }
  Vec3 box_hi() const { return hi_; }
  float min_value() const { return min_; }
  float max_value() const { return max_; }
  // Mean length over the distinct edges: the mesh's voxel unit (SPEC §2).
  double mean_edge_length() const { return mean_edge_; }
  // Longest edge: no straight segment inside one tetrahedron is longer.
  double max_edge_length() const { return max_edge_; }
  // The region rays are cut to (SPEC §12 "clip"): TetWalk trims its pieces
  // to it, so the ray-casting methods cut each tetrahedron's chord there.
  void set_clip(ClipRegion region) { clip_ = std::move(region); }
  const ClipRegion& clip_region() const { return clip_; }

 private:
  std::vector<Vec3> points_;
  std::vector<Tet> tets_;
  std::vector<float> scalars_;
  std::vector<std::int32_t> neighbors_;
  MemoryCharge charge_;  // the arrays above, held against the process's budget
  std::size_t dropped_ = 0;
  Vec3 lo_, hi_;
  float min_ = 0, max_ = 0;
  double mean_edge_ = 0, max_edge_ = 0;
  ClipRegion clip_;
};

}  // namespace vri
