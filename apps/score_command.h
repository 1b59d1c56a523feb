#pragma once

#include <string>
#include <vector>

namespace plywood::apps {

// plywood score trajectory|lines|grid RUN_DIR FILE [--out FILE.json] [...]: scores a file computed
// elsewhere against a finished run's ground truth with the runner's own scorers (eval/score/),
// prints a table and writes the metrics under metrics.json's keys.
int ScoreCommand(const std::vector<std::string>& args);

}  // namespace plywood::apps
