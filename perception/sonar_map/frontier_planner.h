#pragma once

#include <Eigen/Core>
#include <vector>

namespace plywood::perception {

// Exploration past the seed's places: the robot keeps going to unknown frontiers (Yamauchi 1997,
// "A frontier-based approach for autonomous exploration") until every frontier near the map has
// been looked at from close by. The sonar network only fills a +-0.7 m window around the robot,
// so a part of the room the robot never came near stays unknown, and the room and its obstacles
// are fitted to what was seen; the seed's places live inside the fitted room and cannot reach it.
// The constants (cluster size, clearance, view distance) are SonarExplorerOptions' frontier_*.
enum class CellState : char { kUnknown, kFree, kOccupied };

// A raster of cell states, row-major (index = iy * width + ix).
struct CellMap {
  int width = 0, height = 0;
  std::vector<CellState> cells;
  CellState At(int ix, int iy) const { return cells[static_cast<std::size_t>(iy) * width + ix]; }
  bool Contains(int ix, int iy) const { return ix >= 0 && iy >= 0 && ix < width && iy < height; }
};

// Free cells with a 4-neighbour that is unknown (cells outside the raster are not unknown).
std::vector<char> FrontierMask(const CellMap& map);
// Keeps only the 8-connected clusters of `mask` with at least min_cells cells.
std::vector<char> KeepClusters(const std::vector<char>& mask, int width, int height, int min_cells);
// Free cells with no occupied cell whose centre is closer than radius_cells (Euclidean, in cells).
std::vector<char> ClearMask(const CellMap& map, double radius_cells);

// Dijkstra over the 8-connected `traversable` cells (steps cost 1 and sqrt 2; a diagonal step
// needs both side cells traversable) from `start` (always allowed) to the nearest cell with
// goal set. Returns the cells start..goal, or empty when no goal is reachable. Ties are broken by
// the lowest cell index, so the answer is deterministic.
std::vector<Eigen::Vector2i> ShortestCellPath(const std::vector<char>& traversable,
                                              const std::vector<char>& goal, int width, int height,
                                              const Eigen::Vector2i& start);
// Line of sight between two cell centres: every cell the segment passes through is traversable
// (the segment is sampled every quarter cell; the end cells are not checked). Unlike
// ShortestCellPath it lets a segment through the shared corner of two diagonal blocked cells and
// can miss a very thin clip of a corner: the explorer's traversable cells are the free space
// shrunk by path_clearance_m, so such a gap never sits next to anything solid.
bool LineOfSight(const std::vector<char>& traversable, int width, int height,
                 const Eigen::Vector2i& a, const Eigen::Vector2i& b);
// Drops the cells of a path that the line of sight lets the robot skip (string pulling): keeps
// the start, each cell from which the next kept cell cannot be seen, and the end.
std::vector<Eigen::Vector2i> SimplifyPath(const std::vector<Eigen::Vector2i>& path,
                                          const std::vector<char>& traversable, int width,
                                          int height);

}  // namespace plywood::perception
