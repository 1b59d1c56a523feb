#include "render/video_encoder.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

extern char** environ;

namespace plywood::render {

namespace {

std::filesystem::path StagedPath(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error)) {
    return path;  // a device such as /dev/null: a rename would replace it
  }
  return path.parent_path() / (path.stem().string() + ".partial-" + std::to_string(getpid()) +
                               path.extension().string());
}

void ReplaceAll(std::string& text, const std::string& from, const std::string& to) {
  if (from.empty() || from == to) return;
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

}  // namespace

VideoEncoder::VideoEncoder(const std::filesystem::path& path, double fps)
    : path_(path), staged_(StagedPath(path)), fps_(fps) {
  if (!(fps >= 1.0 && fps <= 240.0)) {
    throw std::invalid_argument("fps: must be in [1, 240], got " + std::to_string(fps));
  }
}

VideoEncoder::~VideoEncoder() {
  if (pid_ >= 0 && std::uncaught_exceptions() > 0) {
    Abandon();
  } else if (pid_ >= 0) {
    try {
      Close();
    } catch (const std::exception& e) {
      std::cerr << "plywood: " << e.what() << "\n";
    }
  }
  if (ffmpeg_errors_) std::fclose(ffmpeg_errors_);
}

void VideoEncoder::Abandon() {
  if (pipe_fd_ >= 0) close(pipe_fd_);
  pipe_fd_ = -1;
  kill(pid_, SIGTERM);
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  std::error_code ignored;
  if (staged_ != path_) std::filesystem::remove(staged_, ignored);
}

std::string VideoEncoder::FfmpegSaid() const {
  if (!ffmpeg_errors_) return "";
  std::fflush(ffmpeg_errors_);
  std::rewind(ffmpeg_errors_);
  char line[512];
  while (std::fgets(line, sizeof line, ffmpeg_errors_)) {
    std::string text = line;
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    // The user gave path_; the staged name is ours.
    ReplaceAll(text, "file:" + staged_.string(), path_.string());
    ReplaceAll(text, staged_.string(), path_.string());
    if (!text.empty()) return text;
  }
  return "";
}

void VideoEncoder::Start(int width, int height) {
  width_ = width;
  height_ = height;
  // A socket rather than a pipe: send(MSG_NOSIGNAL) reports a dead ffmpeg as an error instead of
  // killing the process with SIGPIPE.
  int fds[2];
  if (socketpair(AF_UNIX, SOCK_STREAM, 0, fds) != 0) {
    throw std::runtime_error(path_.string() +
                             ": cannot open a pipe to ffmpeg: " + std::strerror(errno));
  }
  const std::string size =
      std::to_string(width + width % 2) + "x" + std::to_string(height + height % 2);
  const std::string rate = std::to_string(fps_);
  // ffmpeg reads its output argument as a protocol URL or an option: `file:a.mp4` was written as
  // a.partial-PID.mp4 (the rename then failed), `pipe:1.mp4` and `tcp:x.mp4` were no files,
  // `-y.mp4` an unknown option, each after the whole run (s61). `file:` names the file as given.
  const std::string output = "file:" + staged_.string();
  std::vector<std::string> args = {
      "ffmpeg",   "-hide_banner", "-loglevel",  "error",   "-y",      "-f",       "rawvideo",
      "-pix_fmt", "rgb24",        "-s",         size,      "-r",      rate,       "-i",
      "pipe:0",   "-an",          "-c:v",       "libx264", "-preset", "veryfast", "-pix_fmt",
      "yuv420p",  "-movflags",    "+faststart", output};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[1]);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  ffmpeg_errors_ = std::tmpfile();
  if (ffmpeg_errors_)
    posix_spawn_file_actions_adddup2(&actions, fileno(ffmpeg_errors_), STDERR_FILENO);
  const int error = posix_spawnp(&pid_, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  close(fds[0]);
  if (error != 0) {
    close(fds[1]);
    pid_ = -1;
    throw std::runtime_error(path_.string() + ": cannot start ffmpeg (" + std::strerror(error) +
                             "; Debian package ffmpeg)");
  }
  pipe_fd_ = fds[1];
}

void VideoEncoder::AddFrame(const RgbImage& frame) {
  if (frames_ == 0 && pid_ < 0) Start(frame.width, frame.height);
  if (frame.width != width_ || frame.height != height_) {
    throw std::runtime_error(path_.string() + ": frame " + std::to_string(frames_) + " is " +
                             std::to_string(frame.width) + " x " + std::to_string(frame.height) +
                             ", the first was " + std::to_string(width_) + " x " +
                             std::to_string(height_));
  }
  if (pipe_fd_ < 0) throw std::runtime_error(path_.string() + ": the video is already closed");
  const int padded_width = width_ + width_ % 2;
  std::vector<std::uint8_t> row(static_cast<std::size_t>(padded_width) * 3, 0);
  const auto send_all = [&](const std::uint8_t* data, std::size_t size) {
    while (size > 0) {
      const ssize_t sent = send(pipe_fd_, data, size, MSG_NOSIGNAL);
      if (sent < 0 && errno == EINTR) continue;
      if (sent <= 0) {
        const std::string why = std::strerror(errno);
        const std::string said = FfmpegSaid();
        throw std::runtime_error(path_.string() + ": ffmpeg stopped reading frames (" + why + ")" +
                                 (said.empty() ? "" : ": " + said));
      }
      data += sent;
      size -= static_cast<std::size_t>(sent);
    }
  };
  for (int y = 0; y < height_; ++y) {
    std::copy_n(frame.At(0, y), static_cast<std::size_t>(width_) * 3, row.begin());
    send_all(row.data(), row.size());
  }
  if (height_ % 2) {
    std::fill(row.begin(), row.end(), 0);
    send_all(row.data(), row.size());
  }
  ++frames_;
}

void VideoEncoder::Close() {
  if (pipe_fd_ >= 0) {
    close(pipe_fd_);
    pipe_fd_ = -1;
  }
  if (pid_ < 0) {
    if (frames_ == 0) throw std::runtime_error(path_.string() + ": no frames to encode");
    return;
  }
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  const std::string said = FfmpegSaid();
  const bool failed = !said.empty() || !WIFEXITED(status) || WEXITSTATUS(status) != 0;
  std::error_code error;
  if (!failed) {
    if (staged_ == path_) return;
    std::filesystem::rename(staged_, path_, error);
    if (!error) return;
    std::error_code ignored;
    std::filesystem::remove(staged_, ignored);
    throw std::runtime_error(path_.string() +
                             ": cannot move the finished video into place: " + error.message());
  }
  // What ffmpeg left is no playable video: it goes, so that it is never taken for a result, and
  // an earlier file at the path stays (a device given as the path is written in place and stays).
  if (staged_ != path_) std::filesystem::remove(staged_, error);
  if (!said.empty()) throw std::runtime_error(path_.string() + ": ffmpeg: " + said);
  throw std::runtime_error(path_.string() + ": ffmpeg failed (exit status " +
                           std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
}

}  // namespace plywood::render
