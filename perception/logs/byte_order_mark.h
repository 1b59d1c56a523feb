#pragma once

#include <string>
#include <string_view>

namespace plywood::perception {

// The three bytes an editor's "UTF-8 with BOM" puts before a file's first line. Every reader of a
// text file made elsewhere (logs, CSV and TUM files, profiles) drops them: kept, they became part
// of the first field or key, and the error named an invisible prefix.
inline constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

// `text` (a file's first line, or the whole file) without a leading UTF-8 byte-order mark.
inline void DropUtf8ByteOrderMark(std::string& text) {
  if (text.starts_with(kUtf8ByteOrderMark)) text.erase(0, kUtf8ByteOrderMark.size());
}

}  // namespace plywood::perception
