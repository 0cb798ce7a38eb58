#include "vri/volume.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <span>
#include <random>
#include <utility>

#include "test_support.hpp"
#include "volume/float_sampler.hpp"
#include "vri/error.hpp"
#include "vri/memory.hpp"
#include "volume/builtin_volumes.hpp"

namespace vri {
namespace {

TEST(GridVolume, TrilinearReproducesTrilinearFields) {
  // a + bx + cy + dz + exy + fxz + gyz + hxyz is reproduced exactly by trilinear interpolation
  auto f = [](double x, double y, double z) {
    return 1 + 0.5 * x - 0.25 * y + 0.125 * z + 0.01 * x * y - 0.02 * x * z + 0.03 * y * z + 0.001 * x * y * z;
  };
  const auto vol = test::volume_from({5, 4, 6}, f, {0.5, 2, 1.5}, {-1, 3, 2});
  for (Vec3 p : {Vec3{-1, 3, 2}, Vec3{0.3, 4.1, 5.5}, Vec3{1, 9, 9.5}, Vec3{0.77, 7.3, 3.21}})
    EXPECT_NEAR(vol.sample(p), f(p.x, p.y, p.z), 1e-5) << p.x << " " << p.y << " " << p.z;
}

TEST(GridVolume, ViewsSamplesItDoesNotOwnAndKeepsTheirOwnerAlive) {
  auto data = std::make_shared<std::vector<std::uint16_t>>(std::vector<std::uint16_t>{0, 1, 2, 3, 4, 5, 6, 700});
  const std::weak_ptr<std::vector<std::uint16_t>> watch = data;
  {
    const GridVolume view({2, 2, 2}, GridVolume::SampleView(std::span<const std::uint16_t>(*data)), data);
    data.reset();
    EXPECT_FALSE(watch.expired());
    const GridVolume copy = view;  // shares the samples: the same memory
    EXPECT_EQ(copy.type(), ScalarType::UInt16);
    EXPECT_EQ(copy.at(1, 1, 1), 700.f);
    EXPECT_EQ(copy.max_value(), 700.f);
    copy.visit([&](auto a) { view.visit([&](auto b) { EXPECT_EQ(static_cast<const void*>(a.data()), b.data()); }); });
  }
  EXPECT_TRUE(watch.expired());  // the last copy let the owner go
  const std::vector<float> bad{0, 1, 2, 3, 4, 5, 6, std::nanf("")};
  EXPECT_THROW(GridVolume({2, 2, 2}, GridVolume::SampleView(std::span<const float>(bad)), nullptr), Error);
}

TEST(GridVolume, BoxAndVoxelUnit) {
  const auto vol = test::volume_from({5, 4, 6}, [](double, double, double) { return 0; }, {0.5, 2, 1.5}, {-1, 3, 2});
  EXPECT_DOUBLE_EQ(vol.box_hi().x, 1);
  EXPECT_DOUBLE_EQ(vol.box_hi().y, 9);
  EXPECT_DOUBLE_EQ(vol.box_hi().z, 9.5);
  EXPECT_DOUBLE_EQ(vol.voxel_unit(), 0.5);
}

TEST(GridVolume, SamplesOutsideAreClampedToTheBox) {
  const auto vol = test::volume_from({3, 3, 3}, [](double x, double, double) { return x; });
  EXPECT_DOUBLE_EQ(vol.sample({-5, 1, 1}), 0);
  EXPECT_DOUBLE_EQ(vol.sample({9, 1, 1}), 2);
  EXPECT_DOUBLE_EQ(vol.sample({2, 2, 2}), 2);  // the far corner uses the last cell
}

TEST(GridVolume, MinMax) {
  const auto vol = test::volume_from({3, 4, 5}, [](double x, double y, double z) { return x - y * z; });
  EXPECT_FLOAT_EQ(vol.min_value(), -12);
  EXPECT_FLOAT_EQ(vol.max_value(), 2);
}

// A volume of storage type T with random samples, and the float volume of the same values.
template <class T>
std::pair<GridVolume, GridVolume> typed_and_float(std::array<int, 3> dims, int lo, int hi) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> u(lo, hi);
  std::vector<T> typed(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2]);
  std::vector<float> same(typed.size());
  for (std::size_t i = 0; i < typed.size(); ++i) same[i] = typed[i] = static_cast<T>(u(rng));
  return {GridVolume(dims, std::move(typed), {0.5, 1, 2}, {1, -2, 3}), GridVolume(dims, std::move(same), {0.5, 1, 2}, {1, -2, 3})};
}

template <class T>
void expect_samples_as_float(ScalarType type, int lo, int hi) {
  const auto [typed, floats] = typed_and_float<T>({7, 5, 6}, lo, hi);
  EXPECT_EQ(typed.type(), type);
  EXPECT_EQ(typed.bytes(), 7u * 5 * 6 * sizeof(T));
  EXPECT_EQ(floats.bytes(), 7u * 5 * 6 * sizeof(float));
  EXPECT_EQ(typed.min_value(), floats.min_value());
  EXPECT_EQ(typed.max_value(), floats.max_value());
  EXPECT_EQ(test::floats(typed), test::floats(floats));
  EXPECT_EQ(typed.at(6, 4, 5), floats.at(6, 4, 5));
  const FloatSampler sampler(typed);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> x(0, 4), y(-3, 3), z(2, 14);  // beyond the box too: clamped
  for (int n = 0; n < 500; ++n) {
    const Vec3 p{x(rng), y(rng), z(rng)};
    ASSERT_EQ(typed.sample(p), floats.sample(p)) << n;
    const Vec3 u = sampler.grid(p);
    const float a = typed.visit([&](auto v) { return sampler.at(v.data(), u); });
    const float b = floats.visit([&](auto v) { return sampler.at(v.data(), u); });
    ASSERT_EQ(a, b) << n;
  }
}

