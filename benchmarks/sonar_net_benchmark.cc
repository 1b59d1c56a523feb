// The sonar interpretation net's forward pass (seed 001's 5 inputs, default 16,16 hidden).
#include <benchmark/benchmark.h>

#include "perception/sonar_map/sonar_net.h"

namespace plywood::perception {
namespace {

void BM_SonarNetForward(benchmark::State& state) {
  const SonarNet net({16, 16}, 1);
  Eigen::Matrix<double, 5, 1> x;
  x << 0.3, 0.5, 0.7, -0.2, 0.4;
  for (auto _ : state) {
    double p = net.Forward(x);
    benchmark::DoNotOptimize(p);
    x[0] = p;  // depend on the last answer so the call cannot be hoisted
  }
}
BENCHMARK(BM_SonarNetForward);

}  // namespace
}  // namespace plywood::perception
