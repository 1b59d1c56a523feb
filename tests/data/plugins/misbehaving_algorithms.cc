// A plug-in whose line extractors break their contract, for tests/plugin_errors_test.cc:
// `nan_lines` returns one segment of NaN per scan, `throwing_lines` throws an int.
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "perception/lines/line_extractor.h"
#include "perception/plugins/plugin.h"

namespace {

using plywood::perception::LineSegment;
using plywood::perception::ScanPoints;

class NanLines : public plywood::perception::LineExtractor {
 public:
  std::string name() const override { return "nan_lines"; }
  std::vector<LineSegment> Extract(const ScanPoints&) const override {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    LineSegment s;
    s.alpha_rad = s.r_m = nan;
    s.start = s.end = Eigen::Vector2d(nan, nan);
    s.num_points = 5;
    return {s};
  }
};

class ThrowingLines : public plywood::perception::LineExtractor {
 public:
  std::string name() const override { return "throwing_lines"; }
  std::vector<LineSegment> Extract(const ScanPoints&) const override { throw 42; }
};

}  // namespace

PLYWOOD_PLUGIN(registry) {
  registry.line_extractors.Add({"nan_lines", [](const plywood::robot::ParameterMap&) {
                                  return std::make_unique<NanLines>();
                                }});
  registry.line_extractors.Add({"throwing_lines", [](const plywood::robot::ParameterMap&) {
                                  return std::make_unique<ThrowingLines>();
                                }});
}
