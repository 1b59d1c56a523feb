// Family `room`: an empty rectangle, L or T room, 3-10 m along each side of its bounding box, at
// any rotation.
#include <algorithm>
#include <cstdio>

#include "sim/world/generator/wall_builder.h"
#include "sim/world/generator/world_families.h"

namespace plywood::sim::worldgen {

using Eigen::Vector2d;

namespace {

constexpr double kMinSideM = 3.0, kMaxSideM = 10.0;
constexpr double kMinArmM = 1.2;  // narrowest part of an L or T: two robots' widths and margins

std::string Describe(const std::string& shape, double w, double d, double rotation) {
  char text[160];
  std::snprintf(text, sizeof(text), "%s room, bounding box %.2f x %.2f m, turned %.1f deg",
                shape.c_str(), w, d, rotation);
  return text;
}

}  // namespace

std::optional<double> DrawRoomWorld(WorldRng& rng, GeneratedWorld& world) {
  const int shape = rng.Int(0, 2);
  const double w = rng.Rounded(kMinSideM, kMaxSideM, 0.01);
  const double d = rng.Rounded(kMinSideM, kMaxSideM, 0.01);
  const double rotation = rng.Rounded(0.0, 359.9, 0.1);
  std::vector<Vector2d> outline;
  std::string shape_name;
  if (shape == 0) {
    shape_name = "rectangle";
    outline = {{0, 0}, {w, 0}, {w, d}, {0, d}};
  } else if (shape == 1) {
    // An L: the north-east corner cut away (the rotation makes every corner equally likely).
    shape_name = "L";
    const double nw = rng.Rounded(std::max(0.6, 0.25 * w), std::min(0.6 * w, w - kMinArmM), 0.01);
    const double nd = rng.Rounded(std::max(0.6, 0.25 * d), std::min(0.6 * d, d - kMinArmM), 0.01);
    outline = {{0, 0}, {w, 0}, {w, d - nd}, {w - nw, d - nd}, {w - nw, d}, {0, d}};
    world.AddParameter("notch_width_m", nw);
    world.AddParameter("notch_depth_m", nd);
  } else {
    // A T: a bar across the north, a stem down to the south.
    shape_name = "T";
    const double stem =
        rng.Rounded(std::max(kMinArmM, 0.3 * w), std::min(0.7 * w, w - kMinArmM), 0.01);
    const double bar =
        rng.Rounded(std::max(kMinArmM, 0.3 * d), std::min(0.6 * d, d - kMinArmM), 0.01);
    const double centre = rng.Rounded(stem / 2 + 0.6, w - stem / 2 - 0.6, 0.01);
    const double x0 = centre - stem / 2, x1 = centre + stem / 2, y = d - bar;
    outline = {{x0, 0}, {x1, 0}, {x1, y}, {w, y}, {w, d}, {0, d}, {0, y}, {x0, y}};
    world.AddParameter("stem_width_m", stem);
    world.AddParameter("bar_depth_m", bar);
    world.AddParameter("stem_centre_m", centre);
  }
  for (Vector2d& p : outline) p -= Vector2d(w / 2, d / 2);
  world.parameters.insert(world.parameters.begin(), {{"shape", JsonString(shape_name)},
                                                     {"width_m", JsonNumber(w)},
                                                     {"depth_m", JsonNumber(d)},
                                                     {"rotation_deg", JsonNumber(rotation)}});
  AddOutlineWalls(world, outline, std::vector<OutlineEdge>(outline.size()));
  world.interiors.push_back(outline);
  world.closed = true;
  world.summary = Describe(shape_name, w, d, rotation);
  return rotation;
}

}  // namespace plywood::sim::worldgen
