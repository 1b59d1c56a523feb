#include "eval/sonar_map/sonar_net_training.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "tests/support/file_size_limit.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::eval {
namespace {

namespace fs = std::filesystem;

std::string Slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

SonarNetTrainingOptions Tiny(const fs::path& out) {
  SonarNetTrainingOptions options;
  options.rooms = 2;
  options.test_rooms = 1;
  options.poses = 3;
  options.train.epochs = 2;
  options.out = out;
  return options;
}

TEST(SonarNetTrainingTest, TheShippedWeightsAreRefusedHoweverSpelled) {
  const fs::path shipped = ShippedSonarNetPath();
  ASSERT_TRUE(fs::exists(shipped));
  EXPECT_THROW(RefuseShippedSonarNet(shipped), std::invalid_argument);
  EXPECT_THROW(RefuseShippedSonarNet(shipped.parent_path() / ".." / "models" / shipped.filename()),
               std::invalid_argument);
  const fs::path dir = testing::MakeTempDir("sonar_net_training_refuse");
  fs::create_hard_link(shipped, dir / "alias.txt");  // same file, other name
  EXPECT_THROW(RefuseShippedSonarNet(dir / "alias.txt"), std::invalid_argument);
  EXPECT_NO_THROW(RefuseShippedSonarNet(dir / "net.txt"));
  EXPECT_NO_THROW(RefuseShippedSonarNet("runs/sonar_net/sonar_net.txt"));
  EXPECT_THROW(TrainSonarNet(Tiny(shipped)), std::invalid_argument);
  for (const fs::path& other : ShippedSonarNetPaths()) {
    ASSERT_TRUE(fs::exists(other)) << other;
    EXPECT_THROW(RefuseShippedSonarNet(other), std::invalid_argument) << other;
  }
}

// `train --out FILE` wrote FILE in place: a failed write (a full disk) left a 0-byte FILE where
// the earlier weights had been. Now the weights are staged beside FILE and renamed into place, so
// a failure leaves the earlier FILE as it was, no partial file, and names the OS's reason.
TEST(SonarNetTrainingTest, AFailedSaveLeavesTheEarlierWeightsAsTheyWere) {
  const fs::path dir = testing::MakeTempDir("sonar_net_training_failed_save");
  const fs::path out = dir / "net.txt";
  { std::ofstream(out) << "earlier weights\n"; }
  SonarNetTrainingOptions options = Tiny(out);
  options.train.hidden = {64, 64};
  std::string error;
  try {
    // A net of 2 x 64 units writes about 70 kB of weights; the training rooms are under 2 kB each.
    const testing::FileSizeLimit limit(16 * 1024);
    ASSERT_TRUE(limit.active());
    TrainSonarNet(options);
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  EXPECT_EQ(error, out.string() + ": write failed: File too large");
  EXPECT_EQ(Slurp(out), "earlier weights\n");
  for (const auto& entry : fs::directory_iterator(dir)) EXPECT_EQ(entry.path(), out);
}

// s51: one held-out room at one pose (seed 1) gave 196 cells, all free; the report scored the
// net, the cone model and the constant base rate on them (the net and the constant both accuracy
// 1.0000), exit 0. A set of one class is refused naming its flag, before the training and before
// any weights are written.
TEST(SonarNetTrainingTest, ASetOfOneClassIsRefusedNamingItsFlag) {
  const fs::path dir = testing::MakeTempDir("sonar_net_training_one_class");
  SonarNetTrainingOptions options = Tiny(dir / "net.txt");
  options.rooms = 1;
  options.test_rooms = 1;
  options.poses = 1;
  options.train.seed = 1;
  std::string error = "no error";
  try {
    TrainSonarNet(options);
  } catch (const std::invalid_argument& e) {
    error = e.what();
  }
  EXPECT_EQ(error.rfind("train: --test-rooms: the 196 cells of 1 room x 1 pose are all free", 0),
            0u)
      << error;
  EXPECT_FALSE(fs::exists(dir / "net.txt"));
}

TEST(SonarNetTrainingTest, SameOptionsSameWeightsAndScoresOnHeldOutRooms) {
  const fs::path dir = testing::MakeTempDir("sonar_net_training_same");
  int data_calls = 0;
  const SonarNetTrainingReport a =
      TrainSonarNet(Tiny(dir / "a" / "net.txt"), [&](const SonarNetDataSummary&) { ++data_calls; });
  const SonarNetTrainingReport b = TrainSonarNet(Tiny(dir / "b" / "net.txt"));
  EXPECT_EQ(data_calls, 1);
  // 14 x 14 cells for each of 3 poses a room.
  EXPECT_EQ(a.data.train_cells, 2u * 3u * 196u);
  EXPECT_EQ(a.data.test_cells, 1u * 3u * 196u);
  const std::string weights = Slurp(dir / "a" / "net.txt");
  EXPECT_EQ(weights.rfind("plywood-sonar-net", 0), 0u) << weights.substr(0, 40);
  EXPECT_EQ(weights, Slurp(dir / "b" / "net.txt"));
  EXPECT_EQ(a.net.cross_entropy, b.net.cross_entropy);
  SonarNetTrainingOptions bad = Tiny(dir / "c.txt");
  bad.poses = 0;
  EXPECT_THROW(TrainSonarNet(bad), std::invalid_argument);
  EXPECT_FALSE(fs::exists(dir / "c.txt"));
}

// The rings are read with options.sonar: a sonar that hears convex edges gives other rings in
// rooms with boxes, so the held-out classical score (a fixed model of the rings alone) and the
// weights move; were the option ignored, both would be those of the default sonar.
TEST(SonarNetTrainingTest, TheRingsAreReadWithTheGivenSonar) {
  const fs::path dir = testing::MakeTempDir("sonar_net_training_sonar");
  SonarNetTrainingOptions specular = Tiny(dir / "specular.txt");
  specular.rooms = 4;
  specular.test_rooms = 2;
  specular.poses = 10;
  SonarNetTrainingOptions edges = specular;
  edges.out = dir / "edges.txt";
  edges.sonar.edge_echoes = true;
  const SonarNetTrainingReport a = TrainSonarNet(specular);
  const SonarNetTrainingReport b = TrainSonarNet(edges);
  EXPECT_EQ(a.data.test_cells, b.data.test_cells);  // the same rooms and poses
  EXPECT_NE(a.classical.cross_entropy, b.classical.cross_entropy);
  EXPECT_NE(Slurp(dir / "specular.txt"), Slurp(dir / "edges.txt"));
}

}  // namespace
}  // namespace plywood::eval
