#include "sim/world/generator/world_rng.h"

#include <cmath>

namespace plywood::sim::worldgen {
namespace {

std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// FNV-1a: a stable hash of the family's name (std::hash is not stable across libraries).
std::uint64_t Fnv1a(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return h;
}

}  // namespace

std::uint64_t WorldStreamSeed(const std::string& family, std::uint64_t seed, std::uint64_t index) {
  return SplitMix64(SplitMix64(SplitMix64(Fnv1a(family)) ^ seed) ^ index);
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
