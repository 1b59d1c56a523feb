#include "sim/world/generator/world_rng.h"

#include <cmath>

#include "msgs/stable_hash.h"

namespace plywood::sim::worldgen {

std::uint64_t WorldStreamSeed(const std::string& family, std::uint64_t seed, std::uint64_t index) {
  return SplitMix64(SplitMix64(SplitMix64(Fnv1a64(family)) ^ seed) ^ index);
}

WorldRng::WorldRng(const std::string& family, std::uint64_t seed, std::uint64_t index)
    : engine_(WorldStreamSeed(family, seed, index)) {}

double WorldRng::Uniform01() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

double WorldRng::Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform01(); }

int WorldRng::Int(int lo, int hi) {
  if (hi < lo) return lo;  // an empty range: no draw
  const auto span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo + 1);
  // Multiply-shift on the top 32 bits: the bias is below 2^-32 * span, far below anything a
  // world generator can notice.
  const std::uint64_t top = engine_() >> 32;
  return lo + static_cast<int>((top * span) >> 32);
}

bool WorldRng::Chance(double p) { return Uniform01() < p; }

double WorldRng::Rounded(double lo, double hi, double step) {
  if (!(hi >= lo)) return lo;  // an empty range: no draw
  const double steps = std::floor((hi - lo) / step + 1e-9);
  return lo + step * Int(0, static_cast<int>(steps));
}

}  // namespace plywood::sim::worldgen
