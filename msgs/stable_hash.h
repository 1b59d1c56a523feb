#pragma once

#include <cstdint>
#include <string_view>

// Hashes whose values are part of the outputs (run seeds, generated worlds, sweep run ids), so they
// must be the same on every machine and compiler: std::hash is neither. Defined once for every
// layer.
namespace plywood {

// FNV-1a, 64 bit.
constexpr std::uint64_t Fnv1a64(std::string_view text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

// SplitMix64's finaliser: decorrelates nearby seeds.
constexpr std::uint64_t SplitMix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

static_assert(Fnv1a64("") == 0xcbf29ce484222325ULL);
static_assert(Fnv1a64("a") == 0xaf63dc4c8601ec8cULL);  // the published FNV-1a test vector

}  // namespace plywood
