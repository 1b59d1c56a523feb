#include "sim/runner/text_file.h"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "sim/runner/file_writer.h"

namespace plywood::sim {

std::string ReadTextFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::filesystem::path StagedTextFilePath(const std::filesystem::path& path) {
  return path.string() + ".partial-" + std::to_string(getpid());
}

std::optional<long> StagedCopyPid(std::string_view name, std::string_view of) {
  constexpr std::string_view kInfix = ".partial-";
  if (name.size() <= of.size() + kInfix.size() || !name.starts_with(of) ||
      name.substr(of.size(), kInfix.size()) != kInfix) {
    return std::nullopt;
  }
  const std::string_view digits = name.substr(of.size() + kInfix.size());
  if (digits.size() > 9 ||
      !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  return std::stol(std::string(digits));
}

bool IsADeviceOrAPipe(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  return !error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
         !std::filesystem::is_directory(status);
}

void WriteTextFile(const std::filesystem::path& path, const std::string& text) {
  std::error_code error;
  // A device or a FIFO (/dev/null, /dev/stdout) is written to: a rename would replace it.
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error)) {
    FileWriter file(path);
    file.out() << text;
    file.Close();
    return;
  }
  const std::filesystem::path partial = StagedTextFilePath(path);
  try {
    FileWriter file(partial, path.string());
    file.out() << text;
    file.Close();
  } catch (const std::runtime_error&) {
    std::filesystem::remove(partial, error);  // no half file left beside the earlier one
    throw;
  }
  std::filesystem::rename(partial, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(partial, ignored);
    throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
  }
}

}  // namespace plywood::sim
