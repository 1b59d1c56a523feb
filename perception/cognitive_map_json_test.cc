#include "perception/cognitive_map_json.h"

#include <gtest/gtest.h>

#include <string>

namespace plywood::perception {
namespace {

// A 3 x 2 m room with a 1 x 1 m obstacle against its south wall: three free partitions around
// it, built by the same calls the map builder makes.
CognitiveMap HandMadeMap() {
  CognitiveMap map;
  map.room = {0.0, 0.0, 3.0, 2.0};
  map.obstacles = {{1.0, 0.0, 2.0, 1.0}};
  map.corners = {{0.0, 0.0}, {3.0, 0.0}, {3.0, 2.0}, {0.0, 2.0}};
  map.partitions = PartitionMap(map.room);
  map.partitions.InsertObstacle(map.obstacles[0]);
  map.partitions.Merge();
  map.adjacency = map.partitions.Adjacencies(1e-6);
  map.negative = InitialNegativeExperience(map.partitions, map.adjacency, 0.45);
  map.graph = BuildGraph(map.partitions, map.adjacency, map.negative);
  return map;
}

TEST(CognitiveMapJsonTest, HandMadeMapGivesExactlyTheseBytes) {
  const CognitiveMap map = HandMadeMap();
  ASSERT_EQ(map.partitions.partitions().size(), 4u);
  std::string partitions, arcs, forbidden;
  // The expected text is assembled from the map's own partition order, so the test pins the
  // format, not PartitionMap's ordering (which partition_map_test.cc pins).
  for (std::size_t i = 0; i < map.partitions.partitions().size(); ++i) {
    const Partition& p = map.partitions.partitions()[i];
    char line[160];
    std::snprintf(line, sizeof(line),
                  "    {\"rect\": [%.4f, %.4f, %.4f, %.4f], \"label\": \"%s\"}%s\n", p.rect.x0,
                  p.rect.y0, p.rect.x1, p.rect.y1, p.label == Label::kFree ? "free" : "obstacle",
                  i + 1 < map.partitions.partitions().size() ? "," : "");
    partitions += line;
  }
  EXPECT_EQ(map.negative.size(), 3u);    // into the obstacle from west, east and north
  EXPECT_EQ(map.graph.arcs.size(), 2u);  // west-north and east-north
  const std::string json = CognitiveMapToJson(map);
  EXPECT_EQ(json.substr(0, json.find("\"partitions\"")),
            "{\n"
            "  \"room\": [0.0000, 0.0000, 3.0000, 2.0000],\n"
            "  \"obstacles\": [\n"
            "    [1.0000, 0.0000, 2.0000, 1.0000]\n"
            "  ],\n"
            "  \"corners\": [\n"
            "    [0.0000, 0.0000],\n"
            "    [3.0000, 0.0000],\n"
            "    [3.0000, 2.0000],\n"
            "    [0.0000, 2.0000]\n"
            "  ],\n"
            "  ");
  EXPECT_NE(json.find("  \"partitions\": [\n" + partitions + "  ],\n"), std::string::npos) << json;
  // D and the graph by index: check them against the map itself.
  for (const auto& [a, b] : map.negative.pairs()) {
    if (a > b) continue;
    EXPECT_NE(json.find("[" + std::to_string(a) + ", " + std::to_string(b) + "]"),
              std::string::npos)
        << json;
  }
  for (const Adjacency& arc : map.graph.arcs)
    EXPECT_NE(json.find("{\"a\": " + std::to_string(arc.a) + ", \"b\": " + std::to_string(arc.b) +
                        ", \"door\": "),
              std::string::npos)
        << json;
  EXPECT_EQ(json.back(), '\n');
}

TEST(CognitiveMapJsonTest, EmptyListsAndNegativeZero) {
  CognitiveMap map;
  map.room = {-0.00001, 0.0, 1.0, 1.0};  // rounds to -0.0000, written as 0.0000
  map.partitions = PartitionMap(map.room);
  EXPECT_EQ(CognitiveMapToJson(map),
            "{\n"
            "  \"room\": [0.0000, 0.0000, 1.0000, 1.0000],\n"
            "  \"obstacles\": [],\n"
            "  \"corners\": [],\n"
            "  \"partitions\": [\n"
            "    {\"rect\": [0.0000, 0.0000, 1.0000, 1.0000], \"label\": \"free\"}\n"
            "  ],\n"
            "  \"negative_experience\": [],\n"
            "  \"graph\": {\n"
            "    \"nodes\": [],\n"
            "    \"arcs\": []\n"
            "  }\n"
            "}\n");
}

}  // namespace
}  // namespace plywood::perception
