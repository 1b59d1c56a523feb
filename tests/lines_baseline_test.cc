// CI gate for line extraction: with a fixed seed and realistic LMS 200 noise (the laser of
// experiments/seed000_rooms.yaml), two back-to-back lasers at the origin of each seed-000 room and
// at the office's four free spots; fails when an extractor's recall or precision falls below the
// committed baseline (tests/baselines/lines.json) minus its margin, and prints every figure.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <string>

#include "eval/lines/seed000_rooms.h"
#include "plywood_paths.h"
#include "sim/config/experiment_config.h"

namespace plywood {
namespace {

void Check(const YAML::Node& baseline, double margin, const std::string& set,
           const std::vector<eval::ExtractorScore>& scores) {
  for (const auto& s : scores) {
    const YAML::Node expected = baseline[set][s.name];
    std::printf(
        "%-7s %-16s recall %.4f precision %.4f sigma_r %.4f m sigma_alpha %.3f deg "
        "points/line %.1f (%ld scans)\n",
        set.c_str(), s.name.c_str(), s.score.Recall(), s.score.Precision(), s.score.SigmaRM(),
        s.score.SigmaAlphaDeg(), s.score.PointsPerLine(), s.score.scans);
    ASSERT_TRUE(expected.IsDefined()) << set << "." << s.name << " missing from the baseline";
    EXPECT_GE(s.score.Recall(), expected["recall"].as<double>() - margin) << set << " " << s.name;
    EXPECT_GE(s.score.Precision(), expected["precision"].as<double>() - margin)
        << set << " " << s.name;
  }
}

TEST(LinesBaselineTest, RecallAndPrecisionDoNotWorsen) {
  const std::string root = PLYWOOD_SOURCE_ROOT;
  const YAML::Node baseline = YAML::LoadFile(root + "/tests/baselines/lines.json");
  const double margin = baseline["margin"].as<double>();
  const int scans = baseline["scans"].as<int>();
  const sim::ExperimentConfig config = sim::LoadExperimentConfig(
      root + "/experiments/seed000_rooms.yaml", {"seed=" + baseline["seed"].as<std::string>()});

  // The four seed-000 rooms at their paper range cuts.
  std::vector<eval::ExtractorScore> rooms;
  for (const auto& room : eval::ReadSeed000RoomsOptions(config).rooms) {
    const auto result = eval::RunSeed000Room(config, room, scans);
    if (rooms.empty()) {
      rooms = result.scores;
    } else {
      for (std::size_t e = 0; e < rooms.size(); ++e) rooms[e].score.Add(result.scores[e].score);
    }
  }
  Check(baseline, margin, "rooms", rooms);

  // The office (tables, legs, columns, doors) at its free spots, the full 8 m range.
  sim::ExperimentConfig office = config;
  office.world = "worlds/office.xml";
  office.world_path = root + "/worlds/office.xml";
  std::vector<eval::TruthScan> office_scans;
  for (const auto& spot : baseline["office_spots"]) {
    const auto rig =
        eval::TakeBackToBackScans(office, {spot[0].as<double>(), spot[1].as<double>()}, 0.0, scans);
    for (auto& scan : eval::MakeTruthScans(rig, office.sensors.laser->range_max_m))
      office_scans.push_back(std::move(scan));
  }
  Check(baseline, margin, "office", eval::ScoreExtractors(office_scans, config.lines));
}

}  // namespace
}  // namespace plywood
