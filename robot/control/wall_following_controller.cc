#include "robot/control/wall_following_controller.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "msgs/shortest_number.h"
#include "robot/control/tick_time_slack.h"
#include "robot/drive/diff_drive_kinematics.h"

namespace plywood::robot {
namespace {

// A point further than this from the first line fitted beside the robot belongs to something else
// (the next wall at a corner, a door jamb, a table leg): about twice the sonar's 1 % noise at 2 m
// plus what an echo placed on the beam axis is off by when it came from the edge of the cone.
constexpr double kOutlierM = 0.1;
// Laser returns closer together than this along a scan add nothing to the fit but cost memory.
constexpr double kMinPointSpacingM = 0.03;
// CollectPoints sorts the old points (ahead test only) about an anchor pose and keeps the lists
// while the robot stays within this of it and turns by at most kAnchorTurnRad: a new reading
// re-sorts them first in a run (10 Hz rings, 0.25 m/s, at most 1 rad/s).
constexpr double kAnchorSlackM = 0.05;
constexpr double kAnchorTurnRad = 0.15;
// Speed at the near end of the slow-down zone, as a fraction of speed_m_s: still enough to creep.
constexpr double kMinSpeedFraction = 0.5;
// An arc around the end of a wall turns by at most half a turn (a thin wall or a door jamb); one
// that finds nothing by then would only circle, so the robot drives straight to find a wall.
constexpr double kMaxArcRad = std::numbers::pi;

// Folds a line direction into (-pi/2, pi/2]: a wall has no arrow, we take the one ahead.
double FoldLineAngle(double angle_rad) {
  double a = msgs::WrapAngle(angle_rad);
  if (a > std::numbers::pi / 2.0) a -= std::numbers::pi;
  if (a <= -std::numbers::pi / 2.0) a += std::numbers::pi;
  return a;
}

// Beyond this range from the centre of rotation a remembered point changes nothing: it is no side
// point (max_wall_range_m), and as a front point it would lie further ahead than
// front_clearance_m + distance_m, where the lane counts as clear and the speed is not reduced, just
// as with no point at all. Padded so rounding in the squared-distance test cannot matter.
double RelevantRange(const WallFollowingOptions& o) {
  const double clear_m = o.front_clearance_m + o.distance_m;
  const double cos_front = std::cos(o.front_window_rad);
  if (!(cos_front > 1e-3)) return std::numeric_limits<double>::infinity();
  const double front_m = std::max(std::hypot(clear_m, o.lane_half_width_m), clear_m / cos_front);
  return std::max(o.max_wall_range_m, front_m) * (1.0 + 1e-6) + 1e-6;
}

// A point's range std::hypot(x, y), taken only where a comparison needs it: sqrt(x^2 + y^2) is
// within a few ulps of it, so a comparison that this estimate decides by more than kSlack
// (relative) has the same outcome with std::hypot, and only the others call it. Same outcomes as
// comparing with std::hypot throughout, at a fraction of the libm calls.
class PointRange {
 public:
  PointRange(double x, double y) : x_(x), y_(y) {}

  // range * factor <= value, for a finite factor.
  bool AtMostTimes(double value, double factor) {
    const double product = Estimate() * factor;
    if (Sure()) {
      const double slack = kSlack * std::abs(product);
      if (value > product + slack) return true;
      if (value < product - slack) return false;
    }
    return Exact() * factor <= value;
  }

  // range <= limit.
  bool AtMost(double limit) {
    Estimate();
    if (Sure()) {
      const double slack = kSlack * std::abs(limit);
      if (estimate_ < limit - slack) return true;
      if (estimate_ > limit + slack) return false;
    }
    return Exact() <= limit;
  }

