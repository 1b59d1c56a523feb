#pragma once

#include <string>
#include <vector>

namespace plywood::apps {

// plywood train sonar-net [--out FILE] [--rooms N] [--test-rooms N] [--poses N] [--epochs N]
//                         [--hidden H1,H2] [--seed N]
// Generates labelled sonar data in random rooms (never the seed 001 evaluation rooms), trains the
// sonar interpretation network, prints held-out cross-entropy and accuracy beside the classical
// cone model, and writes the weights. Returns the exit code.
int TrainCommand(const std::vector<std::string>& args);

}  // namespace plywood::apps
