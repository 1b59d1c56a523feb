#pragma once

#include "eval/protocol.h"

namespace plywood::eval {

// `protocol: seed004_ransac` (Bertocco et al., seed 004): drives the experiment once, accumulates
// its laser returns in the world frame twice -- placed by the ground-truth pose and by the
// odometry pose -- and runs sequential RANSAC (perception/lines/ransac_extractor.h, the seed's
// defects fixed) on each cloud. Lines are scored against the wall faces
// (perception/lines/line_scoring.h, world frame); a line that matches no face is false, and is
// reported as "on legs" when most of its inliers hit geoms that are no wall face (table legs,
// columns). Writes metrics.json (seed004.<truth|odometry>.*), lines_<cloud>.csv, cloud_<cloud>.png
// and config.yaml.
//   seed004_ransac: {scan_stride: 5, beam_stride: 4, ransac: {distance_threshold_m: 0.03, ...}}
int Seed004RansacProtocol(const ProtocolContext& context);
// Reads the `seed004_ransac:` section as the protocol does. @throws sim::ConfigError.
void CheckSeed004RansacOptions(const sim::ExperimentConfig& config);

}  // namespace plywood::eval
