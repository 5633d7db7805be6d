// The centered scheme's numerical frequency w~ = (2/dt) asin(w dt/2) (1.18) and its series (1.19).
#include "core/analysis/frequency/numerical_frequency.hpp"

#include <cmath>
#include <cstdio>

#include "core/error.hpp"

namespace vibra {

double numerical_frequency(double w, double dt) {
  if (!(w > 0) || !(dt > 0)) throw UsageError("the numerical frequency needs w > 0 and dt > 0");
  if (w * dt > 2) {
    char message[200];
    std::snprintf(message, sizeof message,
                  "dt=%g is above the stability limit 2/w = %g, where w~ is complex and the solution grows: use dt <= %g",
                  dt, 2 / w, 2 / w);
    throw UsageError(message);
  }
  return 2 / dt * std::asin(w * dt / 2);
}

double numerical_frequency_series(double w, double dt) { return w * (1 + w * w * dt * dt / 24); }

}  // namespace vibra