 private:
  static constexpr double kSlack = 1e-12;
  // Squares neither underflow nor overflow: the estimate's few-ulp bound holds.
  bool Sure() const { return estimate_ > 1e-100 && estimate_ < 1e100; }
  double Estimate() {
    if (estimate_ < 0.0) estimate_ = std::sqrt(x_ * x_ + y_ * y_);
    return estimate_;
  }
  double Exact() {
    if (exact_ < 0.0) exact_ = std::hypot(x_, y_);
    return exact_;
  }

  double x_, y_;
  double estimate_ = -1.0;
  double exact_ = -1.0;
};

}  // namespace

std::string_view ToString(WallSide side) { return side == WallSide::kLeft ? "left" : "right"; }

std::string_view ToString(WallSensor sensor) {
  return sensor == WallSensor::kSonar ? "sonar" : "laser";
}

WallSide ParseWallSide(std::string_view text) {
  if (text == "left") return WallSide::kLeft;
  if (text == "right") return WallSide::kRight;
  throw std::invalid_argument("side: must be \"left\" or \"right\", got \"" + std::string(text) +
                              "\"");
}

WallSensor ParseWallSensor(std::string_view text) {
  if (text == "sonar") return WallSensor::kSonar;
  if (text == "laser") return WallSensor::kLaser;
  throw std::invalid_argument("sensor: must be \"sonar\" or \"laser\", got \"" + std::string(text) +
                              "\"");
}

void WallFollowingOptions::Validate() const {
  if (side != WallSide::kLeft && side != WallSide::kRight) {
    throw std::invalid_argument("side: must be left or right");
  }
  if (sensor != WallSensor::kSonar && sensor != WallSensor::kLaser) {
    throw std::invalid_argument("sensor: must be sonar or laser");
  }
  internal::RequirePositive("distance_m", distance_m);
  internal::RequirePositive("speed_m_s", speed_m_s);
  internal::RequirePositive("accel_m_s2", accel_m_s2);
  internal::RequirePositive("max_turn_rate_rad_s", max_turn_rate_rad_s);
  internal::RequirePositive("distance_gain_rad_per_m", distance_gain_rad_per_m);
  internal::RequirePositive("angle_gain_per_s", angle_gain_per_s);
  internal::RequirePositive("max_approach_angle_rad", max_approach_angle_rad);
  if (max_approach_angle_rad >= std::numbers::pi / 2.0) {
    throw std::invalid_argument("max_approach_angle_rad: must be < pi/2, got " +
                                msgs::ShortestNumber(max_approach_angle_rad));
  }
  internal::RequirePositive("side_window_rad", side_window_rad);
  internal::RequirePositive("front_window_rad", front_window_rad);
  // Half-angles about an axis, tested through their cosines: beyond pi they wrap round, and
  // front_window_rad 7 ran exactly as 7 - 2 pi = 0.717 (s54).
  for (const auto& [name, half_angle] :
       {std::pair{"side_window_rad", side_window_rad}, {"front_window_rad", front_window_rad}}) {
    if (half_angle > std::numbers::pi) {
      throw std::invalid_argument(std::string(name) +
                                  ": must be at most pi (a half-angle about its axis; a wider one "
                                  "wraps round), got " +
                                  msgs::ShortestNumber(half_angle));
    }
  }
  internal::RequirePositive("max_wall_range_m", max_wall_range_m);
  if (max_wall_range_m <= distance_m) {
    throw std::invalid_argument("max_wall_range_m: must exceed distance_m, got " +
                                msgs::ShortestNumber(max_wall_range_m));
  }
  internal::RequirePositive("front_clearance_m", front_clearance_m);
  internal::RequirePositive("lane_half_width_m", lane_half_width_m);
  internal::RequireNonNegative("memory_s", memory_s);
  internal::RequireNonNegative("wall_memory_s", wall_memory_s);
  if (wall_memory_s > memory_s) {
    throw std::invalid_argument("wall_memory_s: must not exceed memory_s, got " +
                                msgs::ShortestNumber(wall_memory_s));
  }
  internal::RequireNonNegative("duration_s", duration_s);
}

WallFollowingController::WallFollowingController(const DiffDriveSpec& spec,
                                                 const WallFollowingOptions& options)
    : spec_(spec),
      options_(options),
      side_sign_(options.side == WallSide::kLeft ? 1.0 : -1.0),
      relevant_range_m_(RelevantRange(options)) {
  spec_.Validate();
  options_.Validate();
  internal::RequireDrivableSpeed(spec_, "speed_m_s", options_.speed_m_s);
}

void WallFollowingController::AddPoint(const msgs::Pose2D& X_WR, const msgs::Pose2D& X_RS,
                                       double beam_rad, double range_m, double time_s) {
  const msgs::Pose2D X_WP =
      X_WR * X_RS * msgs::Pose2D{range_m * std::cos(beam_rad), range_m * std::sin(beam_rad), 0.0};
  memory_.push_back({{X_WP.x_m, X_WP.y_m}, time_s});
}

void WallFollowingController::Remember(const ControllerInput& input) {
  const double time_s =
      options_.sensor == WallSensor::kSonar ? input.sonar->time_s : input.laser->time_s;
  if (last_reading_time_s_ && time_s <= *last_reading_time_s_) return;
  last_reading_time_s_ = time_s;
  // Stale points go before the new ones arrive, so the latest reading always counts in full.
  const auto fresh =
      std::find_if(memory_.begin() + memory_head_, memory_.end(), [&](const StampedPoint& p) {
        return p.time_s >= time_s - options_.memory_s - kTickTimeSlackS;
      });
  memory_head_ = static_cast<std::size_t>(fresh - memory_.begin());
  // The stale points are dropped in bulk once they are half of memory_, not at every reading:
  // erasing the front moves everything behind it, so each point is moved a bounded number of
  // times instead of once per reading while it is remembered.
  if (memory_head_ > memory_.size() / 2) {
    memory_.erase(memory_.begin(), fresh);
    memory_head_ = 0;
  }
  old_points_sorted_ = false;  // memory_ and the split between old and recent points change
  const msgs::Pose2D& X_WR = input.X_WR_estimate;
  if (options_.sensor == WallSensor::kSonar) {
    // No echo is not free space (specular miss): only echoes go in, placed on the beam axis.
    for (const msgs::RangeReading& reading : input.sonar->readings) {
      if (!reading.echo || reading.range_m < input.sonar->range_min_m ||
          reading.range_m > input.sonar->range_max_m) {
        continue;
      }
      AddPoint(X_WR, reading.X_RS, 0.0, reading.range_m, time_s);
    }
  } else {
    const msgs::LaserScan& scan = *input.laser;
    std::optional<Point> last_W;
    for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
      if (!scan.IsReturn(i)) continue;
      AddPoint(X_WR, scan.X_RS, scan.BeamAngleRad(i), scan.ranges_m[i], time_s);
      const Point p_W = memory_.back().p_W;
      if (last_W && std::hypot(p_W.x_m - last_W->x_m, p_W.y_m - last_W->y_m) < kMinPointSpacingM) {
        memory_.pop_back();
      } else {
        last_W = p_W;
      }
    }
  }
}

