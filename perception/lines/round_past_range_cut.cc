#include "perception/lines/round_past_range_cut.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "perception/lines/end_point_fit.h"

namespace plywood::perception {
namespace {

// Beams of a full turn for a closed scan (beam indices wrap), else none.
int TurnBeams(const ScanPoints& scan) {
  if (!scan.closed || scan.angle_increment_rad == 0.0) return 0;
  return static_cast<int>(std::lround(2.0 * std::numbers::pi / std::abs(scan.angle_increment_rad)));
}

// The returns past the cut on the consecutive beams next to point `from`, walking by `step` (-1
// or +1), nearest first (indices into scan.beyond_cut_*). The walk stops at a beam without such a
// return or at a jump wider than `max_jump_m` (always a breakpoint). When it stops at a beam
// whose return lies inside the cut, that point is `*inside` (else -1).
std::vector<int> BeyondCutRun(const ScanPoints& scan, int from, int step, double max_jump_m,
                              int* inside) {
  std::vector<int> run;
  *inside = -1;
  const std::vector<int>& beams = scan.beyond_cut_beam_index;
  const int turn = TurnBeams(scan);
  const int count = static_cast<int>(beams.size());
  Eigen::Vector2d previous = scan.points[from];
  for (int want = scan.beam_index[from] + step; static_cast<int>(run.size()) < count;
       want += step) {
    int b = want;
    if (turn > 0) b = ((b % turn) + turn) % turn;
    const auto it = std::lower_bound(beams.begin(), beams.end(), b);
    if (it == beams.end() || *it != b) {
      if (run.empty()) break;
      const auto own = std::lower_bound(scan.beam_index.begin(), scan.beam_index.end(), b);
      if (own != scan.beam_index.end() && *own == b) {
        *inside = static_cast<int>(own - scan.beam_index.begin());
      }
      break;
    }
    const int k = static_cast<int>(it - beams.begin());
    const double r = scan.beyond_cut_range_m[k], bearing = scan.beyond_cut_bearing_rad[k];
    const Eigen::Vector2d p(r * std::cos(bearing), r * std::sin(bearing));
    if ((p - previous).norm() > max_jump_m) break;
    run.push_back(k);
    previous = p;
  }
  return run;
}

}  // namespace

void RemoveRoundObjectsPastRangeCut(const ScanPoints& scan, const BreakpointOptions& breakpoints,
                                    double split_threshold_m, const RoundObjectOptions& options,
                                    const std::vector<int>& group,
                                    std::vector<std::vector<int>>* lines) {
  if (!options.reject_round_objects || scan.beyond_cut_beam_index.empty() || lines->empty() ||
      group.empty() || !scan.HasScanOrder()) {
    return;
  }
  int inside_before = -1, inside_after = -1;
  const std::vector<int> before =
      BeyondCutRun(scan, group.front(), -1, breakpoints.max_m, &inside_before);
  const std::vector<int> after =
      BeyondCutRun(scan, group.back(), +1, breakpoints.max_m, &inside_after);
  if (before.empty() && after.empty()) return;
  // The extended group as a scan of its own, in beam order (beam indices unwrapped so they grow).
  ScanPoints local;
  local.angle_increment_rad = scan.angle_increment_rad;
  const int turn = TurnBeams(scan);
  int last_beam = 0;
  const auto add = [&](double r, double bearing, int beam) {
    if (!local.empty()) {
      while (beam <= last_beam && turn > 0) beam += turn;
    }
    local.Add(r, bearing, beam);
    last_beam = beam;
  };
  // A return inside the cut where a walk stopped closes the extension: the breakpoint rule says
  // whether the surface comes back inside the cut there.
  if (inside_before >= 0) {
    add(scan.range_m[inside_before], scan.bearing_rad[inside_before],
        scan.beam_index[inside_before]);
  }
  const int sentinel_before = inside_before >= 0 ? 0 : -1;
  for (auto k = before.rbegin(); k != before.rend(); ++k) {
    add(scan.beyond_cut_range_m[*k], scan.beyond_cut_bearing_rad[*k],
        scan.beyond_cut_beam_index[*k]);
  }
  const int first_own = static_cast<int>(local.size());
  for (int i : group) add(scan.range_m[i], scan.bearing_rad[i], scan.beam_index[i]);
  const int last_own = static_cast<int>(local.size()) - 1;
  for (int k : after) {
    add(scan.beyond_cut_range_m[k], scan.beyond_cut_bearing_rad[k], scan.beyond_cut_beam_index[k]);
  }
  const int sentinel_after = inside_after >= 0 ? static_cast<int>(local.size()) : -1;
  if (inside_after >= 0) {
    add(scan.range_m[inside_after], scan.bearing_rad[inside_after], scan.beam_index[inside_after]);
  }
  // The breakpoint rule decides how far the group continues past the cut.
  std::vector<int> extended;
  for (std::vector<int>& g : SplitAtBreakpoints(local, breakpoints)) {
    if (std::find(g.begin(), g.end(), first_own) != g.end()) extended = std::move(g);
  }
  if (std::find(extended.begin(), extended.end(), last_own) == extended.end()) return;
  // Past the cut the object must end at a break on both sides (its silhouette): a surface that
  // continues to returns inside the cut is no object seen whole -- a wall grazing the cut, whose
  // returns fall inside or outside it by the noise alone, looks like a cap bulging towards the
  // sensor (the inside ones are those the noise brought nearer).
  for (int sentinel : {sentinel_before, sentinel_after}) {
    if (sentinel >= 0 && std::find(extended.begin(), extended.end(), sentinel) != extended.end())
      return;
  }
  if (static_cast<int>(extended.size()) == last_own - first_own + 1) return;  // nothing past it
  std::vector<std::vector<int>> pieces =
      SplitByEndPointFit(local.points, extended, split_threshold_m,
                         /*skip_single_outliers=*/true);
  const std::vector<std::vector<int>> all = pieces;
  RemoveRoundObjects(local.points, breakpoints.sigma_m, options, &pieces);
  if (pieces.size() == all.size()) return;
  // Local points on a dropped (round) piece and on a kept one; the end-point fit may leave a
  // single outlier on neither.
  std::vector<char> on_round(local.size(), 0), on_kept(local.size(), 0);
  for (const auto& piece : all)
    for (int i : piece) on_round[i] = 1;
  for (const auto& piece : pieces)
    for (int i : piece) on_kept[i] = 1, on_round[i] = 0;
  std::vector<int> local_of(scan.size(), -1);  // a group point's index in `local`
  for (std::size_t k = 0; k < group.size(); ++k)
    local_of[group[k]] = first_own + static_cast<int>(k);
  // A line goes when all its points but at most one such outlier lie on the round object.
  std::erase_if(*lines, [&](const std::vector<int>& line) {
    int round = 0;
    for (int i : line) {
      const int j = local_of[i];
      if (j < 0 || on_kept[j]) return false;
      round += on_round[j];
    }
    return round + 1 >= static_cast<int>(line.size());
  });
}

}  // namespace plywood::perception
