#pragma once

#include <Eigen/Core>
#include <set>
#include <utility>
#include <vector>

namespace plywood::perception {

// An axis-aligned rectangle [x0, x1] x [y0, y1] (metres).
struct Rect {
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  double Area() const { return (x1 - x0) * (y1 - y0); }
  bool Contains(const Eigen::Vector2d& p) const {
    return p.x() >= x0 && p.x() <= x1 && p.y() >= y0 && p.y() <= y1;
  }
  Eigen::Vector2d Centre() const { return {0.5 * (x0 + x1), 0.5 * (y0 + y1)}; }
  bool operator==(const Rect&) const = default;
};

enum class Label { kFree, kObstacle };

struct Partition {
  Rect rect;
  Label label = Label::kFree;
};

// Two partitions that share a stretch of edge of positive length, and that stretch.
struct Adjacency {
  int a = 0, b = 0;                // a < b
  Eigen::Vector2d door_a, door_b;  // ends of the shared stretch
  double Length() const { return (door_b - door_a).norm(); }
};

// The seed's variable-resolution map: axis-aligned rectangles that tile the room, labelled free or
// obstacle. Obstacles are inserted one at a time; each corner of the new obstacle is connected to
// the nearest perpendicular edge of the partition it lies in, i.e. the free partitions it cuts are
// split along the obstacle's edge lines as far as their own edges; then neighbours with the same
// label whose union is a rectangle are merged (first along x, then along y, lowest index first).
class PartitionMap {
 public:
  PartitionMap() = default;
  explicit PartitionMap(const Rect& room) { partitions_.push_back({room, Label::kFree}); }

  // Splits every partition whose interior the obstacle's edge lines cross (within the obstacle's
  // extent) and labels the pieces inside `obstacle` as obstacle. Parts outside the room are
  // ignored.
  void InsertObstacle(const Rect& obstacle);
  // Splits the partition containing `corner` in its interior by the segment from the corner to the
  // nearest of its edges, along the perpendicular to that edge (the seed's corner rule).
  // Returns false (nothing changed) if no partition has the corner strictly inside.
  bool SplitAtCorner(const Eigen::Vector2d& corner);
  // Merges same-label neighbours whose union is a rectangle until none is left.
  void Merge();

  // Partition whose rectangle contains p (lowest index on shared edges), or -1.
  int Find(const Eigen::Vector2d& p) const;
  std::vector<Adjacency> Adjacencies(double tolerance_m = 1e-9) const;

  const std::vector<Partition>& partitions() const { return partitions_; }
  std::vector<Partition>& mutable_partitions() { return partitions_; }

 private:
  std::vector<Partition> partitions_;
};

// The negative-experience set D: transitions (alpha, beta) known to be impossible, stored as
// ordered pairs (both directions). The seed records (alpha, beta, false) when a move fails; here
// it starts with every transition into an obstacle partition and every free-free stretch narrower
// than the robot, and the explorer adds the moves that failed.
class NegativeExperience {
 public:
  void Forbid(int alpha, int beta) {
    set_.insert({alpha, beta});
    set_.insert({beta, alpha});
  }
  bool Forbidden(int alpha, int beta) const { return set_.count({alpha, beta}) > 0; }
  std::size_t size() const { return set_.size() / 2; }
  const std::set<std::pair<int, int>>& pairs() const { return set_; }

 private:
  std::set<std::pair<int, int>> set_;
};

NegativeExperience InitialNegativeExperience(const PartitionMap& map,
                                             const std::vector<Adjacency>& adjacency,
                                             double min_passage_m);

// Topological graph: the free partitions are nodes, the adjacencies not in D are arcs.
struct TopologicalGraph {
  std::vector<int> nodes;                      // partition indices (free ones)
  std::vector<Adjacency> arcs;                 // adjacencies between nodes, minus D
  std::vector<std::vector<int>> arcs_of_node;  // by partition index: arc indices
};
TopologicalGraph BuildGraph(const PartitionMap& map, const std::vector<Adjacency>& adjacency,
                            const NegativeExperience& d);

// Shortest path from `from` to `to` (points in free partitions) moving only parallel to x or y:
// through the midpoint of each shared stretch, each leg an x move then a y move. Cost is the
// Manhattan length. Returns the waypoints after `from` (ending at `to`), empty when unreachable.
std::vector<Eigen::Vector2d> PlanPath(const PartitionMap& map, const TopologicalGraph& graph,
                                      const Eigen::Vector2d& from, const Eigen::Vector2d& to);

}  // namespace plywood::perception
