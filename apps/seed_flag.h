#pragma once

#include <string>
#include <vector>

#include "apps/command.h"

namespace plywood::apps {

// `--seed N` is `--set seed=N` (docs/experiments.md), applied after every --set. Given beside a
// --set of the seed, it won whatever the order: `run e.yaml --seed 3 --set seed=4` ran seed 3 and
// dropped the 4 without a word (s62). `command` names the subcommand in the error.
// @throws UsageError when an override already sets the seed.
inline std::vector<std::string> WithSeedFlag(std::vector<std::string> overrides,
                                             const CLI::Option& seed_option,
                                             const std::string& seed, const std::string& command) {
  if (seed_option.count() == 0) return overrides;
  for (const std::string& assignment : overrides) {
    if (assignment.substr(0, assignment.find('=')) == "seed") {
      throw UsageError(command + ": --seed " + seed + " and --set " + assignment +
                       " both give the seed: give one of them");
    }
  }
  overrides.push_back("seed=" + seed);
  return overrides;
}

}  // namespace plywood::apps
