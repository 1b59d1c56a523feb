#include "eval/sonar_map/squared_distance_transform.h"

#include <algorithm>
#include <cstddef>
#include <limits>

namespace plywood::eval {
namespace {

// d[q] = min over p of (q - p)^2 + f[p] along one row or column; v, z are scratch of n and n + 1.
void SquaredDistance1d(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v,
                       std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  const double inf = std::numeric_limits<double>::infinity();
  int k = 0;
  v[0] = 0;
  z[0] = -inf;
  z[1] = inf;
  // Where the parabola rooted at q overtakes the one rooted at p.
  const auto crossing = [&](int q, int p) {
    return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * q - 2.0 * p);
  };
  for (int q = 1; q < n; ++q) {
    double s = crossing(q, v[k]);
    while (s <= z[k]) s = crossing(q, v[--k]);
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = inf;
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    const double dq = q - v[k];
    d[q] = std::min(kNoSetCell, dq * dq + f[v[k]]);
  }
}

}  // namespace

std::vector<double> SquaredDistanceToSet(const std::vector<char>& set, int width, int height) {
  std::vector<double> out(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) out[i] = set[i] ? 0.0 : kNoSetCell;
  const int longest = std::max(width, height);
  std::vector<double> f, d;
  std::vector<int> v(static_cast<std::size_t>(longest));
  std::vector<double> z(static_cast<std::size_t>(longest) + 1);
  // Transforms `lines` lines of `length` cells each, cell k of line l at first * l + step * k.
  const auto transform = [&](int lines, int length, std::size_t first, std::size_t step) {
    if (length == 0) return;
    f.resize(static_cast<std::size_t>(length));
    d.resize(f.size());
    for (int l = 0; l < lines; ++l) {
      for (int k = 0; k < length; ++k) f[k] = out[first * l + step * k];
      SquaredDistance1d(f, d, v, z);
      for (int k = 0; k < length; ++k) out[first * l + step * k] = d[k];
    }
  };
  const auto w = static_cast<std::size_t>(width);
  transform(width, height, 1, w);  // the columns, then the rows
  transform(height, width, w, 1);
  return out;
}

}  // namespace plywood::eval
