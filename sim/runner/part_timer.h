#pragma once

#include <chrono>

namespace plywood::sim {

// Wall time spent in each part of a run's step loop, summed over the run (plywood bench).
struct StepPartTimes {
  double physics_s = 0.0;     // Scene::Step (mj_step)
  double laser_s = 0.0;       // laser casting and noise
  double sonar_s = 0.0;       // sonar casting and noise
  double controller_s = 0.0;  // Controller::Update
  double recording_s = 0.0;   // laser ground-truth labels, record copies, trajectory samples
  double other_s = 0.0;       // encoders, gyro, bumpers, IR, estimators
};

// Adds the wall time of its scope to `*total_s`; with a null target it reads no clock, so
// timers left in the step loop cost one branch when nobody is profiling.
class PartTimer {
 public:
  explicit PartTimer(double* total_s) : total_s_(total_s) {
    if (total_s_ != nullptr) start_ = std::chrono::steady_clock::now();
  }
  ~PartTimer() {
    if (total_s_ != nullptr) {
      *total_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    }
  }
  PartTimer(const PartTimer&) = delete;
  PartTimer& operator=(const PartTimer&) = delete;

 private:
  double* total_s_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace plywood::sim
