#include "eval/sonar_map/cognitive_map_json.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

namespace plywood::eval {
using namespace perception;
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
  // Partitions west, north, obstacle, east (the order partition_map_test.cc pins); D is the three
  // ways into the obstacle; the graph joins west and east to north through their shared stretches.
  EXPECT_EQ(CognitiveMapToJson(HandMadeMap()),
            "{\n"
            "  \"room\": [0.0000, 0.0000, 3.0000, 2.0000],\n"
            "  \"obstacles\": [\n"
            "    [1.0000, 0.0000, 2.0000, 1.0000]\n"
            "  ],\n"
            "  \"bridges\": [],\n"
            "  \"corners\": [\n"
            "    [0.0000, 0.0000],\n"
            "    [3.0000, 0.0000],\n"
            "    [3.0000, 2.0000],\n"
            "    [0.0000, 2.0000]\n"
            "  ],\n"
            "  \"partitions\": [\n"
            "    {\"rect\": [0.0000, 0.0000, 1.0000, 1.0000], \"label\": \"free\"},\n"
            "    {\"rect\": [0.0000, 1.0000, 3.0000, 2.0000], \"label\": \"free\"},\n"
            "    {\"rect\": [1.0000, 0.0000, 2.0000, 1.0000], \"label\": \"obstacle\"},\n"
            "    {\"rect\": [2.0000, 0.0000, 3.0000, 1.0000], \"label\": \"free\"}\n"
            "  ],\n"
            "  \"negative_experience\": [\n"
            "    [0, 2],\n"
            "    [1, 2],\n"
            "    [2, 3]\n"
            "  ],\n"
            "  \"graph\": {\n"
            "    \"nodes\": [0, 1, 3],\n"
            "    \"arcs\": [\n"
            "      {\"a\": 0, \"b\": 1, \"door\": [[0.0000, 1.0000], [1.0000, 1.0000]]},\n"
            "      {\"a\": 1, \"b\": 3, \"door\": [[2.0000, 1.0000], [3.0000, 1.0000]]}\n"
            "    ]\n"
            "  }\n"
            "}\n");
}

TEST(CognitiveMapJsonTest, NonFiniteNumbersAreNull) {
  CognitiveMap map;
  map.room = {0.0, 0.0, std::numeric_limits<double>::quiet_NaN(),
              std::numeric_limits<double>::infinity()};
  const std::string json = CognitiveMapToJson(map);
  EXPECT_NE(json.find("\"room\": [0.0000, 0.0000, null, null],"), std::string::npos) << json;
}

TEST(CognitiveMapJsonTest, EmptyListsAndNegativeZero) {
  CognitiveMap map;
  map.room = {-0.00001, 0.0, 1.0, 1.0};  // rounds to -0.0000, written as 0.0000
  map.partitions = PartitionMap(map.room);
  EXPECT_EQ(CognitiveMapToJson(map),
            "{\n"
            "  \"room\": [0.0000, 0.0000, 1.0000, 1.0000],\n"
            "  \"obstacles\": [],\n"
            "  \"bridges\": [],\n"
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
}  // namespace plywood::eval
