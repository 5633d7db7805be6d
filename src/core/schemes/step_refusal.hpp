// Why an adaptive run cannot go on (docs/schemes.md, "Adaptive"): the one
// line that ends it, naming the setting to change.
#pragma once

namespace vibra {

/// The ways an adaptive step can fail for good.
enum class StepFailure {
  step_underflow,     ///< h fell below what doubles resolve at t
  non_finite_error,   ///< every step size down to that gave a non-finite error norm
  rejected_in_a_row,  ///< StepControllerLimits::rejections_in_a_row rejections
};

/// Throws the UsageError for `failure` of `scheme` at time t with step h.
[[noreturn, gnu::cold]] void refuse_adaptive_step(const char* scheme, StepFailure failure, double t, double h);

}  // namespace vibra
