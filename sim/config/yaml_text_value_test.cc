// YamlTextValue: code that writes a path into YAML text or a --set (a sweep's world files, bench's
// --world) gets back exactly that path, and ordinary paths are written unchanged.

#include "sim/config/yaml_text_value.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <string>

namespace plywood::sim {
namespace {

TEST(YamlTextValueTest, EveryTextReadsBackAsItself) {
  for (const std::string text : {"/tmp/room #2.xml",
                                 "/tmp/a: b/room.xml",
                                 "room.xml\nduration_s: 5",
                                 "[1, 2]",
                                 "{a: 1}",
                                 "~",
                                 "null",
                                 "",
                                 "*alias",
                                 "&anchor x",
                                 "!tag",
                                 "'quoted'",
                                 "\"double\"",
                                 "- item",
                                 "? key",
                                 "a # b",
                                 "%YAML",
                                 "@SWEEP/x",
                                 "`tick`",
                                 " leading",
                                 "trailing ",
                                 "tab\there",
                                 "caf\xc3\xa9.xml"}) {
    SCOPED_TRACE(text);
    const YAML::Node read = YAML::Load("world: " + YamlTextValue(text));
    ASSERT_TRUE(read["world"].IsScalar());
    EXPECT_EQ(read["world"].Scalar(), text);
  }
}

TEST(YamlTextValueTest, OrdinaryPathsAreWrittenUnchanged) {
  for (const std::string path :
       {"/work/worlds/hall.xml", "worlds/seed000_room_1.xml",
        "/tmp/sweep/worlds/room-seed5/room_0001.xml", "../a/b-c_d.e.xml"}) {
    EXPECT_EQ(YamlTextValue(path), path);
  }
}

}  // namespace
}  // namespace plywood::sim
