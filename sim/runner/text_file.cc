#include "sim/runner/text_file.h"

#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace plywood::sim {

std::string ReadTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void WriteTextFile(const std::filesystem::path& path, const std::string& text) {
  // The pid keeps two processes writing the same file (Slurm tasks, a sweep and --collect) apart.
  const std::filesystem::path partial = path.string() + ".partial-" + std::to_string(getpid());
  {
    std::ofstream out(partial, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error("cannot write " + path.string());
  }
  std::error_code error;
  std::filesystem::rename(partial, path, error);
  if (error) throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
}

}  // namespace plywood::sim
