#pragma once

#include <string>
#include <vector>

namespace plywood::apps {

// plywood bench [--seconds S] [--world PATH]: real-time factor and rays per second of a P3-DX
// with a 361-beam LMS 200 at 10 Hz and 16 sonars at 10 Hz wall-following in the office, on one
// core, and the ray casters' cost per ray. Prints figures; asserts nothing.
int BenchCommand(const std::vector<std::string>& args);

}  // namespace plywood::apps