void WallFollowingController::SortOldPoints(const msgs::Pose2D& X_WR, std::size_t old_count) {
  // A pose within the slack of the anchor sees a point within inner of the anchor within reach,
  // and one beyond outer out of reach (triangle inequality); the padding covers the rounding of
  // these tests and of the per-pose test, which are all far below a nanometre.
  const double pad_m = 1e-9 * (1.0 + relevant_range_m_);
  const double inner_m = std::max(0.0, relevant_range_m_ - kAnchorSlackM - pad_m);
  const double outer_m = relevant_range_m_ + kAnchorSlackM + pad_m;
  const double inner_squared = inner_m * inner_m, outer_squared = outer_m * outer_m;
  // A point kept (within outer of the anchor) lies ahead of a pose within the slack and the turn
  // of the anchor by at most its distance ahead of the anchor + outer * turn + slack: a point
  // further behind than that is behind every such pose, and the ahead test wants x > 0.
  const double behind_m = -(outer_m * kAnchorTurnRad + kAnchorSlackM + pad_m);
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  old_inside_.clear();
  old_boundary_.clear();
  for (std::size_t i = 0; i < old_count; ++i) {
    const Point& p_W = memory_[memory_head_ + i].p_W;
    const double dx = p_W.x_m - X_WR.x_m, dy = p_W.y_m - X_WR.y_m;
    const double d_squared = dx * dx + dy * dy;
    if (d_squared > outer_squared || c * dx + s * dy < behind_m) continue;
    if (d_squared < inner_squared) {
      old_inside_.push_back(p_W);
    } else {
      old_boundary_.push_back(p_W);
    }
  }
  old_anchor_x_m_ = X_WR.x_m;
  old_anchor_y_m_ = X_WR.y_m;
  old_anchor_theta_rad_ = X_WR.theta_rad;
  old_points_sorted_ = true;
}

