#include "perception/sonar_map/partition_map.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace plywood::perception {
namespace {

constexpr double kEps = 1e-9;

// Splits r by the vertical line x = c (if strictly inside) into pieces appended to `out`.
void SplitX(const Partition& p, double c, std::vector<Partition>* out) {
  if (c > p.rect.x0 + kEps && c < p.rect.x1 - kEps) {
    out->push_back({{p.rect.x0, p.rect.y0, c, p.rect.y1}, p.label});
    out->push_back({{c, p.rect.y0, p.rect.x1, p.rect.y1}, p.label});
  } else {
    out->push_back(p);
  }
}

void SplitY(const Partition& p, double c, std::vector<Partition>* out) {
  if (c > p.rect.y0 + kEps && c < p.rect.y1 - kEps) {
    out->push_back({{p.rect.x0, p.rect.y0, p.rect.x1, c}, p.label});
    out->push_back({{p.rect.x0, c, p.rect.x1, p.rect.y1}, p.label});
  } else {
    out->push_back(p);
  }
}

bool Overlaps(const Rect& a, const Rect& b) {
  return a.x0 < b.x1 - kEps && b.x0 < a.x1 - kEps && a.y0 < b.y1 - kEps && b.y0 < a.y1 - kEps;
}

double Manhattan(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::abs(a.x() - b.x()) + std::abs(a.y() - b.y());
}

}  // namespace

void PartitionMap::InsertObstacle(const Rect& obstacle) {
  std::vector<Partition> next;
  for (const Partition& p : partitions_) {
    if (!Overlaps(p.rect, obstacle)) {
      next.push_back(p);
      continue;
    }
    // Cut by the obstacle's edge lines: x0 and x1 first, then y0 and y1 on each piece.
    std::vector<Partition> a, b, c, d;
    SplitX(p, obstacle.x0, &a);
    for (const Partition& q : a) SplitX(q, obstacle.x1, &b);
    for (const Partition& q : b) SplitY(q, obstacle.y0, &c);
    for (const Partition& q : c) SplitY(q, obstacle.y1, &d);
    for (Partition q : d) {
      if (obstacle.Contains(q.rect.Centre())) q.label = Label::kObstacle;
      next.push_back(q);
    }
  }
  partitions_ = std::move(next);
}

bool PartitionMap::SplitAtCorner(const Eigen::Vector2d& corner) {
  for (std::size_t i = 0; i < partitions_.size(); ++i) {
    const Rect r = partitions_[i].rect;
    if (!(corner.x() > r.x0 + kEps && corner.x() < r.x1 - kEps && corner.y() > r.y0 + kEps &&
          corner.y() < r.y1 - kEps))
      continue;
    // Nearest edge; a segment perpendicular to a vertical edge is horizontal (y = corner.y).
    const double to_left = corner.x() - r.x0, to_right = r.x1 - corner.x();
    const double to_bottom = corner.y() - r.y0, to_top = r.y1 - corner.y();
    const double nearest = std::min({to_left, to_right, to_bottom, to_top});
    const Partition p = partitions_[i];
    std::vector<Partition> pieces;
    if (nearest == to_left || nearest == to_right) {
      // Horizontal segment to the vertical edge: the part of the rectangle beside the segment is
      // cut off as [x0, corner.x] (or [corner.x, x1]) x [y0, y1] split at corner.y.
      const bool left = nearest == to_left;
      Partition side = p, rest = p;
      if (left) {
        side.rect.x1 = corner.x();
        rest.rect.x0 = corner.x();
      } else {
        side.rect.x0 = corner.x();
        rest.rect.x1 = corner.x();
      }
      SplitY(side, corner.y(), &pieces);
      pieces.push_back(rest);
    } else {
      const bool bottom = nearest == to_bottom;
      Partition side = p, rest = p;
      if (bottom) {
        side.rect.y1 = corner.y();
        rest.rect.y0 = corner.y();
      } else {
        side.rect.y0 = corner.y();
        rest.rect.y1 = corner.y();
      }
      SplitX(side, corner.x(), &pieces);
      pieces.push_back(rest);
    }
    partitions_.erase(partitions_.begin() + static_cast<long>(i));
    partitions_.insert(partitions_.begin() + static_cast<long>(i), pieces.begin(), pieces.end());
    return true;
  }
  return false;
}

void PartitionMap::Merge() {
  auto near = [](double a, double b) { return std::abs(a - b) < 1e-6; };
  // Along x, then along y, again until neither pass finds anything.
  for (bool changed = true; changed;) {
    changed = false;
    for (int pass = 0; pass < 2; ++pass) {  // 0: along x, 1: along y
      bool merged = true;
      while (merged) {
        merged = false;
        for (std::size_t i = 0; i < partitions_.size() && !merged; ++i) {
          for (std::size_t j = 0; j < partitions_.size() && !merged; ++j) {
            if (i == j || partitions_[i].label != partitions_[j].label) continue;
            Rect& a = partitions_[i].rect;
            const Rect& b = partitions_[j].rect;
            if (pass == 0 && near(a.y0, b.y0) && near(a.y1, b.y1) && near(a.x1, b.x0)) {
              a.x1 = b.x1;
              merged = true;
            } else if (pass == 1 && near(a.x0, b.x0) && near(a.x1, b.x1) && near(a.y1, b.y0)) {
              a.y1 = b.y1;
              merged = true;
            }
            if (merged) {
              partitions_.erase(partitions_.begin() + static_cast<long>(j));
              changed = true;
            }
          }
        }
      }
    }
  }
}

