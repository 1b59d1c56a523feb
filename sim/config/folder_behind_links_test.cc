#include "sim/config/folder_behind_links.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;

// A link beside its file, a link to a file in another folder (relative and absolute), and a link
// whose relative target climbs ("..") out of a folder itself reached through a link: each gives
// the folder the file is read from.
TEST(FolderBehindLinksTest, GivesTheFolderTheFileIsReadFrom) {
  const fs::path dir =
      fs::temp_directory_path() / ("plywood-FolderBehindLinks-" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "data/lab");
  fs::create_directories(dir / "data/mine");
  fs::create_directories(dir / "work");
  std::ofstream(dir / "data/lab/e.yaml") << "name: e\n";
  EXPECT_EQ(FolderBehindLinks(dir / "data/lab/e.yaml"), dir / "data/lab");
  fs::create_symlink("e.yaml", dir / "data/lab/same.yaml");
  EXPECT_EQ(FolderBehindLinks(dir / "data/lab/same.yaml"), dir / "data/lab");
  fs::create_symlink("../lab/e.yaml", dir / "data/mine/e.yaml");
  EXPECT_EQ(FolderBehindLinks(dir / "data/mine/e.yaml"), dir / "data/lab");
  fs::create_symlink(dir / "data/lab/e.yaml", dir / "data/mine/absolute.yaml");
  EXPECT_EQ(FolderBehindLinks(dir / "data/mine/absolute.yaml"), dir / "data/lab");
  // work/mine is data/mine: its e.yaml's "../lab" is data/lab, not work/lab (which is not there).
  fs::create_directory_symlink(dir / "data/mine", dir / "work/mine");
  EXPECT_EQ(FolderBehindLinks(dir / "work/mine/e.yaml"), fs::canonical(dir / "data/lab"));
  // A link to nowhere: its lexical folder, for the read that follows to name.
  fs::create_symlink("../gone/e.yaml", dir / "data/mine/gone.yaml");
  EXPECT_EQ(FolderBehindLinks(dir / "data/mine/gone.yaml"), dir / "data/gone");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace plywood::sim
