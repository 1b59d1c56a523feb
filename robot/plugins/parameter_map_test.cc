#include "robot/plugins/parameter_map.h"

#include <gtest/gtest.h>

#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "robot/plugins/registry.h"

namespace plywood::robot {
namespace {

ParameterMap Params(std::map<std::string, std::string> values) {
  return ParameterMap(std::move(values));
}

// The message of the std::invalid_argument `f` throws ("" when it throws nothing).
template <typename F>
std::string ErrorOf(F&& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ParameterMapTest, TypedGettersParseTheTextAndFallBackWhenAbsent) {
  const ParameterMap p =
      Params({{"gain", "0.5"}, {"count", "-3"}, {"on", "true"}, {"mode", "fast"}});
  EXPECT_EQ(p.GetDouble("gain", 1.0), 0.5);
  EXPECT_EQ(p.GetDouble("absent", 1.25), 1.25);
  EXPECT_EQ(p.GetInt("count", 0), -3);
  EXPECT_TRUE(p.GetBool("on", false));
  EXPECT_EQ(p.GetString("mode", "slow"), "fast");
  EXPECT_EQ(Params({{"x", "1e-3"}}).GetDouble("x", 0.0), 1e-3);
}

TEST(ParameterMapTest, BadValuesNameTheKeyAndTheText) {
  const ParameterMap p = Params({{"gain", "1.5"}, {"n", "2.5"}, {"nan", "nan"}, {"flag", "yes"}});
  EXPECT_EQ(ErrorOf([&] { p.GetDouble("gain", 0.0, 0.0, 1.0); }),
            "gain: expected a number in [0, 1], got '1.5'");
  EXPECT_EQ(ErrorOf([&] { p.GetDouble("gain", 0.0, 2.0); }),
            "gain: expected a number >= 2, got '1.5'");
  EXPECT_EQ(ErrorOf([&] { p.GetInt("n", 0); }), "n: expected a whole number, got '2.5'");
  EXPECT_EQ(ErrorOf([&] { p.GetDouble("nan", 0.0); }), "nan: expected a finite number, got 'nan'");
  EXPECT_EQ(ErrorOf([&] { p.GetBool("flag", false); }), "flag: expected true or false, got 'yes'");
  EXPECT_EQ(ErrorOf([&] {
              Params({{"n", "7"}}).GetInt("n", 0, 1, 5);
            }),
            "n: expected a whole number in [1, 5], got '7'");
  EXPECT_EQ(ErrorOf([&] {
              Params({{"n", "99999999999"}}).GetInt("n", 0);
            }),
            "n: expected a whole number <= 2147483647, got '99999999999'");
}

TEST(ParameterMapTest, CheckAllReadReportsTheFirstKeyNoGetterAskedFor) {
  const ParameterMap p = Params({{"gain", "0.5"}, {"gian", "1"}});
  EXPECT_EQ(ErrorOf([&] { p.CheckAllRead(); }),
            "gain: unknown key (this algorithm takes no options)");
  p.GetDouble("gain", 1.0);
  p.GetInt("window", 3);  // asked for but absent: listed as known
  EXPECT_EQ(ErrorOf([&] { p.CheckAllRead(); }), "gian: unknown key (known here: gain, window)");
  EXPECT_EQ(ErrorOf([&] { Params({{"gain", "1"}}).GetDouble("gain", 0.0); }), "");
}

struct Thing {
  virtual ~Thing() = default;
  double value = 0.0;
};

struct RegisteredThing {
  std::string name;
  std::function<std::unique_ptr<Thing>(double scale, const ParameterMap&)> make;
};

TEST(RegistryTest, AddsFindsAndBuildsCheckingEveryOptionWasRead) {
  Registry<RegisteredThing> registry;
  registry.Add({"scaled", [](double scale, const ParameterMap& o) {
                  auto thing = std::make_unique<Thing>();
                  thing->value = scale * o.GetDouble("gain", 1.0);
                  return thing;
                }});
  ASSERT_NE(registry.Find("scaled"), nullptr);
  EXPECT_EQ(registry.Find("other"), nullptr);
  EXPECT_EQ(registry.Names(), std::vector<std::string>{"scaled"});
  EXPECT_EQ(MakeRegistered(*registry.Find("scaled"), Params({{"gain", "3"}}), 2.0)->value, 6.0);
  EXPECT_EQ(ErrorOf([&] {
              MakeRegistered(*registry.Find("scaled"), Params({{"gian", "3"}}), 2.0);
            }),
            "gian: unknown key (known here: gain)");
}

TEST(RegistryTest, RejectsBadAndRepeatedNamesAndMissingFactories) {
  Registry<RegisteredThing> registry;
  const auto make = [](double, const ParameterMap&) { return std::make_unique<Thing>(); };
  registry.Add({"a_1", make});
  EXPECT_NE(ErrorOf([&] {
              registry.Add({"a_1", make});
            }).find("registered twice"),
            std::string::npos);
  for (const char* bad : {"", "Upper", "1st", "with space", "dot.ted"}) {
    EXPECT_NE(ErrorOf([&] {
                registry.Add({bad, make});
              }).find("not a valid algorithm name"),
              std::string::npos)
        << bad;
  }
  EXPECT_NE(ErrorOf([&] {
              registry.Add({"no_factory", nullptr});
            }).find("has no factory"),
            std::string::npos);
  EXPECT_EQ(registry.Names().size(), 1u);
  const Registry<RegisteredThing> empty;
  EXPECT_TRUE(empty.empty());
}

TEST(RegistryTest, AFactoryThatReturnsNothingIsAnError) {
  const RegisteredThing null_maker{
      "null", [](double, const ParameterMap&) { return std::unique_ptr<Thing>(); }};
  EXPECT_EQ(ErrorOf([&] { MakeRegistered(null_maker, ParameterMap(), 1.0); }),
            "the factory of 'null' returned nothing");
}

}  // namespace
}  // namespace plywood::robot
