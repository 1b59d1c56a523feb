#include "sim/runner/text_file.h"

#include <limits.h>
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
  const std::string suffix = ".partial-" + std::to_string(getpid());
  const std::string name = path.filename().string();
  // A name the file system takes (up to NAME_MAX bytes) whose staged copy's would be longer is
  // staged under its head: "FILE: cannot write: File name too long" named a legal name (s64).
  if (name.size() + suffix.size() > NAME_MAX && name.size() <= NAME_MAX) {
    return path.parent_path() / (name.substr(0, NAME_MAX - suffix.size()) + suffix);
  }
  return path.string() + suffix;
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

std::error_code WriteStagedThenRename(
    const std::filesystem::path& path,
    const std::function<void(const std::filesystem::path& target)>& write) {
  std::error_code error;
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error)) {
    write(path);
    return {};
  }
  const std::filesystem::path partial = StagedTextFilePath(path);
  try {
    write(partial);
  } catch (const std::runtime_error&) {
    std::filesystem::remove(partial, error);  // no half file left beside the earlier one
    throw;
  }
  std::filesystem::rename(partial, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(partial, ignored);
  }
  return error;
}

void WriteTextFile(const std::filesystem::path& path, const std::string& text) {
  const std::error_code error = WriteStagedThenRename(path, [&](const std::filesystem::path& to) {
    FileWriter file(to, path.string());
    file.out() << text;
    file.Close();
  });
  if (error) throw std::runtime_error("cannot write " + path.string() + ": " + error.message());
}

}  // namespace plywood::sim
