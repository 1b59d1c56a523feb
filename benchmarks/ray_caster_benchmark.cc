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

void BM_GridRayCaster2DOffice(benchmark::State& state) {
  const std::string world = (DataRoot() / "worlds" / "office.xml").string();
  char error[1000] = "";
  mjModel* model = mj_loadXML(world.c_str(), nullptr, error, sizeof(error));
  if (model == nullptr) throw std::runtime_error(world + ": " + error);
  mjData* data = mj_makeData(model);
  mj_forward(model, data);
  {
    const GridRayCaster2D caster(model, data);
    // 361 beams over 180 deg from the corridor (spawn_0 of office.xml), 8 m range like an LMS 200.
    const Eigen::Vector3d origin(-6.5, 0.0, 0.3);
    RayHit hit;
    long hits = 0;
    for (auto _ : state) {
      for (int i = 0; i < 361; ++i) {
        const double a = -std::numbers::pi / 2 + i * std::numbers::pi / 360;
        hits += caster.Cast(origin, Eigen::Vector3d(std::cos(a), std::sin(a), 0.0), 8.0, &hit);
      }
    }
    benchmark::DoNotOptimize(hits);
    state.SetItemsProcessed(state.iterations() * 361);
  }
  mj_deleteData(data);
  mj_deleteModel(model);
}
BENCHMARK(BM_GridRayCaster2DOffice);

// The same scan as one fan (what PlanarScan casts since the sixth round of docs/performance.md):
// one set-up for the 361 beams, no normals.
void BM_GridRayCaster2DOfficeFan(benchmark::State& state) {
  const std::string world = (DataRoot() / "worlds" / "office.xml").string();
  char error[1000] = "";
  mjModel* model = mj_loadXML(world.c_str(), nullptr, error, sizeof(error));
  if (model == nullptr) throw std::runtime_error(world + ": " + error);
  mjData* data = mj_makeData(model);
  mj_forward(model, data);
  {
    const GridRayCaster2D caster(model, data);
    const Eigen::Vector3d origin(-6.5, 0.0, 0.3);
    std::vector<Eigen::Vector3d> dirs;
    for (int i = 0; i < 361; ++i) {
      const double a = -std::numbers::pi / 2 + i * std::numbers::pi / 360;
      dirs.emplace_back(std::cos(a), std::sin(a), 0.0);
    }
    std::vector<RayHit> hits(dirs.size());
    std::unique_ptr<bool[]> found(new bool[dirs.size()]);
    long count = 0;
    for (auto _ : state) {
      caster.CastFanWithoutNormal(origin, dirs.data(), 361, 8.0, hits.data(), found.get());
      count += found[180];
    }
    benchmark::DoNotOptimize(count);
    state.SetItemsProcessed(state.iterations() * 361);
  }
  mj_deleteData(data);
  mj_deleteModel(model);
}
BENCHMARK(BM_GridRayCaster2DOfficeFan);

}  // namespace
}  // namespace plywood::sim
