#pragma once

#include <cmath>

namespace plywood::testing {

// Running mean and population standard deviation of samples, for the noise tests.
class SampleStats {
 public:
  void Add(double x) {
    sum_ += x;
    sum_sq_ += x * x;
    ++count_;
  }
  int count() const { return count_; }
  double Mean() const { return sum_ / count_; }
  double Sigma() const {
    const double mean = Mean();
    return std::sqrt(sum_sq_ / count_ - mean * mean);
  }

 private:
  double sum_ = 0.0;
  double sum_sq_ = 0.0;
  int count_ = 0;
};

}  // namespace plywood::testing
