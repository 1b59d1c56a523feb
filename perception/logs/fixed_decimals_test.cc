#include "perception/logs/fixed_decimals.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace plywood::perception {
namespace {

std::string Fast(double v, int decimals) {
  char buffer[400];
  return std::string(buffer, WriteFixedDecimals(buffer, buffer + sizeof(buffer), v, decimals));
}

std::string Reference(double v, int decimals) {
  char buffer[400];
  return std::string(
      buffer,
      std::to_chars(buffer, buffer + sizeof(buffer), v, std::chars_format::fixed, decimals).ptr);
}

void ExpectSame(double v, int decimals) {
  ASSERT_EQ(Fast(v, decimals), Reference(v, decimals))
      << "value " << std::hexfloat << v << " decimals " << decimals;
}

// printf's own rounding of the same value, as the comparison's anchor.
TEST(WriteFixedDecimalsTest, MatchesPrintfOnKnownCases) {
  for (const double v : {0.0, -0.0, 0.0625, 0.1875, 2.5, 3.5, -2.5, 0.0005, 0.0015, 1.0005, -0.0004,
                         7.9995, 8.0, 123456.789, 1e-320, -1e-320}) {
    for (const int decimals : {0, 1, 3, 6, 9}) {
      char expected[400];
      std::snprintf(expected, sizeof(expected), "%.*f", decimals, v);
      EXPECT_EQ(Fast(v, decimals), expected) << v << " " << decimals;
    }
  }
}

// Exact ties (values k / 2^m that are a half at the last decimal), their neighbours one ulp
// either side, and the halves of every decimal in a range around them.
TEST(WriteFixedDecimalsTest, TiesAndTheirNeighboursMatchToChars) {
  for (int decimals = 0; decimals <= 9; ++decimals) {
    const double scale = std::pow(10.0, decimals);
    for (int k = 0; k < 20000; ++k) {
      for (const double base : {(k + 0.5) / scale, k / 1024.0, k / 65536.0, (k + 0.5) / 64.0}) {
        for (const double v : {base, std::nextafter(base, 0.0), std::nextafter(base, 1e300)}) {
          ExpectSame(v, decimals);
          ExpectSame(-v, decimals);
        }
      }
    }
  }
}

TEST(WriteFixedDecimalsTest, RandomValuesOfEveryMagnitudeMatchToChars) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> exponent(-60, 60);
  for (int i = 0; i < 400000; ++i) {
    const double v = std::ldexp(unit(rng), exponent(rng)) * (i % 2 ? -1.0 : 1.0);
    ExpectSame(v, i % 10);
    ExpectSame(v, 3);
    ExpectSame(v, 6);
  }
  // Laser ranges as the logs carry them: metres with millimetre-scale noise.
  std::normal_distribution<double> range(4.0, 2.0);
  for (int i = 0; i < 400000; ++i) ExpectSame(range(rng), 3);
}

TEST(WriteFixedDecimalsTest, LargeAndNonFiniteValuesGoToToChars) {
  for (const double v :
       {4503599627370496.0, 1e300, std::numeric_limits<double>::max(),
        std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::quiet_NaN(), 4503599.627370497}) {
    for (const int decimals : {0, 3, 6, 9, 12, 17}) ExpectSame(v, decimals);
  }
}

}  // namespace
}  // namespace plywood::perception
