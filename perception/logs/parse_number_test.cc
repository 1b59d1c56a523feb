#include "perception/logs/parse_number.h"

#include <gtest/gtest.h>

namespace plywood::perception {
namespace {

TEST(ParseFiniteNumberTest, AcceptsWholeDecimalNumbers) {
  EXPECT_EQ(ParseFiniteNumber("3"), 3.0);
  EXPECT_EQ(ParseFiniteNumber("-0.25"), -0.25);
  EXPECT_EQ(ParseFiniteNumber("+1e-3"), 1e-3);
  EXPECT_EQ(ParseFiniteNumber("81.91"), 81.91);
}

TEST(ParseFiniteNumberTest, RejectsEverythingElse) {
  for (const char* bad :
       {"", " 1", "1 ", "1.5x", "abc", "nan", "NaN", "inf", "-inf", "1e999", "0x10", "--1", "+"}) {
    EXPECT_FALSE(ParseFiniteNumber(bad).has_value()) << "'" << bad << "'";
  }
}

// Found by fuzz/parse_number_fuzz.cc: stripping the '+' once left "-0" (and "-5") to from_chars.
TEST(ParseFiniteNumberTest, RejectsTwoSigns) {
  for (const char* bad : {"+-0", "+-5", "++5", "-+5"}) {
    EXPECT_FALSE(ParseFiniteNumber(bad).has_value()) << "'" << bad << "'";
  }
}

}  // namespace
}  // namespace plywood::perception
