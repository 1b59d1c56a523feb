#include "sim/world/mujoco_handles.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "perception/logs/regular_file.h"
#include "sim/world/referenced_files.h"

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
  RequireRegularReferencedFiles(mjcf, std::filesystem::path(virtual_path).parent_path(),
                                std::filesystem::path(virtual_path).filename().string());
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
  if (perception::IsRegularFile(path)) {  // else MuJoCo names what is wrong
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    RequireRegularReferencedFiles(text.str(), std::filesystem::path(path).parent_path(),
                                  std::filesystem::path(path).filename().string());
  }
  char error[1024] = "";
  mjModel* model = mj_loadXML(path.c_str(), nullptr, error, sizeof(error));
  if (model == nullptr) throw std::runtime_error(error);
  return MjModelPtr(model);
}

}  // namespace plywood::sim
