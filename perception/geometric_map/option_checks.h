#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "msgs/pose2d.h"
#include "msgs/shortest_number.h"

namespace plywood::perception {

// The check behind the geometric map's Validate()s: throws std::invalid_argument "<field>: <what>,
// got <value>", so the message starts with the field's name as the YAML layer spells it. NaN fails
// every range written as `ok` = (lo <= v && v <= hi).
inline void RequireOption(bool ok, const char* field, const char* what, double value) {
  if (!ok) {
    throw std::invalid_argument(std::string(field) + ": " + what + ", got " +
                                msgs::ShortestNumber(value));
  }
}

// A pose handed in with a scan: NaN or inf would go into the map (and its histograms) for good.
// Throws std::invalid_argument "<field>: must be finite, got (x, y, theta)".
inline void RequireFinitePose(const char* field, const msgs::Pose2D& pose) {
  if (!std::isfinite(pose.x_m) || !std::isfinite(pose.y_m) || !std::isfinite(pose.theta_rad)) {
    throw std::invalid_argument(
        std::string(field) + ": must be finite, got (" + msgs::ShortestNumber(pose.x_m) + ", " +
        msgs::ShortestNumber(pose.y_m) + ", " + msgs::ShortestNumber(pose.theta_rad) + ")");
  }
}

}  // namespace plywood::perception
