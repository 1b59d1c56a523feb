#pragma once

#include <string>

namespace plywood::sim {

// `text` as a YAML value that reads back as exactly that string: unchanged when YAML already reads
// it so (every ordinary path), else double-quoted. For values put into YAML text or a
// `--set KEY=VALUE` by code (a sweep's world files, bench's --world): a path such as
// "room #2.xml" or "/tmp/a: b/room.xml" would otherwise read as "room" or as a mapping.
std::string YamlTextValue(const std::string& text);

}  // namespace plywood::sim