double WallFollowingController::CollectPoints(const msgs::Pose2D& X_WR, std::vector<Point>* side) {
  // Hot loop over up to a few thousand points at the control rate: rotate by hand, compare bearings
  // through their cosines, skip the points too far away to matter before any of that, and take a
  // point's range (std::hypot) only when a test needs it. Every test on a point that is not skipped
  // is the same arithmetic as before, so the wall fit and the commands do not change.
  const double c = std::cos(X_WR.theta_rad), s = std::sin(X_WR.theta_rad);
  const double cos_side = std::cos(options_.side_window_rad);
  const double cos_front = std::cos(options_.front_window_rad);
  const double newest_s = last_reading_time_s_.value_or(0.0);
  const double oldest_side_s = newest_s - options_.wall_memory_s - kTickTimeSlackS;
  const double reach_squared = relevant_range_m_ * relevant_range_m_;
  double ahead_m = std::numeric_limits<double>::infinity();
  // The ahead test: the nearest point in the lane or the front window, a minimum over the points,
  // so the same whatever order they come in.
  const auto ahead = [&](const Point& p, PointRange& range) {
    if (p.x_m > 0.0 && p.x_m < ahead_m &&
        (std::abs(p.y_m) <= options_.lane_half_width_m || range.AtMostTimes(p.x_m, cos_front))) {
      ahead_m = p.x_m;
    }
  };
  // memory_ is in time order: the points before `recent` are too old for the wall fit (the side
  // test) and count only for the ahead test.
  const auto recent =
      std::partition_point(memory_.begin() + memory_head_, memory_.end(),
                           [&](const StampedPoint& p) { return p.time_s < oldest_side_s; });
  // A point on the far side (side_sign_ * y < 0) is no side point: range * cos_side >= 0 > that.
  const bool far_side_fails = cos_side >= 0.0;
  for (auto it = recent; it != memory_.end(); ++it) {
    const double dx = it->p_W.x_m - X_WR.x_m, dy = it->p_W.y_m - X_WR.y_m;
    if (dx * dx + dy * dy > reach_squared) continue;
    const Point p{c * dx + s * dy, -s * dx + c * dy};
    PointRange range(p.x_m, p.y_m);
    const double towards_side_m = side_sign_ * p.y_m;
    if (!(far_side_fails && towards_side_m < 0.0) && range.AtMostTimes(towards_side_m, cos_side) &&
        range.AtMost(options_.max_wall_range_m)) {
      side->push_back(p);
    }
    ahead(p, range);
  }
  // The same test for an old point (no side test), its y taken only when x could count.
  const auto old_ahead = [&](double dx, double dy) {
    const double x_m = c * dx + s * dy;
    if (!(x_m > 0.0 && x_m < ahead_m)) return;
    const double y_m = -s * dx + c * dy;
    if (std::abs(y_m) <= options_.lane_half_width_m ||
        PointRange(x_m, y_m).AtMostTimes(x_m, cos_front)) {
      ahead_m = x_m;
    }
  };
  const auto old_count = static_cast<std::size_t>(recent - (memory_.begin() + memory_head_));
  if (!std::isfinite(reach_squared)) {
    for (std::size_t i = 0; i < old_count; ++i) {
      const Point& p_W = memory_[memory_head_ + i].p_W;
      old_ahead(p_W.x_m - X_WR.x_m, p_W.y_m - X_WR.y_m);
    }
    return ahead_m;
  }
  // The old points about an anchor pose (SortOldPoints): those surely within reach skip the reach
  // test, those surely beyond it or behind the robot are not visited, the rest take it.
  const double ax = X_WR.x_m - old_anchor_x_m_, ay = X_WR.y_m - old_anchor_y_m_;
  if (!old_points_sorted_ || !(ax * ax + ay * ay <= kAnchorSlackM * kAnchorSlackM) ||
      !(std::abs(X_WR.theta_rad - old_anchor_theta_rad_) <= kAnchorTurnRad)) {
    SortOldPoints(X_WR, old_count);
  }
  for (const Point& p_W : old_boundary_) {
    const double dx = p_W.x_m - X_WR.x_m, dy = p_W.y_m - X_WR.y_m;
    if (dx * dx + dy * dy > reach_squared) continue;
    old_ahead(dx, dy);
  }
  for (const Point& p_W : old_inside_) old_ahead(p_W.x_m - X_WR.x_m, p_W.y_m - X_WR.y_m);
  return ahead_m;
}

