#include "perception/lines/small_round_groups.h"

#include <algorithm>
#include <cmath>

#include "perception/lines/circle_fit.h"

namespace plywood::perception {
namespace {

// How far the group's points lie beyond the chord between its ends, towards the sensor.
double BulgeM(const ScanPoints& scan, const std::vector<int>& group) {
  const Eigen::Vector2d a = scan.points[group.front()], b = scan.points[group.back()];
  Eigen::Vector2d normal(a.y() - b.y(), b.x() - a.x());
  if (normal.norm() < 1e-12) return 0.0;
  normal.normalize();
  if (normal.dot(-a) < 0.0) normal = -normal;  // towards the sensor
  double bulge_m = 0.0;
  for (int i : group) bulge_m = std::max(bulge_m, normal.dot(scan.points[i] - a));
  return bulge_m;
}

}  // namespace

std::vector<CircleFeature> SmallRoundGroups(const ScanPoints& scan,
                                            const BreakpointOptions& breakpoints,
                                            const SmallRoundGroupOptions& options) {
  std::vector<CircleFeature> found;
  const double sigma_m = breakpoints.sigma_m;
  for (const std::vector<int>& group : SplitAtBreakpoints(scan, breakpoints)) {
    const int n = static_cast<int>(group.size());
    if (n < options.min_points || n > options.max_points) continue;
    if (BulgeM(scan, group) < options.min_bulge_sigmas * sigma_m) continue;
    const std::optional<CircleFit> fit = FitCircle(scan.points, group);
    if (!fit || fit->radius_m > options.max_radius_m) continue;
    if (fit->centre.norm() <= fit->radius_m) continue;  // around the sensor: a curved wall
    if (fit->max_residual_m > options.max_residual_sigmas * sigma_m) continue;
    // The points are the circle's near side (a far side is never seen).
    Eigen::Vector2d mean_direction = Eigen::Vector2d::Zero();
    for (int i : group) mean_direction += (scan.points[i] - fit->centre).normalized();
    if (mean_direction.dot(-fit->centre) <= 0.0) continue;
    CircleFeature circle;
    circle.centre = fit->centre;
    circle.radius_m = fit->radius_m;
    circle.rms_m = std::sqrt(fit->rss_m2 / n);
    circle.point_indices = group;
    found.push_back(std::move(circle));
  }
  return found;
}

}  // namespace plywood::perception
