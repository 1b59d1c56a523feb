#include "sim/world/model_field_comparison.h"

namespace plywood::sim {

std::vector<int> IdsOnBodies(const int* body_of, int count, int first_body, int end_body) {
  std::vector<int> ids;
  for (int i = 0; i < count; ++i) {
    if (body_of[i] >= first_body && body_of[i] < end_body) ids.push_back(i);
  }
  return ids;
}

}  // namespace plywood::sim
