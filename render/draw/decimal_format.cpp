// Writes a number with one decimal exactly as printf("%.1f") would, without printf's cost.
#include "render/draw/decimal_format.hpp"

#include <cmath>
#include <cstdio>

namespace vibra::render {

// x * 10 is exact in long double (64-bit mantissa), so ties are found
// exactly and, like glibc, rounded to even.
char* format_one_decimal(char* out, double x) {
  if (!(std::abs(x) < 1e15)) return out + std::snprintf(out, 320, "%.1f", x);
  const long double tenths = static_cast<long double>(std::abs(x)) * 10;
  const long double whole = std::floor(tenths), fraction = tenths - whole;
  unsigned long long k = static_cast<unsigned long long>(whole);
  if (fraction > 0.5L || (fraction == 0.5L && (k & 1))) ++k;
  if (std::signbit(x)) *out++ = '-';  // printf keeps the sign of -0.0 and of -0.04
  char digits[24];
  int n = 0;
  do digits[n++] = char('0' + k % 10), k /= 10;
  while (k > 0);
  if (n == 1) digits[n++] = '0';
  for (int i = n - 1; i >= 1; --i) *out++ = digits[i];
  *out++ = '.';
  *out++ = digits[0];
  return out;
}

}  // namespace vibra::render
