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
  const auto at = [&](int ix, int iy) -> double& {
    return out[static_cast<std::size_t>(iy) * width + ix];
  };
  f.resize(static_cast<std::size_t>(height));
  d.resize(f.size());
  for (int ix = 0; ix < width && height > 0; ++ix) {
    for (int iy = 0; iy < height; ++iy) f[iy] = at(ix, iy);
    SquaredDistance1d(f, d, v, z);
    for (int iy = 0; iy < height; ++iy) at(ix, iy) = d[iy];
  }
  f.resize(static_cast<std::size_t>(width));
  d.resize(f.size());
  for (int iy = 0; iy < height && width > 0; ++iy) {
    for (int ix = 0; ix < width; ++ix) f[ix] = at(ix, iy);
    SquaredDistance1d(f, d, v, z);
    for (int ix = 0; ix < width; ++ix) at(ix, iy) = d[ix];
  }
  return out;
}

}  // namespace plywood::eval
