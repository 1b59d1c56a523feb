#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "perception/logs/tum_trajectory.h"

namespace plywood::eval {

// One trajectory of a file, poses at strictly increasing times.
struct NamedTrajectory {
  std::string name;
  std::vector<perception::TimedPose> poses;
};

// Whether `path` has Plywood's trajectory.csv layout: its first line that is not blank or a '#'
// comment starts with `time_s`, quoted or not (else it is read as TUM).
bool IsPlywoodCsvLayout(const std::filesystem::path& path);

// Reads the trajectories of `path`, whichever of two layouts it has:
// - Plywood's trajectory.csv (the first line not a '#' comment starts with `time_s`, quoted or
//   not; fields as RFC 4180 quotes them): a header
//   `time_s` then groups `NAME_x_m,NAME_y_m,NAME_theta_rad`, one trajectory per group (`truth`
//   included) in column order;
// - otherwise TUM (perception/logs/tum_trajectory.h): one trajectory named `tum_name`.
// `name_flag` is the user's --name, if any: it names a TUM file's one estimate; a CSV, whose
// header names its estimates, is refused with it rather than silently ignoring it.
// @throws sim::ConfigError "FILE:LINE: FIELD: what is wrong" for a bad header, a wrong column
// count, a field that is not a finite number, a coordinate beyond 1e9 m or a heading beyond
// 1e9 rad, times that do not increase, a CSV given with a name_flag; "FILE: ..." for a missing
// or empty file.
std::vector<NamedTrajectory> ReadTrajectoryFile(const std::filesystem::path& path,
                                                const std::string& tum_name,
                                                const std::string& name_flag = "");

// The name a trajectory file gives its estimate: the file name without its extension and
// without a leading "trajectory." (trajectory.encoder.tum -> encoder), characters other than
// letters, digits, '_' and '-' replaced by '_'.
std::string TrajectoryNameOf(const std::filesystem::path& path);

}  // namespace plywood::eval
