#include "tests/support/metrics_json_test_support.h"

#include <gtest/gtest.h>

#include <cctype>

namespace plywood::testing {
namespace {

class Flattener {
 public:
  explicit Flattener(const std::string& json) : json_(json) {}

  std::map<std::string, std::string> Run() {
    Object("");
    Skip();
    EXPECT_EQ(pos_, json_.size()) << "trailing text in the JSON";
    return leaves_;
  }

 private:
  void Skip() {
    while (pos_ < json_.size() && std::isspace(static_cast<unsigned char>(json_[pos_]))) ++pos_;
  }
  bool Eat(char c) {
    Skip();
    if (pos_ < json_.size() && json_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  std::string String() {
    const std::size_t start = pos_;
    EXPECT_TRUE(Eat('"')) << "expected a string at " << pos_;
    while (pos_ < json_.size() && json_[pos_] != '"') pos_ += json_[pos_] == '\\' ? 2 : 1;
    ++pos_;
    return json_.substr(start, pos_ - start);
  }
  void Object(const std::string& prefix) {
    EXPECT_TRUE(Eat('{')) << "expected an object at " << pos_;
    if (Eat('}')) return;
    do {
      Skip();
      const std::string quoted = String();
      const std::string key = prefix + quoted.substr(1, quoted.size() - 2);
      EXPECT_TRUE(Eat(':')) << "expected ':' at " << pos_;
      Skip();
      if (pos_ < json_.size() && json_[pos_] == '{') {
        Object(key + ".");
      } else if (pos_ < json_.size() && json_[pos_] == '"') {
        leaves_[key] = String();
      } else {
        const std::size_t start = pos_;
        while (pos_ < json_.size() && json_[pos_] != ',' && json_[pos_] != '}' &&
               !std::isspace(static_cast<unsigned char>(json_[pos_]))) {
          ++pos_;
        }
        leaves_[key] = json_.substr(start, pos_ - start);
      }
    } while (Eat(',') && pos_ < json_.size());
    EXPECT_TRUE(Eat('}')) << "expected '}' at " << pos_;
  }

  const std::string& json_;
  std::size_t pos_ = 0;
  std::map<std::string, std::string> leaves_;
};

}  // namespace

std::map<std::string, std::string> FlattenMetricsJson(const std::string& json) {
  return Flattener(json).Run();
}

}  // namespace plywood::testing
