// SolutionStream: a scheme's samples one at a time in constant memory, stopping at a non-finite value.
#include "core/solution_stream.hpp"

#include <cstdio>

namespace vibra {

void report_non_finite(long long index, double t) {
  char time[32];
  std::snprintf(time, sizeof time, "%.6g", t);
  // At the start or after one step no scheme can have grown unstable: the
  // input itself is infinite or overflows (F=ln(0), I=1e300 squared).
  if (index <= 1)
    throw SolutionError("the solution is non-finite at step " + std::to_string(index) + " (t = " + time +
                            "): an input is infinite or overflows, e.g. a formula that gives inf or nan such as "
                            "ln(0) or 1/0, or a value too large: check the --set values",
                        index, t);
  throw SolutionError("the solution became non-finite at step " + std::to_string(index) + " (t = " + time +
                      "): reduce dt or choose a stable scheme",
                      index, t);
}

}  // namespace vibra
