#include "perception/logs/fixed_decimals.h"

#include <charconv>
#include <cmath>
#include <cstdint>

namespace plywood::perception {

char* WriteFixedDecimals(char* first, char* last, double value, int decimals) {
  static constexpr double kScale[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  static constexpr std::uint64_t kPower[] = {1,      10,      100,      1000,      10000,
                                             100000, 1000000, 10000000, 100000000, 1000000000};
  if (decimals < 0 || decimals > 9 || !std::isfinite(value)) {
    return std::to_chars(first, last, value, std::chars_format::fixed, decimals).ptr;
  }
  const double scale = kScale[decimals];  // exact: 10^9 < 2^53
  const double magnitude = std::fabs(value);
  const double p = magnitude * scale;  // rounded product
  if (!(p < 4503599627370496.0)) {     // 2^52: the integer and the halves below stay exact
    return std::to_chars(first, last, value, std::chars_format::fixed, decimals).ptr;
  }
  // The exact product is p + e (fma gives the product's rounding error exactly; no underflow
  // matters: below 2^-900 the value rounds to 0 whatever e is).
  const double e = std::fma(magnitude, scale, -p);
  double n = std::nearbyint(p);  // round half to even, the default rounding mode
  const double r = p - n;        // exact (Sterbenz), a multiple of p's ulp, in [-0.5, 0.5]
  // p's rounding error e is at most half an ulp of p, so the exact product lies on the other
  // side of a half from n only when p itself is the half: then e decides, and e == 0 is a true
  // tie, which nearbyint already broke to even.
  if (r == 0.5 && e > 0.0) n += 1.0;
  if (r == -0.5 && e < 0.0) n -= 1.0;
  auto digits = static_cast<std::uint64_t>(n);
  char* out = first;
  if (std::signbit(value)) *out++ = '-';
  const std::uint64_t power = kPower[decimals];
  out = std::to_chars(out, last, digits / power).ptr;
  if (decimals > 0) {
    *out++ = '.';
    std::uint64_t fraction = digits % power;
    for (int i = decimals - 1; i >= 0; --i) {
      out[i] = static_cast<char>('0' + fraction % 10);
      fraction /= 10;
    }
    out += decimals;
  }
  return out;
}

}  // namespace plywood::perception
