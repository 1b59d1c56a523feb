#include "perception/logs/gzip_trailing_bytes.h"

#include <zlib.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <vector>

namespace plywood::perception {
namespace {

// The two bytes every gzip member starts with (RFC 1952).
constexpr unsigned char kGzipMagic0 = 0x1f;
constexpr unsigned char kGzipMagic1 = 0x8b;

// Inflates one gzip member from `offset` to its end, discarding the output. Returns the offset
// just past the member, or nothing when the member is damaged or cut short.
std::optional<std::uintmax_t> SkipMember(std::ifstream& in, std::uintmax_t offset) {
  in.clear();
  in.seekg(static_cast<std::streamoff>(offset));
  z_stream stream{};
  if (inflateInit2(&stream, 15 + 16) != Z_OK) return std::nullopt;  // 16: gzip wrapper only
  // 128 kB of buffers, on the heap: on the stack they crashed a replay under `ulimit -s 128`
  // (SIGSEGV, no line; s65 fifty-fourth pass).
  std::vector<unsigned char> input(1 << 16);
  std::vector<unsigned char> output(1 << 16);
  std::uintmax_t read = 0;
  int status = Z_OK;
  while (status != Z_STREAM_END) {
    if (stream.avail_in == 0) {
      in.read(reinterpret_cast<char*>(input.data()), input.size());
      const std::streamsize got = in.gcount();
      if (got <= 0) break;
      read += static_cast<std::uintmax_t>(got);
      stream.next_in = input.data();
      stream.avail_in = static_cast<uInt>(got);
    }
    stream.next_out = output.data();
    stream.avail_out = output.size();
    status = inflate(&stream, Z_NO_FLUSH);
    if (status != Z_OK && status != Z_STREAM_END) break;
  }
  const std::uintmax_t end = offset + read - stream.avail_in;
  inflateEnd(&stream);
  if (status != Z_STREAM_END) return std::nullopt;
  return end;
}

}  // namespace

std::optional<std::string> DescribeBytesAfterGzipData(const std::filesystem::path& path) {
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  if (error || !in) return std::nullopt;  // the reader itself reports a file it cannot read
  std::uintmax_t offset = 0;
  while (offset < size) {
    std::array<char, 2> magic{};
    in.clear();
    in.seekg(static_cast<std::streamoff>(offset));
    in.read(magic.data(), magic.size());
    const bool member = in.gcount() == 2 && static_cast<unsigned char>(magic[0]) == kGzipMagic0 &&
                        static_cast<unsigned char>(magic[1]) == kGzipMagic1;
    if (member) {
      if (const auto end = SkipMember(in, offset)) {
        offset = *end;
        continue;
      }
    }
    if (offset == 0) return std::nullopt;  // not gzip at all, or damaged: zlib says so itself
    // Zero bytes to the end are padding; anything else is data zlib would drop.
    in.clear();
    in.seekg(static_cast<std::streamoff>(offset));
    bool only_zeros = true;
    for (char c; only_zeros && in.get(c);) only_zeros = c == 0;
    if (only_zeros) return std::nullopt;
    const std::uintmax_t left = size - offset;
    return std::to_string(left) + (left == 1 ? " byte" : " bytes") +
           " after the gzip data, which ends at byte " + std::to_string(offset) + " of " +
           std::to_string(size) + ", " + (left == 1 ? "is" : "are") +
           " not a whole gzip member (an uncompressed log appended to a compressed one, or a "
           "member cut short): zlib would end the log there without a word; decompress the "
           "parts, join them and compress the whole again";
  }
  return std::nullopt;
}

}  // namespace plywood::perception
