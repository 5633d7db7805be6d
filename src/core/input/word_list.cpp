// Splits a comma-separated option value into words, refusing an empty one.
#include "core/input/word_list.hpp"

#include <sstream>

#include "core/error.hpp"

namespace vibra {

std::vector<std::string> word_list(const std::string& option, const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    std::erase(item, ' ');
    if (!item.empty()) out.push_back(item);
  }
  if (out.empty()) throw UsageError(option + " is empty: give a comma-separated list");
  return out;
}

}  // namespace vibra
