#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace plywood::sim {

// The sensors' noise draws. The C++ standard fixes std::mt19937_64's output sequence but not how
// std::uniform_real_distribution or std::normal_distribution map it to numbers (libc++ and
// libstdc++ differ), so a run's noise, and with it every output, depended on the standard library.
// The mapping is written out here instead, with the arithmetic of libstdc++ (GCC 12), which made
// every output so far: those keep their bytes, and the same seed now gives the same noise with any
// library (as sim/world/generator/world_rng.h does for generated worlds). Not faster: GCC folds
// libstdc++'s constants, and the engine's own work is most of a draw (callgrind, office bench).

// [0, 1) from one draw of an engine with 64 random bits (std::mt19937_64): the draw scaled by
// 2^-64, the largest double below 1 where rounding to double reaches 1 (libstdc++'s
// generate_canonical<double, 53>).
template <typename Engine>
double UnitUniform(Engine& engine) {
  static_assert(std::is_same_v<typename Engine::result_type, std::uint64_t> && Engine::min() == 0 &&
                    Engine::max() == std::numeric_limits<std::uint64_t>::max(),
                "UnitUniform needs an engine of 64 random bits");
  const double u = static_cast<double>(engine()) * 0x1p-64;
  return u < 1.0 ? u : std::nextafter(1.0, 0.0);
}

// Normal draws by Marsaglia's polar method: each accepted pair of uniforms gives two values, and
// the second is kept for the next call (libstdc++'s std::normal_distribution). A new NormalDraws
// starts without a kept value, as a new std::normal_distribution does; a sensor that made its
// distribution per scan makes a NormalDraws per scan.
class NormalDraws {
 public:
  // mean + stddev x a standard normal value (in that arithmetic, as libstdc++ computes it).
  template <typename Engine>
  double operator()(Engine& engine, double mean = 0.0, double stddev = 1.0) {
    double value;
    if (has_kept_) {
      has_kept_ = false;
      value = kept_;
    } else {
      double x, y, r2;
      do {
        x = 2.0 * UnitUniform(engine) - 1.0;
        y = 2.0 * UnitUniform(engine) - 1.0;
        r2 = x * x + y * y;
      } while (r2 > 1.0 || r2 == 0.0);
      const double scale = std::sqrt(-2.0 * std::log(r2) / r2);
      kept_ = x * scale;
      has_kept_ = true;
      value = y * scale;
    }
    return value * stddev + mean;
  }

 private:
  double kept_ = 0.0;
  bool has_kept_ = false;
};

}  // namespace plywood::sim