std::optional<WallFollowingController::WallEstimate> WallFollowingController::FitWall(
    const std::vector<Point>& side, double theta_estimate_rad) {
  if (side.empty()) return std::nullopt;
  // Centroid and principal axis (the total-least-squares line direction) of the points `use`
  // accepts; nullopt for the angle when they do not spread along a line.
  struct Fit {
    double cx = 0.0, cy = 0.0;
    std::optional<double> angle_rad;
    int count = 0;
  };
  const auto fit = [&](const auto& use) {
    Fit f;
    for (const Point& p : side) {
      if (!use(p)) continue;
      f.cx += p.x_m;
      f.cy += p.y_m;
      ++f.count;
    }
    if (f.count == 0) return f;
    f.cx /= f.count;
    f.cy /= f.count;
    double sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (const Point& p : side) {
      if (!use(p)) continue;
      sxx += (p.x_m - f.cx) * (p.x_m - f.cx);
      syy += (p.y_m - f.cy) * (p.y_m - f.cy);
      sxy += (p.x_m - f.cx) * (p.y_m - f.cy);
    }
    if (sxx + syy > 1e-12) f.angle_rad = FoldLineAngle(0.5 * std::atan2(2.0 * sxy, sxx - syy));
    return f;
  };
  Fit f = fit([](const Point&) { return true; });
  if (f.angle_rad) {
    const Fit all = f;
    const double s = std::sin(*all.angle_rad), c = std::cos(*all.angle_rad);
    const Fit inliers = fit([&](const Point& p) {
      return std::abs((p.x_m - all.cx) * s - (p.y_m - all.cy) * c) <= kOutlierM;
    });
    if (inliers.count > 0 && inliers.count < all.count) f = inliers;
  }
  double angle_rad = 0.0;
  if (f.angle_rad) {
    angle_rad = *f.angle_rad;
    wall_heading_W_rad_ = theta_estimate_rad + angle_rad;
  } else if (wall_heading_W_rad_) {
    angle_rad = FoldLineAngle(*wall_heading_W_rad_ - theta_estimate_rad);
  }
  // Distance from the centre of rotation to the line through the centroid.
  const double distance_m = std::abs(f.cx * std::sin(angle_rad) - f.cy * std::cos(angle_rad));
  return WallEstimate{distance_m, angle_rad};
}

