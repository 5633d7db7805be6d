// The messages that end an adaptive run which cannot advance in doubles.
#include "core/schemes/step_refusal.hpp"

#include <string>

#include "core/error.hpp"
#include "core/input/quoted_value.hpp"
#include "core/schemes/step_controller.hpp"

namespace vibra {

namespace {
/// What went wrong and what to do, by failure; the caller adds where.
struct Advice {
  StepFailure failure;
  const char* problem;
  const char* fix;
};
static_assert(StepControllerLimits::rejections_in_a_row == 100, "kAdvice's rejected_in_a_row says 100");
constexpr Advice kAdvice[] = {
    {StepFailure::step_underflow, "the step size fell below what doubles resolve",
     "the solution blows up or jumps there, or the tolerances ask too much: end T before it, or raise rtol/atol"},
    {StepFailure::non_finite_error, "the error estimate is not finite for any step size",
     "an input is infinite or undefined just after (e.g. sqrt of a negative F): check the --set values, or end T before it"},
    {StepFailure::rejected_in_a_row, "100 step sizes in a row were rejected",
     "the tolerances ask for more than doubles resolve there: raise rtol/atol"},
};
}  // namespace

void refuse_adaptive_step(const char* scheme, StepFailure failure, double t, double h) {
  for (const Advice& advice : kAdvice)
    if (advice.failure == failure)
      throw UsageError(std::string(scheme) + ": " + advice.problem + " at t = " + short_number(t) +
                       " (h = " + short_number(h) + "): " + advice.fix);
  throw UsageError(std::string(scheme) + ": the run cannot advance at t = " + short_number(t));
}

}  // namespace vibra
