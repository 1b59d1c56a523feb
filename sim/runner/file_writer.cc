#include "sim/runner/file_writer.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace plywood::sim {
namespace {

int OpenForWriting(const std::filesystem::path& path, const std::string& name) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (fd < 0) throw std::runtime_error(name + ": cannot write: " + std::strerror(errno));
  return fd;
}

}  // namespace

FileWriter::Buffer::Buffer(int fd) : fd_(fd), storage_(1 << 16) {
  setp(storage_.data(), storage_.data() + storage_.size());
}

bool FileWriter::Buffer::Drain() {
  if (error_ != 0) return false;
  const char* next = pbase();
  while (next < pptr()) {
    const ssize_t written = ::write(fd_, next, static_cast<std::size_t>(pptr() - next));
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) {
      error_ = written < 0 ? errno : EIO;
      return false;
    }
    next += written;
  }
  setp(storage_.data(), storage_.data() + storage_.size());
  return true;
}

FileWriter::Buffer::int_type FileWriter::Buffer::overflow(int_type c) {
  if (!Drain()) return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

FileWriter::FileWriter(const std::filesystem::path& path, std::string name_in_errors)
    : name_(name_in_errors.empty() ? path.string() : std::move(name_in_errors)),
      buffer_(OpenForWriting(path, name_)),
      stream_(&buffer_) {}

FileWriter::~FileWriter() {
  if (!closed_) ::close(buffer_.fd());
}

void FileWriter::Close() {
  if (closed_) return;
  closed_ = true;
  buffer_.Drain();
  int error = buffer_.error();
  if (::close(buffer_.fd()) != 0 && error == 0) error = errno;  // NFS reports some errors here
  if (error == 0 && !stream_) error = EIO;                      // a failure the buffer did not see
  if (error != 0) throw std::runtime_error(name_ + ": write failed: " + std::strerror(error));
}

}  // namespace plywood::sim