msgs::WheelSpeedCommand WallFollowingController::Update(const ControllerInput& input) {
  const double dt_s = last_time_s_ ? input.time_s - *last_time_s_ : 0.0;
  last_time_s_ = input.time_s;
  if (!start_time_s_) start_time_s_ = input.time_s;
  if (options_.duration_s > 0.0 &&
      input.time_s - *start_time_s_ >= options_.duration_s - kTickTimeSlackS) {
    finished_ = true;
  }
  const bool have_data =
      options_.sensor == WallSensor::kSonar ? input.sonar != nullptr : input.laser != nullptr;
  if (finished_ || !have_data) {
    speed_m_s_ = 0.0;
    turning_away_ = false;
    return {};
  }

  Remember(input);
  side_scratch_.clear();
  const double ahead_m = CollectPoints(input.X_WR_estimate, &side_scratch_);
  wall_ = FitWall(side_scratch_, input.X_WR_estimate.theta_rad);
  // Hysteresis: once blocked, keep turning until the way ahead is clear by a further distance_m
  // and the side sees a wall roughly parallel (or none), else the wall being left behind pulls the
  // robot straight back into the corner. Clutter (a wardrobe in a corner, table legs) may never
  // fit as one parallel wall: after half a turn a clear way ahead is enough.
  if (ahead_m < options_.front_clearance_m) {
    if (!turning_away_) turned_away_rad_ = 0.0;
    turning_away_ = true;
  }
  if (turning_away_ && ahead_m > options_.front_clearance_m + options_.distance_m &&
      (!wall_ || std::abs(wall_->angle_rad) < options_.max_approach_angle_rad / 2.0 ||
       turned_away_rad_ > std::numbers::pi)) {
    turning_away_ = false;
  }
  if (turning_away_) {
    speed_m_s_ = 0.0;
    turned_away_rad_ += options_.max_turn_rate_rad_s * dt_s;
    return TwistToWheelSpeeds(spec_, {0.0, -side_sign_ * options_.max_turn_rate_rad_s});
  }

  // Slow down linearly over the last distance_m before the clearance, so that the robot does not
  // reach it faster than the sonar (a few hertz) can tell.
  const double slow_fraction = std::clamp(
      (ahead_m - options_.front_clearance_m) / options_.distance_m, kMinSpeedFraction, 1.0);
  speed_m_s_ = dt_s > 0.0 ? std::min(options_.speed_m_s * slow_fraction,
                                     speed_m_s_ + options_.accel_m_s2 * dt_s)
                          : 0.0;
  double yaw_rate_rad_s = 0.0;
  if (!wall_) {
    if (wall_heading_W_rad_ && arc_turned_rad_ < kMaxArcRad) {
      yaw_rate_rad_s = side_sign_ * speed_m_s_ / options_.distance_m;
      arc_turned_rad_ += std::abs(yaw_rate_rad_s) * dt_s;
    }
  } else {
    arc_turned_rad_ = 0.0;
    const double distance_error_m = wall_->distance_m - options_.distance_m;
    // Heading relative to the wall is minus the wall's direction seen from the robot.
    const double heading_to_wall_rad = -wall_->angle_rad;
    const double heading_wanted_rad =
        side_sign_ * std::clamp(options_.distance_gain_rad_per_m * distance_error_m,
                                -options_.max_approach_angle_rad, options_.max_approach_angle_rad);
    yaw_rate_rad_s = options_.angle_gain_per_s * (heading_wanted_rad - heading_to_wall_rad);
  }
  yaw_rate_rad_s =
      std::clamp(yaw_rate_rad_s, -options_.max_turn_rate_rad_s, options_.max_turn_rate_rad_s);
  return TwistToWheelSpeeds(spec_, {speed_m_s_, yaw_rate_rad_s});
}

}  // namespace plywood::robot
