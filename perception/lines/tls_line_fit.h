#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "perception/lines/line_segment.h"

namespace plywood::perception {

// Running first and second moments of a point set: O(1) to add or remove a point, O(1) to fit,
// which makes incremental extraction and merge tests cheap.
class LineMoments {
 public:
  // Inline: the extractors add every point of a scan several times (merge tests, refits).
  void Add(const Eigen::Vector2d& p) {
    if (n_ == 0) {
      origin_ = p;
      sx_ = sy_ = sxx_ = syy_ = sxy_ = 0.0;
    }
    const double x = p.x() - origin_.x(), y = p.y() - origin_.y();
    ++n_;
    sx_ += x;
    sy_ += y;
    sxx_ += x * x;
    syy_ += y * y;
    sxy_ += x * y;
  }
  void Remove(const Eigen::Vector2d& p) {
    const double x = p.x() - origin_.x(), y = p.y() - origin_.y();
    --n_;
    sx_ -= x;
    sy_ -= y;
    sxx_ -= x * x;
    syy_ -= y * y;
    sxy_ -= x * y;
  }
  int count() const { return n_; }
  // Total-least-squares line in normal form (alpha, r >= 0): minimises the sum of squared
  // perpendicular distances. Returns the residual sum of squares in *rss_m2 when given.
  // @pre count() >= 2.
  void Fit(double* alpha_rad, double* r_m, double* rss_m2 = nullptr) const;
  // Fit, and the line's unit normal: *cos_alpha and *sin_alpha are std::cos and std::sin of
  // *alpha_rad bit for bit, taken from the fit's own (cos, sin) where the normal form did not flip
  // it (a distance test then needs no second sincos); null cos_alpha / sin_alpha: Fit.
  void FitWithNormal(double* alpha_rad, double* r_m, double* cos_alpha, double* sin_alpha,
                     double* rss_m2 = nullptr) const;
  // |distance| of q from the Fit line: x cos(alpha) + y sin(alpha) - r with FitWithNormal's
  // (cos, sin), LineSegment::SignedLineDistance's arithmetic bit for bit.
  double FitDistance(const Eigen::Vector2d& q) const;

 private:
  int n_ = 0;
  // Sums relative to the first point added, so far-away points (world-frame clouds) keep
  // precision.
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  double sx_ = 0, sy_ = 0, sxx_ = 0, syy_ = 0, sxy_ = 0;
};

// A segment from `points[indices]` fitted by total least squares in normal form, with endpoints
// the projections of the extreme points along the line, and the (alpha, r) covariance.
// @pre indices.size() >= 2.
LineSegment FitSegmentTls(std::span<const Eigen::Vector2d> points, std::span<const int> indices);

// FitSegmentTls, then up to `rounds` times: drop the points farther from the line than
// max(trim_sigmas * 1.4826 * median |residual|, 1e-9 m) and refit. Removes points of a
// neighbouring wall that a distance gate let in near a corner (RANSAC, Hough, incremental), and
// leaves exact points exact.
LineSegment FitSegmentTrimmed(std::span<const Eigen::Vector2d> points, std::vector<int> indices,
                              double trim_sigmas = 3.0, int rounds = 2);

// Seed 003's modal filter (Skrzypczynski & Wozniak 1994), in normal form so vertical lines work:
// directions of point pairs `pair_step` apart are histogrammed in bins of `bin_deg`; the mode
// (with its two neighbouring bins) gives the direction as the mean of its pairs; r is the mean of
// p . n over the points of those pairs. Robust to single outliers, which pull a least-squares fit.
struct ModalFitOptions {
  int pair_step = 3;
  double bin_deg = 2.0;
  void Validate() const;
};
LineSegment FitSegmentModal(std::span<const Eigen::Vector2d> points, std::span<const int> indices,
                            const ModalFitOptions& options);

// Largest perpendicular distance of points[indices] from the line (alpha, r).
double MaxLineDistance(std::span<const Eigen::Vector2d> points, std::span<const int> indices,
                       double alpha_rad, double r_m);
// Whether MaxLineDistance(points, indices, alpha, r) <= max_distance_m (>= 0), with the line's
// (cos alpha, sin alpha) given (LineMoments::FitWithNormal): the same distances, and it stops at
// the first point farther than max_distance_m.
bool WithinLineDistance(std::span<const Eigen::Vector2d> points, std::span<const int> indices,
                        double cos_alpha, double sin_alpha, double r_m, double max_distance_m);

}  // namespace plywood::perception
