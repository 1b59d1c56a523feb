#include "eval/single_run_protocol.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <system_error>
#include <thread>

#include "eval/geometric_map/geometric_map_run.h"
#include "eval/lines/line_scan_scorer.h"
#include "eval/lines/lines_csv.h"
#include "eval/printed_figure.h"
#include "eval/sonar_map/sonar_map_scorer.h"
#include "render/async_snapshot_writer.h"
#include "render/offscreen_context.h"
#include "render/overlay.h"
#include "sim/runner/experiment_runner.h"
#include "sim/runner/out_of_memory.h"
#include "sim/runner/run_writer.h"
#include "sim/runner/sensor_log_stream.h"
#include "sim/runner/text_file.h"

namespace plywood::eval {
namespace {

std::vector<render::PathOverlay> TrajectoryOverlays(const sim::RunRecord& record) {
  std::vector<render::PathOverlay> paths(1 + record.estimator_names.size());
  paths[0].label = "ground truth";
  paths[0].colour = render::colours::kBlack;
  paths[0].width_px = 3.0;
  for (std::size_t e = 0; e < record.estimator_names.size(); ++e) {
    paths[e + 1].label = record.estimator_names[e];
    paths[e + 1].colour = render::colours::kPalette[e % std::size(render::colours::kPalette)];
  }
  for (const auto& sample : record.trajectory) {
    paths[0].points_W.emplace_back(sample.truth.x_m, sample.truth.y_m);
    for (std::size_t e = 0; e < sample.estimates.size(); ++e) {
      paths[e + 1].points_W.emplace_back(sample.estimates[e].x_m, sample.estimates[e].y_m);
    }
  }
  return paths;
}

void PrintSummary(const sim::ExperimentRunner& runner) {
  const sim::RunCost& cost = runner.cost();
  const sim::Metrics& m = runner.record().metrics;
  std::printf("\n%-34s %s\n", "experiment", runner.config().name.c_str());
  std::printf("%-34s %.2f s in %.2f s wall (%.0fx real time), %ld rays\n", "simulated",
              cost.simulated_s, cost.wall_s, cost.RealTimeFactor(), cost.rays);
  std::printf("%-34s %.3f m\n", "distance travelled (truth)", m.Number("truth.distance_m"));
  for (const auto& name : runner.record().estimator_names) {
    const std::string key = "odometry." + name + ".";
    // metrics.json's null (the truth travelled less than 1 cm) is printed as null, not nan.
    const double drift = m.Number(key + "drift_percent");
    char drift_text[64] = "null (travelled < 1 cm)";
    if (std::isfinite(drift)) std::snprintf(drift_text, sizeof drift_text, "%.2f %%", drift);
    std::printf("%-34s final %.3f m, heading %.2f deg, drift %s, ATE %.3f m\n", name.c_str(),
                m.Number(key + "final_error_m"), m.Number(key + "heading_error_deg"), drift_text,
                m.Number(key + "ate_rms_m"));
  }
  if (m.values().count("occupancy.error")) {
    std::printf(
        "%-34s e %.4f (grid %.4f), %.0f partitions, graph %.0f nodes / %.0f arcs%s\n",
        "cognitive map (seed 001)", m.Number("occupancy.error"), m.Number("occupancy.grid_error"),
        m.Number("occupancy.partitions"), m.Number("occupancy.graph_nodes"),
        m.Number("occupancy.graph_edges"),
        m.Number("occupancy.explored") > 0.0 ? "" : " (time limit before the map was complete)");
  }
  if (m.values().count("geometric_map.recall")) {
    std::printf(
        "%-34s recall %.3f, precision %.3f, endpoint error %s, %.0f segments, %.0f "
        "clusters, IR-invisible %.0f/%.0f\n",
        "geometric map (seed 003)", m.Number("geometric_map.recall"),
        m.Number("geometric_map.precision"),
        PrintedFigure(m.Number("geometric_map.endpoint_error_m"), "%.3f", "m").c_str(),
        m.Number("geometric_map.segments"), m.Number("geometric_map.clusters"),
        m.Number("geometric_map.ir_invisible_mapped"),
        m.Number("geometric_map.ir_invisible_geoms"));
    std::printf("%-34s corrected %.2f deg / %.3f m, odometry %.2f deg / %.3f m (final)\n",
                "geometric map pose error",
                m.Number("geometric_map.pose.corrected.final_heading_error_deg"),
                m.Number("geometric_map.pose.corrected.final_position_error_m"),
                m.Number("geometric_map.pose.odometry.final_heading_error_deg"),
                m.Number("geometric_map.pose.odometry.final_position_error_m"));
  }
  if (m.values().count("sensors.bumpers.contact_samples")) {
    std::printf("%-34s %.0f\n", "bumper contact samples",
                m.Number("sensors.bumpers.contact_samples"));
  }
}

}  // namespace

int SingleRunProtocol(const ProtocolContext& context) {
  const sim::ExperimentConfig& config = context.config;
  const std::string out_dir = context.out_dir.string();
  const bool quiet = context.quiet;
  const bool snapshots = context.snapshots;
  // The snapshot's library loads beside the scene's compile: the snapshot thread's static frame
  // (docs/performance.md, "Stop 67") then starts that much earlier and is more often done by the
  // run's last pose. Joined when the protocol returns or throws. Not under `ulimit -v`: with it,
  // runs under 400-700 MB ended in std::bad_alloc or an abort in llvmpipe's JIT ("LLVM
  // ERROR: Unable to allocate section memory") or hung, where without it every one ran (review68).
  std::optional<std::jthread> preload;
  if (snapshots && context.observer == nullptr && render::kHasOffscreenRendering &&
      sim::MemoryLimitNote().empty()) {
    try {
      preload.emplace([] { render::PreloadOffscreenLibrary(); });
    } catch (const std::system_error&) {
      // No thread to spare (a process limit): the snapshot's own thread loads the library.
    }
  }
  sim::ExperimentRunner runner(config);
  // Seed 001's ground truth, checked before the run and scored against after it.
  const auto sonar_map_truth = RequireASonarMapTruth(runner);
  runner.SetObserver(context.observer);
  render::SnapshotOptions snapshot_options;
  snapshot_options.view.longer_side_px = config.output.snapshot_size_px;
  // The snapshot's renderer gets ready on its own thread while the run goes on; with an observer
  // (viewer, video) drawing on this thread meanwhile, it starts after the run instead.
  std::optional<render::AsyncSnapshotWriter> snapshot;
  if (snapshots && context.observer == nullptr) {
    snapshot.emplace(runner.scene().model(), snapshot_options);
  }
  // The largest sensor logs are formatted on their own thread as the records come in (every
  // simulated second), so that little of them is left for after the run, when the snapshot's
  // final frame wants both cores.
  sim::SensorLogStream sensor_logs(config);
  // A live progress bar on a terminal; in logs (CI, batch) a line every 10 %.
  const bool terminal = isatty(fileno(stderr));
  int last_decile = 0;
  runner.Run([&](double fraction, double simulated_s) {
    sensor_logs.Feed(runner.record());
    if (quiet) return;
    if (terminal) {
      std::fprintf(stderr, "\r[%-30s] %5.1f%%  t = %.0f s ",
                   std::string(30 * fraction, '#').c_str(), 100.0 * fraction, simulated_s);
    } else if (static_cast<int>(10 * fraction) > last_decile) {
      last_decile = static_cast<int>(10 * fraction);
      std::fprintf(stderr, "plywood: %s %3d%% (t = %.0f s)\n", config.name.c_str(),
                   10 * last_decile, simulated_s);
    }
  });
  if (!quiet && terminal) std::fprintf(stderr, "\r%60s\r", "");

  if (snapshots) {
    if (!snapshot) snapshot.emplace(runner.scene().model(), snapshot_options);
    snapshot->Write(runner.scene().data(), TrajectoryOverlays(runner.record()),
                    out_dir + "/snapshot.png");
  }
  // After the snapshot's hand-over (the head of the chain after the run), before the scorers
  // below, which may change the record.
  const sim::FormattedSensorLogs formatted = sensor_logs.Finish(runner.record());

  AddSonarMapMetrics(runner, sonar_map_truth.get());  // seed 001 map scores, if it explored
  GeometricMapRun geometric_map;  // seed 003's map, with a geometric_map: section
  const bool has_geometric_map = AddGeometricMapMetrics(runner, &geometric_map);
  // Line extraction scores (lines: section); wall-clock time per scan goes to timing.json only.
  const std::vector<eval::ExtractorScore> line_scores = eval::AddLineMetrics(runner);
  sim::WriteRunOutputs(config, runner.record(), out_dir, &formatted);
  WriteSonarMap(runner, out_dir);
  if (snapshots) WriteSonarMapPictures(runner, out_dir);
  if (has_geometric_map) {
    WriteGeometricMapJson(geometric_map, out_dir);
    if (snapshots) WriteGeometricMapPicture(runner, geometric_map, out_dir);
  }
  if (snapshot) snapshot->Finish();
  if (!line_scores.empty()) {
    sim::WriteTextFile(context.out_dir / "timing.json", eval::LineTimingJson(line_scores));
    WriteLinesCsv(context.out_dir / "lines.csv", LinesCsvRows(line_scores));
    WriteCirclesCsv(context.out_dir / "circles.csv", line_scores);
  }
  if (!quiet) PrintSummary(runner);
  if (!quiet) {
    for (const auto& s : line_scores) {
      std::printf(
          "%-34s recall %.3f, precision %.3f, sigma_r %s, sigma_alpha %s, "
          "%s, %.1f us/scan\n",
          ("lines " + s.name).c_str(), s.score.Recall(), s.score.Precision(),
          PrintedFigure(s.score.SigmaRM(), "%.4f", "m").c_str(),
          PrintedFigure(s.score.SigmaAlphaDeg(), "%.3f", "deg").c_str(),
          (std::isfinite(s.score.PointsPerLine())
               ? PrintedFigure(s.score.PointsPerLine(), "%.1f") + " points/line"
               : std::string("points/line null"))
              .c_str(),
          s.us_per_scan);
    }
  }
  return 0;
}

}  // namespace plywood::eval
