// The error column (--panels error): a run with e^n = u^n - u_e(t_n) added.
#pragma once
#include <memory>

#include "core/trajectory.hpp"

namespace vibra {

/// The run with one more column, `error` = main quantity - exact solution
/// (`--panels error`): the scheme's global error e^n = u^n - u_e(t_n) at every
/// sample and between them. Throws UsageError when the run has no exact
/// solution (an approximation such as the pendulum's small-angle one does
/// not count: its difference is not the scheme's error).
std::unique_ptr<Trajectory> with_error_column(std::unique_ptr<Trajectory> run);

}  // namespace vibra
