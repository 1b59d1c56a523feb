#include "perception/lines/small_round_groups.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "perception/lines/scan_scene_test_support.h"

namespace plywood::perception {
namespace {

using testing::Disc;
using testing::Panel;
using testing::ScanScene;

const std::vector<Eigen::Vector2d> kRoom{{-2.5, -2.0}, {4.0, -2.0}, {4.0, 3.0}, {-2.5, 3.0}};

// The median of 10 scans has ~4 mm of noise (1.25 x 1 cm / sqrt(10)).
constexpr double kQuietSigmaM = 0.004;

BreakpointOptions Quiet() {
  BreakpointOptions options;
  options.sigma_m = kQuietSigmaM;
  return options;
}

TEST(SmallRoundGroupsTest, AThinLegsFourReturnsAreRound) {
  // A r = 5 cm leg 3.5 m away in front of a wall 0.5 m behind it, a quarter beam off a beam's
  // bearing: 4 returns over ~9 cm, the middle ones 1-2 cm nearer than the chord of the ends (stop
  // 63: the 4-point chords one scan cannot tell from a box face and the round-object stage never
  // tests).
  const double bearing = 0.25 * std::numbers::pi / 180.0;
  const Disc leg{{3.5 * std::cos(bearing), 3.5 * std::sin(bearing)}, 0.05};
  int found = 0;
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const ScanPoints scan = ScanScene({kRoom}, {leg}, kQuietSigmaM, 20.0, seed);
    for (const CircleFeature& c : SmallRoundGroups(scan, Quiet())) {
      EXPECT_LT((c.centre - leg.centre).norm(), 0.03);
      EXPECT_GE(c.num_points(), 4);
      ++found;
    }
  }
  EXPECT_GE(found, 18) << "of 20 quiet scans";
}

TEST(SmallRoundGroupsTest, SmallFlatFacesAndWallsAreNot) {
  // 0.1-0.15 m panels 3-3.8 m away (4-6 returns each, square on and turned), and the room's
  // walls: flat within the quiet noise, no bulge, no circle.
  const std::vector<std::vector<Eigen::Vector2d>> scene{
      kRoom, Panel({3.0, -0.05}, {3.0, 0.05}), Panel({3.3, 0.8}, {3.4, 0.91}),
      Panel({-1.6, 2.4}, {-1.45, 2.45}), Panel({3.6, -1.2}, {3.7, -1.32})};
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const ScanPoints scan = ScanScene(scene, {}, kQuietSigmaM, 20.0, seed);
    EXPECT_TRUE(SmallRoundGroups(scan, Quiet()).empty()) << "seed " << seed;
  }
}

}  // namespace
}  // namespace plywood::perception
