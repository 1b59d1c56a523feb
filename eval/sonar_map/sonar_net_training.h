#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <vector>

#include "perception/sonar_map/sonar_net.h"
#include "sim/sensors/sonar_sensor.h"

namespace plywood::eval {

// The most sonar rings ((rooms + test_rooms) x poses) one training makes: about 2 GB of cells.
inline constexpr long kMaxSonarRings = 100000;

struct SonarNetTrainingOptions {
  int rooms = 60;       // random training rooms
  int test_rooms = 15;  // held-out rooms, scored after training
  int poses = 25;       // robot poses per room, one sonar ring each
  // The ring the data is read with: a network learns the sensor it will read, so a run whose
  // sonar hears convex edges (edge_echoes) wants weights trained with them.
  sim::SonarOptions sonar;
  perception::SonarNetTrainOptions train = {.epochs = 30};
  std::filesystem::path out = "runs/sonar_net/sonar_net.txt";  // where the weights go
  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

struct SonarNetDataSummary {
  int rooms = 0, test_rooms = 0;
  std::size_t train_cells = 0, test_cells = 0;
};

struct SonarNetTrainingReport {
  SonarNetDataSummary data;
  double train_loss = 0.0;  // mean cross-entropy of the last epoch (nats)
  // On the held-out rooms: the network, seed 001's classical cone model (Elfes) and the constant
  // base rate of the training cells.
  perception::BinaryScore net, classical, base_rate;
  std::filesystem::path out;
};

// models/sonar_net_v1.txt: the weights the shipped experiments use, which training never writes.
std::filesystem::path ShippedSonarNetPath();

// Every weights file shipped in models/ (sonar_net_v1.txt, and sonar_net_edges_v1.txt for runs
// whose sonar hears convex edges): training writes none of them.
std::vector<std::filesystem::path> ShippedSonarNetPaths();

// @throws std::invalid_argument when `out` is a shipped weights file (however it is spelled:
// relative, through symbolic links or a hard link).
void RefuseShippedSonarNet(const std::filesystem::path& out);

// @throws std::invalid_argument "train: --out: OUT: cannot write there: REASON" when no file can be
// made beside `out` (a read-only file system, a folder of /sys), so training does not start.
void RequireWritablePlace(const std::filesystem::path& out);

// Generates labelled sonar data in random rooms (2-5 m by 2-4.5 m with 0-3 boxes; never the seed
// 001 evaluation rooms): for each robot pose a sonar ring and the 14 x 14 local grid's cells
// labelled from the reachable-space ground truth. Trains the sonar interpretation network on the
// training rooms, scores it on the held-out ones beside the classical model, and writes the
// weights to options.out (its folder created). `on_data` is called once the data is made, before
// the (longer) training. The same options give the same bytes.
// @throws std::invalid_argument for bad options or the shipped weights as options.out.
SonarNetTrainingReport TrainSonarNet(
    const SonarNetTrainingOptions& options,
    const std::function<void(const SonarNetDataSummary&)>& on_data = {});

}  // namespace plywood::eval