int PartitionMap::Find(const Eigen::Vector2d& p) const {
  for (std::size_t i = 0; i < partitions_.size(); ++i)
    if (partitions_[i].rect.Contains(p)) return static_cast<int>(i);
  return -1;
}

std::vector<Adjacency> PartitionMap::Adjacencies(double tol) const {
  std::vector<Adjacency> out;
  for (std::size_t i = 0; i < partitions_.size(); ++i) {
    for (std::size_t j = i + 1; j < partitions_.size(); ++j) {
      const Rect& a = partitions_[i].rect;
      const Rect& b = partitions_[j].rect;
      Adjacency adj{static_cast<int>(i), static_cast<int>(j), {}, {}};
      if (std::abs(a.x1 - b.x0) < tol || std::abs(b.x1 - a.x0) < tol) {
        const double x = std::abs(a.x1 - b.x0) < tol ? a.x1 : a.x0;
        const double lo = std::max(a.y0, b.y0), hi = std::min(a.y1, b.y1);
        if (hi - lo > tol) {
          adj.door_a = {x, lo};
          adj.door_b = {x, hi};
          out.push_back(adj);
          continue;
        }
      }
      if (std::abs(a.y1 - b.y0) < tol || std::abs(b.y1 - a.y0) < tol) {
        const double y = std::abs(a.y1 - b.y0) < tol ? a.y1 : a.y0;
        const double lo = std::max(a.x0, b.x0), hi = std::min(a.x1, b.x1);
        if (hi - lo > tol) {
          adj.door_a = {lo, y};
          adj.door_b = {hi, y};
          out.push_back(adj);
        }
      }
    }
  }
  return out;
}

NegativeExperience InitialNegativeExperience(const PartitionMap& map,
                                             const std::vector<Adjacency>& adjacency,
                                             double min_passage_m) {
  NegativeExperience d;
  for (const Adjacency& adj : adjacency) {
    const bool obstacle = map.partitions()[adj.a].label == Label::kObstacle ||
                          map.partitions()[adj.b].label == Label::kObstacle;
    if (obstacle || adj.Length() < min_passage_m) d.Forbid(adj.a, adj.b);
  }
  return d;
}

TopologicalGraph BuildGraph(const PartitionMap& map, const std::vector<Adjacency>& adjacency,
                            const NegativeExperience& d) {
  TopologicalGraph g;
  g.arcs_of_node.resize(map.partitions().size());
  for (std::size_t i = 0; i < map.partitions().size(); ++i)
    if (map.partitions()[i].label == Label::kFree) g.nodes.push_back(static_cast<int>(i));
  for (const Adjacency& adj : adjacency) {
    if (map.partitions()[adj.a].label != Label::kFree ||
        map.partitions()[adj.b].label != Label::kFree || d.Forbidden(adj.a, adj.b))
      continue;
    g.arcs_of_node[adj.a].push_back(static_cast<int>(g.arcs.size()));
    g.arcs_of_node[adj.b].push_back(static_cast<int>(g.arcs.size()));
    g.arcs.push_back(adj);
  }
  return g;
}

std::vector<Eigen::Vector2d> PlanPath(const PartitionMap& map, const TopologicalGraph& graph,
                                      const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const int s = map.Find(from), t = map.Find(to);
  if (s < 0 || t < 0) return {};
  const std::size_t n = map.partitions().size();
  // Dijkstra over partitions; each is entered at the midpoint of the stretch crossed.
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  std::vector<int> prev(n, -1);
  std::vector<Eigen::Vector2d> entry(n, from);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  dist[s] = 0.0;
  queue.push({0.0, s});
  while (!queue.empty()) {
    const auto [du, u] = queue.top();
    queue.pop();
    if (du > dist[u]) continue;
    for (int arc : graph.arcs_of_node[u]) {
      const Adjacency& adj = graph.arcs[arc];
      const int v = adj.a == u ? adj.b : adj.a;
      const Eigen::Vector2d door = 0.5 * (adj.door_a + adj.door_b);
      const double dv = du + Manhattan(entry[u], door);
      if (dv < dist[v] - 1e-12) {
        dist[v] = dv;
        prev[v] = u;
        entry[v] = door;
        queue.push({dv, v});
      }
    }
  }
  if (!std::isfinite(dist[t])) return {};
  std::vector<int> chain;
  for (int v = t; v != -1; v = prev[v]) chain.push_back(v);
  std::reverse(chain.begin(), chain.end());
  // Inside a rectangle any x-then-y move stays inside, so each leg is an L.
  std::vector<Eigen::Vector2d> points;
  Eigen::Vector2d at = from;
  auto leg = [&](const Eigen::Vector2d& q) {
    if (std::abs(q.x() - at.x()) > 1e-9 && std::abs(q.y() - at.y()) > 1e-9)
      points.emplace_back(q.x(), at.y());
    points.push_back(q);
    at = q;
  };
  for (std::size_t k = 1; k < chain.size(); ++k) leg(entry[chain[k]]);
  leg(to);
  return points;
}

}  // namespace plywood::perception
