// The messages that end an adaptive run which cannot advance: each failure's problem and fix, with where, in one line.
#include <catch2/catch.hpp>
#include <string>

#include "core/error.hpp"
#include "core/schemes/step_controller.hpp"
#include "core/schemes/step_refusal.hpp"

using namespace vibra;

namespace {
std::string refusal(StepFailure failure) {
  try {
    refuse_adaptive_step("rkf45", failure, 2.5, 1e-300);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no refusal";
}
}  // namespace

TEST_CASE("each way an adaptive run cannot advance is refused with its problem, where, and its fix", "[step_refusal]") {
  CHECK(refusal(StepFailure::step_underflow) ==
        "rkf45: the step size fell below what doubles resolve at t = 2.5 (h = 1e-300): the solution blows up or jumps "
        "there, or the tolerances ask too much: end T before it, or raise rtol/atol");
  CHECK(refusal(StepFailure::non_finite_error).rfind(
            "rkf45: the error estimate is not finite for any step size at t = 2.5 (h = 1e-300): an input is infinite", 0) == 0);
  CHECK(refusal(StepFailure::rejected_in_a_row) ==
        "rkf45: 100 step sizes in a row were rejected at t = 2.5 (h = 1e-300): the tolerances ask for more than "
        "doubles resolve there: raise rtol/atol");
}
