// Reads a comma-separated list of positive numbers (expressions allowed) for an experiment's option.
#include "jobs/list_option.hpp"

#include <cmath>
#include <sstream>

#include "core/error.hpp"
#include "core/input/expression.hpp"

namespace vibra::app {

std::vector<double> positive_list(const std::string& option, const std::string& text) {
  std::vector<double> out;
  for (const auto& item : word_list(option, text)) {
    const double x = evaluate_constant(option, item);
    if (!(x > 0) || !std::isfinite(x)) throw UsageError(option + " value '" + item + "' must be a positive number");
    out.push_back(x);
  }
  return out;
}

}  // namespace vibra::app
