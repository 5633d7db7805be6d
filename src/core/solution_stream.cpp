#include "core/solution_stream.hpp"

#include <cstdio>

namespace vibra {

void report_non_finite(long long index, double t) {
  char time[32];
  std::snprintf(time, sizeof time, "%.6g", t);
  throw SolutionError("the solution became non-finite at step " + std::to_string(index) + " (t = " + time +
                      "): reduce dt or choose a stable scheme",
                      index, t);
}

}  // namespace vibra
