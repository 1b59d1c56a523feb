// The log-odds grid update: one 16-transducer ring through the classical (Elfes) model.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>

#include "perception/sonar_map/log_odds_grid.h"
#include "perception/sonar_map/sonar_cell_model.h"

namespace plywood::perception {
namespace {

msgs::RangeRing SixteenSonars() {
  msgs::RangeRing ring;
  ring.range_min_m = 0.1;
  ring.range_max_m = 5.0;
  for (int i = 0; i < 16; ++i) {
    const double a = i * 2.0 * std::numbers::pi / 16;
    msgs::RangeReading r;
    r.X_RS = {0.2 * std::cos(a), 0.2 * std::sin(a), a};
    r.range_m = 1.0 + 0.1 * i;
    r.echo = true;
    ring.readings.push_back(r);
  }
  return ring;
}

void BM_LogOddsIntegrateRing(benchmark::State& state) {
  LogOddsGrid grid;
  const ClassicalSonarModel model;
  const msgs::RangeRing ring = SixteenSonars();
  const msgs::Pose2D X_WR{0.1, -0.2, 0.3};
  for (auto _ : state) {
    grid.Integrate(model, ring, X_WR);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations());  // rings
}
BENCHMARK(BM_LogOddsIntegrateRing);

}  // namespace
}  // namespace plywood::perception
