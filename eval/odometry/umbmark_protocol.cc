#include "eval/odometry/umbmark_protocol.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "eval/odometry/umbmark_experiment.h"
#include "sim/config/experiment_config.h"
#include "sim/runner/run_writer.h"
#include "sim/runner/text_file.h"

namespace plywood::eval {
namespace {

std::string RunsCsv(const eval::UmbmarkOutcome& outcome) {
  std::string csv = "stage,direction,run,error_x_m,error_y_m\n";
  const auto add = [&](const char* stage, const eval::UmbmarkStage& s) {
    int cw = 0, ccw = 0;
    for (const auto& run : s.runs) {
      const bool is_cw = run.direction == robot::SquareDirection::kClockwise;
      csv += std::string(stage) + "," + std::string(robot::ToString(run.direction)) + "," +
             std::to_string(is_cw ? ++cw : ++ccw) + "," + sim::FormatNumber(run.error_x_m) + "," +
             sim::FormatNumber(run.error_y_m) + "\n";
    }
  };
  add("before", outcome.before);
  add("after", outcome.after);
  return csv;
}

}  // namespace

void CheckUmbmarkOptions(const sim::ExperimentConfig& config) { eval::ReadUmbmarkOptions(config); }

int UmbmarkProtocol(const ProtocolContext& context) {
  const sim::ExperimentConfig& config = context.config;
  const eval::UmbmarkOptions options = eval::ReadUmbmarkOptions(config);
  // Fail on a config that cannot drive UMBmark before any run.
  const std::filesystem::path out = context.out_dir;
  int done = 0;
  const int total = 2 * options.runs_per_direction * (options.correct ? 2 : 1);
  const eval::UmbmarkOutcome outcome =
      eval::RunUmbmark(config, options,
                       [&](const std::string& stage, const std::string& name,
                           const sim::ExperimentConfig& run, const sim::RunRecord& record) {
                         if (options.write_runs)
                           sim::WriteRunOutputs(run, record, out / stage / name);
                         ++done;
                         if (!context.quiet) {
                           std::fprintf(stderr, "plywood: umbmark %s %s done (%d/%d)\n",
                                        stage.c_str(), name.c_str(), done, total);
                         }
                       });
  std::filesystem::create_directories(out);
  sim::WriteTextFile(out / "config.yaml", sim::ExperimentConfigToYaml(config));
  sim::WriteTextFile(out / "metrics.json", outcome.metrics.ToJson());
  sim::WriteTextFile(out / "umbmark_runs.csv", RunsCsv(outcome));
  if (!context.quiet) {
    const auto& b = outcome.before.result;
    std::printf("\n%-34s %s (%d + %d squares of %.1f m, steered by %s)\n", "UMBmark",
                config.name.c_str(), b.runs_cw, b.runs_ccw, config.controller.square_path.side_m,
                config.controller.steer_by.c_str());
    std::printf("%-34s cw (%.4f, %.4f) m, ccw (%.4f, %.4f) m\n", "centres of gravity before",
                b.x_cg_cw_m, b.y_cg_cw_m, b.x_cg_ccw_m, b.y_cg_ccw_m);
    std::printf("%-34s %.4f m\n", "E_max,syst before", b.e_max_syst_m);
    std::printf("%-34s alpha %.4f deg, beta %.4f deg\n", "errors",
                b.alpha_rad * 180.0 / 3.141592653589793, b.beta_rad * 180.0 / 3.141592653589793);
    std::printf("%-34s E_d %.5f, E_b %.5f\n", "measured", b.ed, b.eb);
    std::printf("%-34s wheel_diameter_ratio %.5f, track_ratio %.5f\n", "corrected calibration",
                outcome.corrected.wheel_diameter_ratio, outcome.corrected.track_ratio);
    const auto& t = outcome.before.turn_calibration;
    std::printf("%-34s %d turns, mean error %.3f deg (sigma %.3f), track ratio %.5f\n",
                "turn calibration (seed 001)", t.turns, t.mean_error_deg, t.error_sigma_deg,
                t.track_ratio);
    if (options.correct) {
      const auto& a = outcome.after.result;
      std::printf("%-34s cw (%.4f, %.4f) m, ccw (%.4f, %.4f) m\n", "centres of gravity after",
                  a.x_cg_cw_m, a.y_cg_cw_m, a.x_cg_ccw_m, a.y_cg_ccw_m);
      std::printf("%-34s %.4f m (%.1fx smaller)\n", "E_max,syst after", a.e_max_syst_m,
                  a.e_max_syst_m > 0 ? b.e_max_syst_m / a.e_max_syst_m : 0.0);
    }
  }
  return 0;
}

}  // namespace plywood::eval
