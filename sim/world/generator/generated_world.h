#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "sim/world/generator/footprint_2d.h"

namespace plywood::sim::worldgen {

// Plywood walls (worlds/README.md): 18 mm thick, 1 m tall.
inline constexpr double kWallThicknessM = 0.018;
inline constexpr double kWallHeightM = 1.0;

// One static upright geom of a generated world, as it goes into the MJCF.
struct WorldGeom {
  enum class Shape { kBox, kCylinder };
  Shape shape = Shape::kBox;
  std::string name;        // wall_N, obstacle_N, column_N, table_N_top, table_N_leg_K, ...
  std::string geom_class;  // a default class of worlds/README.md: wall, obstacle, table_top, ...
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  Eigen::Vector2d half_size = Eigen::Vector2d::Zero();  // boxes
  double radius_m = 0.0;                                // cylinders
  double yaw_deg = 0.0;                                 // boxes
  double z_min_m = 0.0;
  double z_max_m = 0.0;

  Footprint footprint() const;
};

struct SpawnPose {
  double x_m = 0.0;
  double y_m = 0.0;
  double yaw_deg = 0.0;
};

// A drawn parameter for the sidecar: its key and its value as JSON text.
struct WorldParameter {
  std::string key;
  std::string json;
};

// JSON text of values (numbers with at most 6 decimals, so the bytes do not depend on printf's
// handling of the last binary digits).
std::string JsonNumber(double value);
std::string JsonString(const std::string& value);
std::string JsonArray(const std::vector<std::string>& items);
std::string JsonNumbers(const std::vector<double>& values);
std::string JsonObject(const std::vector<WorldParameter>& members);

// A generated world before it is written: its geoms, the regions a robot may start in, spawn poses
// and the parameters that were drawn. Families build it in a local frame; the generator then turns
// and shifts it so that spawn_0 lies on the world origin.
struct GeneratedWorld {
  std::string family;
  std::uint64_t seed = 0;
  int index = 0;
  int attempts = 1;  // layouts drawn until one had free spawn poses

  std::vector<WorldGeom> geoms;
  // The rooms' inner outlines (counter-clockwise): spawn poses must lie inside one of them.
  std::vector<std::vector<Eigen::Vector2d>> interiors;
  std::vector<SpawnPose> spawns;
  std::vector<WorldParameter> parameters;
  bool closed = true;  // no opening leads outside (a flood fill from a spawn stays inside)
  double rig_coverage =
      0.0;  // fraction of the seed-000 rig's rays from spawn_0 that hit within range
  double rotation_deg = 0.0;  // local frame -> world: turn by this about the local origin, then
  Eigen::Vector2d translation = Eigen::Vector2d::Zero();  // shift by this
  std::string summary;                                    // one line for the MJCF comment

  std::string Name() const;  // FAMILY_sSEED_IIIII, also the file stem

  void AddParameter(const std::string& key, double value);
  void AddParameter(const std::string& key, const std::string& json_text);

  // Geoms with their names numbered per kind. `z_max_m` is the height; every geom stands on the
  // floor.
  WorldGeom& AddWallBox(const Eigen::Vector2d& centre, double half_length_m, double yaw_deg);
  WorldGeom& AddBox(const std::string& kind, const std::string& geom_class,
                    const Eigen::Vector2d& centre, const Eigen::Vector2d& half_size, double yaw_deg,
                    double height_m);
  WorldGeom& AddCylinder(const std::string& kind, const std::string& geom_class,
                         const Eigen::Vector2d& centre, double radius_m, double height_m);
  // A table: a top of `half_size` at `height_m` (30 mm thick) on four cylinder legs of
  // `leg_radius_m`, inset `leg_inset_m` from the top's corners. Returns its footprint (the top).
  Footprint AddTable(const Eigen::Vector2d& centre, const Eigen::Vector2d& half_size,
                     double yaw_deg, double height_m, double leg_radius_m, double leg_inset_m);

  // Every geom's footprint, optionally only those whose vertical extent contains `height_m`.
  std::vector<Footprint> Footprints() const;
  std::vector<Footprint> FootprintsAtHeight(double height_m) const;

  // Turns the whole world by `rotation_deg` about the origin, then shifts it by `shift`.
  void Transform(double rotation_deg, const Eigen::Vector2d& shift);

 private:
  int NextNumber(const std::string& kind);
  std::vector<std::pair<std::string, int>> counters_;
};

}  // namespace plywood::sim::worldgen
