#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "perception/sonar_map/sonar_cell_model.h"

namespace plywood::perception {

// One labelled cell: normalised features (NormalisedFeatures) and 1 = occupied, 0 = free.
struct SonarSample {
  Eigen::Matrix<double, 5, 1> x;
  double occupied = 0.0;
};

// Training of the sonar interpretation network: plain mini-batch back-propagation with momentum on
// the cross-entropy, samples shuffled by a std::mt19937_64 seeded from `seed`, so the same data and
// options give the same weights bit for bit on one machine and compiler.
struct SonarNetTrainOptions {
  std::vector<int> hidden = {16, 16};  // tanh units per hidden layer
  int epochs = 20;
  int batch_size = 64;
  double learning_rate = 0.05;
  double momentum = 0.9;
  std::uint64_t seed = 1;
  // @throws std::invalid_argument naming the field.
  void Validate() const;
};

// The seed's sonar interpretation network (Thrun 1998 style): 5 inputs, tanh hidden layers, one
// logistic output = P(occupied). Output is clamped to [p_clamp, 1 - p_clamp] so that one reading
// can never make a cell certain (the product formula needs p strictly inside (0, 1)).
class SonarNet final : public SonarCellModel {
 public:
  static constexpr const char* kFileMagic = "plywood-sonar-net";
  static constexpr int kFileVersion = 1;

  // Random (Xavier-uniform) weights from `seed`. @throws std::invalid_argument "hidden: ..." for a
  // layer size outside [1, 256] or more than 7 hidden layers (what a weights file holds).
  SonarNet(const std::vector<int>& hidden, std::uint64_t seed);

  double Forward(const Eigen::Matrix<double, 5, 1>& x) const;
  double Probability(const msgs::RangeRing& ring, const Eigen::Vector2d& p_R) const override;

  // Trains in place; returns the mean training cross-entropy of the last epoch.
  double Train(const std::vector<SonarSample>& samples, const SonarNetTrainOptions& options);

  // Text file: magic + version line, layer sizes, then each layer's weights and biases written
  // with 17 significant digits, so Save(Load(f)) reproduces f byte for byte.
  // @throws std::runtime_error naming `path`, writing nothing, for weights Load would refuse.
  void Save(const std::filesystem::path& path) const;
  // @throws std::runtime_error "<destination>: ..." for a weight or bias that is not finite or is
  // beyond the +-1e6 Load accepts: a file no run could load is never written.
  void RequireLoadable(const std::string& destination) const;
  std::string ToText() const;
  // @throws std::runtime_error "<path>: line N: <what is wrong>" for a missing, truncated or
  // malformed file (wrong magic or version, bad sizes, non-numbers, non-finite weights).
  static SonarNet Load(const std::filesystem::path& path);
  static SonarNet FromText(const std::string& text, const std::string& source_name);

  double p_clamp = 0.02;

 private:
  SonarNet() = default;
  std::vector<Eigen::MatrixXd> weights_;  // layer l: (out x in)
  std::vector<Eigen::VectorXd> biases_;
};

// Mean binary cross-entropy (nats) and accuracy (threshold 0.5) of probabilities against labels;
// probabilities are clamped to [1e-6, 1 - 1e-6].
struct BinaryScore {
  double cross_entropy = 0.0;
  double accuracy = 0.0;
};
BinaryScore ScoreProbabilities(const std::vector<double>& p, const std::vector<double>& labels);

}  // namespace plywood::perception
