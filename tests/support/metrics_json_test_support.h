#pragma once

#include <map>
#include <string>

namespace plywood::testing {

// The leaves of a metrics.json (nested objects of numbers, strings and null) by dotted key, each
// as its text in the file ("0.1", "\"office.xml\""), so that equal text means the same double.
// Fails the calling test (and returns what it has) on anything else.
std::map<std::string, std::string> FlattenMetricsJson(const std::string& json);

}  // namespace plywood::testing
