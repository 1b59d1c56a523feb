#pragma once

#include <Eigen/Core>
#include <memory>

#include "eval/sonar_map/sonar_ground_truth.h"

namespace plywood::eval {

// The free space of `raster` a robot with a round body of `body_radius_m` can map by going there
// from `start_W`: what a point reaches from the start without entering space that only a body
// standing beyond a gap narrower than the body would sweep. So the corners and nooks of the
// robot's own space count, and so do the narrow gaps; rooms behind such gaps do not (bar nooks of
// theirs that touch the gap). A body fits where its centre is at least the radius from every
// occupied cell; the raster's faces lie between cell centres, so measuring to occupied cells'
// centres is half a cell generous, and a gap passes when it is at least twice the radius less one
// cell. The body stands where it was spawned even if that is less clear than the radius (the
// spawn check allowed it): the radius is then the start's clearance. The start must be free
// (MakeOccupancyTruth checked it).
ReachableSpace ComputeBodyReachableSpace(const sim::OccupancyRaster& raster,
                                         const Eigen::Vector2d& start_W, double body_radius_m);

// `truth` with its free space cut to ComputeBodyReachableSpace, the free space it leaves out
// unscored (the robot can neither go there nor be blamed for what it says of it, right or wrong)
// and its scored box that of the space left: seed 001's error e of what the robot's body can reach
// (issue 14, question 6 to steering).
std::unique_ptr<OccupancyTruth> MakeBodyReachTruth(const OccupancyTruth& truth,
                                                   const Eigen::Vector2d& start_W,
                                                   double body_radius_m);

}  // namespace plywood::eval
