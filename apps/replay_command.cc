#include "apps/replay_command.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "apps/command_line.h"
#include "perception/lines/line_extractor_factory.h"
#include "perception/logs/carmen_log.h"
#include "perception/logs/log_replay.h"
#include "render/overlay.h"
#include "render/png_image.h"
#include "render/world_to_pixel.h"
#include "sim/config/lines_config.h"
#include "sim/config/yaml_fields.h"
#include "sim/runner/metrics.h"

namespace plywood::apps {

int ReplayCommand(const std::vector<std::string>& args) {
  const CommandLine line(args, {"--extractor", "--out", "--set"}, {"--skip-bad"});
  if (line.positional().size() != 1) {
    throw UsageError{
        "usage: plywood replay LOG --extractor NAME [--out DIR] [--skip-bad] "
        "[--set EXTRACTOR.KEY=VALUE]..."};
  }
  const std::filesystem::path log_path = line.positional()[0];
  const std::string name = line.Value("--extractor").value_or("split_and_merge");
  // Extractor options as in an experiment's `lines:` section, e.g.
  // --set split_and_merge.min_points=5 (ConfigError naming the key: exit 2).
  YAML::Node lines_node(YAML::NodeType::Map);
  for (const std::string& assignment : line.Values("--set")) {
    sim::ApplyOverride(lines_node, assignment, "--set " + assignment);
  }
  sim::LinesConfig lines;
  sim::ReadLinesConfig(sim::YamlFields(lines_node, "--set", ""), lines);
  const auto extractor = perception::MakeLineExtractor(name, lines.options);  // exit 2 if bad
  if (!std::filesystem::is_regular_file(log_path)) {
    throw std::invalid_argument(log_path.string() + ": no such log file");
  }
  perception::CarmenReadOptions read_options;
  read_options.skip_bad = line.Switch("--skip-bad");
  perception::CarmenLog log;
  try {
    log = perception::ReadCarmenLog(log_path, read_options);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // a malformed log is bad input: one line, exit 2
  }
  const std::filesystem::path out_dir =
      line.Value("--out").value_or("runs/replay-" + log_path.filename().string() + "-" + name);
  const perception::ReplayResult result = perception::ReplayLog(log, *extractor);

  std::filesystem::create_directories(out_dir);
  sim::Metrics metrics;
  metrics.Set("replay.extractor", name);
  metrics.Set("replay.scans", static_cast<double>(result.scans));
  metrics.Set("replay.skipped_lines", static_cast<double>(log.skipped_lines));
  metrics.Set("replay.valid_rays", static_cast<double>(result.rays.rays));
  metrics.Set("replay.lines", static_cast<double>(result.lines));
  metrics.Set("replay.rays_explained", result.rays.Fraction());
  metrics.Set("replay.rms_m", result.rays.RmsM());
  metrics.Set("replay.rays_per_line", result.RaysPerLine());
  metrics.Set("replay.lines_per_scan", result.LinesPerScan());
  std::ofstream(out_dir / "metrics.json") << metrics.ToJson();
  std::ofstream(out_dir / "timing.json")
      << "{\"replay\": {\"us_per_scan\": " << sim::FormatNumber(result.UsPerScan()) << "}}\n";

  // The segments of every scan, placed by the logged laser poses, on a white page.
  render::WorldBounds bounds = render::WorldBounds::Empty();
  for (const auto& [a, b] : result.segments_W) bounds.Extend(a), bounds.Extend(b);
  for (const auto& record : log.lasers)
    bounds.Extend(Eigen::Vector2d(record.X_WL.x_m, record.X_WL.y_m));
  if (!bounds.IsEmpty() && bounds.width_m() + bounds.height_m() > 0.0) {
    const render::TopDownFrame frame = render::FrameBounds(bounds.Padded(1.0), 1600);
    render::RgbImage image(frame.width_px, frame.height_px);
    render::Fill(image, render::colours::kWhite);
    for (const auto& [a, b] : result.segments_W)
      render::DrawSegment(image, frame.world_to_pixel, a, b, render::colours::kBlue, 1.0);
    for (const auto& record : log.lasers)
      render::DrawPoint(image, frame.world_to_pixel, {record.X_WL.x_m, record.X_WL.y_m},
                        render::colours::kRed, 1.0);
    render::WritePng(image, out_dir / "segments.png");
  }

  std::printf("%-22s %s (%ld scans, %ld lines skipped)\n", "log", log_path.c_str(), result.scans,
              static_cast<long>(log.skipped_lines));
  std::printf("%-22s %s\n", "extractor", name.c_str());
  std::printf("%-22s %.4f of %ld valid rays\n", "rays explained", result.rays.Fraction(),
              result.rays.rays);
  std::printf("%-22s %.4f m\n", "rms distance", result.rays.RmsM());
  std::printf("%-22s %.1f\n", "rays per line", result.RaysPerLine());
  std::printf("%-22s %.2f\n", "lines per scan", result.LinesPerScan());
  std::printf("%-22s %.1f us (%.0f scans/s)\n", "time per scan", result.UsPerScan(),
              result.UsPerScan() > 0 ? 1e6 / result.UsPerScan() : 0.0);
  std::printf("%-22s %s\n", "results", out_dir.c_str());
  return 0;
}

}  // namespace plywood::apps
