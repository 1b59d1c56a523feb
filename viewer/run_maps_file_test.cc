#include "viewer/run_maps_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "sim/config/config_error.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::viewer {
namespace {

std::filesystem::path Write(const std::string& name, const std::string& text) {
  const std::filesystem::path path = testing::MakeTempDir("run_maps_file") / name;
  std::ofstream(path) << text;
  return path;
}

TEST(RunMapsFileTest, ReadsTheCognitiveMapsPartitionsAndArcsThroughTheirDoors) {
  const MapView map = ReadCognitiveMapFile(Write("cognitive_map.json", R"({
    "room": [0, 0, 4, 2], "obstacles": [], "corners": [], "negative_experience": [],
    "partitions": [{"rect": [0, 0, 2, 2], "label": "free"}, {"rect": [2, 0, 4, 2], "label": "obstacle"}],
    "graph": {"nodes": [0], "arcs": [{"a": 0, "b": 1, "door": [[2, 0.5], [2, 1.5]]}]}})"));
  ASSERT_EQ(map.partitions.size(), 2u);
  EXPECT_TRUE(map.partitions[0].free);
  EXPECT_FALSE(map.partitions[1].free);
  EXPECT_EQ(map.partitions[1].min_W, Eigen::Vector2d(2, 0));
  ASSERT_EQ(map.graph_arcs.size(), 2u);  // centre -> door -> centre
  EXPECT_EQ(map.graph_arcs[0].first, Eigen::Vector2d(1, 1));
  EXPECT_EQ(map.graph_arcs[0].second, Eigen::Vector2d(2, 1));
  EXPECT_EQ(map.graph_arcs[1].second, Eigen::Vector2d(3, 1));
}

TEST(RunMapsFileTest, ReadsTheGeometricMapWithoutUnconfirmedSegments) {
  const GeometricMapView map = ReadGeometricMapFile(Write("geometric_map.json", R"({
    "segments": [
      {"start": [0, 0], "end": [1, 0], "tag": "real", "points": 50, "inliers": 48, "observations": 3},
      {"start": [0, 1], "end": [1, 1], "tag": "unconfirmed", "points": 9, "inliers": 9, "observations": 1},
      {"start": [0, 2], "end": [3, 2], "tag": "pseudo", "points": 1, "inliers": 0, "observations": 1}],
    "clusters": [{"min": [0.5, 0.5], "max": [0.7, 0.6], "points": 4}],
    "corrected_poses": []})"));
  ASSERT_EQ(map.segments.size(), 2u);
  EXPECT_FALSE(map.segments[0].pseudo);
  EXPECT_TRUE(map.segments[1].pseudo);
  EXPECT_EQ(map.segments[1].b_W, Eigen::Vector2d(3, 2));
  ASSERT_EQ(map.clusters.size(), 1u);
  EXPECT_EQ(map.clusters[0].second, Eigen::Vector2d(0.7, 0.6));
}

// Each bad file is refused with its file and field named.
TEST(RunMapsFileTest, BadFilesNameTheFileAndField) {
  const std::pair<std::string, std::string> cases[] = {
      {"{\"segments\": [", "not JSON"},
      {R"({"clusters": []})", "segments: is missing"},
      {R"({"segments": [{"start": [0, 0], "end": [1], "tag": "real"}], "clusters": []})",
       "segments[0].end: must be a point"},
      {R"({"segments": [{"start": [0, 0], "end": [1, 1], "tag": "wall"}], "clusters": []})",
       "segments[0].tag: must be real, pseudo or unconfirmed"},
      {R"({"segments": [{"start": [0, 0], "end": [1, "x"], "tag": "real"}], "clusters": []})",
       "segments[0].end: must be a finite number"},
      // s63: a pseudo segment 1e300 m long hung the replay's dash loop.
      {R"({"segments": [{"start": [1e300, 0], "end": [1, 1], "tag": "pseudo"}], "clusters": []})",
       "segments[0].start: must be within 1e+09 m of the origin, got 1e+300"},
      {R"({"segments": [], "clusters": [{"min": [0, -2e9], "max": [1, 1]}]})",
       "clusters[0].min: must be within 1e+09 m of the origin, got -2e+09"},
  };
  for (const auto& [text, expected] : cases) {
    const std::filesystem::path path = Write("geometric_map.json", text);
    try {
      ReadGeometricMapFile(path);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const sim::ConfigError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(path.string()), std::string::npos) << what;
      EXPECT_NE(what.find(expected), std::string::npos) << what;
    }
  }
  // The same bound for the cognitive map's partitions.
  const std::filesystem::path far = Write("cognitive_map.json", R"({
    "partitions": [{"rect": [0, 0, 1e300, 2], "label": "free"}], "graph": {"arcs": []}})");
  try {
    ReadCognitiveMapFile(far);
    ADD_FAILURE() << "accepted a partition 1e300 m wide";
  } catch (const sim::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "partitions[0]: must be within 1e+09 m of the origin, got 1e+300"),
              std::string::npos)
        << e.what();
  }
  const std::filesystem::path arcs = Write("cognitive_map.json", R"({
    "partitions": [{"rect": [0, 0, 2, 2], "label": "free"}],
    "graph": {"arcs": [{"a": 0, "b": 7, "door": [[2, 0.5], [2, 1.5]]}]}})");
  EXPECT_THROW(
      {
        try {
          ReadCognitiveMapFile(arcs);
        } catch (const sim::ConfigError& e) {
          EXPECT_NE(std::string(e.what()).find("graph.arcs[0].b"), std::string::npos) << e.what();
          throw;
        }
      },
      sim::ConfigError);
}

}  // namespace
}  // namespace plywood::viewer