TEST(GridVolume, EachStorageTypeSamplesAsTheFloatVolume) {
  expect_samples_as_float<std::uint8_t>(ScalarType::UInt8, 0, 255);
  expect_samples_as_float<std::uint16_t>(ScalarType::UInt16, 0, 65535);
  expect_samples_as_float<std::int16_t>(ScalarType::Int16, -32768, 32767);
  expect_samples_as_float<float>(ScalarType::Float32, -1000, 1000);
}

TEST(GridVolume, DecodeKeepsTheStoredTypesAndSwapsInPlace) {
  std::vector<std::byte> bytes(16);
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = std::byte(i + 1);  // 01 02 03 ... 10
  const auto from = [&](std::span<std::byte> out) { std::copy(bytes.begin(), bytes.begin() + out.size(), out.begin()); };
  const GridVolume u16({2, 2, 2}, GridVolume::decode(ScalarType::UInt16, Endian::Big, 8, from));
  EXPECT_EQ(u16.type(), ScalarType::UInt16);
  EXPECT_EQ(u16.value(0), 0x0102);
  EXPECT_EQ(u16.value(7), 0x0f10);
  const GridVolume i16({2, 2, 2}, GridVolume::decode(ScalarType::Int16, Endian::Little, 8, from));
  EXPECT_EQ(i16.type(), ScalarType::Int16);
  EXPECT_EQ(i16.value(1), 0x0403);
  const GridVolume u8({2, 2, 2}, GridVolume::decode(ScalarType::UInt8, Endian::Big, 8, from));
  EXPECT_EQ(u8.type(), ScalarType::UInt8);
  EXPECT_EQ(u8.value(7), 8);
  EXPECT_EQ(u8.bytes(), 8u);
  const GridVolume i8({2, 2, 2}, GridVolume::decode(ScalarType::Int8, Endian::Little, 8, from));
  EXPECT_EQ(i8.type(), ScalarType::Float32);  // converted
  EXPECT_EQ(i8.value(7), 8);
}

TEST(GridVolume, RejectsBadConstruction) {
  EXPECT_THROW(GridVolume({1, 4, 4}, std::vector<float>(16)), Error);
  EXPECT_THROW(GridVolume({2, 2, 2}, std::vector<float>(7)), Error);
  std::vector<float> nan(8, 0.f);
  nan[3] = std::nanf("");
  EXPECT_THROW(GridVolume({2, 2, 2}, nan), Error);
  EXPECT_THROW(GridVolume({2, 2, 2}, std::vector<float>(8), {1, 0, 1}), Error);
  EXPECT_THROW(GridVolume::checked_sample_count({100000, 100000, 100000}), Error);
  EXPECT_THROW(GridVolume::checked_sample_count({-3, 10, 10}), Error);
  EXPECT_EQ(GridVolume::checked_sample_count({64, 64, 64}), 262144u);
}

// Issue 17 defect 1: 2^24 per axis (2^72 samples) and 2^24 x 2^24 x 2^16 (2^64)
// wrapped to 0 in the count check and passed it.
TEST(GridVolume, SampleCountCheckDoesNotWrap) {
  const std::int64_t big = std::int64_t{1} << 24;
  EXPECT_THROW(GridVolume::checked_sample_count({big, big, big}), Error);
  EXPECT_THROW(GridVolume::checked_sample_count({big, big, std::int64_t{1} << 16}), Error);
  EXPECT_THROW(GridVolume::checked_sample_count({big, big, 2}), Error);
  EXPECT_EQ(GridVolume::checked_sample_count({1024, 1024, 1024}), std::uint64_t{1} << 30);
}

// The memory budget refuses a volume before allocating it, saying how to raise it.
TEST(GridVolume, MemoryLimitRefusesBigVolumes) {
  set_memory_limit(1000);
  try {
    random_field({32, 32, 32});
    ADD_FAILURE() << "expected the memory limit to refuse 128 KiB";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--max-memory"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("131072 bytes"), std::string::npos) << e.what();
  }
  set_memory_limit(0);
  EXPECT_EQ(random_field({32, 32, 32}).size(), 32768u);
  EXPECT_GT(memory_limit(), 0u);
}

TEST(GridVolume, ParsesByteSizes) {
  EXPECT_EQ(parse_byte_size("512M"), std::uint64_t{512} << 20);
  EXPECT_EQ(parse_byte_size("4G"), std::uint64_t{4} << 30);
  EXPECT_EQ(parse_byte_size("4GiB"), std::uint64_t{4} << 30);
  EXPECT_EQ(parse_byte_size("1.5K"), 1536u);
  EXPECT_EQ(parse_byte_size("1000"), 1000u);
  EXPECT_EQ(parse_byte_size("-1"), std::nullopt);
  EXPECT_EQ(parse_byte_size("4X"), std::nullopt);
  EXPECT_EQ(parse_byte_size("0"), std::nullopt);
  EXPECT_EQ(parse_byte_size("1e30"), std::nullopt);
}

}  // namespace
}  // namespace vri
