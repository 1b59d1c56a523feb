// Every registered line extractor on plywood bench's 361-point scan.
#include <benchmark/benchmark.h>

#include <string>

#include "eval/lines/line_bench.h"
#include "perception/lines/line_extractor_factory.h"
#include "perception/lines/scan_points.h"

namespace plywood::perception {
namespace {

void BM_LineExtractor(benchmark::State& state, const std::string& name) {
  const ScanPoints scan = MakeScanPoints(eval::LineBenchScan(), ScanFilter{});
  const auto extractor = MakeLineExtractor(name);
  for (auto _ : state) {
    auto lines = extractor->Extract(scan);
    benchmark::DoNotOptimize(lines);
  }
  state.SetItemsProcessed(state.iterations());  // scans
}

// Registered at start-up so a new extractor is benchmarked without editing this file.
const bool registered = [] {
  for (const std::string& name : LineExtractorNames()) {
    benchmark::RegisterBenchmark(("BM_LineExtractor/" + name).c_str(), BM_LineExtractor, name);
  }
  return true;
}();

}  // namespace
}  // namespace plywood::perception
