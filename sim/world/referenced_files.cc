#include "sim/world/referenced_files.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

#include "perception/logs/regular_file.h"

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;

struct Attribute {
  std::string name;
  std::string value;
};

// Every name="value" (or name='value') in the text: a scan, not a parser; a comment's attributes
// are checked too, which costs nothing when the file they name is not there.
std::vector<Attribute> Attributes(const std::string& text) {
  std::vector<Attribute> found;
  for (std::size_t eq = text.find('='); eq != std::string::npos; eq = text.find('=', eq + 1)) {
    std::size_t end = eq;
    while (end > 0 && std::isspace(static_cast<unsigned char>(text[end - 1]))) --end;
    std::size_t start = end;
    while (start > 0 &&
           (std::isalnum(static_cast<unsigned char>(text[start - 1])) || text[start - 1] == '_')) {
      --start;
    }
    std::size_t open = eq + 1;
    while (open < text.size() && std::isspace(static_cast<unsigned char>(text[open]))) ++open;
    if (start == end || open >= text.size() || (text[open] != '"' && text[open] != '\'')) continue;
    const std::size_t close = text.find(text[open], open + 1);
    if (close == std::string::npos) break;
    found.push_back({text.substr(start, end - start), text.substr(open + 1, close - open - 1)});
  }
  return found;
}

bool Exists(const fs::path& path) {
  std::error_code refused;
  return fs::exists(path, refused);
}

std::string ReadText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Checks the files `text` names and appends each one found (a regular file) to `found`, once.
void Check(const std::string& text, const fs::path& dir, const fs::path& file_dir,
           const std::string& source_name, std::set<fs::path>& scanned,
           std::vector<fs::path>& found, int depth) {
  const std::vector<Attribute> attributes = Attributes(text);
  std::vector<fs::path> folders = {dir, file_dir};
  for (const Attribute& a : attributes) {
    if (a.name == "meshdir" || a.name == "texturedir" || a.name == "assetdir") {
      folders.push_back(fs::path(a.value).is_absolute() ? fs::path(a.value) : dir / a.value);
    }
  }
  for (const Attribute& a : attributes) {
    if (a.name.rfind("file", 0) != 0 || a.value.empty()) continue;
    std::vector<fs::path> candidates;
    if (fs::path(a.value).is_absolute()) {
      candidates.push_back(a.value);
    } else {
      for (const fs::path& folder : folders) candidates.push_back(folder / a.value);
    }
    for (const fs::path& candidate : candidates) {
      if (!Exists(candidate)) continue;
      if (!perception::IsRegularFile(candidate)) {
        throw std::runtime_error(candidate.lexically_normal().string() + ": " +
                                 perception::WhyNotARegularFile(candidate) + ", named by " +
                                 a.name + "= in " + source_name);
      }
      const fs::path key = fs::weakly_canonical(candidate);
      if (std::find(found.begin(), found.end(), key) == found.end()) found.push_back(key);
      // An included model names files of its own.
      if (candidate.extension() == ".xml" && depth < 16 && scanned.insert(key).second) {
        Check(ReadText(candidate), dir, candidate.parent_path(), candidate.filename().string(),
              scanned, found, depth + 1);
      }
    }
  }
}

}  // namespace

void RequireRegularReferencedFiles(const std::string& mjcf, const fs::path& dir,
                                   const std::string& source_name) {
  ReferencedFiles(mjcf, dir, source_name);
}

std::vector<fs::path> ReferencedFiles(const std::string& mjcf, const fs::path& dir,
                                      const std::string& source_name) {
  std::set<fs::path> scanned;
  std::vector<fs::path> found;
  Check(mjcf, dir, dir, source_name, scanned, found, 0);
  return found;
}

}  // namespace plywood::sim
