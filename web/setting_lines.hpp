// The browser API's settings argument: one KEY=VALUE a line, as a list (empty lines dropped).
#pragma once
#include <sstream>
#include <string>
#include <vector>

namespace vibra::web {

inline std::vector<std::string> lines_of(const char* text) {
  std::vector<std::string> lines;
  std::istringstream in(text ? text : "");
  for (std::string line; std::getline(in, line);)
    if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace vibra::web
