#include "sim/world/mujoco_handles.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "perception/logs/regular_file.h"
#include "sim/runner/out_of_memory.h"
#include "sim/world/referenced_files.h"

namespace plywood::sim {
namespace {

std::mutex warning_mutex;
std::string last_warning;

void ThrowOnMujocoError(const char* message) {
  if (IsMujocoOutOfMemory(message)) throw OutOfMemory(std::string("MuJoCo: ") + message);
  throw std::runtime_error(std::string("MuJoCo error: ") + message);
}

// A model MuJoCo could not compile: out of memory, or the file's fault (its message).
[[noreturn]] void ThrowCompileError(const std::string& file, const char* error) {
  if (IsMujocoOutOfMemory(error)) throw OutOfMemory("compiling " + file + ": " + error);
  throw std::runtime_error(error);
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
  // On the heap: an mjVFS is 2 MB of file-name slots, which on the stack crashed every run under
  // a stack limit below that (`ulimit -s 1024`: SIGSEGV, no line; s65 fifty-fourth pass).
  const auto vfs = std::make_unique<mjVFS>();
  mj_defaultVFS(vfs.get());
  // The VFS strips directories from its file names, so the model reads as `virtual_path` while the
  // compiler still resolves relative includes against virtual_path's directory on disk.
  const std::string name = virtual_path.substr(virtual_path.find_last_of('/') + 1);
  if (mj_makeEmptyFileVFS(vfs.get(), name.c_str(), static_cast<int>(mjcf.size())) != 0) {
    throw std::runtime_error("could not allocate MuJoCo VFS file for " + virtual_path);
  }
  std::memcpy(vfs->filedata[vfs->nfile - 1], mjcf.data(), mjcf.size());
  char error[1024] = "";
  mjModel* model = mj_loadXML(virtual_path.c_str(), vfs.get(), error, sizeof(error));
  mj_deleteVFS(vfs.get());
  if (model == nullptr) ThrowCompileError(virtual_path, error);
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
  if (model == nullptr) ThrowCompileError(path, error);
  return MjModelPtr(model);
}

}  // namespace plywood::sim
