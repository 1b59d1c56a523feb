// The grid ray caster on the office, as the laser uses it: horizontal rays at scan height.
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/config/robot_catalog.h"
#include "sim/raycast/grid_ray_caster_2d.h"

namespace plywood::sim {
namespace {

// office.xml loaded and forwarded once per benchmark; freed with it.
struct OfficeModel {
  OfficeModel() {
    const std::string world = (DataRoot() / "worlds" / "office.xml").string();
    char error[1000] = "";
    model = mj_loadXML(world.c_str(), nullptr, error, sizeof(error));
    if (model == nullptr) throw std::runtime_error(world + ": " + error);
    data = mj_makeData(model);
    mj_forward(model, data);
  }
  ~OfficeModel() {
    mj_deleteData(data);
    mj_deleteModel(model);
  }
  OfficeModel(const OfficeModel&) = delete;
  OfficeModel& operator=(const OfficeModel&) = delete;
  mjModel* model = nullptr;
  mjData* data = nullptr;
};

// 361 beams over 180 deg from the corridor (spawn_0 of office.xml), 8 m range like an LMS 200.
const Eigen::Vector3d kScanOrigin(-6.5, 0.0, 0.3);
constexpr int kBeams = 361;
constexpr double kRangeM = 8.0;

std::vector<Eigen::Vector3d> ScanDirections() {
  std::vector<Eigen::Vector3d> dirs;
  for (int i = 0; i < kBeams; ++i) {
    const double a = -std::numbers::pi / 2 + i * std::numbers::pi / 360;
    dirs.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  return dirs;
}

void BM_GridRayCaster2DOffice(benchmark::State& state) {
  const OfficeModel office;
  const GridRayCaster2D caster(office.model, office.data);
  const std::vector<Eigen::Vector3d> dirs = ScanDirections();
  RayHit hit;
  long hits = 0;
  for (auto _ : state) {
    for (const Eigen::Vector3d& dir : dirs) hits += caster.Cast(kScanOrigin, dir, kRangeM, &hit);
  }
  benchmark::DoNotOptimize(hits);
  state.SetItemsProcessed(state.iterations() * kBeams);
}
BENCHMARK(BM_GridRayCaster2DOffice);

// The same scan as one fan (what PlanarScan casts since the sixth round of docs/performance.md):
// one set-up for the 361 beams, no normals.
void BM_GridRayCaster2DOfficeFan(benchmark::State& state) {
  const OfficeModel office;
  const GridRayCaster2D caster(office.model, office.data);
  const std::vector<Eigen::Vector3d> dirs = ScanDirections();
  std::vector<RayHit> hits(dirs.size());
  std::unique_ptr<bool[]> found(new bool[dirs.size()]);
  long count = 0;
  for (auto _ : state) {
    caster.CastFanWithoutNormal(kScanOrigin, dirs.data(), kBeams, kRangeM, hits.data(),
                                found.get());
    count += found[kBeams / 2];
  }
  benchmark::DoNotOptimize(count);
  state.SetItemsProcessed(state.iterations() * kBeams);
}
BENCHMARK(BM_GridRayCaster2DOfficeFan);

}  // namespace
}  // namespace plywood::sim
