// The phase lag of a numerical maximum behind the exact solution's (Exercise 1.2).
#pragma once
#include <functional>

namespace vibra {

/// The phase by which a numerical maximum at t_max lags the exact solution's
/// nearest maximum (Exercise 1.2): 2 pi (t_max - t_exact) / period, in
/// radians; negative when the numerical solution runs ahead (the centered
/// scheme's w~ > w). The exact maximum is searched within half a period of
/// t_max, so lags up to pi are told apart.
double phase_lag(const std::function<double(double)>& exact, double period, double t_max);

}  // namespace vibra
