#include "sim/world/mujoco_handles.h"

#include <cstring>
#include <mutex>
#include <stdexcept>

namespace plywood::sim {
namespace {

std::mutex warning_mutex;
std::string last_warning;

void ThrowOnMujocoError(const char* message) {
  throw std::runtime_error(std::string("MuJoCo error: ") + message);
}

void RecordMujocoWarning(const char* message) {
  std::lock_guard<std::mutex> lock(warning_mutex);
  last_warning = message;
}

}  // namespace

void InstallMujocoErrorHandlers() {
  mju_user_error = ThrowOnMujocoError;
  mju_user_warning = RecordMujocoWarning;
}

std::string LastMujocoWarning() {
  std::lock_guard<std::mutex> lock(warning_mutex);
  return last_warning;
}

MjModelPtr LoadModelFromString(const std::string& mjcf, const std::string& virtual_path) {
  InstallMujocoErrorHandlers();
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  // The VFS strips directories from its file names, so the model reads as `virtual_path` while the
  // compiler still resolves relative includes against virtual_path's directory on disk.
  const std::string name = virtual_path.substr(virtual_path.find_last_of('/') + 1);
  if (mj_makeEmptyFileVFS(&vfs, name.c_str(), static_cast<int>(mjcf.size())) != 0) {
    throw std::runtime_error("could not allocate MuJoCo VFS file for " + virtual_path);
  }
  std::memcpy(vfs.filedata[vfs.nfile - 1], mjcf.data(), mjcf.size());
  char error[1024] = "";
  mjModel* model = mj_loadXML(virtual_path.c_str(), &vfs, error, sizeof(error));
  mj_deleteVFS(&vfs);
  if (model == nullptr) throw std::runtime_error(error);
  return MjModelPtr(model);
}

MjModelPtr LoadModelFromFile(const std::string& path) {
  InstallMujocoErrorHandlers();
  char error[1024] = "";
  mjModel* model = mj_loadXML(path.c_str(), nullptr, error, sizeof(error));
  if (model == nullptr) throw std::runtime_error(error);
  return MjModelPtr(model);
}

}  // namespace plywood::sim
