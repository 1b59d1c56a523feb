#pragma once

#include <mujoco/mujoco.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "msgs/shortest_number.h"

namespace plywood::sim {

// The ids of the objects of one kind that belong to the bodies [first_body, end_body), in order.
std::vector<int> IdsOnBodies(const int* body_of, int count, int first_body, int end_body);

// Compares objects' fields between a scene (world and robot compiled as one model) and one of its
// files compiled alone; the first difference found is kept as "KIND 'NAME': FIELD is X
// IN_SCENE, Y IN_ALONE". RobotChangedByWorld and WorldChangedByRobot word it for their file.
class ModelFieldComparison {
 public:
  // `in_scene` / `in_alone`: how the message places the two values ("in this world", "in the
  // robot's file alone"); `unnamed_suffix` follows an unnamed object's "KIND #N".
  ModelFieldComparison(const mjModel* alone, std::string in_scene, std::string in_alone,
                       std::string unnamed_suffix)
      : alone_(alone),
        in_scene_(std::move(in_scene)),
        in_alone_(std::move(in_alone)),
        unnamed_suffix_(std::move(unnamed_suffix)) {}

  // Object `s` of the scene is object `a` of the file alone; messages name the file's object
  // `named` of `type` (a degree of freedom is named by its joint).
  void Object(mjtObj type, const char* kind, int s, int a, int named = -1) {
    type_ = type, kind_ = kind, s_ = s, a_ = a, named_ = named < 0 ? a : named;
  }

  // Field `name`, n values per object, in each model's array.
  template <typename T>
  void Field(const char* name, const T* in_scene, const T* alone, int n) {
    if (problem_) return;
    const T* x = in_scene + static_cast<long>(n) * s_;
    const T* y = alone + static_cast<long>(n) * a_;
    if (std::equal(x, x + n, y)) return;
    const char* object_name = mj_id2name(alone_, type_, named_);
    const std::string object = object_name ? std::string(kind_) + " '" + object_name + "'"
                                           : "unnamed " + std::string(kind_) + " #" +
                                                 std::to_string(named_) + unnamed_suffix_;
    problem_ = object + ": " + name + " is " + Values(x, n) + " " + in_scene_ + ", " +
               Values(y, n) + " " + in_alone_;
  }

  const std::optional<std::string>& problem() const { return problem_; }

 private:
  template <typename T>
  static std::string Values(const T* v, int n) {
    std::string text;
    for (int i = 0; i < n; ++i) text += (i ? " " : "") + msgs::ShortestNumber(double(v[i]));
    return text;
  }

  const mjModel* alone_;
  std::string in_scene_, in_alone_, unnamed_suffix_;
  mjtObj type_ = mjOBJ_BODY;
  const char* kind_ = "body";
  int s_ = 0, a_ = 0, named_ = 0;
  std::optional<std::string> problem_;
};

}  // namespace plywood::sim
