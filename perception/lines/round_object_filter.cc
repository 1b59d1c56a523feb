#include "perception/lines/round_object_filter.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "msgs/shortest_number.h"
#include "perception/lines/circle_feature.h"
#include "perception/lines/circle_fit.h"
#include "perception/lines/end_point_fit.h"
#include "perception/lines/tls_line_fit.h"

namespace plywood::perception {
namespace {

constexpr double kTrimSigmas = 3.0;
constexpr double kMinKeptFraction = 0.8;
constexpr double kNoiseLevelSigmas = 1.5;
constexpr double kChiSquarePerParameter = 3.0;
constexpr double kMinBulgeSigmas = 3.0;
// A thin column (r 3-10 cm) gives one chord of 5-10 points whose bulge is 1-3 noise sigmas; a
// circle has 3 parameters, so 5 points leave it 2 degrees of freedom.
constexpr int kMinChordPoints = 5;
constexpr double kMinChordBulgeSigmas = 1.5;
// A run that is not its whole group is a piece of something larger (a column in one group with
// the wall behind it, or a stretch of a wall): it must bend away from one straight line by more
// than noise does. One line through its points leaves at least this many sigma^2 more residual
// than the circle (on a straight wall the circle's one extra parameter buys a chi-square gain
// with 1 degree of freedom: 25 is 5 sigma). Without it a 45 deg arc let noise bumps in straight
// walls pass (CircleFeatureTest: a 9-point bump 2 m away, R 0.1 m over 84 deg); the generated
// `columns` sweep (seed 1) lost no dropped line to it.
constexpr double kMinPartialRunGainSigma2 = 25.0;

// The circle of lines[first..last] (inclusive) when they are one round object.
std::optional<CircleFeature> RoundRun(std::span<const Eigen::Vector2d> points, double noise_sigma_m,
                                      const RoundObjectOptions& options,
                                      const std::vector<std::vector<int>>& lines, int first,
                                      int last) {
  // Both ends of the run are breaks: the object is seen whole, its own silhouette.
  const bool whole_group = first == 0 && last == static_cast<int>(lines.size()) - 1;
  // The run's points are lines[first..last] concatenated; gathered into `run` only for a run
  // that passes the bulge test below (most do not: no allocation for them).
  int total = 0, front = -1, back = -1;
  for (int k = first; k <= last; ++k) {
    if (lines[k].empty()) continue;
    total += static_cast<int>(lines[k].size());
    if (front < 0) front = lines[k].front();
    back = lines[k].back();
  }
  const bool chord = first == last;  // a single free-standing line (the whole group)
  const int min_points = chord ? kMinChordPoints : options.min_round_points;
  if (total < min_points) return std::nullopt;
  // Cheap test first: the near side of a round object bulges towards the sensor, beyond the
  // chord between the run's ends; straight walls and concave corners do not (most runs).
  {
    const Eigen::Vector2d a = points[front], b = points[back];
    Eigen::Vector2d normal(a.y() - b.y(), b.x() - a.x());
    if (normal.norm() < 1e-12) return std::nullopt;
    normal.normalize();
    if (normal.dot(-a) < 0.0) normal = -normal;  // towards the sensor
    double bulge_m = 0.0;
    for (int k = first; k <= last; ++k)
      for (int i : lines[k]) bulge_m = std::max(bulge_m, normal.dot(points[i] - a));
    // A chord c of a circle of radius <= R_max has a sagitta >= R_max - sqrt(R_max^2 - c^2 / 4).
    const double half_chord = 0.5 * (b - a).norm();
    const double r_max = options.max_round_radius_m;
    if (half_chord >= r_max) return std::nullopt;
    const double min_sagitta = r_max - std::sqrt(r_max * r_max - half_chord * half_chord);
    const double noise_m = (chord ? kMinChordBulgeSigmas : kMinBulgeSigmas) * noise_sigma_m;
    if (bulge_m < std::max(noise_m, min_sagitta - noise_m)) return std::nullopt;
  }
  std::vector<int> run;
  run.reserve(total);
  for (int k = first; k <= last; ++k) run.insert(run.end(), lines[k].begin(), lines[k].end());
  std::optional<CircleFit> circle = FitCircle(points, run);
  if (!circle) return std::nullopt;
  // Trim the points off the circle once and refit.
  const double trim_m = kTrimSigmas * noise_sigma_m;
  const auto off_circle = [&](int i) {
    return std::abs((points[i] - circle->centre).norm() - circle->radius_m) > trim_m;
  };
  std::vector<int> kept;
  kept.reserve(run.size());
  std::vector<char> is_kept(run.size());  // in run order: lines[first..last] concatenated
  for (std::size_t j = 0; j < run.size(); ++j) {
    is_kept[j] = !off_circle(run[j]);
    if (is_kept[j]) kept.push_back(run[j]);
  }
  if (kept.size() < kMinKeptFraction * total || static_cast<int>(kept.size()) < min_points) {
    return std::nullopt;
  }
  if (static_cast<int>(kept.size()) < total) {
    circle = FitCircle(points, kept);
    if (!circle) return std::nullopt;
  }
  if (circle->radius_m > options.max_round_radius_m) return std::nullopt;
  // Seen from outside: the sensor (origin) lies outside the circle, so the points are its near
  // side. A concave arc around the sensor is a curved wall, not an object.
  if (circle->centre.norm() <= circle->radius_m) return std::nullopt;
  if (!whole_group) {
    LineMoments straight;
    for (int i : kept) straight.Add(points[i]);
    double alpha = 0.0, r = 0.0, straight_rss_m2 = 0.0;
    straight.Fit(&alpha, &r, &straight_rss_m2);
    if (straight_rss_m2 - circle->rss_m2 < kMinPartialRunGainSigma2 * noise_sigma_m * noise_sigma_m)
      return std::nullopt;
  }
  // A round object seen from outside shows nearly half its circumference (180 deg minus twice
  // asin(R / distance)), centred on the direction to the sensor; clutter that happens to fit a
  // small circle shows a short piece of one.
  std::vector<double> angles;
  angles.reserve(kept.size());
  Eigen::Vector2d mean_direction = Eigen::Vector2d::Zero();
  for (int i : kept) {
    const Eigen::Vector2d d = (points[i] - circle->centre).normalized();
    angles.push_back(std::atan2(d.y(), d.x()));
    mean_direction += d;
  }
  if (mean_direction.dot(-circle->centre) <= 0.0) return std::nullopt;  // the far side: never seen
  std::sort(angles.begin(), angles.end());
  double largest_gap = angles.front() + 2.0 * M_PI - angles.back();
  for (std::size_t k = 1; k < angles.size(); ++k) {
    largest_gap = std::max(largest_gap, angles[k] - angles[k - 1]);
  }
  // A small column seen whole can show less: noise inflates the fitted circle (a r = 0.1 m
  // column 2 m away, 12 points, fits R 0.12-0.14 m) and moves its centre back, so the samples
  // cover 60-100 deg of it. Such a whole group of >= 2 lines is round when every point lies on
  // the circle; a single line (one more parameter buys a flat box face a circle too often) or a
  // circle that needed trimming (a small box seen corner-on) still needs the full arc.
  const bool short_arc = (2.0 * M_PI - largest_gap) * 180.0 / M_PI < options.min_round_arc_deg;
  if (short_arc && (!whole_group || chord || static_cast<int>(kept.size()) < total))
    return std::nullopt;

  // The run's lines refitted to the kept points.
  const int line_count = last - first + 1;
  double lines_rss_m2 = 0.0;
  std::size_t j = 0;
  for (int k = first; k <= last; ++k) {
    LineMoments moments;
    for (int i : lines[k])
      if (is_kept[j++]) moments.Add(points[i]);
    if (moments.count() < 3) continue;  // two points lie on their line exactly
    double alpha = 0.0, r = 0.0, rss = 0.0;
    moments.Fit(&alpha, &r, &rss);
    lines_rss_m2 += rss;
  }
  const int n = static_cast<int>(kept.size());
  const int line_parameters = 3 * line_count - 1;
  if (n <= line_parameters) return std::nullopt;
  // (a) The circle explains the points at least as well as the lines, each residual variance
  // over its degrees of freedom.
  const double circle_variance = circle->rss_m2 / (n - 3);
  // The circle reported: a real fit (circle_feature.h) or none, and then no round object. The
  // circle above was fitted to `kept` already.
  const auto feature = [&]() {
    return CircleFeatureFromFit(*circle, kept,
                                {.max_radius_m = options.max_round_radius_m,
                                 .noise_sigma_m = noise_sigma_m,
                                 .min_points = min_points});
  };
  if (circle_variance <= lines_rss_m2 / (n - line_parameters)) return feature();
  // (b) With few points the lines' extra parameters can fit the noise: the circle still wins when
  // it fits at the sensor's noise level and the lines' gain is what their extra parameters buy
  // from noise alone (a chi-square budget per extra parameter, the noise sigma known).
  const double noise_m2 = noise_sigma_m * noise_sigma_m;
  if (circle_variance <= kNoiseLevelSigmas * kNoiseLevelSigmas * noise_m2 &&
      circle->rss_m2 - lines_rss_m2 <= kChiSquarePerParameter * (line_parameters - 3) * noise_m2) {
    return feature();
  }
  return std::nullopt;
}

}  // namespace

void RoundObjectOptions::Validate() const {
  if (!(max_round_radius_m > 0.0)) {
    throw std::invalid_argument("max_round_radius_m: must be > 0, got " +
                                msgs::ShortestNumber(max_round_radius_m));
  }
  if (!(min_round_arc_deg >= 0.0 && min_round_arc_deg <= 360.0)) {
    throw std::invalid_argument("min_round_arc_deg: must be in [0, 360], got " +
                                msgs::ShortestNumber(min_round_arc_deg));
  }
  if (min_round_points < 4) {
    throw std::invalid_argument("min_round_points: must be >= 4, got " +
                                std::to_string(min_round_points));
  }
}

void RemoveRoundObjects(std::span<const Eigen::Vector2d> points, double noise_sigma_m,
                        const RoundObjectOptions& options, std::vector<std::vector<int>>* lines,
                        std::vector<CircleFeature>* circles) {
  if (!options.reject_round_objects || lines->empty()) return;
  const int count = static_cast<int>(lines->size());
  std::vector<char> drop(count, 0);
  // Points on a circle of radius R lie within 2 R of each other. A line whose first and last
  // points are farther apart than that is in no round run: every box holding it is wider (the
  // box's sides are at least the ends' differences, rounding being monotonic), so the test below
  // would stop at it; its box is not needed.
  const double max_extent_m = 2.0 * options.max_round_radius_m;
  std::vector<char> wide(count, 0);
  // Bounding box of each other line's points.
  std::vector<Eigen::Vector2d> box_lo(count), box_hi(count);
  for (int k = 0; k < count; ++k) {
    if ((*lines)[k].empty()) continue;
    if ((points[(*lines)[k].front()] - points[(*lines)[k].back()]).norm() > max_extent_m) {
      wide[k] = 1;
      continue;
    }
    box_lo[k] = box_hi[k] = points[(*lines)[k].front()];
    for (int i : (*lines)[k]) {
      box_lo[k] = box_lo[k].cwiseMin(points[i]);
      box_hi[k] = box_hi[k].cwiseMax(points[i]);
    }
  }
  for (int first = 0; first < count;) {
    if ((*lines)[first].empty()) {
      ++first;
      continue;
    }
    // The longest round run starting here; a single line only when it is the whole group (both
    // its ends are breaks: a free-standing thin column gives one chord).
    int round_last = -1;
    std::optional<CircleFeature> circle;
    if (count == 1) {
      circle = RoundRun(points, noise_sigma_m, options, *lines, first, first);
      if (circle) round_last = first;
    }
    Eigen::Vector2d lo = box_lo[first], hi = box_hi[first];
    for (int last = first + 1; last < count; ++last) {
      if ((*lines)[last].empty()) break;
      if (wide[first] || wide[last]) break;
      lo = lo.cwiseMin(box_lo[last]), hi = hi.cwiseMax(box_hi[last]);
      if ((hi - lo).norm() > max_extent_m) break;
      if (auto c = RoundRun(points, noise_sigma_m, options, *lines, first, last)) {
        round_last = last;
        circle = std::move(c);
      }
    }
    if (round_last < 0) {
      ++first;
      continue;
    }
    for (int k = first; k <= round_last; ++k) drop[k] = 1;
    if (circles != nullptr) circles->push_back(std::move(*circle));
    first = round_last + 1;
  }
  int out = 0;
  for (int k = 0; k < count; ++k) {
    if (drop[k]) continue;
    if (out != k) (*lines)[out] = std::move((*lines)[k]);  // never self-move: it may clear
    ++out;
  }
  lines->resize(out);
}

void JoinRoundObjectsAcrossOccluders(const ScanPoints& scan, double noise_sigma_m,
                                     const RoundObjectOptions& options,
                                     std::vector<std::vector<std::vector<int>>>* group_lines,
                                     std::vector<CircleFeature>* circles) {
  if (!options.reject_round_objects || !scan.HasScanOrder()) return;
  const int n = static_cast<int>(scan.size());
  auto& groups = *group_lines;
  for (std::size_t g = 0; g + 1 < groups.size(); ++g) {
    if (groups[g].empty() || groups[g + 1].empty()) continue;
    const int end = groups[g].back().back(), start = groups[g + 1].front().front();
    // The returns between the two facing ends: all nearer than both (an occluder), no missing beam.
    const double far_m = std::min(scan.range_m[end], scan.range_m[start]);
    bool occluded = true;
    int between = 0;
    for (int k = end; k != start && occluded; k = (k + 1) % n) {
      const int next = (k + 1) % n;
      if (scan.MissingBeams(k, next) > 0) occluded = false;
      if (next != start) {
        ++between;
        if (!(scan.range_m[next] < far_m)) occluded = false;
      }
      if (between > n / 2) occluded = false;
    }
    if (!occluded || between == 0) continue;
    std::vector<std::vector<int>> joined = groups[g];
    const int first_facing = static_cast<int>(joined.size()) - 1;
    joined.insert(joined.end(), groups[g + 1].begin(), groups[g + 1].end());
    // Which lines RemoveRoundObjects keeps: their first points identify them (disjoint lines).
    std::vector<int> fronts(joined.size());
    for (std::size_t k = 0; k < joined.size(); ++k) fronts[k] = joined[k].front();
    std::vector<CircleFeature> found;
    std::vector<std::vector<int>> kept = joined;
    RemoveRoundObjects(scan.points, noise_sigma_m, options, &kept, &found);
    std::vector<char> dropped(joined.size(), 1);
    for (std::size_t k = 0, from = 0; k < kept.size(); ++k, ++from) {
      while (fronts[from] != kept[k].front()) ++from;
      dropped[from] = 0;
    }
    if (!dropped[first_facing] || !dropped[first_facing + 1]) continue;
    // The run that holds both facing lines: consecutive dropped lines around the junction.
    int lo = first_facing, hi = first_facing + 1;
    while (lo > 0 && dropped[lo - 1]) --lo;
    while (hi + 1 < static_cast<int>(joined.size()) && dropped[hi + 1]) ++hi;
    // Its circle: the one that holds points of the facing lines (one circle per run removed).
    if (circles != nullptr) {
      const auto holds = [&](const CircleFeature& c, const std::vector<int>& line) {
        for (int i : line)
          if (std::find(c.point_indices.begin(), c.point_indices.end(), i) != c.point_indices.end())
            return true;
        return false;
      };
      for (const CircleFeature& c : found) {
        if (holds(c, joined[first_facing]) || holds(c, joined[first_facing + 1])) {
          circles->push_back(c);
          break;
        }
      }
    }
    const int size_g = static_cast<int>(groups[g].size());
    groups[g].erase(groups[g].begin() + lo, groups[g].end());
    groups[g + 1].erase(groups[g + 1].begin(), groups[g + 1].begin() + (hi - size_g + 1));
  }
}

std::vector<char> RoundObjectPoints(const ScanPoints& scan, const BreakpointOptions& breakpoints,
                                    double split_threshold_m, const RoundObjectOptions& options,
                                    std::vector<CircleFeature>* circles) {
  std::vector<char> round(scan.size(), 0);
  if (!options.reject_round_objects) return round;
  // The smallest group the stage can call round: a single chord needs kMinChordPoints, a run of
  // lines min_round_points (RemoveRoundObjects tests both), as split_and_merge's groups get.
  const int min_group_points = std::min(kMinChordPoints, options.min_round_points);
  for (const std::vector<int>& group : SplitAtBreakpoints(scan, breakpoints)) {
    if (static_cast<int>(group.size()) < min_group_points) continue;
    std::vector<std::vector<int>> pieces =
        SplitByEndPointFit(scan.points, group, split_threshold_m, /*skip_single_outliers=*/true);
    const std::vector<std::vector<int>> before = pieces;
    RemoveRoundObjects(scan.points, breakpoints.sigma_m, options, &pieces, circles);
    if (pieces.size() == before.size()) continue;
    // Every point of the group not on a kept piece was on a round object's piece.
    std::vector<char> kept(scan.size(), 0);
    for (const auto& piece : pieces)
      for (int i : piece) kept[i] = 1;
    for (const auto& piece : before)
      for (int i : piece) round[i] = !kept[i];
  }
  return round;
}

}  // namespace plywood::perception
