// Datasets: a scene file keeps its camera and method and gets its transfer
// function as points that load back to the same function; a bare volume gets
// a framing camera; the histogram counts every sample; only listed ids open.
#include "dataset.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "vri/error.hpp"

namespace vri::viewer {
namespace {

const std::filesystem::path kRoot = VRI_SOURCE_DIR;

TEST(Dataset, SceneFileKeepsItsSceneWithAbsolutePaths) {
  const auto d = load_dataset(kRoot / "scenes/neghip.json", "neghip");
  const Scene original = load_scene(kRoot / "scenes/neghip.json");
  EXPECT_EQ(d->scene_json["camera"]["width"], original.camera.width);
  EXPECT_EQ(d->scene_json.count("volume"), 0u);
  const std::filesystem::path file = d->volume_json["file"].get<std::string>();
  EXPECT_TRUE(file.is_absolute());
  EXPECT_TRUE(std::filesystem::exists(file));
  // The scene as the page sends it back, with the volume block: the same scene as the file.
  nlohmann::json saved = d->scene_json;
  saved["volume"] = d->volume_json;
  const Scene again = parse_scene(saved.dump(), "/nonexistent", "saved");
  ASSERT_EQ(again.transfer_function.points().size(), original.transfer_function.points().size());
  for (std::size_t i = 0; i < again.transfer_function.points().size(); ++i) {
    EXPECT_EQ(again.transfer_function.points()[i].s, original.transfer_function.points()[i].s);
    EXPECT_EQ(again.transfer_function.points()[i].tau, original.transfer_function.points()[i].tau);
  }
  EXPECT_EQ(original.method.name, "exact");
  EXPECT_EQ(again.method.name, "preint1");  // exact is the viewer's reference, not its view
  EXPECT_EQ(d->description["volume"]["kind"], "grid");
  EXPECT_EQ(d->description["volume"]["dims"], nlohmann::json({64, 64, 64}));
}

TEST(Dataset, HistogramCountsEverySample) {
  const auto d = load_dataset(kRoot / "scenes/neghip.json", "neghip");
  const auto counts = d->description["histogram"]["counts"].get<std::vector<std::uint64_t>>();
  ASSERT_EQ(counts.size(), 256u);
  EXPECT_EQ(std::accumulate(counts.begin(), counts.end(), std::uint64_t{0}), 64u * 64 * 64);
  const GridVolume& g = std::get<GridVolume>(d->volume);
  EXPECT_EQ(d->description["histogram"]["range"][1].get<double>(), g.max_value());
  EXPECT_GT(counts.back(), 0u);  // the maximum lands in the last bin
}

TEST(Dataset, MeshSceneIsAMesh) {
  const auto d = load_dataset(kRoot / "scenes/blunt_fin.json", "blunt_fin");
  EXPECT_EQ(d->description["volume"]["kind"], "mesh");
  EXPECT_GT(d->description["volume"]["unit_distance"].get<double>(), 0);
}

TEST(Dataset, BareVolumeGetsAFramingCamera) {
  const auto d = load_dataset(kRoot / "data/bonsai.nrrd", "bonsai");
  const Scene scene = parse_scene(d->scene_json.dump(), d->volume, d->base_dir, "default");
  // Every corner of the box projects inside the image.
  const Camera camera(scene.camera);
  const GridVolume& g = std::get<GridVolume>(d->volume);
  for (int c = 0; c < 8; ++c) {
    const Vec3 p{c & 1 ? g.box_hi().x : g.box_lo().x, c & 2 ? g.box_hi().y : g.box_lo().y,
                 c & 4 ? g.box_hi().z : g.box_lo().z};
    const auto px = camera.project(p);
    ASSERT_TRUE(px);
    EXPECT_GE(px->first, 0);
    EXPECT_LE(px->first, camera.width());
    EXPECT_GE(px->second, 0);
    EXPECT_LE(px->second, camera.height());
  }
  EXPECT_EQ(scene.method.name, "preint1");
}

TEST(Dataset, CatalogOpensListedIdsOnly) {
  DatasetCatalog catalog(kRoot / "scenes/neghip.json", kRoot / "scenes");
  EXPECT_EQ(catalog.first_id(), "neghip");
  const nlohmann::json list = catalog.list();
  EXPECT_GT(list.size(), 5u);
  int neghips = 0;
  for (const auto& e : list) neghips += e["id"] == "neghip";
  EXPECT_EQ(neghips, 1);  // the given file is not listed twice
  EXPECT_EQ(catalog.open("neghip"), catalog.open("neghip"));  // loaded once
  EXPECT_THROW(catalog.open("../../etc/passwd"), Error);
  EXPECT_THROW(DatasetCatalog("", "/nonexistent"), Error);
}

TEST(Dataset, UnreadableFilesFailWithOneLine) {
  EXPECT_THROW(load_dataset("/nonexistent/x.json", "x"), Error);
  EXPECT_THROW(load_dataset(kRoot / "presets/bonsai.json", "x"), Error);  // a transfer function, not a scene
}

}  // namespace
}  // namespace vri::viewer
