#pragma once

#include <mujoco/mujoco.h>

#include <memory>
#include <string>

namespace plywood::sim {

struct MjModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct MjDataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using MjModelPtr = std::unique_ptr<mjModel, MjModelDeleter>;
using MjDataPtr = std::unique_ptr<mjData, MjDataDeleter>;

// Routes MuJoCo's fatal errors into C++ exceptions (std::runtime_error) and its warnings into a
// per-process counter instead of stderr and MUJOCO_LOG.TXT. Idempotent; called by every loader.
void InstallMujocoErrorHandlers();

// The text of the last MuJoCo warning since the process started ("" if none).
std::string LastMujocoWarning();

// Compiles MJCF text held in memory. `virtual_path` names the file MuJoCo believes it is reading:
// relative includes and assets resolve against its directory.
// @throws std::runtime_error with MuJoCo's compiler message; sim::OutOfMemory when MuJoCo could
// not allocate.
MjModelPtr LoadModelFromString(const std::string& mjcf, const std::string& virtual_path);

// @throws std::runtime_error with MuJoCo's compiler message; sim::OutOfMemory when MuJoCo could
// not allocate.
MjModelPtr LoadModelFromFile(const std::string& path);

}  // namespace plywood::sim
