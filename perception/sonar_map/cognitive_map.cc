#include "perception/sonar_map/cognitive_map.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "msgs/shortest_number.h"
#include "perception/sonar_map/box_face_sides.h"
#include "perception/sonar_map/faces_heard_apart.h"
#include "perception/sonar_map/line_fit.h"
#include "perception/sonar_map/well_painted_groups.h"

namespace plywood::perception {
namespace {

// Position of one room side from its boundary points: the mode column (or row) of the points
// gives the wall; points within the band around it are fitted with the chi-square line
// u = a + b v, evaluated at the middle of their v span.
std::optional<double> FitSide(const std::vector<Eigen::Vector2d>& uv, double res, double band,
                              double sigma, int min_points) {
  if (static_cast<int>(uv.size()) < min_points) return std::nullopt;
  std::map<long, int> histogram;
  for (const auto& p : uv) ++histogram[std::lround(p.x() / res)];
  long mode = histogram.begin()->first;
  for (const auto& [bin, count] : histogram)
    if (count > histogram[mode]) mode = bin;
  std::vector<double> u, v, s;
  for (const auto& p : uv) {
    if (std::abs(p.x() - mode * res) <= band) {
      u.push_back(p.x());
      v.push_back(p.y());
      s.push_back(sigma);
    }
  }
  if (static_cast<int>(u.size()) < min_points) return std::nullopt;
  const auto [vmin, vmax] = std::minmax_element(v.begin(), v.end());
  if (*vmax - *vmin < 1e-9) return mode * res;
  const LineFit fit = ChiSquareLineFit(v, u, s);
  return fit.a + fit.b * 0.5 * (*vmin + *vmax);
}

// Two obstacles joined when nearer than this may become their extent only if it covers at most this
// factor times their areas plus the gap's: a face split in two, not two boxes side by side.
constexpr double kJoinExtentSlack = 1.15;

// The gap between two rectangles facing each other closer than `join` (their projections overlap
// on one axis, their facing sides are less than `join` apart on the other): the rectangle between
// the facing sides across the overlap. nullopt when they overlap, face each other nowhere, or are
// farther apart.
std::optional<Rect> JoinGap(const Rect& a, const Rect& b, double join) {
  const double gap_x = std::max(a.x0, b.x0) - std::min(a.x1, b.x1);
  const double gap_y = std::max(a.y0, b.y0) - std::min(a.y1, b.y1);
  if (gap_x >= 0.0 && gap_x < join && gap_y < 0.0)
    return Rect{std::min(a.x1, b.x1), std::max(a.y0, b.y0), std::max(a.x0, b.x0),
                std::min(a.y1, b.y1)};
  if (gap_y >= 0.0 && gap_y < join && gap_x < 0.0)
    return Rect{std::max(a.x0, b.x0), std::min(a.y1, b.y1), std::min(a.x1, b.x1),
                std::max(a.y0, b.y0)};
  return std::nullopt;
}

// The median face coordinate of the echoes heard from `direction` (BeamFreeGrid::FaceEcho) within
// `band` of `side` whose transducer stood within [v0, v1] along it (so that the perpendicular foot
// it heard lies on that stretch of the face); nullopt with fewer than min_echoes of them.
std::optional<double> SideFromEchoes(const std::vector<BeamFreeGrid::FaceEcho>& echoes,
                                     BeamFreeGrid::Direction direction, double side, double v0,
                                     double v1, double band, int min_echoes) {
  std::vector<double> faces;
  for (const BeamFreeGrid::FaceEcho& echo : echoes)
    if (echo.direction == direction && std::abs(echo.face - side) <= band && echo.lateral >= v0 &&
        echo.lateral <= v1)
      faces.push_back(echo.face);
  if (faces.empty() || static_cast<int>(faces.size()) < min_echoes) return std::nullopt;
  const auto middle = faces.begin() + static_cast<std::ptrdiff_t>(faces.size() / 2);
  std::nth_element(faces.begin(), middle, faces.end());
  return *middle;
}

// The room side `side` moved out (sign -1 for x0 / y0, +1 for x1 / y1) to the farthest face that
// at least min_echoes echoes heard from `direction` place within `agree` of each other (their
// middle one), counting only faces more than `overrun` beyond `fitted` (the side as the boundary
// points placed it, before any free space moved it); `side` when none lies beyond it.
double FarthestAgreedFace(const std::vector<BeamFreeGrid::FaceEcho>& echoes,
                          BeamFreeGrid::Direction direction, double side, double fitted,
                          double sign, double overrun, int min_echoes, double agree) {
  std::vector<double> faces;
  for (const BeamFreeGrid::FaceEcho& echo : echoes)
    if (echo.direction == direction && sign * (echo.face - fitted) > overrun)
      faces.push_back(echo.face);
  std::sort(faces.begin(), faces.end());
  const std::size_t n = static_cast<std::size_t>(min_echoes);
  double best = side;
  for (std::size_t k = 0; k + n <= faces.size(); ++k)
    if (faces[k + n - 1] - faces[k] <= agree) {
      const double middle = faces[k + (n - 1) / 2];
      if (sign * (middle - best) > 0) best = middle;
    }
  return best;
}

double Snap(double value, const std::vector<double>& earlier, double d_e) {
  double best = value, best_d = d_e;
  for (double e : earlier) {
    if (std::abs(e - value) <= best_d) {
      best_d = std::abs(e - value);
      best = e;
    }
  }
  return best;
}

}  // namespace

std::vector<Eigen::Vector2i> TrimThinEnds(const std::vector<Eigen::Vector2i>& cells,
                                          double min_fill) {
  if (cells.empty()) return cells;
  std::map<int, int> in_row, in_column;
  for (const Eigen::Vector2i& c : cells) {
    ++in_row[c.y()];
    ++in_column[c.x()];
  }
  // The outermost keys whose count reaches min_fill of the largest count.
  auto span = [min_fill](const std::map<int, int>& counts) {
    int fullest = 0;
    for (const auto& [key, n] : counts) fullest = std::max(fullest, n);
    // A row holding exactly min_fill of the fullest counts (0.7 * 10 is 7.000000000000001).
    const double needed = min_fill * fullest - 1e-9;
    int lo = counts.rbegin()->first, hi = counts.begin()->first;
    for (const auto& [key, n] : counts)
      if (n >= needed) lo = std::min(lo, key), hi = std::max(hi, key);
    return std::pair{lo, hi};
  };
  const auto [y0, y1] = span(in_row);
  const auto [x0, x1] = span(in_column);
  std::vector<Eigen::Vector2i> kept;
  for (const Eigen::Vector2i& c : cells)
    if (c.x() >= x0 && c.x() <= x1 && c.y() >= y0 && c.y() <= y1) kept.push_back(c);
  return kept;
}

namespace {

// The smallest box of cells [lo, hi] holding every cell of `cells` (not empty).
std::pair<Eigen::Vector2i, Eigen::Vector2i> CellExtent(const std::vector<Eigen::Vector2i>& cells) {
  Eigen::Vector2i lo = cells.front(), hi = cells.front();
  for (const Eigen::Vector2i& c : cells) lo = lo.cwiseMin(c), hi = hi.cwiseMax(c);
  return {lo, hi};
}

// TrimThinEnds' result `kept` with every dropped end restored whose cells (those of `cells` beyond
// the kept cells' extent on that side) hold at least min_echoes echo points (`echoes`: per cell,
// row-major over a grid `width` cells wide): such an end is a face heard head-on, not a wedge.
std::vector<Eigen::Vector2i> RestoreHeardEnds(const std::vector<Eigen::Vector2i>& cells,
                                              const std::vector<Eigen::Vector2i>& kept,
                                              const std::vector<int>& echoes, int width,
                                              int min_echoes) {
  if (kept.empty()) return kept;
  auto [lo, hi] = CellExtent(kept);
  const auto [all_lo, all_hi] = CellExtent(cells);
  int heard[4] = {0, 0, 0, 0};  // beyond lo.x, hi.x, lo.y, hi.y
  for (const Eigen::Vector2i& c : cells) {
    const int n = echoes[static_cast<std::size_t>(c.y()) * width + c.x()];
    if (c.x() < lo.x()) heard[0] += n;
    if (c.x() > hi.x()) heard[1] += n;
    if (c.y() < lo.y()) heard[2] += n;
    if (c.y() > hi.y()) heard[3] += n;
  }
  if (heard[0] >= min_echoes) lo.x() = all_lo.x();
  if (heard[1] >= min_echoes) hi.x() = all_hi.x();
  if (heard[2] >= min_echoes) lo.y() = all_lo.y();
  if (heard[3] >= min_echoes) hi.y() = all_hi.y();
  std::vector<Eigen::Vector2i> out;
  for (const Eigen::Vector2i& c : cells)
    if ((c.array() >= lo.array()).all() && (c.array() <= hi.array()).all()) out.push_back(c);
  return out;
}

long ExtentArea(const std::vector<Eigen::Vector2i>& cells) {
  if (cells.empty()) return 0;
  const auto [lo, hi] = CellExtent(cells);
  return static_cast<long>(hi.x() - lo.x() + 1) * (hi.y() - lo.y() + 1);
}

// The best cut along one axis (0: between columns, 1: between rows): the coordinate the upper
// side starts at and the summed extent area of both sides.
std::pair<int, long> BestCut(const std::vector<Eigen::Vector2i>& cells, int axis) {
  const int other = 1 - axis;
  std::map<int, std::pair<int, int>> span;  // key along `axis` -> min/max along the other
  for (const Eigen::Vector2i& c : cells) {
    auto it = span.try_emplace(c[axis], c[other], c[other]).first;
    it->second.first = std::min(it->second.first, c[other]);
    it->second.second = std::max(it->second.second, c[other]);
  }
  std::vector<std::pair<int, std::pair<int, int>>> keys(span.begin(), span.end());
  const std::size_t n = keys.size();
  std::pair<int, long> best{0, std::numeric_limits<long>::max()};
  if (n < 2) return best;
  // Extent areas of keys[0..k] and keys[k..n-1] (the keys between are inside either extent).
  std::vector<long> low(n), high(n);
  int lo = keys[0].second.first, hi = keys[0].second.second;
  for (std::size_t k = 0; k < n; ++k) {
    lo = std::min(lo, keys[k].second.first), hi = std::max(hi, keys[k].second.second);
    low[k] = static_cast<long>(keys[k].first - keys[0].first + 1) * (hi - lo + 1);
  }
  lo = keys[n - 1].second.first, hi = keys[n - 1].second.second;
  for (std::size_t k = n; k-- > 0;) {
    lo = std::min(lo, keys[k].second.first), hi = std::max(hi, keys[k].second.second);
    high[k] = static_cast<long>(keys[n - 1].first - keys[k].first + 1) * (hi - lo + 1);
  }
  for (std::size_t k = 0; k + 1 < n; ++k)
    if (low[k] + high[k + 1] < best.second) best = {keys[k + 1].first, low[k] + high[k + 1]};
  return best;
}

void Split(const std::vector<Eigen::Vector2i>& cells, double saving, int depth,
           std::vector<std::vector<Eigen::Vector2i>>& pieces) {
  const long area = ExtentArea(cells);
  if (depth > 0) {
    const auto by_column = BestCut(cells, 0), by_row = BestCut(cells, 1);
    const int axis = by_row.second < by_column.second ? 1 : 0;
    const auto& cut = axis == 0 ? by_column : by_row;
    if (cut.second < area && cut.second <= (1.0 - saving) * static_cast<double>(area)) {
      std::vector<Eigen::Vector2i> below, above;
      for (const Eigen::Vector2i& c : cells) (c[axis] < cut.first ? below : above).push_back(c);
      Split(below, saving, depth - 1, pieces);
      Split(above, saving, depth - 1, pieces);
      return;
    }
  }
  pieces.push_back(cells);
}

}  // namespace

std::vector<Eigen::Vector2i> PeelFreeEdges(const std::vector<Eigen::Vector2i>& cells,
                                           const std::function<bool(int, int)>& is_free,
                                           std::vector<Eigen::Vector2i>& rest) {
  if (cells.empty()) return cells;
  const auto [lo, hi] = CellExtent(cells);
  const int width = hi.x() - lo.x() + 1, height = hi.y() - lo.y() + 1;
  std::vector<char> member(static_cast<std::size_t>(width) * height, 0);
  for (const Eigen::Vector2i& c : cells)
    member[static_cast<std::size_t>(c.y() - lo.y()) * width + (c.x() - lo.x())] = 1;
  auto in = [&](int x, int y) {
    return member[static_cast<std::size_t>(y - lo.y()) * width + (x - lo.x())] != 0;
  };
  // Free cells minus member cells along one row (axis 1) or column (axis 0) of the box [b0, b1].
  auto excess = [&](int axis, int at, const Eigen::Vector2i& b0, const Eigen::Vector2i& b1) {
    int n = 0;
    for (int k = b0[1 - axis]; k <= b1[1 - axis]; ++k) {
      const int x = axis == 0 ? at : k, y = axis == 0 ? k : at;
      n += is_free(x, y) ? 1 : 0;
      n -= in(x, y) ? 1 : 0;
    }
    return n;
  };
  Eigen::Vector2i b0 = lo, b1 = hi;
  while (b0.x() <= b1.x() && b0.y() <= b1.y()) {
    // Edges: x0, x1 (columns), y0, y1 (rows).
    const std::array<int, 4> excesses{excess(0, b0.x(), b0, b1), excess(0, b1.x(), b0, b1),
                                      excess(1, b0.y(), b0, b1), excess(1, b1.y(), b0, b1)};
    const auto best = std::max_element(excesses.begin(), excesses.end());
    if (*best <= 0) break;
    switch (best - excesses.begin()) {
      case 0:
        ++b0.x();
        break;
      case 1:
        --b1.x();
        break;
      case 2:
        ++b0.y();
        break;
      default:
        --b1.y();
        break;
    }
  }
  std::vector<Eigen::Vector2i> kept;
  for (const Eigen::Vector2i& c : cells)
    (c.x() >= b0.x() && c.x() <= b1.x() && c.y() >= b0.y() && c.y() <= b1.y() ? kept : rest)
        .push_back(c);
  return kept;
}

std::vector<std::vector<Eigen::Vector2i>> SplitIntoRectangles(
    const std::vector<Eigen::Vector2i>& cells, double saving, int max_depth) {
  std::vector<std::vector<Eigen::Vector2i>> pieces;
  if (cells.empty()) return pieces;
  Split(cells, saving, max_depth, pieces);
  return pieces;
}

void CognitiveMapOptions::Validate() const {
  if (!(eps > 0.0 && eps < 0.5)) throw std::invalid_argument("eps: must be in (0, 0.5)");
  if (!(snap_distance_m >= 0.0)) throw std::invalid_argument("snap_distance_m: must be >= 0");
  // Outside this range the fits' weights 1 / sigma^2 underflow or overflow.
  if (!(fit_sigma_m >= 1e-3 && fit_sigma_m <= 10.0))
    throw std::invalid_argument("fit_sigma_m: must be in [0.001, 10], got " +
                                msgs::ShortestNumber(fit_sigma_m));
  if (min_wall_points < 2) throw std::invalid_argument("min_wall_points: must be >= 2");
  if (min_obstacle_cells < 1) throw std::invalid_argument("min_obstacle_cells: must be >= 1");
  if (!(obstacle_free_p > 0.0 && obstacle_free_p <= eps))
    throw std::invalid_argument("obstacle_free_p: must be in (0, eps]");
  if (!(std::isfinite(obstacle_join_m) && obstacle_join_m >= 0.0))
    throw std::invalid_argument("obstacle_join_m: must be a finite number >= 0");
  if (!(wall_band_m >= 0.0)) throw std::invalid_argument("wall_band_m: must be >= 0");
  if (!(min_passage_m >= 0.0)) throw std::invalid_argument("min_passage_m: must be >= 0");
  if (!(side_free_overrun_m >= 0.0))
    throw std::invalid_argument("side_free_overrun_m: must be >= 0");
  if (!(obstacle_min_fill >= 0.0 && obstacle_min_fill <= 1.0))
    throw std::invalid_argument("obstacle_min_fill: must be in [0, 1]");
  if (!(obstacle_split_saving >= 0.0 && obstacle_split_saving <= 1.0))
    throw std::invalid_argument("obstacle_split_saving: must be in [0, 1]");
  if (beam_free_min_passes < 0) throw std::invalid_argument("beam_free_min_passes: must be >= 0");
  if (obstacle_cut_min_votes < 0)
    throw std::invalid_argument("obstacle_cut_min_votes: must be >= 0, got " +
                                std::to_string(obstacle_cut_min_votes));
  if (!(std::isfinite(obstacle_peel_net_free_clearance_m) &&
        obstacle_peel_net_free_clearance_m >= 0.0))
    throw std::invalid_argument("obstacle_peel_net_free_clearance_m: must be a finite number >= 0");
  if (!(std::isfinite(open_sides_seen_past_m) && open_sides_seen_past_m >= 0.0))
    throw std::invalid_argument("open_sides_seen_past_m: must be a finite number >= 0");
}

CognitiveMap BuildCognitiveMap(const LogOddsGrid& grid, const Eigen::Vector2d& inside,
                               const CognitiveMapOptions& options, const BeamFreeGrid* beam_free) {
  options.Validate();
  const double res = grid.resolution_m();
  const int W = grid.width(), H = grid.height();
  std::vector<char> occ(static_cast<std::size_t>(W) * H, 0);
  std::vector<char> seen_free(occ.size(), 0);
  // Cells the sonar axes saw free far beyond the network's window (none without a BeamFreeGrid).
  std::vector<char> axis_free(occ.size(), 0);
  if (beam_free != nullptr && options.beam_free_min_passes > 0) {
    if (beam_free->width() != W || beam_free->height() != H)
      throw std::invalid_argument("beam_free: its cells differ from the grid's");
    for (int iy = 0; iy < H; ++iy)
      for (int ix = 0; ix < W; ++ix)
        axis_free[iy * W + ix] = beam_free->Passes(ix, iy) >= options.beam_free_min_passes;
  }
  for (int iy = 0; iy < H; ++iy)
    for (int ix = 0; ix < W; ++ix) {
      const double p = grid.Probability(ix, iy);
      occ[iy * W + ix] = p > 1.0 - options.eps;
      seen_free[iy * W + ix] = p < options.eps || axis_free[iy * W + ix];
    }
  auto is_occ = [&](int ix, int iy) { return occ[static_cast<std::size_t>(iy) * W + ix] != 0; };
  // An obstacle's cells: occupied, and no beam axis passed through them.
  auto is_obstacle_occ = [&](int ix, int iy) {
    return is_occ(ix, iy) && !axis_free[static_cast<std::size_t>(iy) * W + ix];
  };

  // Peeling judges a rectangle's edges by the free space the axes heard, so like them it shapes
  // the reported map only, not the one the robot plans on.
  const bool peel_free =
      options.obstacle_peel_free && beam_free != nullptr && options.beam_free_min_passes > 0;
  // The network's free cells with no occupied cell within the clearance (none when it is 0).
  std::vector<char> net_free_clear(occ.size(), 0);
  if (peel_free && options.obstacle_peel_net_free_clearance_m > 0.0) {
    const int r =
        static_cast<int>(std::ceil(options.obstacle_peel_net_free_clearance_m / res - 1e-9));
    std::vector<char> near_occ(occ.size(), 0);
    for (int iy = 0; iy < H; ++iy)
      for (int ix = 0; ix < W; ++ix) {
        if (!is_occ(ix, iy)) continue;
        for (int y = std::max(0, iy - r); y <= std::min(H - 1, iy + r); ++y)
          for (int x = std::max(0, ix - r); x <= std::min(W - 1, ix + r); ++x)
            near_occ[static_cast<std::size_t>(y) * W + x] = 1;
      }
    for (int iy = 0; iy < H; ++iy)
      for (int ix = 0; ix < W; ++ix) {
        const std::size_t i = static_cast<std::size_t>(iy) * W + ix;
        net_free_clear[i] = grid.Probability(ix, iy) < options.eps && near_occ[i] == 0;
      }
  }
  auto is_axis_free = [&](int ix, int iy) {
    if (!grid.Contains(ix, iy)) return false;
    const std::size_t i = static_cast<std::size_t>(iy) * W + ix;
    return axis_free[i] != 0 || net_free_clear[i] != 0;
  };

  // Echo points of the grid-aligned axes in each obstacle cell (the trim keeps an end holding
  // enough of them; the reported map only, like the peel).
  const bool trim_keeps_heard_ends = peel_free && options.obstacle_trim_keeps_heard_ends;
  // Like the peel, from the reported map only: the robot plans on main's obstacles.
  const bool cut_unheard_gaps = options.obstacle_cut_unheard_gaps && beam_free != nullptr &&
                                options.beam_free_min_passes > 0 && options.obstacle_from_faces;
  // Cells that may lie between two faces of one piece: a gap up to obstacle_join_m.
  const int join_gap_cells = static_cast<int>(std::floor(options.obstacle_join_m / res + 1e-9));
  // Well-painted faces this close stay one group (obstacle_cut_min_votes): a face line the
  // classical model heard with a cell or two missing is one face, however a grazing axis heard it.
  const int well_painted_gap_cells = join_gap_cells / 2;
  std::vector<int> heard_echoes;
  if (trim_keeps_heard_ends) {
    heard_echoes.assign(occ.size(), 0);
    for (int iy = 0; iy < H; ++iy)
      for (int ix = 0; ix < W; ++ix)
        if (is_obstacle_occ(ix, iy))
          for (const auto d : {BeamFreeGrid::kWest, BeamFreeGrid::kEast, BeamFreeGrid::kSouth,
                               BeamFreeGrid::kNorth})
            heard_echoes[static_cast<std::size_t>(iy) * W + ix] += beam_free->Echoes(ix, iy, d);
  }

  Eigen::Vector2i c0 = grid.CellAt(inside);
  if (c0.x() < 0) throw std::invalid_argument("inside: the point is outside the grid");

  // Boundary points nearest the robot: one per row (west, east) and one per column (south, north),
  // at the face of the first occupied cell met when scanning outwards from the inside point.
  std::vector<Eigen::Vector2d> west, east, south, north;  // (u = position, v = along the side)
  for (int iy = 0; iy < H; ++iy) {
    if (is_occ(c0.x(), iy)) continue;
    const double y = grid.CellCentre(0, iy).y();
    for (int ix = c0.x(); ix >= 0; --ix)
      if (is_occ(ix, iy)) {
        west.emplace_back(grid.CellCentre(ix, iy).x() + 0.5 * res, y);
        break;
      }
    for (int ix = c0.x(); ix < W; ++ix)
      if (is_occ(ix, iy)) {
        east.emplace_back(grid.CellCentre(ix, iy).x() - 0.5 * res, y);
        break;
      }
  }
  for (int ix = 0; ix < W; ++ix) {
    if (is_occ(ix, c0.y())) continue;
    const double x = grid.CellCentre(ix, 0).x();
    for (int iy = c0.y(); iy >= 0; --iy)
      if (is_occ(ix, iy)) {
        south.emplace_back(grid.CellCentre(ix, iy).y() + 0.5 * res, x);
        break;
      }
    for (int iy = c0.y(); iy < H; ++iy)
      if (is_occ(ix, iy)) {
        north.emplace_back(grid.CellCentre(ix, iy).y() - 0.5 * res, x);
        break;
      }
  }
  // Fallback for a side never seen occupied: the outermost cell seen free.
  double free_x0 = inside.x(), free_x1 = inside.x(), free_y0 = inside.y(), free_y1 = inside.y();
  for (int iy = 0; iy < H; ++iy)
    for (int ix = 0; ix < W; ++ix)
      if (seen_free[iy * W + ix]) {
        const Eigen::Vector2d c = grid.CellCentre(ix, iy);
        free_x0 = std::min(free_x0, c.x() - 0.5 * res);
        free_x1 = std::max(free_x1, c.x() + 0.5 * res);
        free_y0 = std::min(free_y0, c.y() - 0.5 * res);
        free_y1 = std::max(free_y1, c.y() + 0.5 * res);
      }
  const double band = options.wall_band_m, sigma = options.fit_sigma_m;
  const int min_pts = options.min_wall_points;
  CognitiveMap map;
  map.room.x0 = FitSide(west, res, band, sigma, min_pts).value_or(free_x0);
  map.room.x1 = FitSide(east, res, band, sigma, min_pts).value_or(free_x1);
  map.room.y0 = FitSide(south, res, band, sigma, min_pts).value_or(free_y0);
  map.room.y1 = FitSide(north, res, band, sigma, min_pts).value_or(free_y1);
  // A side fitted well inside space the sonar saw free is an obstacle face against a wall that was
  // never heard (layout 3): no room wall has free space behind it, so the side moves out to the
  // outermost column (row) with at least min_wall_points free cells.
  const Rect fitted = map.room;
  {
    std::vector<int> free_in_column(W, 0), free_in_row(H, 0);
    for (int iy = 0; iy < H; ++iy)
      for (int ix = 0; ix < W; ++ix)
        if (seen_free[iy * W + ix]) {
          ++free_in_column[ix];
          ++free_in_row[iy];
        }
    int cx0 = W, cx1 = -1, cy0 = H, cy1 = -1;
    for (int ix = 0; ix < W; ++ix)
      if (free_in_column[ix] >= min_pts) cx0 = std::min(cx0, ix), cx1 = std::max(cx1, ix);
    for (int iy = 0; iy < H; ++iy)
      if (free_in_row[iy] >= min_pts) cy0 = std::min(cy0, iy), cy1 = std::max(cy1, iy);
    const double overrun = options.side_free_overrun_m;
    if (cx1 >= 0) {
      const double x0 = grid.CellCentre(cx0, 0).x() - 0.5 * res;
      const double x1 = grid.CellCentre(cx1, 0).x() + 0.5 * res;
      if (map.room.x0 - x0 > overrun) map.room.x0 = x0;
      if (x1 - map.room.x1 > overrun) map.room.x1 = x1;
    }
    if (cy1 >= 0) {
      const double y0 = grid.CellCentre(0, cy0).y() - 0.5 * res;
      const double y1 = grid.CellCentre(0, cy1).y() + 0.5 * res;
      if (map.room.y0 - y0 > overrun) map.room.y0 = y0;
      if (y1 - map.room.y1 > overrun) map.room.y1 = y1;
    }
    // The same from the echoes of the axes that got beyond a side (through a gap between boxes
    // too narrow to fill whole columns with free cells): the axis was free up to its echo, so the
    // face it heard bounds the room no nearer than the echo. A side moves out to the outermost
    // such echo heard at least beam_free_min_passes times in one cell, by more than the overrun.
    if (beam_free != nullptr && options.beam_free_min_passes > 0) {
      // The sides before any echo moved them (the oblique faces below may move only those).
      const Rect before_echoes = map.room;
      const int min_echoes = options.beam_free_min_passes;
      for (int iy = 0; iy < H; ++iy)
        for (int ix = 0; ix < W; ++ix) {
          const Eigen::Vector2d c = grid.CellCentre(ix, iy);
          if (beam_free->Echoes(ix, iy, BeamFreeGrid::kWest) >= min_echoes &&
              map.room.x0 - c.x() > overrun)
            map.room.x0 = c.x();
          if (beam_free->Echoes(ix, iy, BeamFreeGrid::kEast) >= min_echoes &&
              c.x() - map.room.x1 > overrun)
            map.room.x1 = c.x();
          if (beam_free->Echoes(ix, iy, BeamFreeGrid::kSouth) >= min_echoes &&
              map.room.y0 - c.y() > overrun)
            map.room.y0 = c.y();
          if (beam_free->Echoes(ix, iy, BeamFreeGrid::kNorth) >= min_echoes &&
              c.y() - map.room.y1 > overrun)
            map.room.y1 = c.y();
        }
      // The same from the faces those echoes place (BeamFreeGrid::face_echoes): min_echoes of them
      // within one cell of each other. Two axes 7 and 10 deg off the grid axis that heard the same
      // wall 2 m away put their echo points in different cells (world 19 seed 2), not their faces.
      // The overrun is counted from the fitted side: a side the free columns already moved out
      // (past an obstacle's face) still reaches the wall the axes heard beyond them, however near
      // that wall lies to the outermost free column (seed 11 world 15 s1: columns to 2.45 m, the
      // east wall heard at 2.73 m).
      const auto& echoes = beam_free->face_echoes();
      map.room.x0 = FarthestAgreedFace(echoes, BeamFreeGrid::kWest, map.room.x0, fitted.x0, -1.0,
                                       overrun, min_echoes, res);
      map.room.x1 = FarthestAgreedFace(echoes, BeamFreeGrid::kEast, map.room.x1, fitted.x1, 1.0,
                                       overrun, min_echoes, res);
      map.room.y0 = FarthestAgreedFace(echoes, BeamFreeGrid::kSouth, map.room.y0, fitted.y0, -1.0,
                                       overrun, min_echoes, res);
      map.room.y1 = FarthestAgreedFace(echoes, BeamFreeGrid::kNorth, map.room.y1, fitted.y1, 1.0,
                                       overrun, min_echoes, res);
      // The same from the oblique transducers' faces (BeamFreeOptions::oblique_face_max_rad; none
      // when it is off): a wall behind a box the robot stood in front of is heard through the gap
      // beside the box by the transducers 22.5 deg round from the one facing it. Such a reading is
      // the wall's only while the cone's ray nearest the wall's normal reached it, so a face counts
      // only when that ray crossed the side it would move out where the grid holds nothing heard
      // (a face heard on that line, the wall itself or a box, would have echoed first: a reading
      // that claims a wall beyond it came from elsewhere, a concave corner farther on heard once
      // that ray was blocked), and lands within the room's other two sides; and like a room
      // side's boundary points, min_wall_points of them, heard from as many transducer cells,
      // must agree within a cell.
      const auto& oblique = beam_free->oblique_face_echoes();
      if (!oblique.empty()) {
        auto through = [&](BeamFreeGrid::Direction direction, double side, double v0, double v1) {
          const bool along_x = direction == BeamFreeGrid::kWest || direction == BeamFreeGrid::kEast;
          std::map<std::pair<int, int>, std::vector<BeamFreeGrid::FaceEcho>> by_cell;
          for (const BeamFreeGrid::ObliqueFaceEcho& o : oblique) {
            const BeamFreeGrid::FaceEcho& echo = o.echo;
            if (echo.direction != direction || echo.lateral < v0 || echo.lateral > v1) continue;
            const double span = echo.face - o.from_face;
            if (std::abs(span) < 1e-9 || (side - o.from_face) / span <= 0.0 ||
                (side - o.from_face) / span >= 1.0)
              continue;  // the side is not between the transducer and the face
            const double v =
                o.from_lateral + (echo.lateral - o.from_lateral) * ((side - o.from_face) / span);
            // The cells on the line and a cell either side of it (the side lies on a cell's edge,
            // the face heard there in the cell beyond it).
            bool heard = false;
            for (const double du : {-res, 0.0, res}) {
              const Eigen::Vector2i cell = grid.CellAt(along_x ? Eigen::Vector2d(side + du, v)
                                                               : Eigen::Vector2d(v, side + du));
              heard = heard || (cell.x() >= 0 && is_occ(cell.x(), cell.y()));
            }
            if (heard) continue;
            // One face per transducer cell (their median): a robot standing still hears the same
            // corner again every ring, while a wall agrees with itself from wherever it is heard.
            const Eigen::Vector2i at =
                grid.CellAt(along_x ? Eigen::Vector2d(o.from_face, o.from_lateral)
                                    : Eigen::Vector2d(o.from_lateral, o.from_face));
            by_cell[{at.x(), at.y()}].push_back(echo);
          }
          std::vector<BeamFreeGrid::FaceEcho> kept;
          for (auto& [cell, faces] : by_cell) {
            std::sort(faces.begin(), faces.end(),
                      [](const BeamFreeGrid::FaceEcho& a, const BeamFreeGrid::FaceEcho& b) {
                        return a.face < b.face;
                      });
            kept.push_back(faces[faces.size() / 2]);
          }
          return kept;
        };
        // Only a side no head-on echo moved: those place a face to the range noise, these to
        // the cone's edge, and the farthest of many such faces agreeing lies a few cm out (a box
        // flush with the wall was then no longer joined to it).
        if (map.room.x0 == before_echoes.x0)
          map.room.x0 = FarthestAgreedFace(
              through(BeamFreeGrid::kWest, map.room.x0, map.room.y0, map.room.y1),
              BeamFreeGrid::kWest, map.room.x0, fitted.x0, -1.0, overrun, min_pts, res);
        if (map.room.x1 == before_echoes.x1)
          map.room.x1 = FarthestAgreedFace(
              through(BeamFreeGrid::kEast, map.room.x1, map.room.y0, map.room.y1),
              BeamFreeGrid::kEast, map.room.x1, fitted.x1, 1.0, overrun, min_pts, res);
        if (map.room.y0 == before_echoes.y0)
          map.room.y0 = FarthestAgreedFace(
              through(BeamFreeGrid::kSouth, map.room.y0, map.room.x0, map.room.x1),
              BeamFreeGrid::kSouth, map.room.y0, fitted.y0, -1.0, overrun, min_pts, res);
        if (map.room.y1 == before_echoes.y1)
          map.room.y1 = FarthestAgreedFace(
              through(BeamFreeGrid::kNorth, map.room.y1, map.room.x0, map.room.x1),
              BeamFreeGrid::kNorth, map.room.y1, fitted.y1, 1.0, overrun, min_pts, res);
      }
    }
  }
  // Each side at the faces the sonar axes pointing that way heard head-on within the wall band of
  // it, when at least min_wall_points did (the fit above places it to a 5 cm cell and the network's
  // blur: about 5 mm short per side).
  // A side the free space moved out stays at or beyond it (within a cell, the columns' grain):
  // the faces heard within the band inside it are the obstacle's the fit had found, with space
  // seen free behind them (seed 11 world 15 s1: the L's face at 2.37 m, columns free to 2.45 m).
  if (beam_free != nullptr && options.beam_free_min_passes > 0) {
    const auto& echoes = beam_free->face_echoes();
    const Rect r0 = map.room;
    // The echoes' side, unless it lies more than a cell inside a side free space moved out.
    auto placed = [res](std::optional<double> side, double moved, double fitted, double sign) {
      if (!side) return moved;
      if (moved != fitted && sign * (moved - *side) > res) return moved;
      return *side;
    };
    map.room.x0 =
        placed(SideFromEchoes(echoes, BeamFreeGrid::kWest, r0.x0, r0.y0, r0.y1, band, min_pts),
               r0.x0, fitted.x0, -1.0);
    map.room.x1 =
        placed(SideFromEchoes(echoes, BeamFreeGrid::kEast, r0.x1, r0.y0, r0.y1, band, min_pts),
               r0.x1, fitted.x1, 1.0);
    map.room.y0 =
        placed(SideFromEchoes(echoes, BeamFreeGrid::kSouth, r0.y0, r0.x0, r0.x1, band, min_pts),
               r0.y0, fitted.y0, -1.0);
    map.room.y1 =
        placed(SideFromEchoes(echoes, BeamFreeGrid::kNorth, r0.y1, r0.x0, r0.x1, band, min_pts),
               r0.y1, fitted.y1, 1.0);
  }
  // A side with floor seen past it through a gap in it is a face nearer than the wall: opened (the
  // reported map only).
  if (options.open_sides_seen_past_m > 0.0 && beam_free != nullptr &&
      options.beam_free_min_passes > 0) {
    CellMap states{W, H, std::vector<CellState>(occ.size(), CellState::kUnknown)};
    for (int iy = 0; iy < H; ++iy)
      for (int ix = 0; ix < W; ++ix) {
        const std::size_t i = static_cast<std::size_t>(iy) * W + ix;
        const double p = grid.Probability(ix, iy);
        if (p < options.eps) states.cells[i] = CellState::kFree;
        if (occ[i]) states.cells[i] = CellState::kOccupied;
      }
    map.room =
        OpenSides(map.room,
                  SidesSeenPastThroughGaps(states, grid, beam_free, options.beam_free_min_passes,
                                           map.room, options.open_sides_seen_past_m, res),
                  grid);
  }
  if (map.room.x1 - map.room.x0 < res || map.room.y1 - map.room.y0 < res) {
    map.room = {inside.x() - res, inside.y() - res, inside.x() + res, inside.y() + res};
  }

  // Obstacles: 8-connected blobs of occupied cells inside the room, away from the wall band.
  std::vector<int> component(occ.size(), -1);
  std::vector<double> xs{map.room.x0, map.room.x1}, ys{map.room.y0, map.room.y1};
  auto interior = [&](int ix, int iy) {
    const Eigen::Vector2d c = grid.CellCentre(ix, iy);
    return c.x() > map.room.x0 + band && c.x() < map.room.x1 - band && c.y() > map.room.y0 + band &&
           c.y() < map.room.y1 - band;
  };
  int next_id = 0;
  std::vector<Rect> blobs;
  std::vector<int> blob_of;  // the blob each piece was cut from
  // Which sides (x0, y0, x1, y1) of each piece the echoes placed: they are not snapped.
  std::vector<std::array<bool, 4>> measured;
  for (int iy = 0; iy < H; ++iy)
    for (int ix = 0; ix < W; ++ix) {
      // Obstacle blobs are the cells never seen free (their inside stays unknown) that touch
      // enough occupied cells: the faces the sonar heard plus the interior it could not see.
      if (!is_obstacle_occ(ix, iy) || component[iy * W + ix] >= 0 || !interior(ix, iy)) continue;
      std::vector<Eigen::Vector2i> cells, stack{{ix, iy}};
      component[iy * W + ix] = next_id;
      while (!stack.empty()) {
        const Eigen::Vector2i c = stack.back();
        stack.pop_back();
        cells.push_back(c);
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const int nx = c.x() + dx, ny = c.y() + dy;
            if (!grid.Contains(nx, ny) || !interior(nx, ny) ||
                grid.Probability(nx, ny) < options.obstacle_free_p || axis_free[ny * W + nx])
              continue;
            if (component[ny * W + nx] >= 0) continue;
            component[ny * W + nx] = next_id;
            stack.push_back({nx, ny});
          }
      }
      ++next_id;
      int occupied_cells = 0;
      for (const auto& c : cells) occupied_cells += is_obstacle_occ(c.x(), c.y());
      if (occupied_cells < options.min_obstacle_cells) continue;
      // Rows and columns are judged full with the unknown inside, which fills them.
      if (options.obstacle_min_fill > 0.0) {
        std::vector<Eigen::Vector2i> kept = TrimThinEnds(cells, options.obstacle_min_fill);
        if (trim_keeps_heard_ends && kept.size() < cells.size())
          kept = RestoreHeardEnds(cells, kept, heard_echoes, W, options.beam_free_min_passes);
        cells = std::move(kept);
      }
      // The blob's unknown cells join the faces heard, but the space never seen between an
      // obstacle and a wall is no part of the obstacle: its sides come from the faces alone.
      if (options.obstacle_from_faces)
        cells.erase(std::remove_if(
                        cells.begin(), cells.end(),
                        [&](const Eigen::Vector2i& c) { return !is_obstacle_occ(c.x(), c.y()); }),
                    cells.end());
      constexpr int kMaxSplitDepth = 3;
      std::vector<std::vector<Eigen::Vector2i>> pieces =
          SplitIntoRectangles(cells, options.obstacle_split_saving, kMaxSplitDepth);
      if (cut_unheard_gaps) {
        // A piece whose faces lie farther apart than obstacle_join_m with nothing heard between
        // them, and a face of one heard from the side the other lies on: one obstacle each, cut
        // as a blob is (faces heard only from outside are one box seen from two sides). Pieces
        // the cut above already separated keep their order (sides snap to earlier lines).
        std::vector<std::vector<Eigen::Vector2i>> apart;
        for (auto& piece : pieces) {
          std::vector<std::vector<Eigen::Vector2i>> groups =
              ClustersHeardApart(piece, join_gap_cells, *beam_free, options.beam_free_min_passes);
          if (groups.size() == 1 && options.obstacle_cut_min_votes > 0) {
            // Faces the network's blur joined within obstacle_join_m: grouped by the cells
            // painted by many readings, the blur going with the nearest group.
            std::vector<int> votes;
            votes.reserve(piece.size());
            for (const auto& c : piece) votes.push_back(grid.OccupiedVotes(c.x(), c.y()));
            groups = ClustersOfWellPaintedCellsHeardApart(
                piece, votes, options.obstacle_cut_min_votes, well_painted_gap_cells, *beam_free,
                options.beam_free_min_passes);
          }
          if (groups.size() == 1) {
            apart.push_back(std::move(piece));
            continue;
          }
          for (const auto& group : groups)
            for (auto& more :
                 SplitIntoRectangles(group, options.obstacle_split_saving, kMaxSplitDepth))
              apart.push_back(std::move(more));
        }
        pieces = std::move(apart);
      }
      if (peel_free) {
        // Each peeled piece's rest is cut and peeled again; it is strictly smaller than the piece
        // unless everything was peeled (more free than occupied in every row or column: no
        // obstacle), so this ends.
        for (std::size_t k = 0; k < pieces.size(); ++k) {
          std::vector<Eigen::Vector2i> rest;
          pieces[k] = PeelFreeEdges(pieces[k], is_axis_free, rest);
          if (pieces[k].empty()) continue;
          int rest_occupied = 0;
          for (const auto& c : rest) rest_occupied += is_obstacle_occ(c.x(), c.y());
          if (rest_occupied < options.min_obstacle_cells) continue;
          for (auto& more :
               SplitIntoRectangles(rest, options.obstacle_split_saving, kMaxSplitDepth))
            pieces.push_back(std::move(more));
        }
      }
      for (const auto& piece : pieces) {
        if (piece.empty()) continue;
        int piece_occupied = 0;
        for (const auto& c : piece) piece_occupied += is_obstacle_occ(c.x(), c.y());
        // A piece nothing was heard in is space never seen, not an obstacle.
        if (piece_occupied < options.min_obstacle_cells) continue;
        // Per row the extreme cells give west/east boundary points, per column south/north.
        std::map<int, std::pair<int, int>> rows, cols;
        for (const auto& c : piece) {
          auto r = rows.try_emplace(c.y(), c.x(), c.x()).first;
          r->second.first = std::min(r->second.first, c.x());
          r->second.second = std::max(r->second.second, c.x());
          auto k = cols.try_emplace(c.x(), c.y(), c.y()).first;
          k->second.first = std::min(k->second.first, c.y());
          k->second.second = std::max(k->second.second, c.y());
        }
        std::vector<Eigen::Vector2d> w, e, s, n;
        for (const auto& [iy2, ext] : rows) {
          const double y = grid.CellCentre(0, iy2).y();
          w.emplace_back(grid.CellCentre(ext.first, 0).x() - 0.5 * res, y);
          e.emplace_back(grid.CellCentre(ext.second, 0).x() + 0.5 * res, y);
        }
        for (const auto& [ix2, ext] : cols) {
          const double x = grid.CellCentre(ix2, 0).x();
          s.emplace_back(grid.CellCentre(0, ext.first).y() - 0.5 * res, x);
          n.emplace_back(grid.CellCentre(0, ext.second).y() + 0.5 * res, x);
        }
        auto extreme = [](const std::vector<Eigen::Vector2d>& pts, bool low) {
          double v = pts.front().x();
          for (const auto& p : pts) v = low ? std::min(v, p.x()) : std::max(v, p.x());
          return v;
        };
        // Obstacle sides are short: fit with a band as wide as the blob so every point counts.
        const double wide = 10.0;
        // The sonar hears an obstacle's faces, never its inside, and seldom all of a face: the
        // piece's extent is the obstacle. A fit would average a face with the edge of the
        // unknown inside where part of that face went unheard.
        Rect r{extreme(w, true), extreme(s, true), extreme(e, false), extreme(n, false)};
        if (options.fit_obstacle_sides) {
          r.x0 = FitSide(w, res, wide, sigma, 2).value_or(r.x0);
          r.x1 = FitSide(e, res, wide, sigma, 2).value_or(r.x1);
          r.y0 = FitSide(s, res, wide, sigma, 2).value_or(r.y0);
          r.y1 = FitSide(n, res, wide, sigma, 2).value_or(r.y1);
        }
        std::array<bool, 4> side_measured{false, false, false, false};
        // Each side at the faces the sonar axes heard head-on there, when at least
        // beam_free_min_passes of them did: an echo gives the face to the range noise (1 cm),
        // the grid's cells to 5 cm and the network's blur.
        if (beam_free != nullptr && options.beam_free_min_passes > 0) {
          const auto& echoes = beam_free->face_echoes();
          const int k = options.beam_free_min_passes;
          const Rect r0 = r;
          const auto x0 = SideFromEchoes(echoes, BeamFreeGrid::kEast, r0.x0, r0.y0, r0.y1, band, k);
          const auto x1 = SideFromEchoes(echoes, BeamFreeGrid::kWest, r0.x1, r0.y0, r0.y1, band, k);
          const auto y0 =
              SideFromEchoes(echoes, BeamFreeGrid::kNorth, r0.y0, r0.x0, r0.x1, band, k);
          const auto y1 =
              SideFromEchoes(echoes, BeamFreeGrid::kSouth, r0.y1, r0.x0, r0.x1, band, k);
          r.x0 = x0.value_or(r0.x0);
          r.x1 = x1.value_or(r0.x1);
          r.y0 = y0.value_or(r0.y0);
          r.y1 = y1.value_or(r0.y1);
          side_measured = {x0.has_value(), y0.has_value(), x1.has_value(), y1.has_value()};
        }
        r.x0 = std::max(r.x0, map.room.x0);
        r.x1 = std::min(r.x1, map.room.x1);
        r.y0 = std::max(r.y0, map.room.y0);
        r.y1 = std::min(r.y1, map.room.y1);
        if (r.x1 - r.x0 < res || r.y1 - r.y0 < res) continue;
        blobs.push_back(r);
        blob_of.push_back(next_id);
        measured.push_back(side_measured);
      }
    }
  // Pieces of different blobs closer than obstacle_join_m to each other: the robot cannot drive
  // through a gap that narrow to see into it, and the sonar splits a face it hears at the edge of
  // its range. Pieces side by side whose extent is about their own area plus the gap's (a face
  // split in two) become that extent; otherwise each keeps its own rectangle and only the gap
  // between their facing sides, across the stretch where both face each other, is filled (a
  // bridge). Pieces that face each other nowhere (diagonal neighbours) stay apart: the extent of
  // two boxes at a corner's distance swallowed the free space beside both.
  const double join = options.obstacle_join_m;
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t i = 0; i < blobs.size() && !merged; ++i)
      for (std::size_t j = i + 1; j < blobs.size() && !merged; ++j) {
        // Pieces of one blob were cut apart on purpose.
        if (blob_of[i] == blob_of[j]) continue;
        const std::optional<Rect> gap = JoinGap(blobs[i], blobs[j], join);
        if (!gap) continue;
        const Rect& a = blobs[i];
        const Rect& b = blobs[j];
        const Rect extent{std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1),
                          std::max(a.y1, b.y1)};
        if (extent.Area() > kJoinExtentSlack * (a.Area() + b.Area() + gap->Area())) continue;
        blobs[i] = extent;
        blobs.erase(blobs.begin() + static_cast<std::ptrdiff_t>(j));
        blob_of.erase(blob_of.begin() + static_cast<std::ptrdiff_t>(j));
        measured[i] = {false, false, false, false};
        measured.erase(measured.begin() + static_cast<std::ptrdiff_t>(j));
        merged = true;
      }
  }
  // Pieces that close to a room side are extended to it, unless (the reported map, with
  // obstacle_wall_join_seen_free) the strip's line along the side holds a cell the peel counts as
  // heard free: then the space behind the piece was heard, and the piece's side there is the
  // network's blur of a face it did not hear head-on, not a box against the wall.
  const bool wall_join_seen_free = peel_free && options.obstacle_wall_join_seen_free;
  auto strip_seen_free = [&](double x0, double y0, double x1, double y1) {
    if (!wall_join_seen_free || x1 - x0 <= 0.0 || y1 - y0 <= 0.0) return false;
    const Eigen::Vector2i a = grid.CellAt({x0, y0}), b = grid.CellAt({x1, y1});
    for (int iy = std::max(0, a.y()); iy <= std::min(H - 1, b.y()); ++iy)
      for (int ix = std::max(0, a.x()); ix <= std::min(W - 1, b.x()); ++ix) {
        const Eigen::Vector2d c = grid.CellCentre(ix, iy);
        if (c.x() > x0 && c.x() < x1 && c.y() > y0 && c.y() < y1 && is_axis_free(ix, iy))
          return true;
      }
    return false;
  };
  // A side the strip's evidence kept off the wall is not snapped onto it either (with
  // obstacle_wall_snap_seen_free): d_e is smaller than obstacle_join_m, so the snap would join
  // every such side nearer than d_e anyway. It may still snap to other lines.
  const bool wall_snap_seen_free = options.obstacle_wall_snap_seen_free;
  auto snap_off_wall = [&](double value, const std::vector<double>& earlier, bool off_wall,
                           double wall) {
    if (!off_wall || !wall_snap_seen_free) return Snap(value, earlier, options.snap_distance_m);
    std::vector<double> others;
    for (double e : earlier)
      if (e != wall) others.push_back(e);
    return Snap(value, others, options.snap_distance_m);
  };
  std::vector<int> kept_blob;
  for (std::size_t k = 0; k < blobs.size(); ++k) {
    Rect r = blobs[k];
    const Rect& room = map.room;
    // Which sides (x0, y0, x1, y1) lie within obstacle_join_m of the room side with the strip's
    // line along it heard free; the others that near are extended to it.
    std::array<bool, 4> off_wall{false, false, false, false};
    if (r.x0 - room.x0 < join) {
      off_wall[0] = strip_seen_free(room.x0, r.y0, std::min(r.x0, room.x0 + res), r.y1);
      if (!off_wall[0]) r.x0 = room.x0;
    }
    if (room.x1 - r.x1 < join) {
      off_wall[2] = strip_seen_free(std::max(r.x1, room.x1 - res), r.y0, room.x1, r.y1);
      if (!off_wall[2]) r.x1 = room.x1;
    }
    if (r.y0 - room.y0 < join) {
      off_wall[1] = strip_seen_free(r.x0, room.y0, r.x1, std::min(r.y0, room.y0 + res));
      if (!off_wall[1]) r.y0 = room.y0;
    }
    if (room.y1 - r.y1 < join) {
      off_wall[3] = strip_seen_free(r.x0, std::max(r.y1, room.y1 - res), r.x1, room.y1);
      if (!off_wall[3]) r.y1 = room.y1;
    }
    if (!measured[k][0]) r.x0 = snap_off_wall(r.x0, xs, off_wall[0], room.x0);
    if (!measured[k][2]) r.x1 = snap_off_wall(r.x1, xs, off_wall[2], room.x1);
    if (!measured[k][1]) r.y0 = snap_off_wall(r.y0, ys, off_wall[1], room.y0);
    if (!measured[k][3]) r.y1 = snap_off_wall(r.y1, ys, off_wall[3], room.y1);
    if (r.x1 - r.x0 < res || r.y1 - r.y0 < res) continue;
    xs.insert(xs.end(), {r.x0, r.x1});
    ys.insert(ys.end(), {r.y0, r.y1});
    map.obstacles.push_back(r);
    kept_blob.push_back(blob_of[k]);
  }
  for (std::size_t i = 0; i < map.obstacles.size(); ++i)
    for (std::size_t j = i + 1; j < map.obstacles.size(); ++j) {
      if (kept_blob[i] == kept_blob[j]) continue;
      if (const std::optional<Rect> gap = JoinGap(map.obstacles[i], map.obstacles[j], join))
        if (gap->x1 - gap->x0 > 1e-9 && gap->y1 - gap->y0 > 1e-9) map.bridges.push_back(*gap);
    }

  map.corners = {{map.room.x0, map.room.y0},
                 {map.room.x1, map.room.y0},
                 {map.room.x1, map.room.y1},
                 {map.room.x0, map.room.y1}};
  map.partitions = PartitionMap(map.room);
  for (const Rect& r : map.obstacles) {
    map.corners.insert(map.corners.end(), {{r.x0, r.y0}, {r.x1, r.y0}, {r.x1, r.y1}, {r.x0, r.y1}});
    map.partitions.InsertObstacle(r);
  }
  for (const Rect& r : map.bridges) map.partitions.InsertObstacle(r);
  map.partitions.Merge();
  map.adjacency = map.partitions.Adjacencies(1e-6);
  map.negative = InitialNegativeExperience(map.partitions, map.adjacency, options.min_passage_m);
  map.graph = BuildGraph(map.partitions, map.adjacency, map.negative);
  return map;
}

}  // namespace plywood::perception
