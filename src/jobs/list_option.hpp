// Reads a comma-separated list of positive numbers (expressions allowed) for an experiment's option.
#pragma once
#include <string>
#include <vector>

#include "core/input/word_list.hpp"

namespace vibra::app {

using vibra::word_list;

/// A comma-separated list of numbers, each > 0 and possibly an expression
/// such as 2*pi/40; throws UsageError naming `option` and the bad item.
std::vector<double> positive_list(const std::string& option, const std::string& text);

}  // namespace vibra::app
