#pragma once
#include <string>
#include <vector>

namespace vibra::app {

/// A comma-separated option value as words (spaces dropped); throws
/// UsageError naming `option` when it is empty.
std::vector<std::string> word_list(const std::string& option, const std::string& text);

/// A comma-separated list of numbers, each > 0 and possibly an expression
/// such as 2*pi/40; throws UsageError naming `option` and the bad item.
std::vector<double> positive_list(const std::string& option, const std::string& text);

}  // namespace vibra::app
