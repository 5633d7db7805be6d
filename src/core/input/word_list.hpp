// Splits a comma-separated option value into words, refusing an empty one.
#pragma once
#include <string>
#include <vector>

namespace vibra {

/// A comma-separated option value as words (spaces dropped); throws
/// UsageError naming `option` when it is empty.
std::vector<std::string> word_list(const std::string& option, const std::string& text);

}  // namespace vibra
