#pragma once

#include <cstdint>

namespace plywood::sim {

// Decides when a sensor sampled at `rate_hz` is due on the simulator's fixed-step clock. Sample k
// is due at the first step whose time satisfies t >= k / rate_hz (k = 0, 1, 2, ...), so samples
// never drift however rate and step relate (a 3 Hz sonar on a 10 ms clock fires at steps 0, 34,
// 67, 100, ...: every sample on the first step at or after its ideal time).
//
// The comparison allows a relative slack of 1e-9 * max(1 s, t) because MuJoCo's time is a running
// sum of timesteps (0.1 arrives as 0.09999999999999999); this is far below any real step.
// A rate faster than the clock cannot be met: one sample per step is taken and the samples whose
// times have already passed are skipped, not queued.
class SensorSchedule {
 public:
  // @throws std::invalid_argument "rate_hz: ..." unless rate_hz is finite and > 0.
  explicit SensorSchedule(double rate_hz);

  // True when a sample is due at `time_s`; the caller then takes it. Advances to the next sample.
  bool Due(double time_s);

  // Starts again from sample 0 (due at t = 0), e.g. after the simulation is reset.
  void Reset() { next_sample_ = 0; }

  double rate_hz() const { return rate_hz_; }
  // Index of the next sample and its ideal time (s).
  std::int64_t next_sample() const { return next_sample_; }
  double NextTimeS() const { return static_cast<double>(next_sample_) / rate_hz_; }

 private:
  double rate_hz_;
  std::int64_t next_sample_ = 0;
};

}  // namespace plywood::sim
