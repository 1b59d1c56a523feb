#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace plywood::perception {

// What follows the last gzip member of `path` that zlib's gzread would skip without a word: zlib
// takes any bytes after a member that do not start another member as "trailing garbage" and ends
// the stream there, so a plain log appended to a compressed one (`cat more.log >> run.log.gz`), or
// a file of two members cut one byte into the second, read as its first member alone, exit 0.
// Returns a one-line description ("N bytes after the gzip data, which ends at byte E of S, ..."),
// or nothing when the file is whole gzip members, optionally followed by zero bytes (block
// padding, which holds no data and which gzip -t accepts too). Reads the file once more: call it
// once a reader has reached the end of the decompressed data.
std::optional<std::string> DescribeBytesAfterGzipData(const std::filesystem::path& path);

}  // namespace plywood::perception
