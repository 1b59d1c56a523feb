#pragma once

#include <string>
#include <vector>

namespace plywood::apps {

// plywood replay LOG --extractor NAME [--out DIR] [--skip-bad]: runs a line extractor on every
// scan of a CARMEN log (plain or .gz) and reports the fraction of valid rays explained by the
// extracted segments (replay.rays_explained), their RMS distance (replay.rms_m), valid rays per
// line, lines per scan and time per scan; writes metrics.json (deterministic figures only),
// timing.json (wall clock) and segments.png (every segment placed by the log's poses) to DIR.
int ReplayCommand(const std::vector<std::string>& args);

}  // namespace plywood::apps
