#pragma once

#include <string>
#include <vector>

#include "eval/geometric_map/joined_faces.h"
#include "msgs/pose2d.h"
#include "perception/geometric_map/geometric_mapper.h"
#include "sim/config/geometric_map_config.h"
#include "sim/runner/experiment_runner.h"

namespace plywood::eval {

// Seed 003's map built from a finished run, with the poses it was built at.
struct GeometricMapRun {
  perception::GeometricMap map;
  long scans = 0;
  long points_seen = 0;
  long sonar_points = 0;                                 // points whose range came from the sonar
  std::vector<msgs::Pose2D> truth, odometry, corrected;  // per IR scan
  // The scored wall surfaces (joined_faces.h), filled by AddGeometricMapMetrics: the most IR beams
  // that hit each in one scan, the scans whose beams on it were enough for a line, and whether a
  // confirmed real segment matched it.
  std::vector<JoinedFace> faces;
  std::vector<int> face_observed_rays;
  std::vector<int> face_line_scans;
  std::vector<char> face_matched;
};

// The ring of `rings` (in time order) nearest in time to `time_s`, or null when it is more than
// max_age_s away. `cursor` remembers where the search stopped: call with non-decreasing times.
const msgs::RangeRing* NearestSonarRing(const std::vector<msgs::RangeRing>& rings, double time_s,
                                        double max_age_s, std::size_t* cursor);

// Feeds every IR scan of `record` (with the sonar ring nearest in time, if within
// config.max_sonar_age_s) at its odometry pose to a perception::GeometricMapper.
GeometricMapRun BuildGeometricMap(const sim::RunRecord& record,
                                  const sim::GeometricMapConfig& config);

// When the experiment has a geometric_map: section: builds the map and adds geometric_map.*
// metrics (docs/geometric_map.md) to the run's record; returns false (nothing done) otherwise.
// Walls are scored with the line-matching rule of perception/lines/line_scoring.h, in the map
// (world) frame, against the wall surfaces (collinear faces joined across gaps the segmentation
// does not break at, joined_faces.h) the IR scanner observed at the true pose: recall counts
// those hit by max(scoring.min_observed_rays, segmentation.min_line_points) beams in each of
// aggregation.min_observations scans (what a confirmed segment needs), recall_single_scan those
// hit by scoring.min_observed_rays beams in one scan. A segment, directed with its observer on
// the left, is matched only with surfaces facing that observer.
// @throws sim::ConfigError when the section is given but sensors.ir_scanner is off.
bool AddGeometricMapMetrics(sim::ExperimentRunner& runner, GeometricMapRun* run);

// DIR/geometric_map.json: segments (endpoints, tag, points, inliers), clusters, poses.
void WriteGeometricMapJson(const GeometricMapRun& run, const std::string& out_dir);

// DIR/geometric_map.png: the world's slice at the IR scanner's height in grey (IR-invisible geoms
// in light blue), the true path in black, real segments solid, pseudo ones dashed, clusters as
// boxes.
void WriteGeometricMapPicture(const sim::ExperimentRunner& runner, const GeometricMapRun& run,
                              const std::string& out_dir);

}  // namespace plywood::eval
