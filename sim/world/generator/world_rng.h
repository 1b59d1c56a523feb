#pragma once

#include <cstdint>
#include <random>
#include <string>

namespace plywood::sim::worldgen {

// The random draws of one generated world. std::mt19937_64's output sequence is fixed by the C++
// standard, the standard distributions are not (libstdc++ and libc++ map it differently), so every
// draw is mapped from the raw 64-bit output here: the same (family, seed, index) gives the same
// world with any standard library. World i's stream depends only on (family, seed, i), so the first
// ten worlds of a generation do not depend on how many are made.
class WorldRng {
 public:
  WorldRng(const std::string& family, std::uint64_t seed, std::uint64_t index);

  // [0, 1) with 53 random bits.
  double Uniform01();
  // [lo, hi).
  double Uniform(double lo, double hi);
  // A whole number in [lo, hi] (inclusive); lo, without a draw, when hi < lo.
  int Int(int lo, int hi);
  // True with probability p.
  bool Chance(double p);
  // Uniform in [lo, hi] on the grid lo + k * step (parameters as a person would write them); lo,
  // without a draw, when hi < lo.
  double Rounded(double lo, double hi, double step);

 private:
  std::mt19937_64 engine_;
};

// The stream seed of world `index` of `family` generated with `seed`: SplitMix64 over a hash of
// the three (exposed for tests).
std::uint64_t WorldStreamSeed(const std::string& family, std::uint64_t seed, std::uint64_t index);

}  // namespace plywood::sim::worldgen
