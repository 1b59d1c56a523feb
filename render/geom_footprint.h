#pragma once

#include <mujoco/mujoco.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "render/image_ops.h"
#include "render/world_to_pixel.h"

namespace plywood::render {

// What a geom looks like from straight above: the convex outline of its projection onto the floor
// (exact for boxes, sampled every 15 deg for round shapes), how high it reaches and its colour.
struct GeomFootprint {
  int geom_id = -1;
  std::vector<Eigen::Vector2d> outline_W;  // counter-clockwise convex polygon, world metres
  double z_top_m = 0.0;
  Rgb colour;
};

// True when geom `g` can never move: its body is welded to the world body, not by way of a mocap
// body.
bool IsStaticGeom(const mjModel* m, int g);

// Pose of static geom `g` in the world from the model alone (composing body_pos/body_quat up to the
// world), so no mj_forward is needed. @pre IsStaticGeom(m, g).
Eigen::Isometry3d StaticGeomPose(const mjModel* m, int g);

// The footprint of geom `g` at pose X_WG. Planes have none (empty outline): they are the floor.
GeomFootprint FootprintOf(const mjModel* m, int g, const Eigen::Isometry3d& X_WG);

// Footprints of every static, visible (alpha > 0), non-plane geom, posed from the model.
std::vector<GeomFootprint> StaticFootprints(const mjModel* m);

// The floor rectangle and height the world's static geometry spans (planes excluded, because
// MuJoCo floors are usually infinite). When there is none: a finite plane's extent, else
// [-1, 1]^2.
struct StaticExtent {
  WorldBounds bounds;
  double z_max_m = 0.0;
};
StaticExtent StaticGeometryExtent(const mjModel* m);

}  // namespace plywood::render
