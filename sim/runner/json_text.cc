#include "sim/runner/json_text.h"

#include <stdexcept>

#include "sim/runner/format_number.h"

namespace plywood::sim {
namespace {

template <typename Json>
class JsonWriter {
 public:
  explicit JsonWriter(const JsonStyle& style) : style_(style) {}

  std::string Write(const Json& json) {
    Value(json, 0, style_.layout == JsonStyle::Layout::kOneLine);
    text_ += '\n';
    return std::move(text_);
  }

 private:
  static bool IsContainer(const Json& json) { return json.is_object() || json.is_array(); }

  // Appends only: GCC 12 at -O3 reports a false -Werror=restrict on "\n" + std::string(...).
  void NewLine(int depth) {
    text_ += '\n';
    text_.append(2 * static_cast<std::size_t>(depth), ' ');
  }

  void String(const std::string& text) {
    text_ += Json(text).dump(-1, ' ', false, Json::error_handler_t::replace);
  }

  void Number(const Json& json) {
    if (json.is_number_integer()) {
      text_ += json.dump();  // integers (signed or not) are exact in nlohmann's dump
    } else {
      const double value = json.template get<double>();
      text_ += style_.fixed_decimals < 0 ? FormatNumber(value)
                                         : FormatFixed(value, style_.fixed_decimals);
    }
  }

  void Value(const Json& json, int depth, bool inline_only) {
    if (json.is_object()) {
      Object(json, depth, inline_only);
    } else if (json.is_array()) {
      Array(json, depth, inline_only);
    } else if (json.is_string()) {
      String(json.template get_ref<const std::string&>());
    } else if (json.is_number()) {
      Number(json);
    } else if (json.is_boolean() || json.is_null()) {
      text_ += json.dump();
    } else {
      throw std::invalid_argument("WriteJson: binary values cannot be written as JSON text");
    }
  }

  void Object(const Json& json, int depth, bool inline_only) {
    if (json.empty()) {
      text_ += "{}";
      return;
    }
    text_ += '{';
    bool first = true;
    for (auto it = json.begin(); it != json.end(); ++it) {
      if (!first) text_ += inline_only ? ", " : ",";
      if (!inline_only) NewLine(depth + 1);
      String(it.key());
      text_ += ": ";
      Value(it.value(), depth + 1, inline_only);
      first = false;
    }
    if (!inline_only) NewLine(depth);
    text_ += '}';
  }

  void Array(const Json& json, int depth, bool inline_only) {
    bool one_per_line = false;
    if (!inline_only) {
      for (const Json& item : json) one_per_line = one_per_line || IsContainer(item);
    }
    text_ += '[';
    bool first = true;
    for (const Json& item : json) {
      if (!first) text_ += one_per_line ? "," : ", ";
      if (one_per_line) NewLine(depth + 1);
      Value(item, depth + 1, /*inline_only=*/true);  // inside an array: one line each
      first = false;
    }
    if (one_per_line) NewLine(depth);
    text_ += ']';
  }

  const JsonStyle style_;
  std::string text_;
};

}  // namespace

std::string WriteJson(const nlohmann::json& json, const JsonStyle& style) {
  return JsonWriter<nlohmann::json>(style).Write(json);
}

std::string WriteJson(const nlohmann::ordered_json& json, const JsonStyle& style) {
  return JsonWriter<nlohmann::ordered_json>(style).Write(json);
}

}  // namespace plywood::sim
