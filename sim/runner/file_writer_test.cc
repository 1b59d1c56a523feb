#include "sim/runner/file_writer.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "sim/runner/text_file.h"
#include "tests/support/file_size_limit.h"
#include "tests/support/mujoco_test_support.h"

namespace plywood::sim {
namespace {

namespace fs = std::filesystem;

std::string WriteAndClose(const fs::path& path, const std::string& text) {
  try {
    FileWriter file(path);
    file.out() << text;
    file.Close();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

// Every byte given arrives, across many buffer refills.
TEST(FileWriterTest, WritesEveryByte) {
  const fs::path path = testing::MakeTempDir("file_writer_bytes") / "big.txt";
  std::string text;
  for (int i = 0; i < 100000; ++i) text += std::to_string(i) + (i % 7 ? "," : "\n");
  EXPECT_EQ(WriteAndClose(path, text), "");
  EXPECT_EQ(ReadTextFile(path), text);
}

// An std::ofstream's writers could say only "write failed"; the OS's reason is kept, for a small
// write (failing on close) and a big one (failing mid-way).
TEST(FileWriterTest, AFullDiskNamesTheFileAndTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  EXPECT_EQ(WriteAndClose("/dev/full", "x"), "/dev/full: write failed: No space left on device");
  EXPECT_EQ(WriteAndClose("/dev/full", std::string(1 << 20, 'x')),
            "/dev/full: write failed: No space left on device");
}

TEST(FileWriterTest, AFileSizeLimitNamesTheFileAndTheReason) {
  const fs::path path = testing::MakeTempDir("file_writer_limit") / "big.txt";
  std::string error;
  {
    const testing::FileSizeLimit limit(4096);
    ASSERT_TRUE(limit.active());
    error = WriteAndClose(path, std::string(100000, 'x'));
  }
  EXPECT_EQ(error, path.string() + ": write failed: File too large");
}

TEST(FileWriterTest, AFileThatCannotBeCreatedNamesTheReason) {
  EXPECT_EQ(WriteAndClose("/no/such/folder/x.txt", "x"),
            "/no/such/folder/x.txt: cannot write: No such file or directory");
}

// WriteTextFile stages: a failed write leaves the earlier file as it was and no partial file.
TEST(FileWriterTest, AFailedWriteTextFileKeepsTheEarlierFile) {
  const fs::path dir = testing::MakeTempDir("file_writer_staged");
  const fs::path path = dir / "weights.txt";
  WriteTextFile(path, "earlier\n");
  std::string error;
  try {
    const testing::FileSizeLimit limit(4096);
    ASSERT_TRUE(limit.active());
    WriteTextFile(path, std::string(100000, 'x'));
  } catch (const std::runtime_error& e) {
    error = e.what();
  }
  EXPECT_EQ(error, path.string() + ": write failed: File too large");
  EXPECT_EQ(ReadTextFile(path), "earlier\n");
  for (const auto& entry : fs::directory_iterator(dir)) {
    EXPECT_EQ(entry.path(), path) << "left behind";
  }
}

// A device is written to, never replaced by a rename (as root that would replace /dev/null).
// The sweep tells what a kill left (its staged copies, and staged world sets) from a user's own
// files, and a dead writer's copy from a live one's, by the name StagedTextFilePath gives.
TEST(FileWriterTest, StagedCopyPidReadsTheNamesStagedTextFilePathGives) {
  const std::filesystem::path staged = StagedTextFilePath("/tmp/results.csv");
  EXPECT_EQ(StagedCopyPid(staged.filename().string(), "results.csv"), static_cast<long>(getpid()));
  EXPECT_EQ(StagedCopyPid("office-seed5.partial-675", "office-seed5"), 675);
  for (const char* name : {"results.csv", "results.csv.partial-", "results.csv.partial-12a",
                           "results.csv.partial-1234567890", "results.csv.old-12",
                           "results.csvx.partial-12", "other.csv.partial-12"}) {
    EXPECT_FALSE(StagedCopyPid(name, "results.csv").has_value()) << name;
  }
}

TEST(FileWriterTest, WriteTextFileWritesIntoADeviceInPlace) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  EXPECT_NO_THROW(WriteTextFile("/dev/null", "x"));
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  try {
    WriteTextFile("/dev/full", "x");
    ADD_FAILURE() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/full: write failed: No space left on device");
  }
  EXPECT_TRUE(fs::is_character_file("/dev/full"));
}

}  // namespace
}  // namespace plywood::sim
