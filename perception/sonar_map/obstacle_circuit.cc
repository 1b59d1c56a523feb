#include "perception/sonar_map/obstacle_circuit.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "perception/sonar_map/line_fit.h"

namespace plywood::perception {
namespace {

// Fits u = a + b v through (v, u) pairs and returns it as a line in (x, y); `u_is_y` says
// which coordinate u is.
std::optional<BoundaryLine> FitSide(const std::vector<Eigen::Vector2d>& vu, bool u_is_y,
                                    double band_m, double sigma_m, int min_points) {
  // A column whose near face went unheard gives a point of the far face: the point farthest
  // from the fitted line is dropped while it lies more than `band_m` off, and the rest refitted.
  std::vector<double> v, u;
  for (const Eigen::Vector2d& p : vu) {
    v.push_back(p.x());
    u.push_back(p.y());
  }
  LineFit fit;
  for (;;) {
    if (static_cast<int>(v.size()) < std::max(2, min_points)) return std::nullopt;
    fit = ChiSquareLineFit(v, u, std::vector<double>(v.size(), sigma_m));
    std::size_t worst = 0;
    double worst_off = -1.0;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const double off = std::abs(u[i] - fit.a - fit.b * v[i]);
      if (off > worst_off) {
        worst_off = off;
        worst = i;
      }
    }
    if (worst_off <= band_m) break;
    v.erase(v.begin() + static_cast<std::ptrdiff_t>(worst));
    u.erase(u.begin() + static_cast<std::ptrdiff_t>(worst));
  }
  const double v0 =
      0.5 * (*std::min_element(v.begin(), v.end()) + *std::max_element(v.begin(), v.end()));
  const Eigen::Vector2d along = Eigen::Vector2d(1.0, fit.b).normalized();
  BoundaryLine line;
  line.point =
      u_is_y ? Eigen::Vector2d(v0, fit.a + fit.b * v0) : Eigen::Vector2d(fit.a + fit.b * v0, v0);
  line.direction = u_is_y ? along : Eigen::Vector2d(along.y(), along.x());
  return line;
}

}  // namespace

std::vector<Eigen::Vector2d> CircuitAround(const Rect& box, double distance,
                                           const Eigen::Vector2d& from) {
  const std::vector<Eigen::Vector2d> ccw = {{box.x0 - distance, box.y0 - distance},
                                            {box.x1 + distance, box.y0 - distance},
                                            {box.x1 + distance, box.y1 + distance},
                                            {box.x0 - distance, box.y1 + distance}};
  std::size_t first = 0;
  for (std::size_t k = 1; k < ccw.size(); ++k)
    if ((ccw[k] - from).norm() < (ccw[first] - from).norm()) first = k;
  std::vector<Eigen::Vector2d> out;
  for (std::size_t k = 0; k < ccw.size(); ++k) out.push_back(ccw[(first + k) % ccw.size()]);
  return out;
}

std::optional<Eigen::Vector2d> Intersect(const BoundaryLine& a, const BoundaryLine& b) {
  // a.point + s a.direction = b.point + t b.direction
  const double det = a.direction.x() * (-b.direction.y()) - a.direction.y() * (-b.direction.x());
  if (std::abs(det) < 1e-9) return std::nullopt;
  const Eigen::Vector2d d = b.point - a.point;
  const double s = (d.x() * (-b.direction.y()) - d.y() * (-b.direction.x())) / det;
  return a.point + s * a.direction;
}

Rect ObstacleOutline::Box() const {
  Rect r{corners[0].x(), corners[0].y(), corners[0].x(), corners[0].y()};
  for (const Eigen::Vector2d& c : corners) {
    r.x0 = std::min(r.x0, c.x());
    r.y0 = std::min(r.y0, c.y());
    r.x1 = std::max(r.x1, c.x());
    r.y1 = std::max(r.y1, c.y());
  }
  return r;
}

std::optional<ObstacleOutline> OutlineFromBoundary(const std::vector<Eigen::Vector2d>& points,
                                                   double cell_m, double sigma_m, int min_points) {
  if (points.empty() || !(cell_m > 0.0)) return std::nullopt;
  // Per column: lowest and highest y; per row: westmost and eastmost x.
  std::map<long, std::pair<double, double>> columns, rows;
  for (const Eigen::Vector2d& p : points) {
    const long c = std::lround(p.x() / cell_m), r = std::lround(p.y() / cell_m);
    auto col = columns.try_emplace(c, p.y(), p.y()).first;
    col->second = {std::min(col->second.first, p.y()), std::max(col->second.second, p.y())};
    auto row = rows.try_emplace(r, p.x(), p.x()).first;
    row->second = {std::min(row->second.first, p.x()), std::max(row->second.second, p.x())};
  }
  std::vector<Eigen::Vector2d> south, north, west, east;  // (v, u) pairs
  for (const auto& [c, ext] : columns) {
    south.emplace_back(c * cell_m, ext.first);
    north.emplace_back(c * cell_m, ext.second);
  }
  for (const auto& [r, ext] : rows) {
    west.emplace_back(r * cell_m, ext.first);
    east.emplace_back(r * cell_m, ext.second);
  }
  const double band = 2.0 * cell_m;
  const auto s = FitSide(south, true, band, sigma_m, min_points);
  const auto e = FitSide(east, false, band, sigma_m, min_points);
  const auto n = FitSide(north, true, band, sigma_m, min_points);
  const auto w = FitSide(west, false, band, sigma_m, min_points);
  if (!s || !e || !n || !w) return std::nullopt;
  // A face never heard leaves its side on the opposite face's points: no obstacle is that thin.
  if (n->point.y() - s->point.y() < cell_m || e->point.x() - w->point.x() < cell_m)
    return std::nullopt;
  ObstacleOutline outline;
  outline.sides = {*s, *e, *n, *w};
  for (int k = 0; k < 4; ++k) {
    // Corner k joins side k-1 and side k: SW = west x south, SE = south x east, ...
    const auto corner = Intersect(outline.sides[(k + 3) % 4], outline.sides[k]);
    if (!corner) return std::nullopt;
    outline.corners[k] = *corner;
  }
  return outline;
}

}  // namespace plywood::perception
