#pragma once

#include <sys/types.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "render/png_image.h"

namespace plywood::render {

// Encodes RGB frames into an H.264 MP4 through Debian's `ffmpeg` executable, fed raw frames on a
// pipe (no libav* linking; ffmpeg found on PATH). Every frame must have the size of the first;
// odd sizes are padded by one black row / column (yuv420p needs even sizes).
class VideoEncoder {
 public:
  // @throws std::invalid_argument when fps is not in [1, 240]; std::runtime_error naming `path`
  // when ffmpeg cannot be started.
  VideoEncoder(const std::filesystem::path& path, double fps);
  // Finishes the file if Close was not called (errors then go to stderr); while an exception
  // unwinds (the run failed) the unfinished video is dropped instead and an earlier file stays.
  ~VideoEncoder();
  VideoEncoder(const VideoEncoder&) = delete;
  VideoEncoder& operator=(const VideoEncoder&) = delete;

  // @throws std::runtime_error when the size changes or ffmpeg stopped reading.
  void AddFrame(const RgbImage& frame);
  // Waits for ffmpeg and renames its staged file into place. @throws std::runtime_error naming the
  // path when it failed; the staged file is then removed and an earlier file at the path stays.
  void Close();

  long frames() const { return frames_; }
  const std::filesystem::path& path() const { return path_; }

 private:
  void Start(int width, int height);
  void Abandon();

  std::filesystem::path path_;
  // ffmpeg writes DIR/STEM.partial-PID.EXT (the extension picks its container) and Close renames
  // it to path_, so a failed video never replaces an earlier one; a device is written in place.
  std::filesystem::path staged_;
  double fps_;
  int width_ = 0, height_ = 0;
  long frames_ = 0;
  pid_t pid_ = -1;
  int pipe_fd_ = -1;
  // ffmpeg's stderr: ffmpeg exits 0 after "Error writing trailer" (a full disk), so any line it
  // writes at -loglevel error is a failure, reported as one line of ours.
  std::FILE* ffmpeg_errors_ = nullptr;
  std::string FfmpegSaid() const;
};

}  // namespace plywood::render
