#include "perception/sonar_map/sonar_net.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "perception/logs/parse_number.h"

namespace plywood::perception {
namespace {

// The shipped networks' weights are within +-13. Within +-1e6 a layer's sum (at most 257
// products) overflows only for an input beyond 1e299, which no feature or tanh unit reaches.
constexpr double kMaxAbsWeight = 1e6;

[[noreturn]] void Fail(const std::string& source, int line, const std::string& what) {
  throw std::runtime_error(source + ": line " + std::to_string(line) + ": " + what);
}

std::string Format(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// The layers a weights file can hold (FromText): shared by training and the constructor.
void ValidateHiddenSizes(const std::vector<int>& hidden) {
  // A weights file holds at most 8 layers (FromText), the output layer one of them; 1000 hidden
  // layers trained for ever and would not have loaded back.
  if (hidden.size() > 7)
    throw std::invalid_argument(
        "hidden: at most 7 layers (8 with the output layer, as a weights "
        "file holds), got " +
        std::to_string(hidden.size()));
  for (int h : hidden)
    if (h < 1 || h > 256)
      throw std::invalid_argument("hidden: layer sizes must be in [1, 256], got " +
                                  std::to_string(h));
}

}  // namespace

void SonarNetTrainOptions::Validate() const {
  if (hidden.empty()) throw std::invalid_argument("hidden: needs at least one layer");
  ValidateHiddenSizes(hidden);
  if (epochs < 1) throw std::invalid_argument("epochs: must be >= 1");
  if (batch_size < 1) throw std::invalid_argument("batch_size: must be >= 1");
  if (!(learning_rate > 0.0)) throw std::invalid_argument("learning_rate: must be > 0");
  if (!(momentum >= 0.0 && momentum < 1.0))
    throw std::invalid_argument("momentum: must be in [0, 1)");
}

SonarNet::SonarNet(const std::vector<int>& hidden, std::uint64_t seed) {
  // A size of 0 gave a network whose output ignores its inputs, a negative one an Eigen matrix of
  // negative size.
  ValidateHiddenSizes(hidden);
  std::mt19937_64 rng(seed);
  int in = 5;
  std::vector<int> sizes = hidden;
  sizes.push_back(1);
  for (int out : sizes) {
    const double limit = std::sqrt(6.0 / (in + out));
    std::uniform_real_distribution<double> u(-limit, limit);
    Eigen::MatrixXd w(out, in);
    // Filled in a fixed order: Eigen's NullaryExpr evaluation order is unspecified.
    for (int r = 0; r < out; ++r)
      for (int c = 0; c < in; ++c) w(r, c) = u(rng);
    weights_.push_back(w);
    biases_.push_back(Eigen::VectorXd::Zero(out));
    in = out;
  }
}

double SonarNet::Forward(const Eigen::Matrix<double, 5, 1>& x) const {
  // Called for every cell under every ring (~500k times a run): the activations live in buffers
  // kept per thread instead of two allocations per layer. Each product is evaluated into its own
  // vector first, as the one-line expressions did, so every activation is the same double.
  thread_local Eigen::VectorXd input, hidden, product;
  input = x;
  const Eigen::VectorXd* a = &input;
  for (std::size_t l = 0; l + 1 < weights_.size(); ++l) {
    product.noalias() = weights_[l] * *a;
    hidden = (product + biases_[l]).array().tanh().matrix();
    a = &hidden;
  }
  product.noalias() = weights_.back() * *a;
  const double z = product(0) + biases_.back()(0);
  const double p = 1.0 / (1.0 + std::exp(-z));
  return std::clamp(p, p_clamp, 1.0 - p_clamp);
}

double SonarNet::Probability(const msgs::RangeRing& ring, const Eigen::Vector2d& p_R) const {
  return Forward(NormalisedFeatures(ComputeCellFeatures(ring, p_R), ring.range_max_m));
}

double SonarNet::Train(const std::vector<SonarSample>& samples,
                       const SonarNetTrainOptions& options) {
  options.Validate();
  if (samples.empty()) throw std::invalid_argument("samples: empty training set");
  std::mt19937_64 rng(options.seed);
  const std::size_t L = weights_.size();
  std::vector<Eigen::MatrixXd> vw(L);
  std::vector<Eigen::VectorXd> vb(L);
  for (std::size_t l = 0; l < L; ++l) {
    vw[l] = Eigen::MatrixXd::Zero(weights_[l].rows(), weights_[l].cols());
    vb[l] = Eigen::VectorXd::Zero(biases_[l].size());
  }
  std::vector<std::size_t> order(samples.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<Eigen::VectorXd> act(L + 1);
  double epoch_loss = 0.0;
  for (int epoch = 0; epoch < options.epochs; ++epoch) {
    // Fisher-Yates with our own draws: std::shuffle's algorithm is implementation-defined.
    for (std::size_t i = order.size(); i > 1; --i) {
      std::swap(order[i - 1], order[rng() % i]);
    }
    epoch_loss = 0.0;
    for (std::size_t start = 0; start < order.size(); start += options.batch_size) {
      const std::size_t end = std::min(order.size(), start + options.batch_size);
      std::vector<Eigen::MatrixXd> gw(L);
      std::vector<Eigen::VectorXd> gb(L);
      for (std::size_t l = 0; l < L; ++l) {
        gw[l] = Eigen::MatrixXd::Zero(weights_[l].rows(), weights_[l].cols());
        gb[l] = Eigen::VectorXd::Zero(biases_[l].size());
      }
      for (std::size_t k = start; k < end; ++k) {
        const SonarSample& s = samples[order[k]];
        act[0] = s.x;
        for (std::size_t l = 0; l + 1 < L; ++l)
          act[l + 1] = (weights_[l] * act[l] + biases_[l]).array().tanh().matrix();
        const double z = (weights_.back() * act[L - 1] + biases_.back())(0);
        const double p = 1.0 / (1.0 + std::exp(-z));
        const double pc = std::clamp(p, 1e-12, 1.0 - 1e-12);
        epoch_loss -= s.occupied * std::log(pc) + (1.0 - s.occupied) * std::log(1.0 - pc);
        // d(cross-entropy)/dz of a logistic output is p - y.
        Eigen::VectorXd delta(1);
        delta(0) = p - s.occupied;
        for (std::size_t l = L; l-- > 0;) {
          gw[l] += delta * act[l].transpose();
          gb[l] += delta;
          if (l > 0) {
            delta = (weights_[l].transpose() * delta)
                        .cwiseProduct((1.0 - act[l].array().square()).matrix());
          }
        }
      }
      const double scale = options.learning_rate / static_cast<double>(end - start);
      for (std::size_t l = 0; l < L; ++l) {
        vw[l] = options.momentum * vw[l] - scale * gw[l];
        vb[l] = options.momentum * vb[l] - scale * gb[l];
        weights_[l] += vw[l];
        biases_[l] += vb[l];
      }
    }
    epoch_loss /= static_cast<double>(samples.size());
  }
  return epoch_loss;
}

std::string SonarNet::ToText() const {
  std::ostringstream out;
  out << kFileMagic << ' ' << kFileVersion << '\n';
  out << "p_clamp " << Format(p_clamp) << '\n';
  out << "layers " << weights_.size() << '\n';
  for (std::size_t l = 0; l < weights_.size(); ++l) {
    out << "layer " << weights_[l].rows() << ' ' << weights_[l].cols() << '\n';
    for (int r = 0; r < weights_[l].rows(); ++r) {
      for (int c = 0; c < weights_[l].cols(); ++c)
        out << (c ? " " : "") << Format(weights_[l](r, c));
      out << ' ' << Format(biases_[l](r)) << '\n';
    }
  }
  return out.str();
}

void SonarNet::RequireLoadable(const std::string& destination) const {
  for (std::size_t l = 0; l < weights_.size(); ++l) {
    for (int r = 0; r < weights_[l].rows(); ++r) {
      for (int c = 0; c <= weights_[l].cols(); ++c) {
        const double v = c < weights_[l].cols() ? weights_[l](r, c) : biases_[l](r);
        if (std::abs(v) <= kMaxAbsWeight) continue;  // NaN fails this too
        throw std::runtime_error(
            destination + ": not written: layer " + std::to_string(l + 1) + " row " +
            std::to_string(r + 1) + " holds " + Format(v) +
            ", beyond the +-1e6 a run loads (training diverged; the shipped networks' are within "
            "+-13)");
      }
    }
  }
}

void SonarNet::Save(const std::filesystem::path& path) const {
  RequireLoadable(path.string());
  std::ofstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path.string() + ": cannot open for writing");
  file << ToText();
  file.close();  // the last buffered bytes are written here: a full disk shows only now
  if (!file) throw std::runtime_error(path.string() + ": write failed");
}

SonarNet SonarNet::Load(const std::filesystem::path& path) {
  // A device or a FIFO (weights_file: /dev/zero) would be read forever.
  std::error_code refused;
  if (std::filesystem::exists(path, refused) && !std::filesystem::is_regular_file(path, refused))
    throw std::runtime_error(path.string() + ": not a regular file (a folder or a device?)");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error(path.string() + ": cannot open sonar network weights");
  std::stringstream buffer;
  buffer << file.rdbuf();
  return FromText(buffer.str(), path.string());
}

SonarNet SonarNet::FromText(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  std::string line;
  int line_no = 0;
  auto next_line = [&](const std::string& expected) {
    if (!std::getline(in, line))
      Fail(source, line_no + 1, "unexpected end of file, expected " + expected);
    ++line_no;
    return std::istringstream(line);
  };
  SonarNet net;
  {
    auto s = next_line("header");
    std::string magic;
    int version = 0;
    if (!(s >> magic) || magic != kFileMagic)
      Fail(source, line_no,
           "not a sonar network file (expected '" + std::string(kFileMagic) + "')");
    std::string extra;
    // Read with >>, "plywood-sonar-net 1.9" was version 1: the rest of a line must be empty.
    if (!(s >> version) || version != kFileVersion || (s >> extra))
      Fail(source, line_no,
           "unsupported version (this build reads version " + std::to_string(kFileVersion) + ")");
  }
  {
    auto s = next_line("p_clamp");
    std::string key, value, extra;
    const bool read = static_cast<bool>(s >> key >> value) && !(s >> extra);
    const std::optional<double> p = read ? ParseFiniteNumber(value) : std::nullopt;
    if (!p || key != "p_clamp" || !(*p > 0.0 && *p < 0.5))
      Fail(source, line_no, "expected 'p_clamp P' with 0 < P < 0.5");
    net.p_clamp = *p;
  }
  int layers = 0;
  {
    auto s = next_line("layers");
    std::string key, extra;
    if (!(s >> key >> layers) || key != "layers" || layers < 1 || layers > 8 || (s >> extra))
      Fail(source, line_no, "expected 'layers N' with 1 <= N <= 8");
  }
  long expected_in = 5;
  for (int l = 0; l < layers; ++l) {
    long rows = 0, cols = 0;
    {
      auto s = next_line("layer header");
      std::string key, extra;
      if (!(s >> key >> rows >> cols) || key != "layer" || rows < 1 || rows > 256 || (s >> extra))
        Fail(source, line_no, "expected 'layer ROWS COLS' with 1 <= ROWS <= 256");
      if (cols != expected_in)
        Fail(source, line_no,
             "layer " + std::to_string(l) + " takes " + std::to_string(cols) +
                 " inputs, the previous layer gives " + std::to_string(expected_in));
      if (l + 1 == layers && rows != 1) Fail(source, line_no, "the last layer must have 1 output");
    }
    Eigen::MatrixXd w(rows, cols);
    Eigen::VectorXd b(rows);
    for (long r = 0; r < rows; ++r) {
      auto s = next_line("weights");
      for (long c = 0; c <= cols; ++c) {
        std::string token;
        if (!(s >> token))
          Fail(source, line_no, "expected " + std::to_string(cols + 1) + " numbers");
        const std::optional<double> parsed = ParseFiniteNumber(token);
        if (!parsed) Fail(source, line_no, "'" + token + "' is not a finite number");
        // Finite but huge weights overflow a layer's sum to inf - inf: the cell's probability is
        // NaN and its log odds stay NaN for the rest of the run.
        if (std::abs(*parsed) > kMaxAbsWeight)
          Fail(source, line_no,
               "'" + token +
                   "' is beyond +-1e6 (the shipped networks' are within +-13): a layer's sum "
                   "of such products overflows and a cell's probability is not a number");
        const double v = *parsed;
        if (c < cols)
          w(r, c) = v;
        else
          b(r) = v;
      }
      std::string extra;
      if (s >> extra) Fail(source, line_no, "more than " + std::to_string(cols + 1) + " numbers");
    }
    net.weights_.push_back(w);
    net.biases_.push_back(b);
    expected_in = rows;
  }
  std::string rest;
  while (std::getline(in, rest)) {
    ++line_no;
    if (rest.find_first_not_of(" \t\r") != std::string::npos)
      Fail(source, line_no, "unexpected text after the last layer");
  }
  return net;
}

BinaryScore ScoreProbabilities(const std::vector<double>& p, const std::vector<double>& labels) {
  BinaryScore score;
  if (p.empty()) return score;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double q = std::clamp(p[i], 1e-6, 1.0 - 1e-6);
    score.cross_entropy -= labels[i] * std::log(q) + (1.0 - labels[i]) * std::log(1.0 - q);
    score.accuracy += ((q >= 0.5) == (labels[i] >= 0.5)) ? 1.0 : 0.0;
  }
  score.cross_entropy /= static_cast<double>(p.size());
  score.accuracy /= static_cast<double>(p.size());
  return score;
}

}  // namespace plywood::perception
