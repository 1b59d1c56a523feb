#include "sim/sensors/noise_draws.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace plywood::sim {
namespace {

// An engine of 64 bits that always returns one value: the edges of the [0, 1) mapping.
struct FixedEngine {
  using result_type = std::uint64_t;
  static constexpr result_type min() { return 0; }
  static constexpr result_type max() { return std::numeric_limits<result_type>::max(); }
  result_type operator()() { return value; }
  result_type value = 0;
};

TEST(NoiseDrawsTest, UnitUniformScalesTheDrawAndStaysBelowOne) {
  FixedEngine engine;
  EXPECT_EQ(UnitUniform(engine), 0.0);
  engine.value = std::uint64_t{1} << 63;
  EXPECT_EQ(UnitUniform(engine), 0.5);
  // 2^64 - 1 rounds to 2^64 as a double: the draw would be 1, which [0, 1) excludes.
  engine.value = FixedEngine::max();
  EXPECT_EQ(UnitUniform(engine), std::nextafter(1.0, 0.0));
  EXPECT_LT(UnitUniform(engine), 1.0);
}

// The same seed gives these numbers with any standard library (std::mt19937_64's sequence is
// fixed by the standard; the mapping is ours). Values from libstdc++'s distributions, which made
// every output before the mapping was written out.
TEST(NoiseDrawsTest, SeedFortyTwoGivesTheRecordedDraws) {
  std::mt19937_64 engine(42);
  EXPECT_EQ(UnitUniform(engine), 0x1.82a3befaddcbcp-1);
  EXPECT_EQ(UnitUniform(engine), 0x1.472f1f73724ap-1);
  EXPECT_EQ(UnitUniform(engine), 0x1.81192cfe1cbcfp-1);
  NormalDraws normal;
  EXPECT_EQ(normal(engine), 0x1.4421e89b91959p-3);
  EXPECT_EQ(normal(engine), -0x1.b91cda61a7305p-1);  // the kept second value of the pair
  EXPECT_EQ(normal(engine), -0x1.698cdcd7b017fp+0);
}

#if defined(__GLIBCXX__)
// Bit for bit what libstdc++'s distributions give, interleaved as the laser draws them (a normal
// value, then a uniform), with a scale and a mean, and with a new NormalDraws per "scan" as the
// laser makes a new std::normal_distribution per scan.
TEST(NoiseDrawsTest, SameBitsAsLibstdcxxDistributions) {
  std::mt19937_64 ours(7), theirs(7);
  for (int scan = 0; scan < 200; ++scan) {
    NormalDraws normal;
    std::normal_distribution<double> std_normal(0.25, 0.01);
    std::uniform_real_distribution<double> std_uniform(0.0, 1.0);
    for (int beam = 0; beam < 181; ++beam) {
      ASSERT_EQ(normal(ours, 0.25, 0.01), std_normal(theirs)) << scan << " " << beam;
      ASSERT_EQ(UnitUniform(ours), std_uniform(theirs)) << scan << " " << beam;
      ASSERT_EQ(UnitUniform(ours), (std::generate_canonical<double, 53>(theirs)));
    }
  }
  NormalDraws unit;
  std::normal_distribution<double> std_unit(0.0, 1.0);
  for (int i = 0; i < 100000; ++i) ASSERT_EQ(unit(ours), std_unit(theirs)) << i;
}
#else
TEST(NoiseDrawsTest, SameBitsAsLibstdcxxDistributions) {
  GTEST_SKIP() << "built without libstdc++: the recorded draws above stand for it";
}
#endif

TEST(NoiseDrawsTest, MomentsAreThoseOfTheDistributions) {
  std::mt19937_64 engine(3);
  NormalDraws normal;
  const int n = 200000;
  double sum_u = 0.0, sum_z = 0.0, sum_z2 = 0.0;
  for (int i = 0; i < n; ++i) {
    sum_u += UnitUniform(engine);
    const double z = normal(engine, 2.0, 0.5);
    sum_z += z;
    sum_z2 += (z - 2.0) * (z - 2.0);
  }
  // Within 5 standard errors: uniform mean 1/2 (sd 1/sqrt(12)); normal mean 2, variance 0.25
  // (the variance of a squared normal's mean is 2 sigma^4 / n).
  EXPECT_NEAR(sum_u / n, 0.5, 5.0 * std::sqrt(1.0 / 12.0 / n));
  EXPECT_NEAR(sum_z / n, 2.0, 5.0 * 0.5 / std::sqrt(n));
  EXPECT_NEAR(sum_z2 / n, 0.25, 5.0 * std::sqrt(2.0 / n) * 0.25);
}

}  // namespace
}  // namespace plywood::sim
