#pragma once

#include <utf8.h>  // utfcpp (Debian libutfcpp-dev)

#include <string_view>

namespace plywood::sim {

// Whether `text` is well-formed UTF-8 (no overlong forms, no surrogates, nothing past U+10FFFF).
// A sweep keeps its files' paths and axis values as JSON text (cells.json, sweep.json), which must
// be UTF-8: a path of other bytes (a file named in Latin-1) would fail there, after the sweep was
// set up, naming neither the file nor the field.
inline bool IsUtf8(std::string_view text) { return utf8::is_valid(text.begin(), text.end()); }

}  // namespace plywood::sim
