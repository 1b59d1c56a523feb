#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace plywood::apps {

// One `plywood` subcommand. Each AddXCommand (apps/x_command.cc, one file per command) registers
// the subcommand, its flags with their defaults and an example on `app`, and returns it with what
// to do once the command line has parsed. `run` returns the exit code (0 ok, 1 a failure during
// the run); bad input throws sim::ConfigError or std::invalid_argument (exit code 2).
struct Command {
  CLI::App* cli = nullptr;
  std::function<int()> run;
  // Runs whatever follows the command's name (a command this build lacks, which only says so).
  bool takes_any_arguments = false;
};

// Bad command-line usage found after parsing: one line, exit code 2.
struct UsageError : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// The words `cli` did not take, without `--`: the mark that ends the flags, so that a file whose
// name starts with '-' can be given (`plywood run -- -e.yaml`), is kept among them by CLI11.
inline std::vector<std::string> WordsNotTaken(const CLI::App& cli) {
  std::vector<std::string> words = cli.remaining();
  std::erase(words, std::string("--"));
  return words;
}

Command AddRunCommand(CLI::App& app);
Command AddBenchCommand(CLI::App& app);
Command AddReplayCommand(CLI::App& app);
Command AddTrainCommand(CLI::App& app);
Command AddScoreCommand(CLI::App& app);
Command AddSweepCommand(CLI::App& app);
Command AddWorldsCommand(CLI::App& app);
Command AddViewCommand(CLI::App& app);

}  // namespace plywood::apps
