#pragma once

#include <filesystem>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace plywood::sim {

// A file written through an std::ostream that keeps the OS's reason when a write fails ("No space
// left on device", "File too large"): an std::ofstream keeps only a failbit, so its writers could
// say no more than "write failed".
class FileWriter {
 public:
  // Creates or truncates `path`. Errors name `name_in_errors` (default: the path).
  // @throws std::runtime_error "NAME: cannot write: REASON" when it cannot be created.
  explicit FileWriter(const std::filesystem::path& path, std::string name_in_errors = {});
  ~FileWriter();  // closes without a word: call Close() to learn whether every byte was written
  FileWriter(const FileWriter&) = delete;
  FileWriter& operator=(const FileWriter&) = delete;

  std::ostream& out() { return stream_; }

  // Writes what is buffered and closes the file (a full disk may show only here).
  // @throws std::runtime_error "NAME: write failed: REASON" when any byte was not written.
  void Close();

 private:
  class Buffer : public std::streambuf {
   public:
    explicit Buffer(int fd);
    int fd() const { return fd_; }
    int error() const { return error_; }  // errno of the first failed write, 0 if none
    bool Drain();                         // writes the put area; false once a write failed

   protected:
    int_type overflow(int_type c) override;
    int sync() override { return Drain() ? 0 : -1; }

   private:
    int fd_;
    int error_ = 0;
    std::vector<char> storage_;
  };

  std::string name_;
  Buffer buffer_;
  std::ostream stream_;
  bool closed_ = false;
};

}  // namespace plywood::sim
