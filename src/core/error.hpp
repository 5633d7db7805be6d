// vibra's error types: UsageError (bad input, exit 2) and SolutionError (a non-finite value).
#pragma once
#include <stdexcept>
#include <string>

namespace vibra {

/// Bad input from the user (unknown key, malformed value, dt above the
/// stability limit...). The message is one line naming the problem and the
/// fix; the CLI prints it and exits with code 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// The solution became non-finite or an implicit step did not converge.
/// The message names the step and time, which are also kept as numbers (for
/// the Python module's exception); the CLI exits with code 2.
struct SolutionError : std::runtime_error {
  SolutionError(const std::string& message, long long step, double t)
      : std::runtime_error(message), step(step), t(t) {}
  long long step;
  double t;
};

}  // namespace vibra
