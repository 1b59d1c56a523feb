#include "eval/lines/line_bench.h"

#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include "perception/lines/line_extractor_factory.h"
#include "perception/lines/ray_polygon.h"

namespace plywood::eval {
msgs::LaserScan LineBenchScan() {
  const std::vector<Eigen::Vector2d> corners{{-1.0, -1.2}, {3.0, -1.2}, {3.0, 0.8},
                                             {1.2, 0.8},   {1.2, 2.5},  {-1.0, 2.5}};
  msgs::LaserScan scan;
  scan.angle_min_rad = -std::numbers::pi / 2;
  scan.angle_increment_rad = std::numbers::pi / 360;
  scan.range_max_m = 8.0;
  std::mt19937_64 rng(1);
  std::normal_distribution<double> noise(0.0, 0.01);
  for (int i = 0; i < 361; ++i) {
    const double a = scan.BeamAngleRad(i);
    const Eigen::Vector2d d(std::cos(a), std::sin(a));
    const double best = perception::RayToPolygonM(d, corners, 8.0);
    scan.ranges_m.push_back(best + noise(rng));
  }
  return scan;
}

LineExtractorBench MeasureLineExtractors(double seconds_per_extractor) {
  const perception::ScanPoints scan =
      perception::MakeScanPoints(LineBenchScan(), perception::ScanFilter{});
  LineExtractorBench bench;
  bench.scan_points = scan.size();
  for (const std::string& name : perception::LineExtractorNames()) {
    const auto extractor = perception::MakeLineExtractor(name);
    std::size_t lines = 0;
    long scans = 0;
    const auto start = std::chrono::steady_clock::now();
    double elapsed = 0.0;
    while (elapsed < seconds_per_extractor) {
      for (int k = 0; k < 20; ++k, ++scans) lines += extractor->Extract(scan).size();
      elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    bench.extractors.push_back(
        {name, scans / elapsed, static_cast<double>(lines) / static_cast<double>(scans)});
  }
  return bench;
}

}  // namespace plywood::eval
