#include "sim/raycast/surface_normal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "plywood_paths.h"
#include "sim/world/mujoco_handles.h"

namespace plywood::sim {
namespace {

// Geoms of each type, posed so their outward normals have closed forms.
constexpr char kShapes[] = R"(
<mujoco>
  <worldbody>
    <geom name="box" type="box" pos="1 2 0.5" euler="0 0 30" size="0.4 0.2 0.5"/>
    <geom name="cylinder" type="cylinder" pos="-1 0 0.4" size="0.3 0.4"/>
    <geom name="sphere" type="sphere" pos="0 -2 1" size="0.5"/>
    <geom name="capsule" type="capsule" pos="3 0 1" euler="90 0 0" size="0.2 0.5"/>
    <geom name="ellipsoid" type="ellipsoid" pos="0 3 1" size="0.3 0.6 0.9"/>
    <geom name="tilted_plane" type="plane" pos="0 0 0" euler="20 0 0" size="5 5 0.1"/>
  </worldbody>
</mujoco>)";

class SurfaceNormalTest : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = LoadModelFromString(kShapes, std::string(PLYWOOD_BINARY_DIR) + "/surface_normal.xml");
    data_.reset(mj_makeData(model_.get()));
    mj_forward(model_.get(), data_.get());
  }
  int Geom(const char* name) const { return mj_name2id(model_.get(), mjOBJ_GEOM, name); }
  Eigen::Vector3d Normal(const char* name, const Eigen::Vector3d& p_W) const {
    return SurfaceNormal(model_.get(), data_.get(), Geom(name), p_W);
  }

  MjModelPtr model_;
  MjDataPtr data_;
};

void ExpectNear(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected) {
  EXPECT_NEAR((actual - expected).norm(), 0.0, 1e-12)
      << actual.transpose() << " vs " << expected.transpose();
}

TEST_F(SurfaceNormalTest, BoxFacesOfAYawedBox) {
  const double yaw = M_PI / 6;
  const Eigen::Vector3d c(1, 2, 0.5), u(std::cos(yaw), std::sin(yaw), 0),
      w(-std::sin(yaw), std::cos(yaw), 0), z(0, 0, 1);
  ExpectNear(Normal("box", c + 0.4 * u + 0.1 * w), u);
  ExpectNear(Normal("box", c - 0.4 * u - 0.15 * w + 0.3 * z), -u);
  ExpectNear(Normal("box", c + 0.3 * u - 0.2 * w), -w);
  ExpectNear(Normal("box", c + 0.3 * u + 0.1 * w + 0.5 * z), z);
}

TEST_F(SurfaceNormalTest, CylinderSideAndCaps) {
  const Eigen::Vector3d c(-1, 0, 0.4);
  const double a = 0.7;
  ExpectNear(Normal("cylinder", c + Eigen::Vector3d(0.3 * std::cos(a), 0.3 * std::sin(a), 0.2)),
             Eigen::Vector3d(std::cos(a), std::sin(a), 0));
  ExpectNear(Normal("cylinder", c + Eigen::Vector3d(0.1, -0.05, 0.4)), Eigen::Vector3d(0, 0, 1));
  ExpectNear(Normal("cylinder", c + Eigen::Vector3d(0.1, -0.05, -0.4)), Eigen::Vector3d(0, 0, -1));
}

TEST_F(SurfaceNormalTest, SphereIsRadial) {
  const Eigen::Vector3d dir = Eigen::Vector3d(1, -2, 0.5).normalized();
  ExpectNear(Normal("sphere", Eigen::Vector3d(0, -2, 1) + 0.5 * dir), dir);
}

TEST_F(SurfaceNormalTest, CapsuleSideAndHemisphere) {
  // euler 90 about x turns the capsule's axis from +z to -y.
  const Eigen::Vector3d c(3, 0, 1);
  ExpectNear(Normal("capsule", c + Eigen::Vector3d(0, 0.3, 0.2)), Eigen::Vector3d(0, 0, 1));
  const Eigen::Vector3d end = c + Eigen::Vector3d(0, -0.5, 0);
  const Eigen::Vector3d dir = Eigen::Vector3d(0.3, -1, 0.2).normalized();
  ExpectNear(Normal("capsule", end + 0.2 * dir), dir);
}

TEST_F(SurfaceNormalTest, EllipsoidGradient) {
  const Eigen::Vector3d c(0, 3, 1), s(0.3, 0.6, 0.9);
  ExpectNear(Normal("ellipsoid", c + Eigen::Vector3d(0, 0, 0.9)), Eigen::Vector3d(0, 0, 1));
  // Surface point at parameters (theta, phi); the normal is p_i / s_i^2, normalised.
  const double th = 0.6, ph = 1.1;
  const Eigen::Vector3d p(s.x() * std::sin(ph) * std::cos(th), s.y() * std::sin(ph) * std::sin(th),
                          s.z() * std::cos(ph));
  const Eigen::Vector3d n =
      Eigen::Vector3d(p.x() / (s.x() * s.x()), p.y() / (s.y() * s.y()), p.z() / (s.z() * s.z()))
          .normalized();
  ExpectNear(Normal("ellipsoid", c + p), n);
}

TEST_F(SurfaceNormalTest, PlaneIsItsLocalZ) {
  const double roll = 20 * M_PI / 180;
  ExpectNear(Normal("tilted_plane", Eigen::Vector3d(1, 0, 0)),
             Eigen::Vector3d(0, -std::sin(roll), std::cos(roll)));
}

}  // namespace
}  // namespace plywood::sim
