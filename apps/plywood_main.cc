// plywood: the command line of the Plywood testbed.
//   plywood run EXPERIMENT.yaml [--out DIR] [--seed N] [--set key.path=value]...
//   plywood bench [--seconds S] [--world PATH]
//   plywood replay LOG --extractor NAME [--out DIR] [--skip-bad]
//   plywood worlds generate FAMILY --count N --seed S --out DIR
// Exit codes: 0 success, 1 a failure during the run, 2 bad input (config, files, usage).

#include <cstdio>
#include <exception>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/bench_command.h"
#include "apps/command_line.h"
#include "apps/replay_command.h"
#include "apps/run_command.h"
#include "apps/train_command.h"
#include "apps/worlds_command.h"
#include "sim/config/config_error.h"

namespace {

constexpr const char* kUsage =
    "usage: plywood <command> [options]\n"
    "  run EXPERIMENT.yaml [--out DIR] [--seed N] [--set key.path=value]... [--quiet]\n"
    "      run one experiment and write its results to DIR (default runs/NAME-seedN)\n"
    "  bench [--seconds S] [--world PATH]\n"
    "      print the real-time factor and ray throughput of a P3-DX with LMS 200 + 16 sonars\n"
    "  replay LOG --extractor NAME [--out DIR] [--skip-bad]\n"
    "      run a line extractor on every scan of a CARMEN log (plain or .gz) and score it\n"
    "  train sonar-net [--out FILE] [--rooms N] [--poses N] [--epochs N] [--seed N]\n"
    "      train seed 001's sonar interpretation network on simulated rooms\n"
    "  worlds generate FAMILY --count N --seed S --out DIR [--pictures] [--quiet]\n"
    "      write N seeded worlds of a family (plywood worlds list; docs/worlds.md)\n";

int Dispatch(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "run") return plywood::apps::RunCommand(rest);
  if (args[0] == "bench") return plywood::apps::BenchCommand(rest);
  if (args[0] == "replay") return plywood::apps::ReplayCommand(rest);
  if (args[0] == "train") return plywood::apps::TrainCommand(rest);
  if (args[0] == "worlds") return plywood::apps::WorldsCommand(rest);
  throw plywood::apps::UsageError{"unknown command '" + args[0] + "' (try plywood --help)"};
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  try {
    return Dispatch(args);
  } catch (const plywood::apps::UsageError& e) {
    std::fprintf(stderr, "plywood: %s\n", e.message.c_str());
    return 2;
  } catch (const plywood::sim::ConfigError& e) {
    std::fprintf(stderr, "plywood: %s\n", e.what());
    return 2;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "plywood: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "plywood: error: %s\n", e.what());
    return 1;
  }
}
