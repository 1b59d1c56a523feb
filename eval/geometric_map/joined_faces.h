#pragma once

#include <Eigen/Core>
#include <vector>

#include "sim/world/ground_truth_walls.h"

namespace plywood::eval {

// One wall surface as seed 003's map scorer counts it: faces of one or more boxes that lie on one
// line, face the same way and follow each other with gaps of at most max_gap_m, joined. Two
// cabinets standing 5 cm apart against a wall are one surface to a scanner whose segmentation does
// not break at 5 cm; scored as two faces, the one segment it gives covers half of each and matches
// neither.
struct JoinedFace {
  // Counter-clockwise around the solid, like sim::WallSegment: the outward normal is b - a turned
  // clockwise.
  Eigen::Vector2d a = Eigen::Vector2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  std::vector<int> members;  // indices of the joined faces, ascending
};

// Collinear means both endpoints of one face within 1 mm of the other's line and directions within
// 0.01 deg (box faces of one plywood wall are exactly collinear). Every face is in exactly one
// JoinedFace; the result is ordered by each one's first member.
std::vector<JoinedFace> JoinCollinearFaces(const std::vector<sim::WallSegment>& faces,
                                           double max_gap_m);

// How much of `face` the segment start..end covers: the overlap of the two along the face's line
// (both projected on it), 0 when they do not overlap. A segment matched with a JoinedFace shows
// only the members it covers: a glass panel's end 18 mm wide on the line of a visible wall's face
// is one surface with that face, but the segment along the wall does not show the glass.
double CoveredLengthM(const sim::WallSegment& face, const Eigen::Vector2d& start,
                      const Eigen::Vector2d& end);

}  // namespace plywood::eval
