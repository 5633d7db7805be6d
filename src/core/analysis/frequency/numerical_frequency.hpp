// The centered scheme's numerical frequency w~ = (2/dt) asin(w dt/2) (1.18) and its series (1.19).
#pragma once

namespace vibra {

/// The centered scheme's frequency w~ = (2/dt) asin(w dt/2) (1.18): its
/// discrete solution is I cos(w~ t_n). Throws UsageError above the stability
/// limit dt = 2/w, where w~ is complex; at the limit w~ = pi/dt.
double numerical_frequency(double w, double dt);

/// The series w (1 + w^2 dt^2/24) of w~ (1.19), accurate to O(dt^4).
double numerical_frequency_series(double w, double dt);

}  // namespace vibra
