// plywood train sonar-net [--out FILE] [--rooms N] [--test-rooms N] [--poses N] [--epochs N]
//                         [--hidden H1,H2] [--seed N] [--quiet]

#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "apps/command.h"
#include "apps/decimal_whole_number.h"
#include "eval/sonar_map/sonar_net_training.h"
#include "sim/config/decimal_whole_number.h"

namespace plywood::apps {
namespace {

// Whole numbers in [1, 100000]; the range is in the error, not in every help line.
const CLI::Validator kCount = CLI::Range(1, 100000).description("");

// Sizes split at every comma: an empty size (`16,`, `,16`, `16,,8`) is refused, where
// std::getline dropped a trailing one and `16,` trained one layer of 16 without a word.
std::vector<int> ParseHidden(const std::string& text) {
  std::vector<int> hidden;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    std::string item =
        text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    item.erase(item.find_last_not_of(" \t") + 1);  // "16 ,8" as "16, 8" (stoi skips leading ones)
    std::size_t used = 0;
    try {
      hidden.push_back(std::stoi(item, &used));
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != item.size()) {
      throw UsageError("train: --hidden: expected sizes like 16,16, got '" + text + "'" +
                       (item.find_first_not_of(' ') == std::string::npos
                            ? " (an empty size between, before or after the commas)"
                            : ""));
    }
    if (comma == std::string::npos) return hidden;
    start = comma + 1;
  }
}

std::string Join(const std::vector<int>& sizes) {
  std::string text;
  for (int size : sizes) text += (text.empty() ? "" : ",") + std::to_string(size);
  return text;
}

void PrintReport(const eval::SonarNetTrainingReport& r) {
  std::printf("training cross-entropy (last epoch)   %.4f nats\n", r.train_loss);
  std::printf("%-34s %-14s %s\n", "held-out model", "cross-entropy", "accuracy");
  std::printf("%-34s %-14.4f %.4f\n", "sonar network", r.net.cross_entropy, r.net.accuracy);
  std::printf("%-34s %-14.4f %.4f\n", "classical cone model (Elfes)", r.classical.cross_entropy,
              r.classical.accuracy);
  std::printf("%-34s %-14.4f %.4f\n", "constant base rate", r.base_rate.cross_entropy,
              r.base_rate.accuracy);
  std::printf("weights written to %s\n", r.out.string().c_str());
}

}  // namespace

Command AddTrainCommand(CLI::App& app) {
  struct Flags {
    std::string model;
    eval::SonarNetTrainingOptions options;
    std::string hidden;
    std::string seed;
    bool quiet = false;
  };
  auto flags = std::make_shared<Flags>();
  flags->hidden = Join(flags->options.train.hidden);
  flags->seed = std::to_string(flags->options.train.seed);
  eval::SonarNetTrainingOptions& o = flags->options;
  CLI::App* cli = app.add_subcommand(
      "train",
      "Train seed 001's sonar interpretation network on simulated random rooms and score it on "
      "held-out rooms beside the classical cone model");
  cli->add_option("MODEL", flags->model, "what to train")
      ->required()
      ->check(CLI::IsMember({"sonar-net"}));
  cli->add_option("--out", o.out,
                  "weights file; never the shipped models/sonar_net_v1.txt (compare, then copy it "
                  "there by hand)")
      ->type_name("FILE")
      ->capture_default_str();
  cli->add_option("--rooms", o.rooms, "random training rooms")
      ->type_name("N")
      ->transform(DecimalWholeNumber())
      ->check(kCount)
      ->capture_default_str();
  cli->add_option("--test-rooms", o.test_rooms, "held-out rooms")
      ->type_name("N")
      ->transform(DecimalWholeNumber())
      ->check(kCount)
      ->capture_default_str();
  cli->add_option("--poses", o.poses, "robot poses per room, one sonar ring each")
      ->type_name("N")
      ->transform(DecimalWholeNumber())
      ->check(kCount)
      ->capture_default_str();
  cli->add_option("--epochs", o.train.epochs, "training epochs")
      ->type_name("N")
      ->transform(DecimalWholeNumber())
      ->check(kCount)
      ->capture_default_str();
  cli->add_option("--hidden", flags->hidden, "tanh units of each hidden layer")
      ->type_name("H1,H2")
      ->capture_default_str();
  cli->add_option("--seed", flags->seed, "seed of the rooms, poses, noise and initial weights")
      ->type_name("N")
      ->transform(DecimalWholeNumber())
      ->capture_default_str();
  cli->add_flag("--edge-echoes", o.sonar.edge_echoes,
                "read the rings with convex edges heard (the sonar's edge_echoes), for runs that "
                "set it");
  cli->add_flag("--quiet", flags->quiet, "print nothing");
  cli->footer(
      "Examples:\n"
      "  plywood train sonar-net\n"
      "  plywood train sonar-net --rooms 10 --test-rooms 3 --epochs 5 --out runs/small_net.txt");
  return {cli, [flags] {
            eval::SonarNetTrainingOptions options = flags->options;
            options.train.hidden = ParseHidden(flags->hidden);
            // One rule for every seed (sim::ParseDecimalWholeNumber): --seed took 1..100000 where a
            // run's seed and worlds generate's take 0 and up to 19 digits (s57's left item).
            const std::optional<std::uint64_t> seed = sim::ParseDecimalWholeNumber(flags->seed);
            if (!seed) {
              throw UsageError(
                  "train: --seed: must be a whole number >= 0 in decimal digits, at most 19 (as a "
                  "run's seed and worlds generate's take), got '" +
                  flags->seed + "'");
            }
            options.train.seed = *seed;
            try {
              options.Validate();  // "hidden: ..." names its flag: "train: --hidden: ..."
            } catch (const std::invalid_argument& e) {
              throw UsageError(std::string("train: --") + e.what());
            }
            const bool quiet = flags->quiet;
            const eval::SonarNetTrainingReport report =
                eval::TrainSonarNet(options, [quiet](const eval::SonarNetDataSummary& d) {
                  if (quiet) return;
                  std::printf(
                      "data: %d training rooms (%zu cells), %d held-out rooms (%zu cells)\n",
                      d.rooms, d.train_cells, d.test_rooms, d.test_cells);
                  std::fflush(stdout);
                });
            if (!quiet) PrintReport(report);
            return 0;
          }};
}

}  // namespace plywood::apps
