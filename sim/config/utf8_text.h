#pragma once

#include <utf8.h>  // utfcpp (Debian libutfcpp-dev)

#include <cstdio>
#include <string>
#include <string_view>

namespace plywood::sim {

// Whether `text` is well-formed UTF-8 (no overlong forms, no surrogates, nothing past U+10FFFF).
// A sweep keeps its files' paths and axis values as JSON text (cells.json, sweep.json), which must
// be UTF-8: a path of other bytes (a file named in Latin-1) would fail there, after the sweep was
// set up, naming neither the file nor the field.
inline bool IsUtf8(std::string_view text) { return utf8::is_valid(text.begin(), text.end()); }

// `text` with every byte of 0x80 or more written as \xNN, for an error line about text that is not
// UTF-8: the raw bytes would print as a replacement sign or garble the terminal.
inline std::string EscapeHighBytes(std::string_view text) {
  std::string shown;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x80) {
      shown += c;
      continue;
    }
    char escaped[5];
    std::snprintf(escaped, sizeof(escaped), "\\x%02X", byte);
    shown += escaped;
  }
  return shown;
}

}  // namespace plywood::sim
