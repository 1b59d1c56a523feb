#include "sim/runner/json_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace plywood::sim {
namespace {

using Json = nlohmann::ordered_json;

TEST(JsonTextTest, OneItemPerLineKeepsScalarArraysAndArrayItemsOnOneLine) {
  const Json json = {
      {"room", {0.5, 1, -2.25}},
      {"items", Json::array({Json{{"id", 1}, {"at", {1.5, 2}}}, Json::array({3, 4})})},
      {"empty", Json::array()},
      {"nested", {{"flag", true}, {"none", nullptr}, {"name", "a\"b\n"}}}};
  EXPECT_EQ(WriteJson(json),
            "{\n"
            "  \"room\": [0.5, 1, -2.25],\n"
            "  \"items\": [\n"
            "    {\"id\": 1, \"at\": [1.5, 2]},\n"
            "    [3, 4]\n"
            "  ],\n"
            "  \"empty\": [],\n"
            "  \"nested\": {\n"
            "    \"flag\": true,\n"
            "    \"none\": null,\n"
            "    \"name\": \"a\\\"b\\n\"\n"
            "  }\n"
            "}\n");
}

TEST(JsonTextTest, OneLineLayout) {
  const Json json = {{"lines", {{"b", {{"us_per_scan", 42.5}}}, {"a", Json::object()}}}};
  EXPECT_EQ(WriteJson(json, {.layout = JsonStyle::Layout::kOneLine}),
            "{\"lines\": {\"b\": {\"us_per_scan\": 42.5}, \"a\": {}}}\n");
}

TEST(JsonTextTest, SortedKeysForPlainJson) {
  nlohmann::json json;
  json["b"] = 1;
  json["a"] = 2;
  EXPECT_EQ(WriteJson(json), "{\n  \"a\": 2,\n  \"b\": 1\n}\n");
}

TEST(JsonTextTest, NumbersAreShortestRoundTripNotNlohmannsDump) {
  // nlohmann's own dump writes 12.0, 0.0001 and 1000000000000000.0 for these three.
  const Json json = Json::array({12.0, 0.0001, 1e15, -2.5e-7, 0.1, 7, -3});
  EXPECT_EQ(WriteJson(json), "[12, 1e-04, 1e+15, -2.5e-07, 0.1, 7, -3]\n");
  EXPECT_EQ(Json(12.0).dump(), "12.0");  // why WriteJson formats numbers itself
}

TEST(JsonTextTest, NonFiniteNumbersAreNull) {
  const Json json = Json::array(
      {std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity()});
  EXPECT_EQ(WriteJson(json), "[null, null]\n");
  EXPECT_EQ(WriteJson(json, {.fixed_decimals = 4}), "[null, null]\n");
}

TEST(JsonTextTest, FixedDecimalsWriteMinusZeroAsZeroAndLeaveIntegersAlone) {
  const Json json = Json::array({1.0, -0.00001, -0.00007, 2.123456, 3});
  EXPECT_EQ(WriteJson(json, {.fixed_decimals = 4}), "[1.0000, 0.0000, -0.0001, 2.1235, 3]\n");
}

TEST(JsonTextTest, EveryDoubleReadsBackExactly) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::uint64_t> bits;
  int checked = 0;
  while (checked < 20000) {
    const std::uint64_t raw = bits(rng);
    double value;
    std::memcpy(&value, &raw, sizeof value);
    if (!std::isfinite(value)) continue;
    const std::string text = WriteJson(Json::array({value}));
    const double back = nlohmann::json::parse(text)[0].get<double>();
    ASSERT_EQ(back, value) << text;
    ++checked;
  }
}

}  // namespace
}  // namespace plywood::sim
